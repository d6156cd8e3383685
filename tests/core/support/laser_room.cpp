#include "laser_room.hpp"

#include <algorithm>
#include <cmath>

namespace legofeup::testing {

std::shared_ptr<const OccupancyGrid> grid_of_boxes(const Vector2& min, const Vector2& max,
                                                   double resolution,
                                                   const std::vector<OccupiedBox>& boxes) {
    const int width = static_cast<int>(std::lround((max.x() - min.x()) / resolution));
    const int height = static_cast<int>(std::lround((max.y() - min.y()) / resolution));
    std::vector<CellState> cells(static_cast<std::size_t>(width) * static_cast<std::size_t>(height),
                                 CellState::Free);
    for (int row = 0; row < height; ++row) {
        for (int col = 0; col < width; ++col) {
            const Vector2 centre = min + resolution * Vector2(col + 0.5, row + 0.5);
            const bool occupied = std::any_of(boxes.begin(), boxes.end(), [&](const auto& box) {
                return (centre.array() >= box.min.array()).all()
                       && (centre.array() <= box.max.array()).all();
            });
            if (occupied) {
                cells[static_cast<std::size_t>(row) * static_cast<std::size_t>(width)
                      + static_cast<std::size_t>(col)] = CellState::Occupied;
            }
        }
    }
    return std::make_shared<const OccupancyGrid>(width, height, resolution,
                                                 Pose2{min.x(), min.y(), 0.0}, std::move(cells));
}

std::shared_ptr<const OccupancyGrid> laser_test_room(const std::vector<OccupiedBox>& extra) {
    std::vector<OccupiedBox> boxes{
        {{-2.1, -2.1}, {2.1, -2.0}},  // walls
        {{-2.1, 2.0}, {2.1, 2.1}},   {{-2.1, -2.1}, {-2.0, 2.1}},
        {{2.0, -2.1}, {2.1, 2.1}},   {{-0.3, 0.1}, {0.2, 0.5}},  // inside the square path
        {{1.4, -0.6}, {1.7, -0.2}},                              // right of it
        {{-1.8, 1.3}, {-1.4, 1.5}},                              // top left
        {{0.5, -1.7}, {0.6, -1.5}},                              // a pillar below it
    };
    boxes.insert(boxes.end(), extra.begin(), extra.end());
    return grid_of_boxes(Vector2(-2.2, -2.2), Vector2(2.2, 2.2), 0.05, boxes);
}

std::shared_ptr<const OccupancyGrid> closet_room(const Vector2& centre) {
    const Vector2 half(0.3, 0.3);
    const Vector2 wall(0.05, 0.05);
    const Vector2 lo = centre - half;
    const Vector2 hi = centre + half;
    return grid_of_boxes(lo - 2.0 * wall, hi + 2.0 * wall, 0.05,
                         {
                             {{lo.x() - wall.x(), lo.y() - wall.y()}, {hi.x() + wall.x(), lo.y()}},
                             {{lo.x() - wall.x(), hi.y()}, {hi.x() + wall.x(), hi.y() + wall.y()}},
                             {{lo.x() - wall.x(), lo.y()}, {lo.x(), hi.y()}},
                             {{hi.x(), lo.y()}, {hi.x() + wall.x(), hi.y()}},
                         });
}

void synthesize_scan(const OccupancyGrid& grid, const Pose2& scanner_pose,
                     const ScanGeometry& geometry, double sigma, std::mt19937_64& rng,
                     LaserScan& out) {
    expected_scan(grid, scanner_pose, geometry, out);
    std::normal_distribution<double> noise(0.0, sigma);
    for (int i = 0; i < out.beam_count; ++i) {
        std::uint16_t& range = out.range_mm[static_cast<std::size_t>(i)];
        if (range < kRangeFirstValid) {
            continue;
        }
        const double noisy = std::round(range + 1000.0 * noise(rng));
        range = static_cast<std::uint16_t>(std::clamp(noisy, double{kRangeFirstValid}, 65535.0));
    }
}

}  // namespace legofeup::testing
