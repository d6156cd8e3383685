// The simulated laser rangefinder (paper 001, docs/sensors.md) in worlds with an occupancy
// map: ranges against analytic distances in rectangular rooms, the noise statistics near and
// far, error codes, dropouts, cadence, determinism, independence from the other sensors, and
// the map seen by the IR sensors and the beacon scanner too.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "laser_scanner.hpp"
#include "legofeup/core/angles.hpp"
#include "legofeup/core/laser_scan.hpp"
#include "legofeup/sim/simulator.hpp"
#include "map_test_support.hpp"
#include "world_test_support.hpp"

namespace legofeup::sim {
namespace {

using test::RoomInside;

// A room of 6 m × 4 m inside a grid of 0.05 m cells with walls two cells (0.1 m) thick:
// inside [0.1, 5.9] × [0.1, 3.9] m in the grid frame.
constexpr int kWidth = 120;
constexpr int kHeight = 80;
constexpr double kCell = 0.05;
constexpr int kWall = 2;

struct Room {
    Pose2 origin;
    RoomInside inside = test::room_inside(kWidth, kHeight, kCell, kWall);

    /// A grid-frame pose in the world.
    Pose2 to_world(const Pose2& grid_pose) const {
        const double c = std::cos(origin.theta);
        const double s = std::sin(origin.theta);
        return {origin.x + c * grid_pose.x - s * grid_pose.y,
                origin.y + s * grid_pose.x + c * grid_pose.y, grid_pose.theta + origin.theta};
    }

    WorldSpec world(const Pose2& grid_start) const {
        WorldSpec world;
        world.name = "room";
        world.map = test::room_map(kWidth, kHeight, kCell, origin, kWall);
        world.start = to_world(grid_start);
        return world;
    }

