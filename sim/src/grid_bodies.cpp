#include "grid_bodies.hpp"

#include <algorithm>
#include <cstddef>
#include <tuple>

#include "box2d_convert.hpp"

namespace legofeup::sim {
namespace {

constexpr float kFriction = 0.3f;  // as the walls

bool occupied(const OccupancyGrid& grid, int col, int row) {
    const auto index = static_cast<std::size_t>(row) * static_cast<std::size_t>(grid.width())
                       + static_cast<std::size_t>(col);
    return grid.cells()[index] == CellState::Occupied;
}

}  // namespace

std::vector<CellRectangle> occupied_rectangles(const OccupancyGrid& grid) {
    std::vector<CellRectangle> done;
    // Rectangles whose top row is the row below the current one, by first column (each
    // column starts at most one run per row, so the first column identifies a run).
    std::vector<CellRectangle> open;
    std::vector<CellRectangle> still_open;
    for (int row = 0; row < grid.height(); ++row) {
        still_open.clear();
        std::size_t below = 0;  // open is sorted by col: walk it alongside the row
        for (int col = 0; col < grid.width();) {
            if (!occupied(grid, col, row)) {
                ++col;
                continue;
            }
            int end = col + 1;  // pass 1: the maximal run [col, end)
            while (end < grid.width() && occupied(grid, end, row)) {
                ++end;
            }
            // Pass 2: the rectangle below that ends in exactly this run grows by one row.
            while (below < open.size() && open[below].col < col) {
                done.push_back(open[below++]);  // its run did not continue: closed
            }
            if (below < open.size() && open[below].col == col && open[below].width == end - col) {
                CellRectangle grown = open[below++];
                ++grown.height;
                still_open.push_back(grown);
            } else {
                still_open.push_back({col, row, end - col, 1});
            }
            col = end;
        }
        done.insert(done.end(), open.begin() + static_cast<std::ptrdiff_t>(below), open.end());
        std::swap(open, still_open);
    }
    done.insert(done.end(), open.begin(), open.end());
    std::sort(done.begin(), done.end(), [](const CellRectangle& a, const CellRectangle& b) {
        return std::tie(a.row, a.col) < std::tie(b.row, b.col);
    });
    return done;
}

b2Body* build_grid_body(b2World& world, const OccupancyGrid& grid) {
    const std::vector<CellRectangle> rectangles = occupied_rectangles(grid);
    if (rectangles.empty()) {
        return nullptr;
    }
    b2BodyDef definition;  // static, at the origin of the grid: its cells are axis-aligned there
    definition.position = to_b2(grid.origin().x, grid.origin().y);
    definition.angle = static_cast<float>(grid.origin().theta);
    b2Body* body = world.CreateBody(&definition);
    const double cell = grid.resolution();
    for (const CellRectangle& rectangle : rectangles) {
        // Cell (c, r) spans [c·s, (c + 1)·s] × [r·s, (r + 1)·s] in the grid frame.
        const double half_width = 0.5 * rectangle.width * cell;
        const double half_height = 0.5 * rectangle.height * cell;
        const b2Vec2 centre =
            to_b2(rectangle.col * cell + half_width, rectangle.row * cell + half_height);
        b2PolygonShape box;
        box.SetAsBox(static_cast<float>(half_width), static_cast<float>(half_height), centre, 0.0f);
        b2FixtureDef fixture;
        fixture.shape = &box;
        fixture.friction = kFriction;
        body->CreateFixture(&fixture);
    }
    return body;
}

}  // namespace legofeup::sim
