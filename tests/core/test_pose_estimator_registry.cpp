// The registry of pose estimators (pose_estimator_registry.hpp) and the interface the loop
// holds them by: every kind has one entry, and an estimator behind PoseEstimator computes
// exactly what its filter class computes called directly.
#include <gtest/gtest.h>

#include <set>

#include "legofeup/core/odometry_process_model.hpp"
#include "legofeup/core/pose_estimator_registry.hpp"
#include "legofeup/core/pose_state_space.hpp"
#include "legofeup/core/unscented_kalman_filter.hpp"
#include "legofeup/core/walls.hpp"

namespace legofeup {
namespace {

TEST(PoseEstimatorRegistry, EveryKindHasOneEntryThatMakesThatKind) {
    std::set<FilterKind> kinds;
    for (const PoseEstimatorEntry& entry : pose_estimators()) {
        EXPECT_TRUE(kinds.insert(entry.kind).second) << to_string(entry.kind) << " twice";
        EXPECT_EQ(entry.make()->kind(), entry.kind);
        EXPECT_EQ(make_pose_estimator(entry.kind)->kind(), entry.kind);
    }
    for (const FilterKind kind : {FilterKind::Ekf, FilterKind::Ukf}) {
        EXPECT_EQ(kinds.count(kind), 1U) << to_string(kind);
    }
}

TEST(PoseEstimatorRegistry, EachShadowIsAnotherRegisteredKind) {
    for (const PoseEstimatorEntry& entry : pose_estimators()) {
        EXPECT_NE(entry.shadow, entry.kind) << to_string(entry.kind);
        EXPECT_EQ(pose_estimator_entry(entry.shadow).kind, entry.shadow);
    }
}

/// A predict and a gated wall update through the interface and on the filter itself.
template <class Filter>
void expect_same_as_the_filter(FilterKind kind) {
    const StateVector x0(-0.5, -1.0, 0.02);
    const StateCovariance P0 = StateVector(1e-4, 2e-4, 1e-3).asDiagonal();
    PoseEstimatorSettings settings;
    settings.limits.min_variance = 1e-10;
    settings.ukf.kappa = 1.0;
    const OdometryProcessModel motion(odometry_increment(13, 14, OdometryParams{}),
                                      Eigen::Vector2d(1e-7, 1e-5).asDiagonal());
    const WallMeasurement wall(standard_arena_walls(ArenaSpec{}).line(0), 1,
                               observe_wall(0.151, 0.149, IrMount{}),
                               Eigen::Vector2d(1e-4, 1e-4).asDiagonal());
    const MahalanobisGate gate{true, 9.21};

    const std::unique_ptr<PoseEstimator> estimator = make_pose_estimator(kind);
    estimator->configure(settings);
    ASSERT_TRUE(estimator->reset(x0, P0));
    Filter filter;
    filter.set_limits(settings.limits);
    if constexpr (requires { filter.set_params(settings.ukf); }) {
        filter.set_params(settings.ukf);
    }
    ASSERT_TRUE(filter.reset(x0, P0));

    for (int step = 0; step < 20; ++step) {
        EXPECT_EQ(estimator->predict(motion), filter.predict(motion));
        const auto through_interface = estimator->update(wall, gate);
        const auto direct = filter.update(wall, gate);
        EXPECT_EQ(through_interface.status, direct.status);
        EXPECT_EQ(through_interface.nis, direct.nis);
        EXPECT_EQ(through_interface.gain, direct.gain);
    }
    EXPECT_EQ(estimator->state(), filter.state());
    EXPECT_EQ(estimator->covariance(), filter.covariance());
    EXPECT_EQ(estimator->last_repairs(), filter.last_repairs());
}

TEST(PoseEstimator, TheEkfBehindTheInterfaceIsTheEkf) {
    expect_same_as_the_filter<ExtendedKalmanFilter<PoseStateSpace>>(FilterKind::Ekf);
}

TEST(PoseEstimator, TheUkfBehindTheInterfaceIsTheUkfWithItsSpread) {
    expect_same_as_the_filter<UnscentedKalmanFilter<PoseStateSpace>>(FilterKind::Ukf);
}

}  // namespace
}  // namespace legofeup
