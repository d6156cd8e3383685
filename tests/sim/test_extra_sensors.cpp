// The further lessons' simulated sensors through the Simulator: beacon scanner, gyroscope,
// accelerometers, compass; their statistics, determinism and independence from the
// encoder/IR noise.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "legofeup/core/angles.hpp"
#include "legofeup/sim/simulator.hpp"
#include "world_test_support.hpp"

namespace legofeup::sim {
namespace {

RobotSpec with_all_sensors() {
    RobotSpec robot;
    robot.beacon_scanner.enabled = true;
    robot.gyro.enabled = true;
    robot.accelerometers.enabled = true;
    robot.compass.enabled = true;
    return robot;
}

// ---- beacon scanner ----

TEST(BeaconScanner, DetectsEachBeaconWithTheConfiguredProbability) {
    WorldSpec world = test::open_floor();
    world.beacons = {{1, {2.0, 0.0}}, {2, {0.0, 2.0}}, {3, {-2.0, 0.0}}, {4, {0.0, -2.0}}};
    for (const double p : {0.5, 0.15}) {
        RobotSpec robot;
        robot.beacon_scanner.enabled = true;
        robot.beacon_scanner.detection_probability = p;
        Simulator simulator(world, robot, {}, 7);
        const int scans = 1000;
        std::array<int, 5> seen{};
        for (int i = 0; i < scans; ++i) {
            simulator.step_control_period();
            const SensorFrame frame = simulator.sensor_frame();
            ASSERT_TRUE(frame.has_beacon_scan);  // one scan per 50 ms period
            for (int k = 0; k < frame.beacons.count; ++k) {
                ++seen.at(frame.beacons.sightings[static_cast<std::size_t>(k)].id);
            }
        }
        // Binomial(1000, p): within 4.5 standard deviations.
        const double sd = std::sqrt(scans * p * (1.0 - p));
        for (int id = 1; id <= 4; ++id) {
            EXPECT_NEAR(seen[static_cast<std::size_t>(id)], scans * p, 4.5 * sd) << "p " << p;
        }
    }
}

TEST(BeaconScanner, BearingIsUnbiasedWithTheConfiguredSpreadAndOrderedById) {
    WorldSpec world = test::open_floor({0.0, 0.0, 0.3});
    // Listed out of order: the scanner reports in id order.
    world.beacons = {{9, {-1.0, -1.0}}, {2, {1.0, 0.5}}, {4, {-0.5, 2.0}}};
    RobotSpec robot;
    robot.beacon_scanner.enabled = true;
    robot.beacon_scanner.detection_probability = 1.0;
    Simulator simulator(world, robot, {}, 11);
    const double truth_2 = std::atan2(0.5, 1.0) - 0.3;
    const double truth_9 = wrap_angle(std::atan2(-1.0, -1.0) - 0.3);
    std::vector<double> errors_2;
    std::vector<double> errors_9;
    for (int i = 0; i < 3000; ++i) {
        simulator.step_control_period();
        const BeaconScan scan = simulator.sensor_frame().beacons;
        ASSERT_EQ(scan.count, 3);
        EXPECT_EQ(scan.sightings[0].id, 2);
        EXPECT_EQ(scan.sightings[1].id, 4);
        EXPECT_EQ(scan.sightings[2].id, 9);
        for (const auto& sighting : scan.sightings) {
            EXPECT_GT(sighting.bearing, -kPi);
            EXPECT_LE(sighting.bearing, kPi);
        }
        errors_2.push_back(wrap_angle(scan.sightings[0].bearing - truth_2));
        errors_9.push_back(wrap_angle(scan.sightings[2].bearing - truth_9));
    }
    const double sigma = std::sqrt(kPi / 8.0);  // the paper's variance π/8
    for (const auto& errors : {errors_2, errors_9}) {
        const test::SampleStats s = test::sample_stats_of(errors);
        EXPECT_NEAR(s.mean, 0.0, 4.0 * sigma / std::sqrt(3000.0));
        EXPECT_NEAR(s.sd, sigma, 0.06 * sigma);  // SE of σ̂ ≈ 1.3 %
    }
}

TEST(BeaconScanner, ABeaconBehindAWallIsNeverSeen) {
    WorldSpec world = test::open_floor();
    world.walls.push_back({"inner", {1.0, -0.5}, {1.0, 0.5}});
    world.beacons = {{1, {2.0, 0.0}}, {2, {-2.0, 0.0}}, {3, {2.0, 2.0}}};  // 1 hidden
    RobotSpec robot;
    robot.beacon_scanner.enabled = true;
    robot.beacon_scanner.detection_probability = 1.0;
    Simulator simulator(world, robot, {}, 3);
    for (int i = 0; i < 300; ++i) {
        simulator.step_control_period();
        const BeaconScan scan = simulator.sensor_frame().beacons;
        ASSERT_EQ(scan.count, 2);
        EXPECT_EQ(scan.sightings[0].id, 2);
        EXPECT_EQ(scan.sightings[1].id, 3);  // past the wall's end: in sight
    }
}

TEST(BeaconScanner, ScansAtItsOwnPeriodAndReportsOnlyFreshScans) {
    WorldSpec world = test::open_floor();
    world.beacons = {{1, {1.0, 0.0}}};
    RobotSpec robot;
    robot.beacon_scanner.enabled = true;
    robot.beacon_scanner.period = 0.1;
    Simulator simulator(world, robot, {}, 3);
    EXPECT_TRUE(simulator.sensor_frame().has_beacon_scan);  // scanned at time 0
    for (int i = 1; i <= 20; ++i) {
        simulator.step_control_period();
        EXPECT_EQ(simulator.sensor_frame().has_beacon_scan, i % 2 == 0) << i;
    }
}

TEST(BeaconScanner, OffByDefaultAndAbsentFromTheFrame) {
    const SensorFrame frame = Simulator(standard_arena(), RobotSpec{}, {}, 1).sensor_frame();
    EXPECT_FALSE(frame.has_beacon_scan);
    EXPECT_FALSE(frame.has_gyro);
    EXPECT_FALSE(frame.has_accelerometers);
    EXPECT_FALSE(frame.has_compass);
    EXPECT_EQ(frame.beacons.count, 0);
}

// ---- gyroscope ----

TEST(Gyroscope, AtRestAveragesOffsetPlusBias) {
    RobotSpec robot;
    robot.gyro.enabled = true;
    robot.gyro.bias_sigma = 3.0;
    robot.gyro.bias_drift = 0.0;
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        Simulator simulator(test::open_floor(), robot, {}, seed);
        const double bias = radians_to_degrees(simulator.ground_truth().gyro_bias_rate);
        std::vector<double> raw;
        for (int i = 0; i < 400; ++i) {
            simulator.step_control_period();
            ASSERT_TRUE(simulator.sensor_frame().has_gyro);
            raw.push_back(simulator.sensor_frame().gyro_raw);
        }
        const test::SampleStats s = test::sample_stats_of(raw);
        // σ = 1 count noise + rounding; 400 samples: SE ≈ 0.05.
        EXPECT_NEAR(s.mean, 600.0 + bias, 0.25) << "seed " << seed;
        EXPECT_NEAR(s.sd, std::sqrt(1.0 + 1.0 / 12.0), 0.15);
    }
    // The bias is drawn per run from N(0, 3²); 300 runs: SE of σ̂ ≈ 4 %.
    std::vector<double> biases;
    for (std::uint64_t seed = 1; seed <= 300; ++seed) {
        const Simulator simulator(test::open_floor(), robot, {}, seed);
        biases.push_back(radians_to_degrees(simulator.ground_truth().gyro_bias_rate));
    }
    const test::SampleStats s = test::sample_stats_of(biases);
    EXPECT_NEAR(s.sd, 3.0, 0.4);
    EXPECT_NEAR(s.mean, 0.0, 4.0 * 3.0 / std::sqrt(300.0));
}

TEST(Gyroscope, ReadsTheTurnRateCounterClockwisePositiveAndSaturates) {
    RobotSpec robot;
    robot.gyro.enabled = true;
    robot.gyro.noise = 0.0;
    robot.gyro.bias_sigma = 0.0;
    robot.gyro.bias_drift = 0.0;
    Simulator simulator(test::open_floor(), robot, {}, 1);
    simulator.set_wheel_command({0.1, -0.1});  // right wheel forward: counter-clockwise
    for (int i = 0; i < 40; ++i) {
        simulator.step_control_period();
    }
    const double rate = radians_to_degrees(simulator.ground_truth().velocity.w);
    EXPECT_GT(rate, 60.0);
    EXPECT_NEAR(simulator.sensor_frame().gyro_raw, 600.0 + rate, 0.5 + 1e-9);

    robot.gyro.range_dps = 50.0;
    simulator.set_robot(robot);
    simulator.step_control_period();
    EXPECT_EQ(simulator.sensor_frame().gyro_raw, 650);
    simulator.set_wheel_command({-0.1, 0.1});
    for (int i = 0; i < 40; ++i) {
        simulator.step_control_period();
    }
    EXPECT_EQ(simulator.sensor_frame().gyro_raw, 550);
}

TEST(Gyroscope, BiasDriftsAsARandomWalk) {
    RobotSpec robot;
    robot.gyro.enabled = true;
    robot.gyro.bias_drift = 2.0;  // counts/√s
    std::vector<double> changes;
    for (std::uint64_t seed = 1; seed <= 200; ++seed) {
        Simulator simulator(test::open_floor(), robot, {}, seed);
        const double start = simulator.ground_truth().gyro_bias_rate;
        for (int i = 0; i < 5; ++i) {  // 0.25 s
            simulator.step_control_period();
        }
        changes.push_back(radians_to_degrees(simulator.ground_truth().gyro_bias_rate - start));
    }
    // Var(Δb) = σ_rw²·T = 4·0.25 = 1 count²; 200 runs: SE of σ̂ ≈ 5 %.
    const test::SampleStats s = test::sample_stats_of(changes);
    EXPECT_NEAR(s.sd, 1.0, 0.2);
    EXPECT_NEAR(s.mean, 0.0, 4.0 / std::sqrt(200.0));
}

// ---- accelerometers ----

AccelerometerSpec exact_accelerometers() {
    AccelerometerSpec accel;
    accel.enabled = true;
    accel.noise = 0.0;
    accel.bias_sigma = 0.0;
    accel.counts_per_g = 2000.0;  // finer than the hardware, to check the kinematics
    return accel;
}

double counts(const AccelerometerSpec& spec, double acceleration) {
    return acceleration / spec.gravity * spec.counts_per_g;
}

TEST(Accelerometers, ReadZeroAtRestAndNoiseWithItsSigma) {
    RobotSpec robot;
    robot.accelerometers = exact_accelerometers();
    Simulator exact(test::open_floor(), robot, {}, 1);
    for (int i = 0; i < 20; ++i) {
        exact.step_control_period();
        const SensorFrame frame = exact.sensor_frame();
        ASSERT_TRUE(frame.has_accelerometers);
        for (const auto& unit : frame.accel_raw) {
            EXPECT_EQ(unit[kAccelForward], 0);
            EXPECT_EQ(unit[kAccelLeft], 0);
        }
    }
    robot.accelerometers = AccelerometerSpec{};
    robot.accelerometers.enabled = true;
    robot.accelerometers.bias_sigma = 0.0;
    Simulator noisy(test::open_floor(), robot, {}, 1);
    std::vector<double> values;
    for (int i = 0; i < 2000; ++i) {
        noisy.step_control_period();
        values.push_back(noisy.sensor_frame().accel_raw[kAccelLeftWheel][kAccelForward]);
    }
    const test::SampleStats s = test::sample_stats_of(values);
    EXPECT_NEAR(s.mean, 0.0, 0.2);
    EXPECT_NEAR(s.sd, std::sqrt(4.0 + 1.0 / 12.0), 0.15);  // σ = 2 counts and rounding
}

TEST(Accelerometers, ReadTheForwardAccelerationWhileSpeedingUpStraight) {
    RobotSpec robot;
    robot.accelerometers = exact_accelerometers();
    robot.motor_time_constant = 0.5;  // v̇ = V/τ·e^(−t/τ): 0.6 m/s² at the start
    Simulator simulator(test::open_floor(), robot, {}, 1);
    simulator.set_wheel_command({0.3, 0.3});
    double previous_speed = 0.0;
    for (int i = 0; i < 30; ++i) {
        simulator.step_control_period();
        const double speed = simulator.ground_truth().velocity.v;
        const double expected = counts(robot.accelerometers, (speed - previous_speed) / 0.05);
        previous_speed = speed;
        const SensorFrame frame = simulator.sensor_frame();
        for (const auto& unit : frame.accel_raw) {
            EXPECT_NEAR(unit[kAccelForward], expected, 0.5 + 0.01 * expected) << i;
            EXPECT_NEAR(unit[kAccelLeft], 0.0, 0.5);
        }
        if (i == 0) {
            EXPECT_GT(expected, 100.0);  // ≈0.6 m/s² ≈ 120 counts at 2000 counts/g
        }
    }
}

TEST(Accelerometers, SeeCentripetalForceOnACircleAndAngularAccelerationOnASpin) {
    RobotSpec robot;
    robot.accelerometers = exact_accelerometers();
    Simulator simulator(test::open_floor(), robot, {}, 1);
    simulator.set_wheel_command({0.2, 0.1});  // a left turn
    for (int i = 0; i < 60; ++i) {
        simulator.step_control_period();
    }
    // Steady: a_left = ω·v ± ω²·b/2 (right wheel outside, left inside), a_forward = 0.
    const GroundTruth truth = simulator.ground_truth();
    const double v = truth.velocity.v;
    const double w = truth.velocity.w;
    const double half_base = 0.06;
    SensorFrame frame = simulator.sensor_frame();
    const auto& right = frame.accel_raw[kAccelRightWheel];
    const auto& left = frame.accel_raw[kAccelLeftWheel];
    EXPECT_NEAR(right[kAccelLeft], counts(robot.accelerometers, w * v + w * w * half_base), 0.6);
    EXPECT_NEAR(left[kAccelLeft], counts(robot.accelerometers, w * v - w * w * half_base), 0.6);
    EXPECT_GT(right[kAccelLeft] - left[kAccelLeft], 10);  // the ω²·b term is seen
    EXPECT_NEAR(right[kAccelForward], 0.0, 0.6);

    // Spinning up on the spot (counter-clockwise): a_forward = v̇ − α·y at lateral offset y,
    // y = −b/2 on the right wheel, +b/2 on the left: +α·b/2 right, −α·b/2 left.
    robot.motor_time_constant = 0.5;
    Simulator spin(test::open_floor(), robot, {}, 1);
    spin.set_wheel_command({0.1, -0.1});
    double previous_rate = 0.0;
    for (int i = 0; i < 10; ++i) {
        spin.step_control_period();
        const double rate = spin.ground_truth().velocity.w;
        const double alpha = (rate - previous_rate) / 0.05;
        previous_rate = rate;
        frame = spin.sensor_frame();
        const double expected = counts(robot.accelerometers, alpha * half_base);
        EXPECT_GT(alpha, 0.0);
        EXPECT_NEAR(frame.accel_raw[kAccelRightWheel][kAccelForward], expected,
                    0.6 + 0.02 * std::abs(expected));
        EXPECT_NEAR(frame.accel_raw[kAccelLeftWheel][kAccelForward], -expected,
                    0.6 + 0.02 * std::abs(expected));
    }
}

// ---- compass ----

TEST(Compass, ErrorIsTheDisturbanceFieldPlusNoiseInWholeDegrees) {
    WorldSpec world = standard_arena();  // 12° disturbance
    RobotSpec robot;
    robot.compass.enabled = true;
    robot.compass.noise_deg = 0.0;
    const auto run = [&](const RobotSpec& spec, std::uint64_t seed) {
        Simulator simulator(world, spec, {}, seed);
        simulator.set_wheel_command({0.15, 0.1});  // circles across the field
        std::vector<double> residuals;
        double largest_disturbance = 0.0;
        for (int i = 0; i < 1500; ++i) {
            simulator.step_control_period();
            const SensorFrame frame = simulator.sensor_frame();
            const GroundTruth truth = simulator.ground_truth();
            EXPECT_TRUE(frame.has_compass);
            EXPECT_GE(frame.compass_deg, 0);
            EXPECT_LT(frame.compass_deg, 360);
            const double disturbance =
                magnetic_disturbance_deg(world.magnetic, {truth.pose.x, truth.pose.y});
            EXPECT_NEAR(truth.magnetic_disturbance, degrees_to_radians(disturbance), 1e-12);
            largest_disturbance = std::max(largest_disturbance, std::abs(disturbance));
            const double error = radians_to_degrees(
                wrap_angle(degrees_to_radians(frame.compass_deg) - truth.pose.theta));
            residuals.push_back(error - disturbance);
        }
        EXPECT_GT(largest_disturbance, 4.0);  // the robot did cross the field
        return residuals;
    };
    for (double residual : run(robot, 1)) {
        ASSERT_LE(std::abs(residual), 0.5 + 1e-6);  // only the 1° quantisation
    }
    robot.compass.noise_deg = 2.0;
    const test::SampleStats s = test::sample_stats_of(run(robot, 1));
    EXPECT_NEAR(s.mean, 0.0, 0.2);
    EXPECT_NEAR(s.sd, std::sqrt(4.0 + 1.0 / 12.0), 0.15);
}

// ---- ground truth, determinism, independence ----

TEST(ExtraSensors, SameSeedSameFramesDifferentSeedDifferentReadings) {
    const RobotSpec robot = with_all_sensors();
    const auto frames = [&](std::uint64_t seed) {
        Simulator simulator(standard_arena(), robot, {}, seed);
        simulator.set_wheel_command({0.12, 0.1});
        std::vector<SensorFrame> out;
        for (int i = 0; i < 200; ++i) {
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
        EXPECT_EQ(first[i].beacons, again[i].beacons);
        EXPECT_EQ(first[i].gyro_raw, again[i].gyro_raw);
        EXPECT_EQ(first[i].accel_raw, again[i].accel_raw);
        EXPECT_EQ(first[i].compass_deg, again[i].compass_deg);
        differing += first[i].beacons != other[i].beacons ? 1 : 0;
        differing += first[i].gyro_raw != other[i].gyro_raw ? 1 : 0;
        differing += first[i].accel_raw != other[i].accel_raw ? 1 : 0;
        differing += first[i].compass_deg != other[i].compass_deg ? 1 : 0;
    }
    EXPECT_GT(differing, 400);
}

TEST(ExtraSensors, DoNotChangeTheEncoderAndIrNoiseOfARun) {
    RobotSpec plain;
    plain.ir_noise = 0.01;
    plain.slip_noise = 0.001;
    RobotSpec extra = with_all_sensors();
    extra.ir_noise = plain.ir_noise;
    extra.slip_noise = plain.slip_noise;
    const auto frames = [](const RobotSpec& robot) {
        Simulator simulator(standard_arena(), robot, {}, 9);
        simulator.set_wheel_command({0.1, 0.09});
        std::vector<SensorFrame> out;
        for (int i = 0; i < 400; ++i) {
            simulator.step_control_period();
            out.push_back(simulator.sensor_frame());
        }
        return out;
    };
    const auto without = frames(plain);
    const auto with = frames(extra);
    int ir_changes = 0;
    for (std::size_t i = 0; i < without.size(); ++i) {
        ASSERT_EQ(without[i].encoder_counts, with[i].encoder_counts) << i;
        ASSERT_EQ(without[i].ir_adc, with[i].ir_adc) << i;
        EXPECT_TRUE(with[i].has_gyro && with[i].has_compass && with[i].has_accelerometers);
        ir_changes += i > 0 && without[i].ir_adc != without[i - 1].ir_adc ? 1 : 0;
    }
    EXPECT_GT(ir_changes, 100);  // the IR noise was really on
}

TEST(ExtraSensors, RefusesInvalidSpecsNamingTheFields) {
    RobotSpec robot;
    robot.beacon_scanner.detection_probability = 1.5;
    robot.gyro.noise = -1.0;
    robot.accelerometers.range_g = std::nan("");
    robot.compass.noise_deg = -2.0;
    std::string fields;
    for (const ConfigIssue& issue : validate(robot)) {
        fields += issue.field + " ";
    }
    EXPECT_EQ(fields,
              "simulator.beacon_scanner.detection_probability simulator.gyro.noise "
              "simulator.accelerometers.range_g simulator.compass.noise_deg ");

    WorldSpec world = test::open_floor();
    world.beacons = {{300, {0.0, 0.0}}, {1, {1.0, 0.0}}, {1, {2.0, 0.0}}};
    world.magnetic.wavelength = 0.0;
    fields.clear();
    for (const ConfigIssue& issue : validate(world)) {
        fields += issue.field + " ";
    }
    EXPECT_EQ(fields, "world.beacon[0].id world.beacon[2].id world.magnetic.wavelength ");
    EXPECT_THROW(Simulator(world, RobotSpec{}, {}, 1), std::invalid_argument);
}

}  // namespace
}  // namespace legofeup::sim
