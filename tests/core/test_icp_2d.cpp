#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include "legofeup/core/icp_2d.hpp"
#include "legofeup/core/laser_scan.hpp"
#include "legofeup/core/occupancy_grid.hpp"
#include "scan_worlds.hpp"

namespace legofeup {
namespace {

/// The transform error: translation (m) and rotation (rad) between two poses.
struct PoseError {
    double translation = 0.0;
    double rotation = 0.0;
};
PoseError error_between(const Pose2& a, const Pose2& b) {
    return {std::hypot(a.x - b.x, a.y - b.y), std::abs(wrap_angle(a.theta - b.theta))};
}

/// The points of the URG scan a scanner at `pose` measures in `grid`, in its own frame, with
/// Gaussian range noise of `sigma` metres.
std::vector<Vector2> scan_points(const OccupancyGrid& grid, const Pose2& pose, double sigma,
                                 std::mt19937& rng) {
    const ScanGeometry urg;
    LaserScan scan;
    expected_scan(grid, pose, urg, scan);
    std::normal_distribution<double> noise(0.0, sigma);
    for (int beam = 0; beam < urg.beam_count; ++beam) {
        std::uint16_t& mm = scan.range_mm[static_cast<std::size_t>(beam)];
        if (mm >= kRangeFirstValid && sigma > 0.0) {
            mm = static_cast<std::uint16_t>(
                std::max<long>(kRangeFirstValid, std::lround(mm + 1000.0 * noise(rng))));
        }
    }
    std::vector<Vector2> points;
    scan_to_points(scan, urg, Pose2{}, points);
    return points;
}

/// A random pose offset of up to ±max_translation in x and y and ±max_rotation.
Pose2 random_offset(std::mt19937& rng, double max_translation, double max_rotation) {
    std::uniform_real_distribution<double> t(-max_translation, max_translation);
    std::uniform_real_distribution<double> r(-max_rotation, max_rotation);
    return {t(rng), t(rng), r(rng)};
}

/// One trial of the lesson's use: the reference is the expected scan at the predicted pose A,
/// the source the (noisy) scan at the true pose B = A ⊕ offset. The transform moving source
/// points (frame B) onto reference points (frame A) is A⁻¹ ⊕ B = offset.
struct Trial {
    Pose2 truth;
    IcpResult result;
};
Trial room_trial(Icp2d& icp, unsigned seed, double sigma) {
    std::mt19937 rng(seed);
    const OccupancyGrid room = testing::room_grid();
    std::uniform_real_distribution<double> x(1.5, 4.5);
    std::uniform_real_distribution<double> y(1.6, 2.6);
    std::uniform_real_distribution<double> heading(-kPi, kPi);
    const Pose2 predicted{x(rng), y(rng), heading(rng)};
    const Pose2 offset = random_offset(rng, 0.2, degrees_to_radians(10.0));
    const Pose2 truth = compose(predicted, offset);
    const std::vector<Vector2> reference = scan_points(room, predicted, 0.0, rng);
    const std::vector<Vector2> source = scan_points(room, truth, sigma, rng);
    icp.set_reference(reference);
    return {compose(inverse(predicted), truth), icp.align(source)};
}

IcpParams lesson_params(IcpMetric metric) {
    IcpParams params;
    params.metric = metric;
    // A 10° error moves a point 5 m away by 0.87 m: the first correspondences must reach it.
    params.max_correspondence_distance = 1.0;
    params.trim_fraction = 0.1;
    // Point-to-point converges linearly (30–60 iterations to the 1e-5 epsilons here),
    // point-to-line quadratically near the solution (4–8).
    params.max_iterations = metric == IcpMetric::PointToPoint ? 100 : 30;
    return params;
}

class IcpMetrics : public ::testing::TestWithParam<IcpMetric> {};

TEST_P(IcpMetrics, RecoversKnownOffsetsInTheRoomWithRangeNoise) {
    // 40 seeds, offsets up to 0.2 m / 10°, 10 mm range noise (the URG's under 1 m).
    Icp2d icp(lesson_params(GetParam()));
    double worst_translation = 0.0;
    double worst_rotation = 0.0;
    for (unsigned seed = 1; seed <= 40; ++seed) {
        const Trial trial = room_trial(icp, seed, 0.010);
        const PoseError e = error_between(trial.result.transform, trial.truth);
        EXPECT_TRUE(trial.result.converged) << "seed " << seed;
        EXPECT_GT(trial.result.matched_points, 400) << "seed " << seed;
        EXPECT_LT(trial.result.rms_residual, 0.03) << "seed " << seed;
        worst_translation = std::max(worst_translation, e.translation);
        worst_rotation = std::max(worst_rotation, e.rotation);
    }
    // Stated tolerance: 2 cm and 0.5° over every seed.
    EXPECT_LT(worst_translation, 0.02);
    EXPECT_LT(worst_rotation, degrees_to_radians(0.5));
    std::cout << to_string(GetParam()) << ": worst error " << worst_translation * 1000.0 << " mm, "
              << radians_to_degrees(worst_rotation) << "°\n";
}

/// The worst pose error of ICP over 20 seeds in the room, offsets up to 0.2 m / 10° from a
/// predicted pose that walks with the seed, 10 mm range noise, after `corrupt` spoils the
/// source scan; every match must converge.
struct WorstError {
    double translation = 0.0;
    double rotation = 0.0;
};

WorstError worst_error_over_seeds(
    Icp2d& icp, unsigned seed_offset,
    const std::function<void(std::vector<Vector2>&, std::mt19937&)>& corrupt) {
    const OccupancyGrid room = testing::room_grid();
    WorstError worst;
    for (unsigned seed = 1; seed <= 20; ++seed) {
        std::mt19937 rng(seed + seed_offset);
        const Pose2 predicted{2.0 + 0.1 * seed, 1.8, -0.4 * seed};
        const Pose2 offset = random_offset(rng, 0.2, degrees_to_radians(10.0));
        const Pose2 truth = compose(predicted, offset);
        icp.set_reference(scan_points(room, predicted, 0.0, rng));
        std::vector<Vector2> source = scan_points(room, truth, 0.010, rng);
        corrupt(source, rng);
        const IcpResult result = icp.align(source);
        const PoseError e = error_between(result.transform, compose(inverse(predicted), truth));
        EXPECT_TRUE(result.converged) << "seed " << seed;
        worst.translation = std::max(worst.translation, e.translation);
        worst.rotation = std::max(worst.rotation, e.rotation);
    }
    std::cout << to_string(icp.params().metric) << ": worst error " << worst.translation * 1000.0
              << " mm, " << radians_to_degrees(worst.rotation) << "°\n";
    return worst;
}

TEST_P(IcpMetrics, RecoversOffsetsWithOutliersInTheSource) {
    // 15 % of the source points replaced by clutter (people, chairs) in front of the walls,
    // 10–50 % of the way back to the scanner. Trimming 20 % drops them.
    IcpParams params = lesson_params(GetParam());
    params.trim_fraction = 0.2;
    Icp2d icp(params);
    const WorstError worst =
        worst_error_over_seeds(icp, 100, [](std::vector<Vector2>& source, std::mt19937& rng) {
            std::uniform_real_distribution<double> shrink(0.5, 0.9);
            std::bernoulli_distribution clutter(0.15);
            for (Vector2& p : source) {
                if (clutter(rng)) {
                    p *= shrink(rng);  // a point in front of the wall along the same beam
                }
            }
        });
    // Stated tolerance: 1 cm and 0.5°.
    EXPECT_LT(worst.translation, 0.01);
    EXPECT_LT(worst.rotation, degrees_to_radians(0.5));
}

TEST_P(IcpMetrics, RecoversOffsetsWithPartialOverlap) {
    // The source sees only the first 60 % of its beams (the rest blocked), and the two poses
    // see different parts of the room.
    Icp2d icp(lesson_params(GetParam()));
    const WorstError worst = worst_error_over_seeds(
        icp, 200,
        [](std::vector<Vector2>& source, std::mt19937&) { source.resize(source.size() * 6 / 10); });
    // Stated tolerance: 1 cm and 0.5°.
    EXPECT_LT(worst.translation, 0.01);
    EXPECT_LT(worst.rotation, degrees_to_radians(0.5));
}

TEST_P(IcpMetrics, UnrelatedCloudsDoNotMatch) {
    Icp2d icp(lesson_params(GetParam()));
    std::mt19937 rng(1);
    icp.set_reference(scan_points(testing::room_grid(), Pose2{2.0, 2.0, 0.0}, 0.0, rng));
    // A cloud 20 m away: no reference point within the correspondence distance.
    std::vector<Vector2> far;
    for (int i = 0; i < 200; ++i) {
        far.emplace_back(20.0 + 0.01 * i, -15.0 + 0.02 * i);
    }
    const IcpResult result = icp.align(far);
    EXPECT_FALSE(result.converged);
    EXPECT_EQ(result.matched_points, 0);
    EXPECT_EQ(result.iterations, 1);
}

TEST_P(IcpMetrics, TooSmallReferenceOrSourceFails) {
    Icp2d icp(lesson_params(GetParam()));
    const std::vector<Vector2> two{Vector2(0, 0), Vector2(1, 0)};
    icp.set_reference(two);
    EXPECT_EQ(icp.reference_size(), 0);
    std::vector<Vector2> source{Vector2(0, 0), Vector2(1, 0), Vector2(0, 1), Vector2(1, 1)};
    IcpResult result = icp.align(source, Pose2{0.1, 0.2, 0.3});
    EXPECT_FALSE(result.converged);
    EXPECT_EQ(result.matched_points, 0);
    EXPECT_EQ(result.iterations, 0);
    EXPECT_EQ(result.transform, (Pose2{0.1, 0.2, 0.3}));  // the guess, untouched

    icp.set_reference(source);
    EXPECT_EQ(icp.reference_size(), 4);
    result = icp.align(std::span<const Vector2>(two));
    EXPECT_FALSE(result.converged);
    EXPECT_EQ(result.iterations, 0);
    // A fresh object has no reference at all.
    Icp2d empty;
    EXPECT_EQ(empty.reference_size(), 0);
    EXPECT_FALSE(empty.align(source).converged);
}

TEST_P(IcpMetrics, MaxIterationsIsRespected) {
    IcpParams params = lesson_params(GetParam());
    params.max_iterations = 2;
    params.translation_epsilon = 1e-12;
    params.rotation_epsilon = 1e-12;
    Icp2d icp(params);
    const Trial trial = room_trial(icp, 3, 0.010);
    EXPECT_EQ(trial.result.iterations, 2);
    EXPECT_FALSE(trial.result.converged);
    EXPECT_GT(trial.result.matched_points, 0);
    // With room to converge it stops early, before the limit.
    params.max_iterations = 200;
    params.translation_epsilon = 1e-5;
    params.rotation_epsilon = 1e-5;
    icp.set_params(params);
    const Trial free_run = room_trial(icp, 3, 0.010);
    EXPECT_TRUE(free_run.result.converged);
    EXPECT_LT(free_run.result.iterations, 200);
}

TEST_P(IcpMetrics, SameInputGivesBitIdenticalResults) {
    Icp2d icp(lesson_params(GetParam()));
    const Trial first = room_trial(icp, 17, 0.010);
    const Trial second = room_trial(icp, 17, 0.010);
    EXPECT_EQ(first.result.transform, second.result.transform);
    EXPECT_EQ(first.result.iterations, second.result.iterations);
    EXPECT_EQ(first.result.matched_points, second.result.matched_points);
}

INSTANTIATE_TEST_SUITE_P(Icp2d, IcpMetrics,
                         ::testing::Values(IcpMetric::PointToPoint, IcpMetric::PointToLine),
                         [](const ::testing::TestParamInfo<IcpMetric>& param_info) {
                             return std::string(to_string(param_info.param));
                         });

/// Points along the closed polygon `corners`, one every `spacing` metres starting `phase`
/// metres along each edge.
std::vector<Vector2> sample_polygon(const std::vector<Vector2>& corners, double spacing,
                                    double phase) {
    std::vector<Vector2> points;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const Vector2& a = corners[i];
        const Vector2& b = corners[(i + 1) % corners.size()];
        const double length = (b - a).norm();
        for (double s = phase; s < length; s += spacing) {
            points.push_back(a + (b - a) * (s / length));
        }
    }
    return points;
}

TEST(Icp2d, PointToPointRecoversAnExactRigidMotion) {
    // The source is the reference moved by T⁻¹ point for point: the closed form is exact.
    const std::vector<Vector2> reference =
        sample_polygon({{0, 0}, {4, 0}, {4, 1}, {2.5, 1}, {2.5, 3}, {0, 3}}, 0.25, 0.1);
    const Pose2 truth{0.06, -0.04, degrees_to_radians(2.0)};
    const Pose2 back = inverse(truth);
    std::vector<Vector2> source;
    for (const Vector2& q : reference) {
        source.push_back(transform_point(back, q));
    }
    IcpParams params;
    params.metric = IcpMetric::PointToPoint;
    params.trim_fraction = 0.0;
    Icp2d icp(params);
    icp.set_reference(reference);
    const IcpResult result = icp.align(source);
    ASSERT_TRUE(result.converged);
    const PoseError e = error_between(result.transform, truth);
    EXPECT_LT(e.translation, 1e-9);
    EXPECT_LT(e.rotation, 1e-9);
    EXPECT_LT(result.rms_residual, 1e-9);
    EXPECT_EQ(result.matched_points, static_cast<int>(reference.size()));
}

TEST(Icp2d, PointToLineIsExactOnResampledLines) {
    // Reference and source sample the same polygon at different places along its edges.
    // Point-to-line only asks source points to lie on the reference's lines, so it recovers
    // the motion almost exactly; point-to-point is biased by the sampling offset (bounded by
    // half the spacing) — the difference the lesson points out.
    const std::vector<Vector2> corners{{0, 0}, {4, 0}, {4, 1}, {2.5, 1}, {2.5, 3}, {0, 3}};
    const std::vector<Vector2> reference = sample_polygon(corners, 0.05, 0.0);
    const Pose2 truth{0.12, -0.08, degrees_to_radians(6.0)};
    const Pose2 back = inverse(truth);
    std::vector<Vector2> source;
    for (const Vector2& q : sample_polygon(corners, 0.05, 0.021)) {
        source.push_back(transform_point(back, q));
    }
    IcpParams params;
    params.metric = IcpMetric::PointToLine;
    params.max_correspondence_distance = 0.5;
    params.trim_fraction = 0.0;
    Icp2d icp(params);
    icp.set_reference(reference);
    const IcpResult line = icp.align(source);
    ASSERT_TRUE(line.converged);
    PoseError e = error_between(line.transform, truth);
    // The normals at the six corners are wrong; their few points leave a sub-millimetre error.
    EXPECT_LT(e.translation, 1e-3);
    EXPECT_LT(e.rotation, degrees_to_radians(0.05));

    // Point-to-point from a smaller offset (its basin is narrower) stops where the along-line
    // pulls of the nearest samples balance: within about half the spacing (2.5 cm) at the
    // ends of the 2–4 m edges, i.e. up to ≈ 0.7° — not exactly.
    const Pose2 small_truth{0.03, -0.02, degrees_to_radians(1.0)};
    source.clear();
    for (const Vector2& q : sample_polygon(corners, 0.05, 0.021)) {
        source.push_back(transform_point(inverse(small_truth), q));
    }
    params.metric = IcpMetric::PointToPoint;
    params.max_iterations = 200;
    icp.set_params(params);
    const IcpResult point = icp.align(source);
    ASSERT_TRUE(point.converged);
    e = error_between(point.transform, small_truth);
    EXPECT_LT(e.translation, 0.025);
    EXPECT_LT(e.rotation, degrees_to_radians(1.0));
    EXPECT_GT(e.translation, 1e-4);  // biased, unlike point-to-line
}

TEST(Icp2d, InitialGuessIsTheStartingTransform) {
    // A large offset (1 m, 30°) is out of reach from the identity but recovered from a guess
    // near it.
    const std::vector<Vector2> reference =
        sample_polygon({{0, 0}, {4, 0}, {4, 1}, {2.5, 1}, {2.5, 3}, {0, 3}}, 0.05, 0.0);
    const Pose2 truth{1.0, 0.5, degrees_to_radians(30.0)};
    std::vector<Vector2> source;
    for (const Vector2& q : reference) {
        source.push_back(transform_point(inverse(truth), q));
    }
    IcpParams params;
    params.max_correspondence_distance = 0.3;
    Icp2d icp(params);
    icp.set_reference(reference);
    const IcpResult guessed = icp.align(source, Pose2{0.95, 0.45, degrees_to_radians(28.0)});
    ASSERT_TRUE(guessed.converged);
    const PoseError e = error_between(guessed.transform, truth);
    EXPECT_LT(e.translation, 1e-3);
    EXPECT_LT(e.rotation, 1e-3);
}

TEST(Icp2d, NonFinitePointsAreIgnored) {
    const std::vector<Vector2> corners{{0, 0}, {4, 0}, {4, 1}, {2.5, 1}, {2.5, 3}, {0, 3}};
    std::vector<Vector2> reference = sample_polygon(corners, 0.05, 0.0);
    const std::size_t finite_size = reference.size();
    reference.emplace_back(std::nan(""), 1.0);
    std::vector<Vector2> source = sample_polygon(corners, 0.05, 0.02);
    source.emplace_back(1.0, std::numeric_limits<double>::infinity());
    Icp2d icp;
    icp.set_reference(reference);
    EXPECT_EQ(icp.reference_size(), static_cast<int>(finite_size));
    const IcpResult result = icp.align(source);
    EXPECT_TRUE(result.converged);
    EXPECT_LT(error_between(result.transform, Pose2{}).translation, 1e-3);
}

TEST(IcpParams, ValidateNamesEachBadField) {
    EXPECT_TRUE(validate(IcpParams{}, "icp").empty());
    const auto field_of = [](const IcpParams& params) {
        const std::vector<ConfigIssue> issues = validate(params, "laser.icp");
        return issues.size() == 1 ? issues[0].field
                                  : std::string("(") + std::to_string(issues.size()) + " issues)";
    };
    IcpParams p;
    p.max_iterations = 0;
    EXPECT_EQ(field_of(p), "laser.icp.max_iterations");
    p = {};
    p.max_correspondence_distance = -0.1;
    EXPECT_EQ(field_of(p), "laser.icp.max_correspondence_distance");
    p = {};
    p.trim_fraction = 1.0;
    EXPECT_EQ(field_of(p), "laser.icp.trim_fraction");
    p = {};
    p.trim_fraction = std::nan("");
    EXPECT_EQ(field_of(p), "laser.icp.trim_fraction");
    p = {};
    p.translation_epsilon = 0.0;
    EXPECT_EQ(field_of(p), "laser.icp.translation_epsilon");
    p = {};
    p.rotation_epsilon = std::numeric_limits<double>::infinity();
    EXPECT_EQ(field_of(p), "laser.icp.rotation_epsilon");
}

TEST(IcpMetric, NamesRoundTrip) {
    for (const IcpMetric metric : {IcpMetric::PointToPoint, IcpMetric::PointToLine}) {
        EXPECT_EQ(icp_metric_from_string(to_string(metric)), metric);
    }
    EXPECT_STREQ(to_string(IcpMetric::PointToLine), "point_to_line");
    EXPECT_FALSE(icp_metric_from_string("point-to-line").has_value());
    EXPECT_FALSE(icp_metric_from_string("").has_value());
}

}  // namespace
}  // namespace legofeup