    /// The true distance of each beam of `spec` from the robot at world pose `robot`
    /// (analytic: the scanner's pose in the grid frame, then the box's sides).
    std::vector<double> distances(const LaserScannerSpec& spec, const Pose2& robot) const {
        const Pose2 scanner = test::in_grid_frame(origin, compose(robot, spec.mount));
        std::vector<double> out;
        for (int beam = 0; beam < spec.geometry.beam_count; ++beam) {
            out.push_back(test::distance_to_box_side(inside, scanner.x, scanner.y,
                                                     scanner.theta + spec.geometry.angle_of(beam)));
        }
        return out;
    }
};

RobotSpec with_laser(double sigma_near = 0.0, double sigma_relative = 0.0) {
    RobotSpec robot;
    robot.laser_scanner.enabled = true;
    robot.laser_scanner.sigma_near = sigma_near;
    robot.laser_scanner.sigma_relative = sigma_relative;
    return robot;
}

/// The scan in `frame` against the analytic distances: noise-free, each reading is the
/// distance rounded to whole millimetres (±0.51 mm for Box2D's float geometry), and beams
/// beyond range_max read kRangeNoEcho. Returns how many beams read kRangeNoEcho.
int expect_exact_scan(const SensorFrame& frame, const std::vector<double>& distances,
                      const ScanGeometry& geometry) {
    EXPECT_TRUE(frame.has_laser_scan);
    EXPECT_EQ(frame.laser.beam_count, geometry.beam_count);
    int no_echo = 0;
    for (int beam = 0; beam < geometry.beam_count; ++beam) {
        const double d = distances[static_cast<std::size_t>(beam)];
        const std::uint16_t reading = frame.laser.range_mm[static_cast<std::size_t>(beam)];
        if (std::abs(d - geometry.range_max) < 1e-3) {
            continue;  // at the edge of the range either answer is right
        }
        if (d > geometry.range_max) {
            EXPECT_EQ(reading, kRangeNoEcho) << "beam " << beam << " at " << d << " m";
            ++no_echo;
        } else {
            EXPECT_NEAR(reading, 1000.0 * d, 0.51) << "beam " << beam;
        }
    }
    return no_echo;
}

// ---- ranges and codes ----

TEST(LaserScanner, NoiseFreeRangesAreTheAnalyticDistancesInARotatedRoom) {
    const Room room{{-1.0, 0.5, 0.3}};
    RobotSpec robot = with_laser();
    robot.laser_scanner.mount = {0.05, 0.01, 0.1};  // ahead, a little left, turned 0.1 rad
    for (const Pose2& start : {Pose2{0.4, 0.4, 0.5}, Pose2{4.5, 3.0, 2.5}, Pose2{0.4, 3.5, -1.2}}) {
        Simulator simulator(room.world(start), robot, {}, 1);
        const SensorFrame frame = simulator.sensor_frame();  // the scan at reset (t = 0)
        const Pose2 truth = simulator.ground_truth().pose;
        const int no_echo = expect_exact_scan(frame, room.distances(robot.laser_scanner, truth),
                                              robot.laser_scanner.geometry);
        EXPECT_EQ(frame.laser.range_mm[kMaxScanBeams - 1], 0);  // beyond beam_count: zeros
        if (start.y == 0.4) {
            // The far corner, 6.5 m away, is in view: the beams 0.19 … 0.68 rad from the grid's
            // x axis reach past 5.6 m, about 80 of them.
            EXPECT_GT(no_echo, 60);
        }
    }
}

TEST(LaserScanner, ReadingsOutsideTheRangeGetTheirErrorCodes) {
    const Room room{};
    RobotSpec robot = with_laser();
    robot.laser_scanner.geometry.range_min = 0.7;
    robot.laser_scanner.geometry.range_max = 3.0;
    // 0.6 m from the right wall looking at it, 1 m from the lower one, 2.8 m from the upper.
    Simulator simulator(room.world({5.3, 1.1, 0.0}), robot, {}, 1);
    const SensorFrame frame = simulator.sensor_frame();
    const std::vector<double> d =
        room.distances(robot.laser_scanner, simulator.ground_truth().pose);
    int too_near = 0;
    int no_echo = 0;
    int valid = 0;
    for (int beam = 0; beam < robot.laser_scanner.geometry.beam_count; ++beam) {
        const double distance = d[static_cast<std::size_t>(beam)];
        const std::uint16_t reading = frame.laser.range_mm[static_cast<std::size_t>(beam)];
        if (distance < 0.7 - 1e-3) {
            EXPECT_EQ(reading, kRangeTooNear) << beam;
            ++too_near;
        } else if (distance > 3.0 + 1e-3) {
            EXPECT_EQ(reading, kRangeNoEcho) << beam;
            ++no_echo;
        } else if (distance > 0.7 + 1e-3 && distance < 3.0 - 1e-3) {
            EXPECT_NEAR(reading, 1000.0 * distance, 0.51) << beam;
            ++valid;
        }
    }
    EXPECT_GT(too_near, 50);
    EXPECT_GT(no_echo, 20);  // the last beams on the left, towards the upper wall behind
    EXPECT_GT(valid, 50);
}

TEST(LaserScanner, TheReadingModelWorkedByHand) {
    LaserScannerSpec spec;  // 10 mm to 1 m, 1 % beyond; 0.02 … 5.6 m
    spec.dropout_probability = 0.25;
    EXPECT_DOUBLE_EQ(laser_range_sigma(spec, 0.4), 0.01);
    EXPECT_DOUBLE_EQ(laser_range_sigma(spec, 1.0), 0.01);
    EXPECT_DOUBLE_EQ(laser_range_sigma(spec, 3.0), 0.03);
    EXPECT_EQ(laser_reading(spec, std::nullopt, 0.0, 0.0), kRangeNoEcho);  // not a dropout
    EXPECT_EQ(laser_reading(spec, 2.0, 1.5, 0.9), 2030);                   // 2 m + 1.5·20 mm
    EXPECT_EQ(laser_reading(spec, 0.5, -2.0, 0.9), 480);                   // 0.5 m − 2·10 mm
    EXPECT_EQ(laser_reading(spec, 1.23449, 0.0, 0.9), 1234);               // rounded to the mm
    EXPECT_EQ(laser_reading(spec, 1.23451, 0.0, 0.9), 1235);
    EXPECT_EQ(laser_reading(spec, 0.025, -1.0, 0.9), kRangeTooNear);  // 15 mm < 20 mm
    EXPECT_EQ(laser_reading(spec, 0.01, 0.0, 0.1), kRangeTooNear);    // codes win over dropout
    EXPECT_EQ(laser_reading(spec, 0.02, 0.0, 0.9), 20);               // the shortest distance
    EXPECT_EQ(laser_reading(spec, 5.55, 1.0, 0.9), kRangeNoEcho);     // pushed beyond 5.6 m
    EXPECT_EQ(laser_reading(spec, 5.6, 0.0, 0.9), 5600);
    EXPECT_EQ(laser_reading(spec, 2.0, 0.0, 0.2499), kRangeDropout);
    EXPECT_EQ(laser_reading(spec, 2.0, 0.0, 0.25), 2000);
}

// ---- noise ----

TEST(LaserScanner, RangeNoiseIsUnbiasedWithSigmaNearAndOnePercentFar) {
    const Room room{};
    // σ_near = 15 mm, distinct from 1 % of any near distance, so a swapped regime shows.
    const RobotSpec robot = with_laser(0.015, 0.01);
    Simulator simulator(room.world({5.3, 1.1, 0.0}), robot, {}, 4);
    const std::vector<double> d =
        room.distances(robot.laser_scanner, simulator.ground_truth().pose);
    std::vector<double> near;  // (r − d)/σ(d), which should be N(0, 1)
    std::vector<double> far;
    for (int scan = 0; scan < 150; ++scan) {
        SensorFrame frame = simulator.sensor_frame();
        ASSERT_TRUE(frame.has_laser_scan);
        for (int beam = 0; beam < robot.laser_scanner.geometry.beam_count; ++beam) {
            const double distance = d[static_cast<std::size_t>(beam)];
            const double range = frame.laser.range_mm[static_cast<std::size_t>(beam)] / 1000.0;
            if (distance < 0.9) {
                near.push_back((range - distance) / 0.015);
            } else if (distance > 2.0 && distance < 5.0) {
                far.push_back((range - distance) / (0.01 * distance));
            }
        }
        simulator.step_control_period();
        simulator.step_control_period();
    }
    for (const auto& [name, errors] : {std::pair{"near", near}, std::pair{"far", far}}) {
        const test::SampleStats s = test::sample_stats_of(errors);
        SCOPED_TRACE(testing::Message()
                     << name << ": " << s.n << " readings, mean " << s.mean << ", sd " << s.sd);
        ASSERT_GT(s.n, 10000U);
        const auto n = static_cast<double>(s.n);
        EXPECT_NEAR(s.mean, 0.0, 4.5 / std::sqrt(n));  // SE of the mean: 1/√n
        // SE of the sd ≈ 1/√(2n); rounding to the mm adds at most (1/12 mm²)/σ² ≈ 0.04 %.
        EXPECT_NEAR(s.sd, 1.0, 4.5 / std::sqrt(2.0 * n) + 0.001);
    }
}

TEST(LaserScanner, DropsOutTheConfiguredFractionOfBeamsThatHadADistance) {
    const Room room{};
    RobotSpec robot = with_laser();
    robot.laser_scanner.dropout_probability = 0.2;
    Simulator simulator(room.world({1.0, 1.2, 0.0}), robot, {}, 8);
    const std::vector<double> d =
        room.distances(robot.laser_scanner, simulator.ground_truth().pose);
    long dropouts = 0;
    long candidates = 0;
    for (int scan = 0; scan < 40; ++scan) {
        const SensorFrame frame = simulator.sensor_frame();
        for (int beam = 0; beam < robot.laser_scanner.geometry.beam_count; ++beam) {
            const std::uint16_t reading = frame.laser.range_mm[static_cast<std::size_t>(beam)];
            if (d[static_cast<std::size_t>(beam)] > 5.6 + 1e-3) {
                EXPECT_EQ(reading, kRangeNoEcho);  // no distance: nothing to drop
            } else if (d[static_cast<std::size_t>(beam)] < 5.6 - 1e-3) {
                ++candidates;
                dropouts += reading == kRangeDropout ? 1 : 0;
            }
        }
        simulator.step_control_period();
        simulator.step_control_period();
    }
    // Binomial(n, 0.2): within 4.5 standard deviations.
    const auto n = static_cast<double>(candidates);
    EXPECT_NEAR(static_cast<double>(dropouts), 0.2 * n, 4.5 * std::sqrt(n * 0.2 * 0.8));
}

// ---- cadence, pose, determinism ----

TEST(LaserScanner, ScansEverySecondFrameAtTheEndOfPeriodPose) {
    const Room room{{0.5, -0.5, -0.2}};
    const RobotSpec robot = with_laser();
    Simulator simulator(room.world({2.0, 2.0, 0.4}), robot, {}, 2);
    simulator.set_wheel_command({0.2, 0.15});              // moving and turning: the pose matters
    ASSERT_TRUE(simulator.sensor_frame().has_laser_scan);  // t = 0
    int scans = 0;
    for (int k = 1; k <= 40; ++k) {
        simulator.step_control_period();
        const SensorFrame frame = simulator.sensor_frame();
        EXPECT_EQ(frame.has_laser_scan, k % 2 == 0) << "frame " << k;
        if (frame.has_laser_scan) {
            ++scans;
            // Taken at the frame's time, at the pose of the end of the period.
            expect_exact_scan(frame,
                              room.distances(robot.laser_scanner, simulator.ground_truth().pose),
                              robot.laser_scanner.geometry);
        } else {
            EXPECT_EQ(frame.laser.beam_count, 0);
        }
    }
    EXPECT_EQ(scans, 20);

    RobotSpec slower = robot;
    slower.laser_scanner.scan_period = 0.15;
    Simulator every_third(room.world({2.0, 2.0, 0.4}), slower, {}, 2);
    for (int k = 1; k <= 30; ++k) {
        every_third.step_control_period();
        EXPECT_EQ(every_third.sensor_frame().has_laser_scan, k % 3 == 0) << "frame " << k;
    }
}

TEST(LaserScanner, OffByDefaultAndSwitchedOnMidRunItKeepsItsCadence) {
    const Room room{};
    Simulator simulator(room.world({2.0, 2.0, 0.0}), RobotSpec{}, {}, 1);
    for (int k = 1; k <= 5; ++k) {
        simulator.step_control_period();
        EXPECT_FALSE(simulator.sensor_frame().has_laser_scan);
    }
    simulator.set_robot(with_laser());  // at t = 0.25 s: the next scan is due at 0.3 s
    simulator.step_control_period();
    EXPECT_TRUE(simulator.sensor_frame().has_laser_scan);
    simulator.step_control_period();
    EXPECT_FALSE(simulator.sensor_frame().has_laser_scan);
}

TEST(LaserScanner, SameSeedSameScansOtherSeedOtherScans) {
    const Room room{};
    RobotSpec robot = with_laser(0.01, 0.01);
    robot.laser_scanner.dropout_probability = 0.05;
    const auto scans = [&](std::uint64_t seed) {
        Simulator simulator(room.world({2.0, 2.0, 0.3}), robot, {}, seed);
        simulator.set_wheel_command({0.1, 0.12});
        std::vector<LaserScan> out;
        for (int k = 0; k < 30; ++k) {
            simulator.step_control_period();
            if (simulator.sensor_frame().has_laser_scan) {
                out.push_back(simulator.sensor_frame().laser);
            }
        }
        return out;
    };
    const auto first = scans(3);
    const auto again = scans(3);
    const auto other = scans(4);
    ASSERT_EQ(first.size(), 15U);
    for (std::size_t i = 0; i < first.size(); ++i) {
        EXPECT_EQ(first[i], again[i]) << "scan " << i;
        EXPECT_NE(first[i], other[i]) << "scan " << i;
    }
}

TEST(LaserScanner, DoesNotChangeAnyOtherReadingOfARun) {
    // The standard arena plus a map, every other sensor on and noisy: with and without the
    // laser scanner, every other field of every frame and the ground truth are bit-identical.
    WorldSpec world = standard_arena();
    world.map = test::room_map(60, 60, 0.05, {-1.5, -1.5, 0.0}, 1);  // 3 m, outside the walls
    RobotSpec plain;
    plain.ir_noise = 0.01;
    plain.slip_noise = 0.001;
    plain.beacon_scanner.enabled = true;
    plain.gyro.enabled = true;
    plain.accelerometers.enabled = true;
    plain.compass.enabled = true;
    RobotSpec laser = plain;
    laser.laser_scanner.enabled = true;
    laser.laser_scanner.dropout_probability = 0.1;
    Simulator without(world, plain, {}, 9);
    Simulator with(world, laser, {}, 9);
    for (Simulator* simulator : {&without, &with}) {
        simulator->set_wheel_command({0.1, 0.09});
    }
    int ir_changes = 0;
    std::array<std::uint16_t, 2> last_ir{};
    for (int i = 0; i < 400; ++i) {
        without.step_control_period();
        with.step_control_period();
        const SensorFrame a = without.sensor_frame();
        const SensorFrame b = with.sensor_frame();
        ASSERT_EQ(a.time, b.time);
        ASSERT_EQ(a.encoder_counts, b.encoder_counts) << i;
        ASSERT_EQ(a.ir_adc, b.ir_adc) << i;
        ASSERT_EQ(a.ir_valid, b.ir_valid) << i;
        ASSERT_EQ(a.beacons, b.beacons) << i;
        ASSERT_EQ(a.gyro_raw, b.gyro_raw) << i;
        ASSERT_EQ(a.accel_raw, b.accel_raw) << i;
        ASSERT_EQ(a.compass_deg, b.compass_deg) << i;
        ASSERT_FALSE(a.has_laser_scan);
        ASSERT_EQ(b.has_laser_scan, i % 2 == 1) << i;
        const GroundTruth ta = without.ground_truth();
        const GroundTruth tb = with.ground_truth();
        ASSERT_EQ(ta.pose, tb.pose) << i;
        ASSERT_EQ(ta.ir_distances, tb.ir_distances) << i;
        ir_changes += a.ir_adc != last_ir ? 1 : 0;
        last_ir = a.ir_adc;
    }
    EXPECT_GT(ir_changes, 100);  // the IR noise was really on
}

// ---- the map in the other sensors ----

TEST(LaserScanner, TheIrSensorsAndTheBeaconScannerSeeTheMapToo) {
    const Room room{};
    // Heading +x, 0.2 m above the lower wall's inside (y = 0.1 m): the IR sensors look
    // along −y from 6 cm right of the axle, so they read 0.2 − 0.06 = 0.14 m.
    WorldSpec world = room.world({2.0, 0.3, 0.0});
    world.beacons = {{1, {3.0, 2.0}}, {2, {3.0, -1.0}}};  // 2 lies beyond the lower wall
    RobotSpec robot;
    robot.beacon_scanner.enabled = true;
    robot.beacon_scanner.detection_probability = 1.0;
    robot.beacon_scanner.bearing_noise = 0.0;
    Simulator simulator(world, robot, {}, 1);
    simulator.step_control_period();
    const GroundTruth truth = simulator.ground_truth();
    const double expected = truth.pose.y - room.inside.y0 - robot.ir_mount.lateral_offset;
    EXPECT_NEAR(truth.ir_distances[0], expected, 1e-5);
    EXPECT_NEAR(truth.ir_distances[1], expected, 1e-5);
    const SensorFrame frame = simulator.sensor_frame();
    ASSERT_TRUE(frame.has_beacon_scan);
    ASSERT_EQ(frame.beacons.count, 1);
    EXPECT_EQ(frame.beacons.sightings[0].id, 1);
}

// ---- validation ----

TEST(LaserScanner, RefusesInvalidSpecsNamingTheFields) {
    RobotSpec robot = with_laser();
    robot.laser_scanner.geometry.beam_count = 0;
    robot.laser_scanner.geometry.range_min = 0.01;  // would read as error codes
    robot.laser_scanner.sigma_near = -0.01;
    robot.laser_scanner.dropout_probability = 1.5;
    robot.laser_scanner.mount.x = std::numeric_limits<double>::quiet_NaN();
    std::string fields;
    for (const ConfigIssue& issue : validate(robot)) {
        fields += issue.field + " ";
    }
    EXPECT_EQ(fields,
              "simulator.laser_scanner.geometry.beam_count "
              "simulator.laser_scanner.geometry.range_min simulator.laser_scanner.mount.x "
              "simulator.laser_scanner.sigma_near "
              "simulator.laser_scanner.dropout_probability ");
    EXPECT_THROW(Simulator(Room{}.world({2.0, 2.0, 0.0}), robot, {}, 1), std::invalid_argument);
}

TEST(LaserScanner, TheScanPeriodMustBeAWholeNumberOfControlPeriods) {
    RobotSpec robot = with_laser();
    SimulatorSettings settings;  // 50 ms
    EXPECT_TRUE(validate(robot, settings).empty());
    for (const double period : {0.075, 0.02, 0.1000001}) {
        robot.laser_scanner.scan_period = period;
        const auto issues = validate(robot, settings);
        ASSERT_EQ(issues.size(), 1U) << period;
        EXPECT_EQ(issues[0].field, "simulator.laser_scanner.scan_period");
        EXPECT_EQ(issues[0].reason, "must be a whole number of control periods (0.05 s)");
        EXPECT_THROW(Simulator(Room{}.world({2.0, 2.0, 0.0}), robot, settings, 1),
                     std::invalid_argument);
    }
    robot.laser_scanner.scan_period = 0.15;
    EXPECT_TRUE(validate(robot, settings).empty());
    RobotSpec off;  // a scanner that is off is not held to it
    off.laser_scanner.scan_period = 0.075;
    EXPECT_TRUE(validate(off, settings).empty());
    Simulator simulator(Room{}.world({2.0, 2.0, 0.0}), RobotSpec{}, settings, 1);
    robot.laser_scanner.scan_period = 0.075;
    EXPECT_THROW(simulator.set_robot(robot), std::invalid_argument);
}

TEST(LaserScanner, RefusesABadMapNamingTheFields) {
    WorldSpec world = Room{}.world({2.0, 2.0, 0.0});
    EXPECT_TRUE(validate(world).empty());
    world.start = {0.02, 1.0, 0.0};  // inside the left wall
    std::string fields;
    for (const ConfigIssue& issue : validate(world)) {
        fields += issue.field + " ";
    }
    EXPECT_EQ(fields, "world.start.x ");
    EXPECT_THROW(Simulator(world, RobotSpec{}, {}, 1), std::invalid_argument);

    world.start = {};
    world.map = std::make_shared<const OccupancyGrid>();  // no cells
    fields.clear();
    for (const ConfigIssue& issue : validate(world)) {
        fields += issue.field + " ";
    }
    EXPECT_EQ(fields, "world.map ");

    world.map = std::make_shared<const OccupancyGrid>(2, 1, 0.001, Pose2{2000.0, 0.0, 0.0},
                                                      std::vector<CellState>(2, CellState::Free));
    fields.clear();
    for (const ConfigIssue& issue : validate(world)) {
        fields += issue.field + " ";
    }
    EXPECT_EQ(fields, "world.map.resolution world.map.origin.x ");

    world.map = std::make_shared<const OccupancyGrid>(
        4000, 1, 0.5, Pose2{}, std::vector<CellState>(4000, CellState::Free));
    fields.clear();
    for (const ConfigIssue& issue : validate(world)) {
        fields += issue.field + " ";
    }
    EXPECT_EQ(fields, "world.map.width ");  // 2000 m wide
}

}  // namespace
}  // namespace legofeup::sim
