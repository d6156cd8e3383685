// Calibration matters on a simulated robot whose sensors have their own true curves (the
// realistic IR model): calibrating each sensor's curve from points taken on that robot lowers
// the RMS error of the LegoFeup lesson's step f against the nominal curve, more than one
// curve for both does. With the ideal model the sensors follow the nominal curve, and
// calibrating changes nothing that matters.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "legofeup/lessons/calibration/simulated_ir_points.hpp"
#include "legofeup/lessons/lesson.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/lessons/run_summary.hpp"
#include "legofeup/sim/simulator.hpp"

namespace legofeup::lessons {
namespace {

using sim::IrSensorModel;

// What a run of step f shows: how far the estimate was, and whether the filter knew it.
struct Outcome {
    double rms = 0.0;     ///< RMS position error, m
    double inside = 0.0;  ///< fraction of the steps whose NEES is inside its 95 % bounds
};

Outcome run_step(const ResolvedRun& run) {
    const auto metrics = result_metrics_to_json(run_lockstep(run));
    return {metrics["rms_position_error_m"].get<double>(),
            metrics["nees_inside_fraction"].get<double>()};
}

// How far the filter's curves read the robot's true sensors: the RMS, over both sensors
// and the wall distances of the arena (10–25 cm), of the distance the filter's curve of each
// sensor gives at that sensor's true A/D value minus the true distance, m.
double curve_error(const LoopConfig& loop, const sim::RobotSpec& robot, std::uint64_t seed) {
    const auto units = sim::Simulator(sim::WorldSpec{}, robot, {}, seed).ir_units();
    double sum = 0.0;
    int n = 0;
    for (const IrSensor sensor : {kFrontSensor, kRearSensor}) {
        const sim::IrUnit& unit = units[static_cast<std::size_t>(sensor)];
        const SharpIrCurve truth = robot.ir_model == IrSensorModel::Realistic
                                       ? sim::unit_curve(robot.ir_curve, unit)
                                       : robot.ir_curve;
        const SharpIrCurve believed = ir_sensor_curve(loop, sensor);
        for (double d = 0.10; d <= 0.25 + 1e-9; d += 0.01) {
            const double error =
                distance_from_adc(adc_from_distance(d, truth), believed).distance - d;
            sum += error * error;
            ++n;
        }
    }
    return std::sqrt(sum / n);
}

struct Calibration {
    Outcome nominal;                      ///< step f with the nominal curve
    Outcome one_curve;                    ///< with one curve fitted to both sensors' points
    Outcome per_sensor;                   ///< with each sensor's own fitted curve
    double nominal_curve_error = 0.0;     ///< curve_error of the nominal curve, m
    double one_curve_error = 0.0;         ///< curve_error of the one fitted curve, m
    double per_sensor_curve_error = 0.0;  ///< curve_error of the per-sensor curves, m
};

// Step f on `seed`, then the same run after calibrating the IR curve on that seed's robot,
// applied to the filter alone as `run --profile` applies a calibrated profile: one curve
// for both sensors (the paper's profile, run only when `one_curve`), then one per sensor.
Calibration calibrate_step_f(IrSensorModel model, std::uint64_t seed, bool one_curve) {
    RunConfig config = legofeup_lesson().find_step("f")->config;
    config.physical.ir_model = model;
    config.seed = seed;
    ResolvedRun run = resolve(config);
    Calibration result;
    result.nominal = run_step(run);
    result.nominal_curve_error = curve_error(run.loop, run.robot, seed);
    const std::vector<double> distances = advised_ir_calibration_distances();
    const auto points = measure_simulated_ir_points(run.robot, seed, distances, 20);
    const SharpIrCurve nominal = run.loop.ir_curve;

    const IrFit fit = fit_ir_curve(points, nominal);
    EXPECT_TRUE(fit.converged) << seed;
    run.loop.ir_curve = fit.curve;
    result.one_curve_error = curve_error(run.loop, run.robot, seed);
    if (one_curve) {
        result.one_curve = run_step(run);
    }
    for (const IrSensor sensor : {kFrontSensor, kRearSensor}) {
        const auto own = points_of(points, sensor);
        EXPECT_EQ(own.size(), distances.size());
        const IrFit sensor_fit = fit_ir_curve(own, nominal);
        EXPECT_TRUE(sensor_fit.converged) << seed;
        run.loop.ir_sensor_parameters[static_cast<std::size_t>(sensor)] =
            curve_parameters(sensor_fit.curve);
    }
    result.per_sensor_curve_error = curve_error(run.loop, run.robot, seed);
    result.per_sensor = run_step(run);
    return result;
}

constexpr std::uint64_t kFirstSeed = 1001;
constexpr int kSeeds = 10;

TEST(IrCalibrationOnSimulator, PointsOfTheIdealModelLieOnTheNominalCurve) {
    sim::RobotSpec robot;  // ideal, no noise
    const std::vector<double> distances = advised_ir_calibration_distances();
    ASSERT_EQ(distances.size(), 17u);
    const auto points = measure_simulated_ir_points(robot, 5, distances, 3);
    ASSERT_EQ(points.size(), 34u);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double d = distances[i % distances.size()];
        EXPECT_EQ(points[i].distance, d);
        EXPECT_EQ(points[i].adc, quantize_adc(adc_from_distance(d, robot.ir_curve), 1023)) << i;
    }
}

TEST(IrCalibrationOnSimulator, PointsOfTheRealisticModelLieOnEachSensorsOwnCurve) {
    sim::RobotSpec robot;
    robot.ir_model = IrSensorModel::Realistic;  // no noise: each point is its unit's value
    const std::vector<double> distances = advised_ir_calibration_distances();
    const auto points = measure_simulated_ir_points(robot, 5, distances, 3);
    sim::WorldSpec world;
    const auto units = sim::Simulator(world, robot, {}, 5).ir_units();
    for (std::size_t i = 0; i < points.size(); ++i) {
        const sim::IrUnit& unit = units[i / distances.size()];
        const double d = distances[i % distances.size()];
        EXPECT_EQ(points[i].adc, realistic_ir_adc(robot.ir_curve, unit, d, 0.0)) << i;
    }
}

TEST(IrCalibrationOnSimulator, RefusesBadReadingsAndDistances) {
    const sim::RobotSpec robot;
    const std::vector<double> good{0.1};
    EXPECT_THROW(measure_simulated_ir_points(robot, 1, good, 0), std::invalid_argument);
    for (const double bad : {0.0, -0.1, 0.81}) {
        const std::vector<double> distances{bad};
        EXPECT_THROW(measure_simulated_ir_points(robot, 1, distances, 5), std::invalid_argument)
            << bad;
    }
}

// Means over the seeds of one way of calibrating.
struct Means {
    double rms = 0.0;
    double inside = 0.0;
    double worst_rms = 0.0;

