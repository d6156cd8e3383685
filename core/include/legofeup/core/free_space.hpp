#pragma once
// Where the robot may be when nothing is known about its pose: the particle filter draws its
// global-localisation cloud and its recovery particles (augmented MCL) from here, and a
// Gaussian filter that "knows nothing" takes this region's mean and covariance.
//
// Two shapes: the free cells of an occupancy-grid map (the laser lessons: a building's
// rooms), or a rectangle (the wall lessons: the box the walls span). A pose is drawn
// uniformly over the region's area, its heading uniformly on (−π, π]. Drawing takes
// uniforms in [0, 1) from the caller, so the random stream — and with it a run's
// bit-for-bit repeatability — stays the filter's own.

#include <Eigen/Core>
#include <array>
#include <vector>

#include "legofeup/core/occupancy_grid.hpp"
#include "legofeup/core/state.hpp"
#include "legofeup/core/walls.hpp"

namespace legofeup {

class FreeSpace {
  public:
    /// No free space at all: empty() is true and nothing can be drawn.
    FreeSpace() = default;

    /// The axis-aligned rectangle [low, high] (empty unless low < high in both axes).
    static FreeSpace rectangle(const Vector2& low, const Vector2& high);
    /// The rectangle spanned by the walls' end points (empty for no walls).
    static FreeSpace bounding(const WallMap& walls);
    /// The free cells of `grid` (unknown and occupied cells excluded).
    static FreeSpace of_grid(const OccupancyGrid& grid);

    bool empty() const { return area_ <= 0.0; }
    double area() const { return area_; }  ///< m²

    /// A pose uniform over the region and in heading, from four uniforms in [0, 1):
    /// u[0] picks the cell (or is the x of the rectangle), u[1] and u[2] place the point in
    /// it, u[3] is the heading. Must not be called when empty().
    Pose2 sample(const std::array<double, 4>& u) const;

    /// The mean and covariance of such a uniform pose: the region's centroid and second
    /// moments (each cell a uniform square), and heading mean 0 with variance π²/3, the
    /// uniform's on (−π, π]. What a Gaussian filter is given as "the pose is unknown".
    StateVector mean() const;
    StateCovariance covariance() const;

  private:
    // A rectangle: one "cell" of size extent_ at low_. A grid: free_cells_ (row-major
    // indices) of squares of side resolution_, placed through the grid's origin.
    Vector2 low_ = Vector2::Zero();
    Vector2 extent_ = Vector2::Zero();
    bool grid_ = false;
    int width_ = 0;
    double resolution_ = 0.0;
    Pose2 origin_;
    std::vector<int> free_cells_;
    double area_ = 0.0;
    Vector2 mean_ = Vector2::Zero();
    Eigen::Matrix2d covariance_ = Eigen::Matrix2d::Zero();
};

}  // namespace legofeup
