// The realistic IR model (sim/ir_sensor_model.hpp): each sensor a unit of its own around the
// nominal curve, noise on the output that grows in distance as the curve flattens; the ideal
// model left as it was.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "legofeup/sim/ir_sensor_model.hpp"
#include "legofeup/sim/simulator.hpp"
#include "world_test_support.hpp"

namespace legofeup::sim {
namespace {

// The robot at the origin heading +x, a wall `distance` from its right-side sensors.
WorldSpec wall_at(double distance) {
    WorldSpec world = test::open_floor();
    const double y = -(distance + IrMount{}.lateral_offset);
    world.walls.push_back({"wall", {-1.0, y}, {1.0, y}});
    return world;
}

// Nominal GP2D120 output by hand: A = 2914/(D[cm] + 1) − 5.
double nominal_adc(double distance) {
    return 2914.0 / (100.0 * distance + 1.0) - 5.0;
}

std::vector<double> distances_read(Simulator& simulator, int sensor, const SharpIrCurve& curve,
                                   int samples) {
    std::vector<double> distances;
    for (int i = 0; i < samples; ++i) {
        simulator.step_control_period();  // 50 ms > 38 ms: a fresh sample each time
        const double adc = simulator.sensor_frame().ir_adc[static_cast<std::size_t>(sensor)];
        distances.push_back(distance_from_adc(adc, curve).distance);
    }
    return distances;
}

TEST(IrSensorModel, NamesRoundTripAndUnknownNamesAreRefused) {
    for (const IrSensorModel model : {IrSensorModel::Ideal, IrSensorModel::Realistic}) {
        EXPECT_EQ(ir_sensor_model_from_string(to_string(model)), model);
    }
    EXPECT_FALSE(ir_sensor_model_from_string("Realistic").has_value());
    EXPECT_FALSE(ir_sensor_model_from_string("").has_value());
}

TEST(IrSensorModel, UnitCurveIsTheScaledAndShiftedNominalOutput) {
    const SharpIrCurve nominal;
    const IrUnit unit{1.07, -12.5};
    const SharpIrCurve curve = unit_curve(nominal, unit);
    for (const double d : {0.04, 0.07, 0.15, 0.22, 0.30, 0.5}) {
        EXPECT_NEAR(adc_from_distance(d, curve), 1.07 * nominal_adc(d) - 12.5, 1e-9) << d;
    }
    // The fold-back and the asymptote move the same way.
    for (const double d : {0.0, 0.01, 0.025}) {
        EXPECT_NEAR(adc_from_distance(d, curve), 1.07 * adc_from_distance(d, nominal) - 12.5, 1e-9)
            << d;
    }
    EXPECT_NEAR(adc_from_distance(std::numeric_limits<double>::infinity(), curve),
                1.07 * -5.0 - 12.5, 1e-12);
    EXPECT_EQ(realistic_ir_adc(nominal, unit, 0.15, 0.0),
              quantize_adc(1.07 * nominal_adc(0.15) - 12.5, 1023));
    EXPECT_EQ(realistic_ir_adc(nominal, unit, 0.15, 3.4),
              quantize_adc(1.07 * nominal_adc(0.15) - 12.5 + 3.4, 1023));
}

TEST(IrSensorModel, OutputNoiseMakesTheDistanceNoiseAtTheReferenceDistance) {
    const SharpIrCurve nominal;
    const double sigma_a = ir_output_noise_counts(nominal, 0.01, 0.15);
    // |dD/dA| by central differences of eq. 2 at the reference distance.
    const double a = nominal_adc(0.15);
    const double h = 1e-3;
    const double slope =
        (distance_from_adc(a - h, nominal).distance - distance_from_adc(a + h, nominal).distance)
        / (2.0 * h);
    EXPECT_NEAR(sigma_a * slope, 0.01, 1e-8);
    EXPECT_NEAR(sigma_a, 0.01 * 2914.0 / (0.01 * 16.0 * 16.0), 1e-9);  // 11.4 counts
}

TEST(IrSensorModel, EachSensorIsItsOwnUnitDrawnFromTheSeed) {
    RobotSpec robot;
    robot.ir_model = IrSensorModel::Realistic;
    const auto units = [&](std::uint64_t seed) {
        return Simulator(wall_at(0.15), robot, {}, seed).ir_units();
    };
    const auto first = units(7);
    const auto again = units(7);
    const auto other = units(8);
    for (std::size_t s = 0; s < 2; ++s) {
        EXPECT_EQ(first[s].gain, again[s].gain);
        EXPECT_EQ(first[s].offset, again[s].offset);
        EXPECT_NE(first[s].gain, other[s].gain);
    }
    EXPECT_NE(first[0].gain, first[1].gain);
    EXPECT_NE(first[0].offset, first[1].offset);

    // Over many seeds: mean 1 and 0, σ as configured (a normal truncated at ±3σ has
    // 0.986σ), never beyond ±3σ. 400 seeds × 2 sensors: the σ estimate is within ±8 %.
    std::vector<double> gains;
    std::vector<double> offsets;
    for (std::uint64_t seed = 1; seed <= 400; ++seed) {
        for (const IrUnit& unit : units(seed)) {
            gains.push_back(unit.gain);
            offsets.push_back(unit.offset);
            EXPECT_LE(std::abs(unit.gain - 1.0), 3.0 * robot.ir_gain_spread + 1e-12);
            EXPECT_LE(std::abs(unit.offset), 3.0 * robot.ir_offset_spread + 1e-12);
        }
    }
    const auto g = test::sample_stats_of(gains);
    const auto o = test::sample_stats_of(offsets);
    EXPECT_NEAR(g.mean, 1.0, 3.0 * 0.044 / std::sqrt(800.0));
    EXPECT_NEAR(o.mean, 0.0, 3.0 * 9.6 / std::sqrt(800.0));
    EXPECT_NEAR(g.sd, 0.986 * 0.044, 0.08 * 0.044);
    EXPECT_NEAR(o.sd, 0.986 * 9.6, 0.08 * 9.6);
}

TEST(IrSensorModel, RealisticReadingsFollowEachSensorsOwnCurve) {
    RobotSpec robot;
    robot.ir_model = IrSensorModel::Realistic;
    Simulator simulator(wall_at(0.12), robot, {}, 3);
    simulator.step_control_period();
    const auto units = simulator.ir_units();
    const auto truth = simulator.ground_truth();
    for (std::size_t s = 0; s < 2; ++s) {
        EXPECT_NEAR(truth.ir_distances[s], 0.12, 1e-6);
        EXPECT_EQ(simulator.sensor_frame().ir_adc[s],
                  quantize_adc(units[s].gain * nominal_adc(truth.ir_distances[s]) + units[s].offset,
                               1023));
    }
    // The same robot with the ideal model reads the nominal curve: the units play no part.
    robot.ir_model = IrSensorModel::Ideal;
    Simulator ideal(wall_at(0.12), robot, {}, 3);
    ideal.step_control_period();
    for (std::size_t s = 0; s < 2; ++s) {
        EXPECT_EQ(ideal.sensor_frame().ir_adc[s],
                  quantize_adc(nominal_adc(ideal.ground_truth().ir_distances[s]), 1023));
    }
}

TEST(IrSensorModel, RealisticNoiseGrowsWithDistanceAsTheCurveFlattens) {
    // No unit spread, so the nominal curve reads the sensor back. σ_D(D) = σ_A·|dD/dA| =
    // 1 cm·((D/a + b)/(15 + 1))²: 0.19 cm at 6 cm, 1 cm at 15 cm, 2.6 cm at 25 cm.
    RobotSpec robot;
    robot.ir_model = IrSensorModel::Realistic;
    robot.ir_gain_spread = 0.0;
    robot.ir_offset_spread = 0.0;
    robot.ir_noise = 0.01;
    const SharpIrCurve nominal;
    std::vector<double> spreads;
    for (const double d : {0.06, 0.15, 0.25}) {
        Simulator simulator(wall_at(d), robot, {}, 11);
        const auto stats = test::sample_stats_of(distances_read(simulator, 0, nominal, 3000));
        const double expected = 0.01 * std::pow((100.0 * d + 1.0) / 16.0, 2.0);
        // 3000 samples: ±4 % on σ (3σ). The curve's curvature over ±σ_A widens σ_D by up to
        // 4.4 % at 25 cm and shifts the mean by 0.1 σ_D (second order, checked by a Monte
        // Carlo of the formula).
        EXPECT_NEAR(stats.sd, expected, 0.1 * expected) << d;
        EXPECT_NEAR(stats.mean, d, 0.2 * expected) << d;
        spreads.push_back(stats.sd);
    }
    EXPECT_GT(spreads[2], 10.0 * spreads[0]);  // (26/7)² = 13.8
}

TEST(IrSensorModel, IdealNoiseStaysConstantInDistance) {
    RobotSpec robot;  // ideal by default
    robot.ir_noise = 0.01;
    const SharpIrCurve nominal;
    for (const double d : {0.08, 0.25}) {
        Simulator simulator(wall_at(d), robot, {}, 11);
        const auto stats = test::sample_stats_of(distances_read(simulator, 0, nominal, 3000));
        EXPECT_NEAR(stats.sd, 0.01, 0.0008) << d;
    }
}

TEST(IrSensorModel, SpreadsAreValidated) {
    RobotSpec robot;
    robot.ir_gain_spread = -0.1;
    robot.ir_offset_spread = 1000.0;
    robot.ir_noise_distance = 0.0;
    std::vector<std::string> fields;
    for (const ConfigIssue& issue : validate(robot)) {
        fields.push_back(issue.field);
    }
    EXPECT_EQ(fields,
              (std::vector<std::string>{"simulator.ir_noise_distance", "simulator.ir_gain_spread",
                                        "simulator.ir_offset_spread"}));
}

}  // namespace
}  // namespace legofeup::sim