    void add(const Outcome& outcome, int seeds) {
        rms += outcome.rms / seeds;
        inside += outcome.inside / seeds;
        worst_rms = std::max(worst_rms, outcome.rms);
    }
};

TEST(IrCalibrationOnSimulator, CalibratingEachSensorHelpsStepFOnlyWhenTheSensorsDiffer) {
    Means nominal;
    Means one_curve;
    Means per_sensor;
    Means ideal_nominal;
    Means ideal_per_sensor;
    int consistent_nominal = 0;  // seeds whose nees_inside_fraction > 0.8, step f's check
    int consistent_per_sensor = 0;
    for (int i = 0; i < kSeeds; ++i) {
        const std::uint64_t seed = kFirstSeed + static_cast<std::uint64_t>(i);
        const Calibration realistic = calibrate_step_f(IrSensorModel::Realistic, seed, true);
        const Calibration ideal = calibrate_step_f(IrSensorModel::Ideal, seed, false);
        std::printf(
            "seed %llu: realistic RMS %.4f -> one curve %.4f, per sensor %.4f m; inside %.2f -> "
            "%.2f, %.2f; curve error %.4f -> %.4f, %.4f m; ideal %.4f -> %.4f m\n",
            static_cast<unsigned long long>(seed), realistic.nominal.rms, realistic.one_curve.rms,
            realistic.per_sensor.rms, realistic.nominal.inside, realistic.one_curve.inside,
            realistic.per_sensor.inside, realistic.nominal_curve_error, realistic.one_curve_error,
            realistic.per_sensor_curve_error, ideal.nominal.rms, ideal.per_sensor.rms);
        // One curve finds what the two sensors share; a curve per sensor finds each unit,
        // to within the readings' noise. With the ideal model the sensors are the nominal
        // curve, and each fit finds it again.
        EXPECT_LT(realistic.one_curve_error, realistic.nominal_curve_error) << seed;
        // Measured on seeds 1001–1010: 0.8–2.3 mm per sensor, 2.1–19 mm with one curve.
        EXPECT_LT(realistic.per_sensor_curve_error, realistic.one_curve_error) << seed;
        EXPECT_LT(realistic.per_sensor_curve_error, 0.003) << seed;
        // Its noise, added to the distance and averaged as A/D counts, leaves the points
        // ≈ 1 mm off the curve where it bends most (measured up to 1.3 mm on seeds 1001–1010),
        // against ≈ 1 cm of a realistic unit.
        EXPECT_LT(ideal.per_sensor_curve_error, 0.002) << seed;
        EXPECT_LT(ideal.nominal_curve_error, 1e-12) << seed;
        nominal.add(realistic.nominal, kSeeds);
        one_curve.add(realistic.one_curve, kSeeds);
        per_sensor.add(realistic.per_sensor, kSeeds);
        ideal_nominal.add(ideal.nominal, kSeeds);
        ideal_per_sensor.add(ideal.per_sensor, kSeeds);
        consistent_nominal += realistic.nominal.inside > 0.8 ? 1 : 0;
        consistent_per_sensor += realistic.per_sensor.inside > 0.8 ? 1 : 0;
    }
    std::printf(
        "means: realistic RMS %.4f -> one curve %.4f, per sensor %.4f m (worst %.4f, %.4f, "
        "%.4f m); inside %.3f -> %.3f, %.3f (> 0.8 on %d, per sensor %d of %d); ideal RMS "
        "%.4f -> %.4f m, inside %.3f -> %.3f\n",
        nominal.rms, one_curve.rms, per_sensor.rms, nominal.worst_rms, one_curve.worst_rms,
        per_sensor.worst_rms, nominal.inside, one_curve.inside, per_sensor.inside,
        consistent_nominal, consistent_per_sensor, kSeeds, ideal_nominal.rms, ideal_per_sensor.rms,
        ideal_nominal.inside, ideal_per_sensor.inside);
    // Measured (seeds 1001–1010): realistic RMS 0.197 -> one curve 0.038, per sensor 0.030 m
    // (seed 1003 is lost with the nominal curve, 1.57 m); worst seed 1.57, 0.066, 0.037 m;
    // inside 0.41 -> 0.66, 0.94 (> 0.8 on 1 -> 10 of 10); ideal RMS 0.0331 -> 0.0311 m,
    // inside 0.97 -> 0.92. Unseen seeds 2001–2020 (docs/calibration.md, CLI): realistic
    // 0.0336 -> 0.0310, 0.0283 m, inside 0.66 -> 0.69, 0.91 (> 0.8 on 7 -> 18 of 20).
    EXPECT_LT(per_sensor.rms, one_curve.rms);
    EXPECT_LT(one_curve.rms, nominal.rms);
    EXPECT_LT(per_sensor.worst_rms, nominal.worst_rms);
    EXPECT_GT(per_sensor.inside, one_curve.inside + 0.1);
    EXPECT_GT(consistent_per_sensor, consistent_nominal);
    // With the ideal model nothing is there to find: the run stays what it was.
    // (Its calibration is slightly off near 4 cm, docs/calibration.md: ≈ 6 % and 0.05 here.)
    EXPECT_NEAR(ideal_per_sensor.rms, ideal_nominal.rms, 0.1 * ideal_nominal.rms);
    EXPECT_NEAR(ideal_per_sensor.inside, ideal_nominal.inside, 0.1);
    EXPECT_GT(nominal.rms - per_sensor.rms,
              5.0 * std::abs(ideal_nominal.rms - ideal_per_sensor.rms));
}

}  // namespace
}  // namespace legofeup::lessons
