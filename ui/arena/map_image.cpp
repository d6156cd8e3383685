#include "legofeup/ui/arena/map_image.hpp"

#include <QPolygonF>
#include <cmath>

namespace legofeup::ui {

QImage map_image(const OccupancyGrid& grid, const MapColors& colors) {
    if (grid.empty() || grid.width() <= 0 || grid.height() <= 0) {
        return {};
    }
    QImage image(grid.width(), grid.height(), QImage::Format_ARGB32_Premultiplied);
    // The picture's pixels are premultiplied by their alpha (a translucent map colour).
    const QRgb occupied = qPremultiply(colors.occupied.rgba());
    const QRgb unknown = qPremultiply(colors.unknown.rgba());
    const QRgb free = qRgba(0, 0, 0, 0);
    const std::vector<CellState>& cells = grid.cells();
    for (int row = 0; row < grid.height(); ++row) {
        // Grid row 0 is the bottom one; the picture's first line is its top.
        auto* line = reinterpret_cast<QRgb*>(image.scanLine(grid.height() - 1 - row));
        const auto first = static_cast<std::size_t>(row) * static_cast<std::size_t>(grid.width());
        for (int col = 0; col < grid.width(); ++col) {
            switch (cells[first + static_cast<std::size_t>(col)]) {
                case CellState::Occupied:
                    line[col] = occupied;
                    break;
                case CellState::Unknown:
                    line[col] = unknown;
                    break;
                case CellState::Free:
                    line[col] = free;
                    break;
            }
        }
    }
    return image;
}

QTransform image_to_world(const OccupancyGrid& grid) {
    // x_w = c·r·u + s·r·v + (o_x − s·r·H)
    // y_w = s·r·u − c·r·v + (o_y + c·r·H)
    // (QTransform: x' = m11·x + m21·y + dx, y' = m12·x + m22·y + dy.)
    const double r = grid.resolution();
    const double c = std::cos(grid.origin().theta);
    const double s = std::sin(grid.origin().theta);
    const double h = grid.height();
    return {c * r, s * r, s * r, -c * r, grid.origin().x - s * r * h, grid.origin().y + c * r * h};
}

QRectF map_world_bounds(const OccupancyGrid& grid) {
    if (grid.empty()) {
        return {};
    }
    const QRectF pixels(0.0, 0.0, grid.width(), grid.height());
    return image_to_world(grid).map(QPolygonF(pixels)).boundingRect();
}

}  // namespace legofeup::ui
