// The particle filter (particle_filter.hpp) against independent calculations: the
// low-variance sampler's copies, the cloud's moments computed here from the particles, a
// noise-free single particle against odometry, the Gaussian posterior of a linear
// measurement, determinism from the seed, and what it does with impossible weights, a new
// particle count, global localisation and recovery.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <vector>

#include "legofeup/core/angles.hpp"
#include "legofeup/core/compass_model.hpp"
#include "legofeup/core/extended_kalman_filter.hpp"
#include "legofeup/core/free_space.hpp"
#include "legofeup/core/laser_pose_measurement.hpp"
#include "legofeup/core/odometry_process_model.hpp"
#include "legofeup/core/particle_filter.hpp"
#include "legofeup/core/pose_state_space.hpp"

namespace legofeup {
namespace {

PoseEstimatorSettings settings_with(int count, std::uint64_t seed = 7, bool recovery = false) {
    PoseEstimatorSettings settings;
    settings.particles.particle_count = count;
    settings.particles.recovery = recovery;
    settings.seed = seed;
    settings.free_space = std::make_shared<const FreeSpace>(
        FreeSpace::rectangle(Vector2(-2.0, -1.0), Vector2(2.0, 1.0)));
    return settings;
}

ParticleFilter filter_with(int count, std::uint64_t seed = 7, bool recovery = false) {
    ParticleFilter filter;
    filter.configure(settings_with(count, seed, recovery));
    return filter;
}

OdometryProcessModel straight(double distance, double rotation, double q11, double q22) {
    OdometryIncrement increment;
    increment.distance = distance;
    increment.rotation = rotation;
    return OdometryProcessModel(increment, Eigen::Vector2d(q11, q22).asDiagonal());
}

TEST(ParticleFilter, LowVarianceResamplingGivesEachParticleItsExpectedCopies) {
    // Ten particles at distinct x with weights ∝ exp(logl); after resampling each must have
    // ⌊N·w⌋ or ⌈N·w⌉ copies (Table 4.4's property) and N·w on average over many draws.
    constexpr int kCount = 10;
    constexpr int kDraws = 4000;
    const std::array<double, kCount> logl{0.0, -0.5, -3.0, 0.7, -1.2, -0.1, -9.0, 0.2, -0.4, -2.0};
    double sum = 0.0;
    for (const double l : logl) {
        sum += std::exp(l);
    }
    std::array<double, kCount> mean_copies{};
    ParticleFilter filter;
    for (int draw = 0; draw < kDraws; ++draw) {
        PoseEstimatorSettings settings = settings_with(kCount, 1000 + static_cast<unsigned>(draw));
        settings.particles.resample_threshold = 1.0;  // resample after every update
        filter.configure(settings);
        filter.reset(StateVector(0.0, 0.0, 0.0), Eigen::Vector3d(1.0, 1.0, 0.1).asDiagonal());
        std::map<double, int> index_of;
        for (int i = 0; i < kCount; ++i) {
            index_of[filter.xs()[static_cast<std::size_t>(i)]] = i;
        }
        ASSERT_EQ(index_of.size(), static_cast<std::size_t>(kCount));
        const StepStatus status = filter.weigh(
            [&](double x, double, double) { return logl[static_cast<std::size_t>(index_of[x])]; },
            1);
        ASSERT_EQ(status, StepStatus::Applied);
        ASSERT_TRUE(filter.summary().resampled);
        std::array<int, kCount> copies{};
        for (const double x : filter.xs()) {
            ASSERT_TRUE(index_of.contains(x));
            ++copies[static_cast<std::size_t>(index_of[x])];
        }
        for (int i = 0; i < kCount; ++i) {
            const double expected = kCount * std::exp(logl[static_cast<std::size_t>(i)]) / sum;
            const int c = copies[static_cast<std::size_t>(i)];
            ASSERT_GE(c, static_cast<int>(std::floor(expected))) << "particle " << i;
            ASSERT_LE(c, static_cast<int>(std::ceil(expected))) << "particle " << i;
            mean_copies[static_cast<std::size_t>(i)] += c / static_cast<double>(kDraws);
        }
    }
    for (int i = 0; i < kCount; ++i) {
        const double expected = kCount * std::exp(logl[static_cast<std::size_t>(i)]) / sum;
        // Copies are ⌊e⌋ + Bernoulli(e − ⌊e⌋): the mean of kDraws has σ ≤ 0.5/√kDraws.
        EXPECT_NEAR(mean_copies[static_cast<std::size_t>(i)], expected,
                    5.0 * 0.5 / std::sqrt(kDraws))
            << "particle " << i;
    }
}

TEST(ParticleFilter, PublishesTheUpdatesEffectiveSampleSizeEvenWhenItResampled) {
    // After a resampling the weights are equal and 1/Σwᵢ² is N; the summary must keep the
    // N_eff of the update's own weights, (Σ pᵢ)² / Σ pᵢ² for likelihoods pᵢ on equal priors,
    // through the predictions that follow, until the next update or a new cloud.
    constexpr int kCount = 10;
    const std::array<double, kCount> logl{0.0, -0.5, -3.0, 0.7, -1.2, -0.1, -9.0, 0.2, -0.4, -2.0};
    double sum = 0.0;
    double sum_squares = 0.0;
    for (const double l : logl) {
        sum += std::exp(l);
        sum_squares += std::exp(2.0 * l);
    }
    const double expected = sum * sum / sum_squares;  // ≈ 5.5 of 10
    PoseEstimatorSettings settings = settings_with(kCount);
    settings.particles.resample_threshold = 1.0;
    ParticleFilter filter;
    filter.configure(settings);
    filter.reset(StateVector(0.0, 0.0, 0.0), Eigen::Vector3d(1.0, 1.0, 0.1).asDiagonal());
    EXPECT_NEAR(filter.summary().effective, kCount, 1e-9);  // a new cloud: equal weights
    std::map<double, std::size_t> index_of;
    for (std::size_t i = 0; i < kCount; ++i) {
        index_of[filter.xs()[i]] = i;
    }
    ASSERT_EQ(filter.weigh([&](double x, double, double) { return logl[index_of.at(x)]; }, 1),
              StepStatus::Applied);
    ASSERT_TRUE(filter.summary().resampled);
    ASSERT_LT(expected, 0.9 * kCount);
    EXPECT_NEAR(filter.summary().effective, expected, 1e-9);
    ASSERT_EQ(filter.predict(straight(0.01, 0.0, 1e-6, 1e-6)), StepStatus::Applied);
    EXPECT_NEAR(filter.summary().effective, expected, 1e-9);
    filter.reset(StateVector(0.0, 0.0, 0.0), Eigen::Vector3d(1.0, 1.0, 0.1).asDiagonal());
    EXPECT_NEAR(filter.summary().effective, kCount, 1e-9);
}

TEST(ParticleFilter, PublishesTheCloudsWeightedMeanOnTheCircleAndItsCovariance) {
    ParticleFilter filter = filter_with(500);
    // Headings around π: a plain average would point the other way.
    filter.reset(StateVector(0.3, -0.2, kPi - 0.05),
                 Eigen::Vector3d(0.04, 0.01, 0.01).asDiagonal());
    filter.weigh([](double x, double y, double) { return -2.0 * x * x - y; }, 2);
    // Recompute from the particles here.
    double sx = 0.0, sy = 0.0, ss = 0.0, sc = 0.0;
    const auto w = filter.weights();
    for (std::size_t i = 0; i < w.size(); ++i) {
        sx += w[i] * filter.xs()[i];
        sy += w[i] * filter.ys()[i];
        ss += w[i] * std::sin(filter.thetas()[i]);
        sc += w[i] * std::cos(filter.thetas()[i]);
    }
    const double heading = std::atan2(ss, sc);
    StateCovariance P = StateCovariance::Zero();
    for (std::size_t i = 0; i < w.size(); ++i) {
        const StateVector d(filter.xs()[i] - sx, filter.ys()[i] - sy,
                            wrap_angle(filter.thetas()[i] - heading));
        P += w[i] * d * d.transpose();
    }
    EXPECT_NEAR(filter.state()(kX), sx, 1e-12);
    EXPECT_NEAR(filter.state()(kY), sy, 1e-12);
    EXPECT_NEAR(std::abs(wrap_angle(filter.state()(kTheta) - heading)), 0.0, 1e-12);
    EXPECT_GT(std::abs(filter.state()(kTheta)), 3.0);
    EXPECT_TRUE(filter.covariance().isApprox(P, 1e-9)) << filter.covariance() << "\n" << P;
    double sum_squares = 0.0;
    for (const double v : w) {
        sum_squares += v * v;
    }
    EXPECT_NEAR(filter.summary().effective, 1.0 / sum_squares, 1e-9);
}

TEST(ParticleFilter, OneParticleWithoutNoiseFollowsOdometryExactly) {
    // A PF with one particle at the exact pose and Q = 0 is dead reckoning: the same bits as
    // the EKF's mean (whose prediction is f(X, U, 0)) step after step.
    PoseEstimatorSettings settings = settings_with(1);
    ParticleFilter filter;
    filter.configure(settings);
    ExtendedKalmanFilter<PoseStateSpace> ekf;
    const StateVector start(-1.0, -1.0, 0.1);
    ASSERT_TRUE(filter.reset(start, StateCovariance::Zero()));
    ekf.reset(start, StateCovariance::Identity() * 1e-6);
    for (int step = 0; step < 400; ++step) {
        const auto model =
            straight(0.01 + 0.001 * (step % 7), 0.02 * std::sin(step * 0.1), 0.0, 0.0);
        ASSERT_EQ(filter.predict(model), StepStatus::Applied) << step;
        ekf.predict(model);
        ASSERT_EQ(filter.xs()[0], ekf.state()(kX)) << step;
        ASSERT_EQ(filter.ys()[0], ekf.state()(kY)) << step;
        ASSERT_EQ(filter.thetas()[0], ekf.state()(kTheta)) << step;
        ASSERT_EQ(filter.state(), ekf.state()) << step;
    }
}

TEST(ParticleFilter, MotionSamplesHaveTheCovarianceQGives) {
    // From a point, one prediction spreads the cloud as the EKF's linearised P does (for a
    // small Q the odometry model is near linear): Var(x) ≈ cos²φ·q11, Var(y), Var(θ) = q22.
    ParticleFilter filter = filter_with(20000);
    filter.reset(StateVector(0.0, 0.0, 0.0), StateCovariance::Zero());
    ExtendedKalmanFilter<PoseStateSpace> ekf;
    ekf.reset(StateVector(0.0, 0.0, 0.0), StateCovariance::Zero());
    const auto model = straight(0.2, 0.1, 1e-4, 1e-3);
    filter.predict(model);
    ekf.predict(model);
    for (int k = 0; k < 3; ++k) {
        const double expected = ekf.covariance()(k, k);
        // A sample variance of n normals has relative σ √(2/n) ≈ 1 %.
        EXPECT_NEAR(filter.covariance()(k, k), expected, 0.05 * expected + 1e-9) << k;
        EXPECT_NEAR(filter.state()(k), ekf.state()(k), 5.0 * std::sqrt(expected / 20000.0) + 1e-6)
            << k;
    }
}

TEST(ParticleFilter, ALinearMeasurementGivesTheKalmanPosterior) {
    // Prior N(x0, P0), z = X + r (H = I): the exact posterior is the Kalman one, which the
    // EKF computes; the weighted cloud must match it to sampling error.
    const StateVector x0(1.0, 0.5, 0.2);
    const StateCovariance P0 = Eigen::Vector3d(0.04, 0.09, 0.02).asDiagonal();
    const LaserPoseMeasurement measurement({1.2, 0.3, 0.25}, StateVector(0.04, 0.03, 0.01));
    ExtendedKalmanFilter<PoseStateSpace> ekf;
    ekf.reset(x0, P0);
    ekf.update(measurement);
    PoseEstimatorSettings settings = settings_with(40000);
    settings.particles.resample_threshold = 0.0;  // keep the weighted cloud itself
    ParticleFilter filter;
    filter.configure(settings);
    filter.reset(x0, P0);
    const auto report = filter.update(measurement);
    ASSERT_EQ(report.status, StepStatus::Applied);
    for (int k = 0; k < 3; ++k) {
        const double sigma = std::sqrt(ekf.covariance()(k, k));
        EXPECT_NEAR(filter.state()(k), ekf.state()(k), 0.05 * sigma) << k;
        EXPECT_NEAR(filter.covariance()(k, k), ekf.covariance()(k, k), 0.1 * ekf.covariance()(k, k))
            << k;
    }
    // The report is the prior cloud's Gaussian summary: S ≈ P0 + R, ν ≈ z − x0.
    const StateCovariance S = P0 + measurement.noise_covariance();
    EXPECT_TRUE(report.innovation_covariance.isApprox(S, 0.05)) << report.innovation_covariance;
    EXPECT_NEAR(report.innovation(kX), 0.2, 0.01);
    EXPECT_NEAR(report.nis,
                report.innovation.dot(report.innovation_covariance.ldlt().solve(report.innovation)),
                1e-9);
}

TEST(ParticleFilter, TheSameSeedGivesTheSameBitsAndAnotherSeedOthers) {
    const auto run = [](std::uint64_t seed) {
        ParticleFilter filter = filter_with(300, seed, true);
        filter.reset(StateVector(0.0, 0.0, 0.0), Eigen::Vector3d(0.01, 0.01, 0.01).asDiagonal());
        for (int step = 0; step < 50; ++step) {
            filter.predict(straight(0.01, 0.01, 1e-5, 1e-4));
            filter.update(CompassMeasurement(0.01 * step, 0.01));
        }
        return std::vector<double>(filter.xs().begin(), filter.xs().end());
    };
    EXPECT_EQ(run(11), run(11));
    EXPECT_NE(run(11), run(12));
}

TEST(ParticleFilter, AllParticlesImpossibleIsRefusedAndKeepsTheWeights) {
    ParticleFilter filter = filter_with(100);
    filter.reset(StateVector(0.0, 0.0, 0.0), Eigen::Vector3d(0.01, 0.01, 0.01).asDiagonal());
    filter.weigh([](double x, double, double) { return x; }, 1);
    const std::vector<double> weights(filter.weights().begin(), filter.weights().end());
    const StateVector before = filter.state();
    EXPECT_EQ(filter.weigh([](double, double, double) { return std::nan(""); }, 1),
              StepStatus::RejectedNonFinite);
    EXPECT_EQ(std::vector<double>(filter.weights().begin(), filter.weights().end()), weights);
    EXPECT_EQ(filter.state(), before);
    // Every likelihood 0 (−∞ in the log) is as impossible.
    EXPECT_EQ(
        filter.weigh(
            [](double, double, double) { return -std::numeric_limits<double>::infinity(); }, 1),
        StepStatus::RejectedNonFinite);
    // Likelihoods far below what a double holds still weigh (the log domain).
    EXPECT_EQ(filter.weigh([](double x, double, double) { return -1e6 + x; }, 1),
              StepStatus::Applied);
    EXPECT_TRUE(filter.state().allFinite());
}

TEST(ParticleFilter, ANewParticleCountKeepsTheDistribution) {
    ParticleFilter filter = filter_with(4000);
    filter.reset(StateVector(1.0, 2.0, 0.5), Eigen::Vector3d(0.04, 0.04, 0.01).asDiagonal());
    PoseEstimatorSettings settings = settings_with(1000);
    filter.configure(settings);
    EXPECT_EQ(filter.xs().size(), 1000u);
    EXPECT_EQ(filter.summary().count, 1000);
    EXPECT_NEAR(filter.state()(kX), 1.0, 0.03);
    EXPECT_NEAR(filter.covariance()(kX, kX), 0.04, 0.01);
}

TEST(ParticleFilter, GlobalLocalisationSpreadsTheCloudOverTheFreeSpace) {
    ParticleFilter filter = filter_with(5000);
    ASSERT_TRUE(filter.reset_uniform());
    for (std::size_t i = 0; i < filter.xs().size(); ++i) {
        ASSERT_GE(filter.xs()[i], -2.0);
        ASSERT_LT(filter.xs()[i], 2.0);
        ASSERT_GE(filter.ys()[i], -1.0);
        ASSERT_LT(filter.ys()[i], 1.0);
    }
    EXPECT_NEAR(filter.state()(kX), 0.0, 0.1);
    EXPECT_NEAR(filter.covariance()(kX, kX), 16.0 / 12.0, 0.1);
    EXPECT_NEAR(filter.covariance()(kTheta, kTheta), kPi * kPi / 3.0, 0.3);
    // Within 0.5 m of the centre of a 4 m × 2 m box: about π·0.25/8 ≈ 0.1 of the weight.
    EXPECT_LT(filter.summary().near_mean_share, 0.2);
    // Without a free space there is nothing to spread over.
    ParticleFilter none;
    PoseEstimatorSettings settings = settings_with(10);
    settings.free_space = nullptr;
    none.configure(settings);
    EXPECT_FALSE(none.reset_uniform());
}

// The recovery of augmented MCL: a cloud tracking at (−1.5, −0.5) whose measurements
// suddenly say the robot is at (1.5, 0.5), 3.2 m away — a kidnapping. With recovery the
// filter injects random particles and ends at the new place; without, it never injects and
// its cloud only creeps towards it, resampling its leading edge step after step.
double distance_after_kidnapping(bool recovery, std::uint64_t seed, int* injected, int steps) {
    ParticleFilter filter = filter_with(300, seed, recovery);
    filter.reset(StateVector(-1.5, -0.5, 0.0), Eigen::Vector3d(0.01, 0.01, 0.01).asDiagonal());
    const StateVector r(0.01, 0.01, 0.05);
    const auto still = straight(0.0, 0.0, 1e-6, 1e-6);
    for (int step = 0; step < 50; ++step) {
        filter.predict(still);
        filter.update(LaserPoseMeasurement({-1.5, -0.5, 0.0}, r));
    }
    *injected = 0;
    const auto wandering = straight(0.0, 0.0, 1e-4, 1e-4);  // lets the cloud refine its fit
    for (int step = 0; step < steps; ++step) {
        filter.predict(wandering);
        filter.update(LaserPoseMeasurement({1.5, 0.5, 0.0}, r));
        *injected += filter.summary().injected;
    }
    return (filter.state().head<2>() - Vector2(1.5, 0.5)).norm();
}

TEST(ParticleFilter, RecoveryInjectsParticlesAfterAKidnappingAndFindsTheRobot) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        int injected = 0;
        // 40 updates after the kidnapping (measured: 0.02–0.15 m with recovery, 2.2 m without).
        EXPECT_LT(distance_after_kidnapping(true, seed, &injected, 40), 0.25) << seed;
        EXPECT_GT(injected, 0) << seed;
        EXPECT_GT(distance_after_kidnapping(false, seed, &injected, 40), 1.5) << seed;
        EXPECT_EQ(injected, 0) << seed;
    }
}

}  // namespace
}  // namespace legofeup
