#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "legofeup/core/angles.hpp"
#include "legofeup/sim/lockstep_link.hpp"
#include "legofeup/sim/simulator.hpp"
#include "world_test_support.hpp"

namespace legofeup::sim {
namespace {

constexpr double kCountsPerMetre = 360.0 / (kPi * 0.0432);

// An empty world, so nothing is in the way.
void run_for(Simulator& simulator, double seconds) {
    const auto periods =
        static_cast<int>(std::lround(seconds / simulator.settings().control_period));
    for (int i = 0; i < periods; ++i) {
        simulator.step_control_period();
    }
}

TEST(Simulator, DrivesStraightAndCountsTheWheelRotation) {
    Simulator simulator(test::open_floor(), RobotSpec{}, {}, 1);
    simulator.set_wheel_command({0.1, 0.1});
    run_for(simulator, 10.0);
    const GroundTruth truth = simulator.ground_truth();
    // 1 m in 10 s, less what the motors lose while spinning up (τ·v = 0.05 s · 0.1 m/s).
    EXPECT_NEAR(truth.pose.x, 1.0 - 0.005, 0.001);
    EXPECT_NEAR(truth.pose.y, 0.0, 1e-4);
    EXPECT_NEAR(truth.pose.theta, 0.0, 1e-4);
    const SensorFrame frame = simulator.sensor_frame();
    EXPECT_NEAR(frame.encoder_counts[0], truth.pose.x * kCountsPerMetre, 1.0);
    EXPECT_EQ(frame.encoder_counts[0], frame.encoder_counts[1]);
    EXPECT_NEAR(frame.time, 10.0, 1e-9);
    EXPECT_EQ(frame.sequence, 200u);
}

TEST(Simulator, MotorsRespondWithFirstOrderLagAndSaturate) {
    RobotSpec robot;
    robot.motor_time_constant = 0.1;
    Simulator simulator(test::open_floor(), robot, {}, 1);
    simulator.set_wheel_command({0.2, 0.2});
    run_for(simulator, 0.1);  // one time constant: 1 − e⁻¹ of the way
    EXPECT_NEAR(simulator.ground_truth().wheel_surface_speeds.right, 0.2 * (1.0 - std::exp(-1.0)),
                1e-9);
    simulator.set_wheel_command({5.0, -5.0});  // far beyond 170 rpm
    run_for(simulator, 2.0);
    const double top_speed = 170.0 * 2.0 * kPi / 60.0 * 0.0216;  // ≈0.385 m/s
    EXPECT_NEAR(simulator.ground_truth().wheel_surface_speeds.right, top_speed, 1e-6);
    EXPECT_NEAR(simulator.ground_truth().wheel_surface_speeds.left, -top_speed, 1e-6);
}

TEST(Simulator, WheelDiameterRatioBendsAStraightCommand) {
    // E_d = 1.005: the right wheel covers 0.5 % more ground per turn, so a straight command
    // turns the robot left by about (E_d − 1)·distance / b = 0.0417 rad per metre.
    RobotSpec robot;
    robot.wheel_diameter_ratio = 1.005;
    Simulator simulator(test::open_floor(), robot, {}, 1);
    simulator.set_wheel_command({0.1, 0.1});
    run_for(simulator, 10.0);
    const double travelled = simulator.ground_truth().pose.x;
    const double expected = 2.0 * 0.005 / 2.005 * travelled / 0.12;  // (D_R − D_L)/D̄ · s / b
    EXPECT_NEAR(simulator.ground_truth().pose.theta, expected, 0.03 * expected);
    EXPECT_GT(simulator.ground_truth().pose.theta, 0.0);
    // The encoders cannot tell: they count the same rotation on both wheels.
    EXPECT_EQ(simulator.sensor_frame().encoder_counts[0],
              simulator.sensor_frame().encoder_counts[1]);
}

TEST(Simulator, WheelBaseRatioShortensTurns) {
    // E_b = 1.03: the wheels are 3 % farther apart than the commands assume, so a turn on
    // the spot commanded for 90° turns only 90°/1.03.
    RobotSpec robot;
    robot.wheel_base_ratio = 1.03;
    robot.motor_time_constant = 0.0;  // no lag, so the commanded angle is exact
    Simulator simulator(test::open_floor(), robot, {}, 1);
    const double w = 0.5;
    simulator.set_wheel_command({0.06 * w, -0.06 * w});
    run_for(simulator, kPi / 2.0 / w);
    simulator.set_wheel_command({0.0, 0.0});
    run_for(simulator, 0.5);
    EXPECT_NEAR(simulator.ground_truth().pose.theta, kPi / 2.0 / 1.03, degrees_to_radians(0.3));
}

TEST(Simulator, EncodersKeepCountingWhenTheRobotIsStuckAgainstAWall) {
    WorldSpec world = test::open_floor();
    world.walls.push_back({"wall", {0.3, -1.0}, {0.3, 1.0}});
    Simulator simulator(world, RobotSpec{}, {}, 1);
    simulator.set_wheel_command({0.1, 0.1});
    run_for(simulator, 10.0);  // would drive 1 m; the wall is 30 cm ahead
    const GroundTruth truth = simulator.ground_truth();
    EXPECT_TRUE(truth.touching_wall);
    EXPECT_NEAR(truth.pose.x, 0.3 - RobotSpec{}.chassis_front, 0.01);
    // The wheels spun the whole time: odometry says ~1 m, the robot moved ~0.22 m.
    EXPECT_GT(simulator.sensor_frame().encoder_counts[0], 0.95 * kCountsPerMetre);
}

TEST(Simulator, IrSensorsMeasureTheNearestWallOnTheRight) {
    WorldSpec world = test::open_floor();
    world.walls.push_back({"near", {-1.0, -0.20}, {1.0, -0.20}});
    world.walls.push_back({"far", {-1.0, -0.40}, {1.0, -0.40}});
    world.walls.push_back({"left", {-1.0, 0.10}, {1.0, 0.10}});  // not seen: wrong side
    Simulator simulator(world, RobotSpec{}, {}, 1);
    const SensorFrame frame = simulator.sensor_frame();
    const SharpIrCurve curve;
    // The sensors sit 6 cm right of the centre: 14 cm from the near wall.
    const std::uint16_t expected = quantize_adc(adc_from_distance(0.14, curve), curve.adc_max);
    EXPECT_EQ(frame.ir_adc[0], expected);
    EXPECT_EQ(frame.ir_adc[1], expected);
    EXPECT_NEAR(simulator.ground_truth().ir_distances[0], 0.14, 1e-6);
}

TEST(Simulator, IrSeesNothingBeyondItsRayAndFoldsBackAtContact) {
    WorldSpec world = test::open_floor();
    Simulator empty(world, RobotSpec{}, {}, 1);
    const SharpIrCurve curve;
    EXPECT_EQ(empty.sensor_frame().ir_adc[0],
              quantize_adc(adc_from_distance(RobotSpec{}.ir_ray_length, curve), curve.adc_max));

    world.walls.push_back({"touching", {-1.0, -0.0605}, {1.0, -0.0605}});  // 0.5 mm away
    Simulator touching(world, RobotSpec{}, {}, 1);
    const IrDistance reading = distance_from_adc(touching.sensor_frame().ir_adc[0], curve);
    EXPECT_EQ(reading.status, IrStatus::InRange);  // the fold-back: it looks 13 cm away
    EXPECT_GT(reading.distance, 0.10);
}

TEST(Simulator, IrValuesAreHeldBetweenUpdatesEvery38Milliseconds) {
    WorldSpec world = test::open_floor();
    world.start = {0.0, 0.0, 0.3};  // drive away from the wall at an angle
    world.walls.push_back({"wall", {-2.0, -0.15}, {3.0, -0.15}});
    SimulatorSettings settings;
    settings.physics_rate = 1000.0;
    Simulator simulator(world, RobotSpec{}, settings, 1);
    simulator.set_wheel_command({0.1, 0.1});
    std::vector<double> change_times;
    std::uint16_t last = simulator.sensor_frame().ir_adc[0];
    for (int i = 0; i < 2000; ++i) {
        simulator.step_physics();
        const std::uint16_t now = simulator.sensor_frame().ir_adc[0];
        if (now != last) {
            change_times.push_back(simulator.time());
            last = now;
        }
    }
    ASSERT_GT(change_times.size(), 10u);
    for (std::size_t i = 1; i < change_times.size(); ++i) {
        const double gap = change_times[i] - change_times[i - 1];
        const double periods = gap / 0.038;
        EXPECT_NEAR(periods, std::round(periods), 0.03) << "gap " << gap;  // whole periods
    }
}

TEST(Simulator, IrNoiseHasTheConfiguredStandardDeviation) {
    WorldSpec world = test::open_floor();
    world.walls.push_back({"wall", {-1.0, -0.21}, {1.0, -0.21}});
    RobotSpec robot;
    robot.ir_noise = 0.01;
    Simulator simulator(world, robot, {}, 42);
    const SharpIrCurve curve;
    std::vector<double> errors;
    for (int i = 0; i < 4000; ++i) {
        simulator.step_control_period();  // 50 ms > 38 ms: a fresh sample each time
        errors.push_back(distance_from_adc(simulator.sensor_frame().ir_adc[0], curve).distance
                         - 0.15);
    }
    const auto count = static_cast<double>(errors.size());
    const double mean = std::accumulate(errors.begin(), errors.end(), 0.0) / count;
    double variance = 0.0;
    for (double e : errors) {
        variance += (e - mean) * (e - mean);
    }
    variance /= count - 1.0;
    // σ = 1 cm plus the A/D's quantisation (≈0.9 mm steps); 4000 samples: ±3 % on σ.
    EXPECT_NEAR(std::sqrt(variance), std::hypot(0.01, 0.0009 / std::sqrt(12.0)), 0.0005);
    EXPECT_NEAR(mean, 0.0, 0.001);
}

TEST(Simulator, SlipNoiseGrowsWithDistanceTravelled) {
    // Random slip of variance slip²·|distance| per wheel: the spread of the heading after a
    // straight drive grows like √distance. Compare 1 m and 4 m over many seeds.
    RobotSpec robot;
    robot.slip_noise = 0.002;
    const auto heading_spread = [&](double seconds) {
        double sum = 0.0;
        double sum_squares = 0.0;
        const int seeds = 60;
        for (int seed = 1; seed <= seeds; ++seed) {
            Simulator simulator(test::open_floor(), robot, {}, static_cast<std::uint64_t>(seed));
            simulator.set_wheel_command({0.1, 0.1});
            run_for(simulator, seconds);
            const double theta = simulator.ground_truth().pose.theta;
            sum += theta;
            sum_squares += theta * theta;
        }
        return std::sqrt(sum_squares / seeds - (sum / seeds) * (sum / seeds));
    };
    const double one_metre = heading_spread(10.0);
    const double four_metres = heading_spread(40.0);
    // Heading random walk: σ_θ = √2·slip·√s / b ⇒ 0.0236 rad at 1 m, doubling at 4 m.
    EXPECT_NEAR(one_metre, std::sqrt(2.0) * 0.002 / 0.12, 0.006);
    EXPECT_NEAR(four_metres / one_metre, 2.0, 0.6);
}

TEST(Simulator, SameSeedSameFramesDifferentSeedDifferentNoise) {
    RobotSpec robot;
    robot.ir_noise = 0.01;
    robot.slip_noise = 0.001;
    const WorldSpec world = standard_arena();
    const auto frames = [&](std::uint64_t seed) {
        Simulator simulator(world, robot, {}, seed);
        std::vector<SensorFrame> out;
        simulator.set_wheel_command({0.1, 0.09});
        for (int i = 0; i < 400; ++i) {
            simulator.step_control_period();
            out.push_back(simulator.sensor_frame());
        }
        return out;
    };
    const auto first = frames(5);
    const auto again = frames(5);
    const auto other = frames(6);
    int differing = 0;
    for (std::size_t i = 0; i < first.size(); ++i) {
        EXPECT_EQ(first[i].encoder_counts, again[i].encoder_counts);
        EXPECT_EQ(first[i].ir_adc, again[i].ir_adc);
        differing += first[i].ir_adc != other[i].ir_adc ? 1 : 0;
    }
    EXPECT_GT(differing, 50);
}

TEST(Simulator, ResetAndTeleport) {
    Simulator simulator(test::open_floor(), RobotSpec{}, {}, 1);
    simulator.set_wheel_command({0.1, 0.1});
    run_for(simulator, 1.0);
    simulator.teleport({2.0, 3.0, 1.0});
    EXPECT_NEAR(simulator.ground_truth().pose.x, 2.0, 1e-6);
    EXPECT_NEAR(simulator.ground_truth().pose.theta, 1.0, 1e-6);
    EXPECT_NEAR(simulator.time(), 1.0, 1e-9);  // time goes on
    simulator.reset({-1.0, -1.0, 0.0}, 2);
    EXPECT_EQ(simulator.time(), 0.0);
    EXPECT_EQ(simulator.sensor_frame().encoder_counts[0], 0);
    EXPECT_NEAR(simulator.ground_truth().pose.x, -1.0, 1e-6);
}

TEST(Simulator, RefusesInvalidSpecsNamingTheFields) {
    RobotSpec robot;
    robot.mass = -1.0;
    robot.ir_noise = std::nan("");
    SimulatorSettings settings;
    settings.physics_rate = 30.0;
    try {
        Simulator simulator(test::open_floor(), robot, settings, 1);
        FAIL();
    } catch (const std::invalid_argument& error) {
        const std::string what = error.what();
        EXPECT_NE(what.find("simulator.mass = -1"), std::string::npos) << what;
        EXPECT_NE(what.find("simulator.ir_noise = nan"), std::string::npos) << what;
        EXPECT_NE(what.find("simulator.physics_rate = 30"), std::string::npos) << what;
    }
    SimulatorSettings uneven;
    uneven.control_period = 0.055;  // 5.5 physics steps
    EXPECT_FALSE(validate(uneven).empty());
}

TEST(LockstepLink, FirstFrameIsTheStartThenOnePeriodPerFrame) {
    Simulator simulator(test::open_floor(), RobotSpec{}, {}, 1);
    LockstepLink link(simulator);
    EXPECT_EQ(link.next_frame()->time, 0.0);
    link.send_command({0.1, 0.1});
    EXPECT_NEAR(link.next_frame()->time, 0.05, 1e-12);
    EXPECT_NEAR(link.next_frame()->time, 0.10, 1e-12);
    EXPECT_GT(simulator.ground_truth().pose.x, 0.0);
}

}  // namespace
}  // namespace legofeup::sim
