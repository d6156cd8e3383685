#include "legofeup/core/free_space.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "legofeup/core/angles.hpp"

namespace legofeup {

FreeSpace FreeSpace::rectangle(const Vector2& low, const Vector2& high) {
    FreeSpace space;
    if (!(low.allFinite() && high.allFinite() && low.x() < high.x() && low.y() < high.y())) {
        return space;
    }
    space.low_ = low;
    space.extent_ = high - low;
    space.area_ = space.extent_.x() * space.extent_.y();
    space.mean_ = 0.5 * (low + high);
    // A uniform on an interval of length L has variance L²/12.
    space.covariance_ = (space.extent_.array().square() / 12.0).matrix().asDiagonal();
    return space;
}

FreeSpace FreeSpace::bounding(const WallMap& walls) {
    if (walls.size() == 0) {
        return {};
    }
    Vector2 low = Vector2::Constant(std::numeric_limits<double>::infinity());
    Vector2 high = -low;
    for (const Wall& wall : walls.walls()) {
        low = low.cwiseMin(wall.start).cwiseMin(wall.end);
        high = high.cwiseMax(wall.start).cwiseMax(wall.end);
    }
    return rectangle(low, high);
}

FreeSpace FreeSpace::of_grid(const OccupancyGrid& grid) {
    FreeSpace space;
    space.grid_ = true;
    space.width_ = grid.width();
    space.resolution_ = grid.resolution();
    space.origin_ = grid.origin();
    const std::vector<CellState>& cells = grid.cells();
    for (std::size_t i = 0; i < cells.size(); ++i) {
        if (cells[i] == CellState::Free) {
            space.free_cells_.push_back(static_cast<int>(i));
        }
    }
    if (space.free_cells_.empty()) {
        return space;
    }
    const double cell_area = space.resolution_ * space.resolution_;
    space.area_ = cell_area * static_cast<double>(space.free_cells_.size());
    // Centroid and second moments of the union of equal squares: the mean of the centres,
    // and their scatter plus each square's own r²/12 per axis.
    Vector2 sum = Vector2::Zero();
    Eigen::Matrix2d outer = Eigen::Matrix2d::Zero();
    for (const int index : space.free_cells_) {
        const Vector2 centre = grid.centre_of({index % space.width_, index / space.width_});
        sum += centre;
        outer += centre * centre.transpose();
    }
    const double n = static_cast<double>(space.free_cells_.size());
    space.mean_ = sum / n;
    space.covariance_ = outer / n - space.mean_ * space.mean_.transpose();
    space.covariance_ += Eigen::Matrix2d::Identity() * (cell_area / 12.0);
    return space;
}

Pose2 FreeSpace::sample(const std::array<double, 4>& u) const {
    const double theta = wrap_angle(kPi * (2.0 * u[3] - 1.0));
    if (!grid_) {
        return {low_.x() + u[0] * extent_.x(), low_.y() + u[1] * extent_.y(), theta};
    }
    const auto count = static_cast<double>(free_cells_.size());
    const auto pick = std::min(free_cells_.size() - 1, static_cast<std::size_t>(u[0] * count));
    const int index = free_cells_[pick];
    // The point in the grid frame, then w = o + R(yaw)·g (OccupancyGrid::centre_of).
    const double gx = (index % width_ + u[1]) * resolution_;
    const double gy = (index / width_ + u[2]) * resolution_;
    const double c = std::cos(origin_.theta);
    const double s = std::sin(origin_.theta);
    return {origin_.x + c * gx - s * gy, origin_.y + s * gx + c * gy, theta};
}

StateVector FreeSpace::mean() const {
    return {mean_.x(), mean_.y(), 0.0};
}

StateCovariance FreeSpace::covariance() const {
    StateCovariance P = StateCovariance::Zero();
    P.topLeftCorner<2, 2>() = covariance_;
    P(kTheta, kTheta) = kPi * kPi / 3.0;
    return P;
}

}  // namespace legofeup
