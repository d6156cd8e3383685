// The free space an unknown pose is drawn from (free_space.hpp): draws fall in free cells
// only, uniformly, and the moments it gives the Gaussian filters are those of the draws.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "legofeup/core/angles.hpp"
#include "legofeup/core/free_space.hpp"

namespace legofeup {
namespace {

std::array<double, 4> uniforms(std::mt19937_64& engine) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    return {u(engine), u(engine), u(engine), u(engine)};
}

// A 6 × 4 grid of 0.5 m cells, rotated by 0.3 rad, with free cells on the bottom row and
// one more at (5, 3); the rest occupied or unknown.
OccupancyGrid small_grid() {
    std::vector<CellState> cells(24, CellState::Occupied);
    for (int col = 0; col < 6; ++col) {
        cells[static_cast<std::size_t>(col)] = CellState::Free;
    }
    cells[3 * 6 + 5] = CellState::Free;
    cells[2 * 6 + 2] = CellState::Unknown;
    return OccupancyGrid(6, 4, 0.5, Pose2{1.0, -2.0, 0.3}, cells);
}

TEST(FreeSpace, GridDrawsFallInFreeCellsInProportionToTheirArea) {
    const OccupancyGrid grid = small_grid();
    const FreeSpace space = FreeSpace::of_grid(grid);
    ASSERT_FALSE(space.empty());
    EXPECT_DOUBLE_EQ(space.area(), 7 * 0.25);
    std::mt19937_64 engine(3);
    int top = 0;
    constexpr int kDraws = 70000;
    Vector2 sum = Vector2::Zero();
    Eigen::Matrix2d outer = Eigen::Matrix2d::Zero();
    double heading_sum = 0.0;
    for (int i = 0; i < kDraws; ++i) {
        const Pose2 pose = space.sample(uniforms(engine));
        const auto cell = grid.cell_of({pose.x, pose.y});
        ASSERT_TRUE(cell.has_value());
        ASSERT_EQ(grid.at(*cell), CellState::Free) << cell->col << "," << cell->row;
        ASSERT_GT(pose.theta, -kPi);
        ASSERT_LE(pose.theta, kPi);
        top += cell->row == 3 ? 1 : 0;
        const Vector2 p(pose.x, pose.y);
        sum += p;
        outer += p * p.transpose();
        heading_sum += pose.theta * pose.theta;
    }
    // One free cell in seven: a binomial share with σ = √(p(1−p)/n).
    const double p = 1.0 / 7.0;
    EXPECT_NEAR(top / static_cast<double>(kDraws), p, 5.0 * std::sqrt(p * (1 - p) / kDraws));
    // The moments handed to the Gaussian filters are the draws'.
    const Vector2 mean = sum / kDraws;
    const Eigen::Matrix2d covariance = outer / kDraws - mean * mean.transpose();
    EXPECT_NEAR(space.mean()(kX), mean.x(), 0.02);
    EXPECT_NEAR(space.mean()(kY), mean.y(), 0.02);
    const Eigen::Matrix2d given = space.covariance().topLeftCorner<2, 2>();
    EXPECT_TRUE(given.isApprox(covariance, 0.03)) << space.covariance() << "\n" << covariance;
    EXPECT_NEAR(space.covariance()(kTheta, kTheta), heading_sum / kDraws, 0.05);
}

TEST(FreeSpace, AMapWithNoFreeCellIsEmpty) {
    const OccupancyGrid grid(3, 3, 0.1, Pose2{}, std::vector<CellState>(9, CellState::Occupied));
    EXPECT_TRUE(FreeSpace::of_grid(grid).empty());
    EXPECT_TRUE(FreeSpace::rectangle(Vector2(0.0, 0.0), Vector2(0.0, 1.0)).empty());
    EXPECT_TRUE(FreeSpace::bounding(WallMap{}).empty());
    EXPECT_TRUE(FreeSpace{}.empty());
}

TEST(FreeSpace, TheWallsBoxIsTheirEndPointsExtent) {
    const FreeSpace space = FreeSpace::bounding(standard_arena_walls(ArenaSpec{}));
    ASSERT_FALSE(space.empty());
    // The standard walls lie at ±1.21 m and run 1 m along their sides from a path corner.
    EXPECT_NEAR(space.mean()(kX), 0.0, 0.11);
    EXPECT_GT(space.area(), 2.0 * 2.0);
    std::mt19937_64 engine(5);
    for (int i = 0; i < 1000; ++i) {
        const Pose2 pose = space.sample(uniforms(engine));
        ASSERT_LE(std::abs(pose.x), 1.21 + 1e-12);
        ASSERT_LE(std::abs(pose.y), 1.21 + 1e-12);
    }
}

}  // namespace
}  // namespace legofeup
