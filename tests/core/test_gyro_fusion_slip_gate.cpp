#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "legofeup/core/angles.hpp"
#include "legofeup/core/gyro_fusion_estimator.hpp"

namespace legofeup {
namespace {

// A robot pinned against a wall: its wheels keep turning (the encoders report the commanded
// v = 0.05 m/s and ω = 0.4 rad/s) while the body stands still (the gyro reads 0 ± noise).
// Returns the final heading after `steps` periods of 50 ms.
double heading_after_slipping(double gate_probability, unsigned seed, int steps,
                              int* encoder_rejections) {
    GyroFusionTuning tuning;
    tuning.use_accelerometers = false;
    tuning.encoder_gate_probability = gate_probability;
    GyroFusionEstimator estimator;
    estimator.reset(StateVector::Zero(), 1e-4 * StateCovariance::Identity(), 1e-4);
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    *encoder_rejections = 0;
    for (int k = 0; k < steps; ++k) {
        const VelocityCommand encoders{0.05 + std::sqrt(tuning.r_v_encoders) * normal(rng),
                                       0.4 + std::sqrt(tuning.r_w_encoders) * normal(rng)};
        const double gyro = std::sqrt(tuning.r_w_gyro) * normal(rng);
        const GyroFusionStep step = estimator.step(0.05, {}, &encoders, &gyro, tuning);
        EXPECT_EQ(step.gyro, StepStatus::Applied);
        if (step.encoders == StepStatus::RejectedByGate) {
            ++*encoder_rejections;
        }
    }
    return wrap_angle(estimator.pose()(kTheta));
}

TEST(GyroFusionSlipGate, RejectsEncodersThatTurnWhileTheGyroDoesNot) {
    for (unsigned seed = 1; seed <= 10; ++seed) {
        int rejected_gated = 0;
        int rejected_ungated = 0;
        const double gated = heading_after_slipping(0.999, seed, 200, &rejected_gated);
        const double ungated = heading_after_slipping(0.0, seed, 200, &rejected_ungated);
        // Without the gate the fused ω is the R-weighted mean 0.4·r_gyro/(r_gyro + r_enc)
        // ≈ 0.036 rad/s: over 10 s the heading wanders ≈ 0.36 rad.
        EXPECT_GT(std::abs(ungated), 0.2) << "seed " << seed;
        EXPECT_EQ(rejected_ungated, 0);
        // With it, almost every encoder reading is rejected and the heading stays put.
        EXPECT_LT(std::abs(gated), 0.03) << "seed " << seed;
        EXPECT_GT(rejected_gated, 190) << "seed " << seed;
    }
}

TEST(GyroFusionSlipGate, AcceptsEncodersThatAgreeWithTheGyro) {
    GyroFusionTuning tuning;
    tuning.use_accelerometers = false;
    GyroFusionEstimator estimator;
    estimator.reset(StateVector::Zero(), 1e-4 * StateCovariance::Identity(), 1e-4);
    std::mt19937_64 rng(7);
    std::normal_distribution<double> normal(0.0, 1.0);
    int rejected = 0;
    const int steps = 2000;
    for (int k = 0; k < steps; ++k) {
        // A square's corners: turning at 0.4 rad/s for 4 s, then straight for 6 s.
        const double w = (k % 200) < 80 ? 0.4 : 0.0;
        const VelocityCommand encoders{0.05 + std::sqrt(tuning.r_v_encoders) * normal(rng),
                                       w + std::sqrt(tuning.r_w_encoders) * normal(rng)};
        const double gyro = w + std::sqrt(tuning.r_w_gyro) * normal(rng);
        if (estimator.step(0.05, {}, &encoders, &gyro, tuning).encoders
            == StepStatus::RejectedByGate) {
            ++rejected;
        }
    }
    // Consistent readings exceed the χ²(2) 99.9 % quantile about 0.1 % of the time; the step
    // changes of ω at the corners add a few more.
    EXPECT_LT(rejected, steps / 50);
}

TEST(GyroFusionSlipGate, IsOffWithoutTheGyro) {
    GyroFusionTuning tuning;
    tuning.use_accelerometers = false;
    tuning.use_gyro = false;
    GyroFusionEstimator estimator;
    estimator.reset(StateVector::Zero(), 1e-4 * StateCovariance::Identity(), 1e-4);
    const VelocityCommand encoders{0.05, 0.4};  // a sudden turn: nothing to judge it by
    const double gyro = 0.0;
    EXPECT_EQ(estimator.step(0.05, {}, &encoders, &gyro, tuning).encoders, StepStatus::Applied);
}

}  // namespace
}  // namespace legofeup
