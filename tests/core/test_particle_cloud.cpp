// The particle cloud's thinning for drawing (particle_cloud.hpp): which particles it shows,
// how many, each cluster's share, relative weights (also of weights no float can hold), and
// what the estimators give through the PoseEstimator interface.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "legofeup/core/free_space.hpp"
#include "legofeup/core/particle_cloud.hpp"
#include "legofeup/core/pose_estimator_registry.hpp"

namespace legofeup {
namespace {

struct Columns {
    std::vector<double> x, y, theta, weight;
    void add(double px, double py, double pt, double w) {
        x.push_back(px);
        y.push_back(py);
        theta.push_back(pt);
        weight.push_back(w);
    }
    std::vector<ParticlePoint> thin(std::size_t max_points) const {
        std::vector<ParticlePoint> out{{9.0F, 9.0F, 9.0F, 9.0F}};  // must be cleared
        thin_particles(x, y, theta, weight, max_points, out);
        return out;
    }
};

TEST(ParticleCloud, ASmallCloudIsShownWholeWithWeightsRelativeToTheHeaviest) {
    Columns cloud;
    cloud.add(1.0, 2.0, 0.5, 0.1);
    cloud.add(-1.0, 0.5, -3.0, 0.4);
    cloud.add(0.25, -0.75, 1.0, 0.2);
    const std::vector<ParticlePoint> points = cloud.thin(1000);
    ASSERT_EQ(points.size(), 3U);
    EXPECT_FLOAT_EQ(points[0].x, 1.0F);
    EXPECT_FLOAT_EQ(points[1].y, 0.5F);
    EXPECT_FLOAT_EQ(points[2].theta, 1.0F);
    EXPECT_FLOAT_EQ(points[0].weight, 0.25F);  // 0.1 / 0.4
    EXPECT_FLOAT_EQ(points[1].weight, 1.0F);
    EXPECT_FLOAT_EQ(points[2].weight, 0.5F);
}

TEST(ParticleCloud, ALargeCloudIsThinnedToAtMostTheLimitByAStride) {
    for (const std::size_t count : {1001U, 2000U, 9999U, 10000U, 10001U}) {
        Columns cloud;
        for (std::size_t i = 0; i < count; ++i) {
            cloud.add(static_cast<double>(i), 0.0, 0.0, 1.0);
        }
        const std::vector<ParticlePoint> points = cloud.thin(1000);
        const std::size_t stride = (count + 999) / 1000;
        SCOPED_TRACE(count);
        ASSERT_LE(points.size(), 1000U);
        ASSERT_EQ(points.size(), (count + stride - 1) / stride);
        EXPECT_GE(points.size(), 500U);  // a stride never shows less than half the limit
        for (std::size_t k = 0; k < points.size(); ++k) {
            EXPECT_FLOAT_EQ(points[k].x, static_cast<float>(k * stride));  // every stride-th
        }
    }
}

TEST(ParticleCloud, ClustersKeepTheirShareOfThePoints) {
    // 10,000 particles, 70 % near (0, 0) and 30 % near (5, 0): together (as resampling leaves
    // copies) and scattered (as free-space draws are).
    const auto share_near_origin = [](const std::vector<ParticlePoint>& points) {
        double near = 0.0;
        for (const ParticlePoint& p : points) {
            near += p.x < 2.5F ? 1.0 : 0.0;
        }
        return near / static_cast<double>(points.size());
    };
    std::mt19937_64 random(42);
    std::normal_distribution<double> spread(0.0, 0.2);
    Columns together;
    Columns scattered;
    std::bernoulli_distribution in_first(0.7);
    int first = 0;
    for (int i = 0; i < 10000; ++i) {
        together.add((i < 7000 ? 0.0 : 5.0) + spread(random), spread(random), 0.0, 1.0);
        const bool a = in_first(random);
        first += a ? 1 : 0;
        scattered.add((a ? 0.0 : 5.0) + spread(random), spread(random), 0.0, 1.0);
    }
    const std::vector<ParticlePoint> thinned_together = together.thin(1000);
    ASSERT_EQ(thinned_together.size(), 1000U);
    EXPECT_NEAR(share_near_origin(thinned_together), 0.7, 1.0 / 1000.0);
    // Scattered: a random sample of 1,000 — within 4 binomial standard deviations.
    const double p = first / 10000.0;
    EXPECT_NEAR(share_near_origin(scattered.thin(1000)), p, 4.0 * std::sqrt(p * (1 - p) / 1000));
}

TEST(ParticleCloud, WeightsBelowAnyFloatAreStillRelativeAndInvalidParticlesAreLeftOut) {
    Columns cloud;
    cloud.add(0.0, 0.0, 0.0, 1e-300);
    cloud.add(1.0, 0.0, 0.0, 4e-300);
    cloud.add(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0, 1.0);
    cloud.add(2.0, std::numeric_limits<double>::infinity(), 0.0, 1.0);
    cloud.add(3.0, 0.0, 0.0, std::numeric_limits<double>::quiet_NaN());
    cloud.add(4.0, 0.0, 0.0, -1.0);
    const std::vector<ParticlePoint> points = cloud.thin(100);
    ASSERT_EQ(points.size(), 2U);
    EXPECT_FLOAT_EQ(points[0].weight, 0.25F);
    EXPECT_FLOAT_EQ(points[1].weight, 1.0F);

    Columns zero;
    zero.add(0.0, 0.0, 0.0, 0.0);
    zero.add(1.0, 0.0, 0.0, 0.0);
    const std::vector<ParticlePoint> equal = zero.thin(10);
    ASSERT_EQ(equal.size(), 2U);
    EXPECT_FLOAT_EQ(equal[1].weight, 1.0F);  // all zero: shown as equal, not as NaN
    EXPECT_TRUE(Columns{}.thin(10).empty());
    EXPECT_TRUE(zero.thin(0).empty());
}

TEST(ParticleCloud, OnlyTheParticleFilterHasACloudToShow) {
    PoseEstimatorSettings settings;
    settings.particles.particle_count = 5000;
    settings.seed = 3;
    settings.free_space = std::make_shared<const FreeSpace>(
        FreeSpace::rectangle(Vector2(-2.0, -1.0), Vector2(2.0, 1.0)));
    for (const FilterKind kind : {FilterKind::Ekf, FilterKind::Ukf, FilterKind::Pf}) {
        const std::unique_ptr<PoseEstimator> estimator = make_pose_estimator(kind);
        estimator->configure(settings);
        ASSERT_TRUE(estimator->reset_uniform());
        std::vector<ParticlePoint> points{{1.0F, 1.0F, 1.0F, 1.0F}};
        estimator->sample_cloud(kParticlesShown, points);
        if (kind != FilterKind::Pf) {
            EXPECT_TRUE(points.empty()) << to_string(kind);
            continue;
        }
        ASSERT_EQ(points.size(), kParticlesShown);
        // Global localisation: the points spread over the free space, as the cloud does.
        double min_x = 1e9;
        double max_x = -1e9;
        for (const ParticlePoint& p : points) {
            ASSERT_GE(p.x, -2.0F);
            ASSERT_LE(p.x, 2.0F);
            ASSERT_GE(p.y, -1.0F);
            ASSERT_LE(p.y, 1.0F);
            EXPECT_FLOAT_EQ(p.weight, 1.0F);  // equal weights
            min_x = std::min(min_x, static_cast<double>(p.x));
            max_x = std::max(max_x, static_cast<double>(p.x));
        }
        EXPECT_LT(min_x, -1.8);
        EXPECT_GT(max_x, 1.8);
    }
}

}  // namespace
}  // namespace legofeup
