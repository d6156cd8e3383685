#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "legofeup/core/extended_kalman_filter.hpp"
#include "legofeup/core/gyro_fusion_model.hpp"
#include "legofeup/core/motion_state_space.hpp"
#include "numeric_jacobian.hpp"

namespace legofeup {
namespace {

constexpr unsigned kMotionThetaOutput = 1U << kMotionTheta;

TEST(GyroFusionModel, PropagatesEquation24) {
    const GyroFusionProcessModel model(0.1, 0.5, -1.0, GyroFusionTuning{});
    MotionStateVector x;
    x << 1.0, 2.0, 0.3, 0.2, 0.4;
    const MotionStateVector next = model.predict_state(x);
    const double phi = 0.3 + 0.4 * 0.05;
    EXPECT_NEAR(next(kMotionX), 1.0 + 0.02 * std::cos(phi), 1e-15);
    EXPECT_NEAR(next(kMotionY), 2.0 + 0.02 * std::sin(phi), 1e-15);
    EXPECT_NEAR(next(kMotionTheta), 0.34, 1e-15);
    EXPECT_NEAR(next(kMotionV), 0.25, 1e-15);
    EXPECT_NEAR(next(kMotionW), 0.3, 1e-15);
}

TEST(GyroFusionModel, JacobiansMatchCentralDifferences) {
    testing::Uniform uniform(11);
    const GyroFusionTuning tuning;
    for (int trial = 0; trial < 20; ++trial) {
        const GyroFusionProcessModel model(uniform(0.01, 0.2), uniform(-1, 1), uniform(-3, 3),
                                           tuning);
        MotionStateVector x;
        x << uniform(-2, 2), uniform(-2, 2), uniform(-kPi, kPi), uniform(-0.5, 0.5), uniform(-3, 3);
        const auto f = [&](const MotionStateVector& s) { return model.predict_state(s); };
        const MotionCovariance numeric =
            testing::central_difference<5, 5>(f, x, 1e-6, kMotionThetaOutput);
        EXPECT_LT((model.state_jacobian(x) - numeric).cwiseAbs().maxCoeff(), 1e-7);
        const auto g = [&](const MotionStateVector& q) { return model.propagate(x, q); };
        const MotionCovariance numeric_q = testing::central_difference<5, 5>(
            g, MotionStateVector::Zero().eval(), 1e-6, kMotionThetaOutput);
        EXPECT_LT((model.noise_jacobian(x) - numeric_q).cwiseAbs().maxCoeff(), 1e-7);

        const EncoderVelocityMeasurement encoders({0.1, 0.2}, 1e-3, 0.5);
        const auto h = [&](const MotionStateVector& s) { return encoders.predict_measurement(s); };
        EXPECT_LT(
            (encoders.jacobian(x) - testing::central_difference<2, 5>(h, x)).cwiseAbs().maxCoeff(),
            1e-7);
        const GyroRateMeasurement gyro(0.2, 3e-4);
        const auto hg = [&](const MotionStateVector& s) { return gyro.predict_measurement(s); };
        EXPECT_LT(
            (gyro.jacobian(x) - testing::central_difference<1, 5>(hg, x)).cwiseAbs().maxCoeff(),
            1e-7);
    }
}

// The robot drives a circle at v = 0.1 m/s, ω = 0.5 rad/s for 20 s (T = 50 ms). The encoders'
// ω reads 10 % high (a wheel-base error) with σ = 0.1 rad/s noise; the gyroscope is right,
// with σ = √3e-4 rad/s. Encoder-only, the heading drifts by 0.05·20 = 1 rad; fused with the
// gyro it must end below a tenth of that, for each of 5 seeds.
TEST(GyroFusionModel, GyroCorrectsABiasedEncoderTurnRate) {
    const double T = 0.05;
    const double v = 0.1;
    const double w = 0.5;
    GyroFusionTuning tuning;
    tuning.q_w = 2e-2;
    tuning.r_v_encoders = 1e-3;
    tuning.r_w_encoders = 0.01;
    tuning.r_w_gyro = 3e-4;
    for (unsigned seed = 1; seed <= 5; ++seed) {
        std::mt19937_64 rng(seed);
        std::normal_distribution<double> normal(0.0, 1.0);
        ExtendedKalmanFilter<MotionStateSpace> fused;
        ExtendedKalmanFilter<MotionStateSpace> encoders_only;
        MotionStateVector x0 = MotionStateVector::Zero();
        const MotionCovariance P0 = 1e-2 * MotionCovariance::Identity();
        ASSERT_TRUE(fused.reset(x0, P0));
        ASSERT_TRUE(encoders_only.reset(x0, P0));
        const GyroFusionProcessModel model(T, 0.0, 0.0, tuning);  // no accelerometers
        for (int k = 1; k <= 400; ++k) {
            const EncoderVelocityMeasurement encoders(
                {v + std::sqrt(tuning.r_v_encoders) * normal(rng),
                 1.1 * w + std::sqrt(tuning.r_w_encoders) * normal(rng)},
                tuning.r_v_encoders, tuning.r_w_encoders);
            const GyroRateMeasurement gyro(w + std::sqrt(tuning.r_w_gyro) * normal(rng),
                                           tuning.r_w_gyro);
            ASSERT_EQ(fused.predict(model), StepStatus::Applied);
            ASSERT_EQ(encoders_only.predict(model), StepStatus::Applied);
            ASSERT_EQ(fused.update(encoders).status, StepStatus::Applied);
            ASSERT_EQ(fused.update(gyro).status, StepStatus::Applied);
            ASSERT_EQ(encoders_only.update(encoders).status, StepStatus::Applied);
        }
        const double truth = wrap_angle(w * 400 * T);
        const double fused_error = std::abs(wrap_angle(fused.state()(kMotionTheta) - truth));
        const double encoder_error =
            std::abs(wrap_angle(encoders_only.state()(kMotionTheta) - truth));
        EXPECT_GT(encoder_error, 0.7) << "seed " << seed;
        EXPECT_LT(fused_error, 0.1) << "seed " << seed;
    }
}

}  // namespace
}  // namespace legofeup
