// The particle filter's α₁…α₄ motion noise (odometry_alphas.hpp) against the variances of
// Probabilistic Robotics' Table 5.6 worked out here for motions where they separate: a turn
// on the spot (α₁ spreads the heading, α₄ the position along it), a straight (α₃ along the
// track, α₂ the heading and, through it, across the track), a straight driven backwards
// (not a half turn: no heading noise from α₁), and α's on top of Q (the variances add).
// From a start heading of 0.3 rad, so that a mix-up of the world and the robot frame shows.
// Sample variances of 40,000 particles have a relative σ of √(2/40000) ≈ 0.7 %: 4 % is
// more than 5σ.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "legofeup/core/angles.hpp"
#include "legofeup/core/odometry_process_model.hpp"
#include "legofeup/core/particle_filter.hpp"

namespace legofeup {
namespace {

constexpr int kParticles = 40000;
constexpr double kStartHeading = 0.3;

struct Spread {
    double along = 0.0;    ///< variance of the displacement along the start heading, m²
    double across = 0.0;   ///< … across it, m²
    double heading = 0.0;  ///< variance of the heading, rad²
    double mean_along = 0.0;
};

/// One prediction of `distance` and `rotation` from the origin at kStartHeading, Q diagonal
/// (q11, q22), with the given α's; the cloud's spread in the start's frame.
Spread spread_after(double distance, double rotation, const OdometryAlphas& alphas,
                    double q11 = 0.0, double q22 = 0.0) {
    PoseEstimatorSettings settings;
    settings.particles.particle_count = kParticles;
    settings.particles.motion_alphas = alphas;
    settings.seed = 2026;
    ParticleFilter filter;
    filter.configure(settings);
    filter.reset(StateVector(0.0, 0.0, kStartHeading), StateCovariance::Zero());
    OdometryIncrement increment;
    increment.distance = distance;
    increment.rotation = rotation;
    EXPECT_EQ(
        filter.predict(OdometryProcessModel(increment, Eigen::Vector2d(q11, q22).asDiagonal())),
        StepStatus::Applied);
    const double c = std::cos(kStartHeading);
    const double s = std::sin(kStartHeading);
    std::vector<double> along, across, heading;
    for (int i = 0; i < kParticles; ++i) {
        const auto k = static_cast<std::size_t>(i);
        along.push_back(c * filter.xs()[k] + s * filter.ys()[k]);
        across.push_back(-s * filter.xs()[k] + c * filter.ys()[k]);
        heading.push_back(filter.thetas()[k]);
    }
    const auto moments = [](const std::vector<double>& v, double& mean) {
        mean = 0.0;
        for (const double value : v) {
            mean += value;
        }
        mean /= static_cast<double>(v.size());
        double sum = 0.0;
        for (const double value : v) {
            sum += (value - mean) * (value - mean);
        }
        return sum / static_cast<double>(v.size());
    };
    Spread spread;
    double unused = 0.0;
    spread.along = moments(along, spread.mean_along);
    spread.across = moments(across, unused);
    spread.heading = moments(heading, unused);
    return spread;
}

TEST(OdometryAlphas, ATurnOnTheSpotSpreadsTheHeadingByAlpha1) {
    OdometryAlphas alphas;
    alphas.rotation_from_rotation = 0.04;
    const Spread spread = spread_after(0.0, 0.5, alphas);
    EXPECT_NEAR(spread.heading, 0.04 * 0.25, 0.04 * 0.04 * 0.25);  // α₁ Δθ²
    EXPECT_EQ(spread.along, 0.0);  // no translation, and α₄ = 0: nobody moved
    EXPECT_EQ(spread.across, 0.0);
}

TEST(OdometryAlphas, ATurnOnTheSpotMovesAlongTheHeadingByAlpha4) {
    OdometryAlphas alphas;
    alphas.translation_from_rotation = 0.01;
    const Spread spread = spread_after(0.0, 0.5, alphas);
    EXPECT_NEAR(spread.along, 0.01 * 0.25, 0.04 * 0.01 * 0.25);  // α₄ (δ_rot1² + δ_rot2²)
    EXPECT_NEAR(spread.across, 0.0, 1e-20);
    EXPECT_NEAR(spread.heading, 0.0, 1e-20);
}

TEST(OdometryAlphas, AStraightSpreadsAlongTheTrackByAlpha3) {
    OdometryAlphas alphas;
    alphas.translation_from_translation = 0.02;
    const Spread spread = spread_after(0.2, 0.0, alphas);
    EXPECT_NEAR(spread.along, 0.02 * 0.04, 0.04 * 0.02 * 0.04);  // α₃ δ_trans²
    EXPECT_NEAR(spread.mean_along, 0.2, 5.0 * std::sqrt(0.02 * 0.04 / kParticles));
    EXPECT_NEAR(spread.across, 0.0, 1e-20);
    EXPECT_NEAR(spread.heading, 0.0, 1e-20);
}

TEST(OdometryAlphas, AStraightTurnsTheHeadingAndTheTrackByAlpha2) {
    OdometryAlphas alphas;
    alphas.rotation_from_translation = 0.05;
    const double rotation_variance = 0.05 * 0.04;  // α₂ δ_trans² for each rotation
    const Spread spread = spread_after(0.2, 0.0, alphas);
    // Both rotations turn the heading; only the first one the track (across ≈ d² σ²_rot1).
    EXPECT_NEAR(spread.heading, 2.0 * rotation_variance, 0.04 * 2.0 * rotation_variance);
    EXPECT_NEAR(spread.across, 0.04 * rotation_variance, 0.05 * 0.04 * rotation_variance);
}

TEST(OdometryAlphas, DrivingBackwardsIsNotAHalfTurn) {
    // Backwards the direction of travel is θ ± π: δ_rot1 ≈ ±π, whose noise α₁ would make a
    // heading spread of α₁π². It counts as no rotation.
    OdometryAlphas alphas;
    alphas.rotation_from_rotation = 0.1;
    alphas.translation_from_translation = 0.02;
    const Spread spread = spread_after(-0.2, 0.0, alphas);
    EXPECT_LT(spread.heading, 1e-20);
    EXPECT_NEAR(spread.along, 0.02 * 0.04, 0.04 * 0.02 * 0.04);
    EXPECT_NEAR(spread.mean_along, -0.2, 5.0 * std::sqrt(0.02 * 0.04 / kParticles));
}

TEST(OdometryAlphas, AddToTheNoiseOfQ) {
    OdometryAlphas alphas;
    alphas.translation_from_translation = 0.02;
    alphas.rotation_from_rotation = 0.04;
    const Spread spread = spread_after(0.2, 0.5, alphas, 1e-4, 1e-3);
    // Along: q11 (the centred heading turns it by cos 0.25 away from the start's frame)
    // plus α₃ d²; heading: q22 + α₁ of δ_rot1 = 0.25 and δ_rot2 = 0.25 (the chord points
    // along the centred heading θ + Δθ/2).
    const double along_expected = (1e-4 + 0.02 * 0.04) * std::cos(0.25) * std::cos(0.25);
    EXPECT_NEAR(spread.along, along_expected, 0.05 * along_expected);
    const double heading_expected = 1e-3 + 0.04 * (0.0625 + 0.0625);
    EXPECT_NEAR(spread.heading, heading_expected, 0.04 * heading_expected);
}

TEST(OdometryAlphas, AllZeroLeavesTheRandomStreamAndTheCloudAsWithout) {
    // With every α zero no draw is made: the same seed gives the same bits as a filter
    // that never heard of them, so runs from before keep their results.
    const Spread without = spread_after(0.2, 0.1, OdometryAlphas{}, 1e-4, 1e-3);
    OdometryAlphas tiny;
    tiny.rotation_from_rotation = 1e-12;
    const Spread with_tiny = spread_after(0.2, 0.1, tiny, 1e-4, 1e-3);
    EXPECT_NE(without.along, with_tiny.along);  // a nonzero α draws, so the stream moves on
    EXPECT_EQ(without.along, spread_after(0.2, 0.1, OdometryAlphas{}, 1e-4, 1e-3).along);
}

}  // namespace
}  // namespace legofeup
