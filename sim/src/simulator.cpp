#include "legofeup/sim/simulator.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "box2d_convert.hpp"
#include "drive_train.hpp"
#include "extra_sensors.hpp"
#include "grid_bodies.hpp"
#include "ir_ray.hpp"
#include "legofeup/core/angles.hpp"
#include "noise_streams.hpp"

namespace legofeup::sim {
namespace {

constexpr int kVelocityIterations = 6;
constexpr int kPositionIterations = 2;
constexpr double kTimeTolerance = 1e-9;  // s, when comparing accumulated sample times

// A standard normal sample truncated to ±3σ (redrawn beyond): unit spreads are taken as
// ±3σ = the data sheet's limits, and units outside them do not ship.
double truncated_normal(GaussianStream& stream) {
    constexpr double kLimit = 3.0;
    double sample = stream.next();
    while (std::abs(sample) > kLimit) {
        sample = stream.next();
    }
    return sample;
}

BeaconMap sorted_by_id(BeaconMap beacons) {
    std::stable_sort(beacons.begin(), beacons.end(),
                     [](const Beacon& a, const Beacon& b) { return a.id < b.id; });
    return beacons;
}

}  // namespace

std::vector<ConfigIssue> validate(const SimulatorSettings& settings) {
    std::vector<ConfigIssue> issues;
    ConfigChecker check(issues);
    check.in_range("simulator.physics_rate", settings.physics_rate, 100.0, 10000.0);
    const double steps = settings.control_period * settings.physics_rate;
    check.require(settings.control_period > 0.0 && settings.control_period <= 1.0
                      && std::abs(steps - std::round(steps)) <= 1e-9 && std::round(steps) >= 1.0,
                  "simulator.control_period", settings.control_period,
                  "must be a whole number of physics steps, at most 1 s");
    const auto& event = settings.displacement;
    check.in_range("simulator.displacement.time", event.time, 0.0, 1e7);
    check.in_range("simulator.displacement.dx", event.dx, -1000.0, 1000.0);
    check.in_range("simulator.displacement.dy", event.dy, -1000.0, 1000.0);
    check.in_range("simulator.displacement.dtheta", event.dtheta, -2.0 * kPi, 2.0 * kPi);
    const auto& kidnap = settings.kidnap;
    check.in_range("simulator.kidnap.time", kidnap.time, 0.0, 1e7);
    check.in_range("simulator.kidnap.pose.x", kidnap.pose.x, -1000.0, 1000.0);
    check.in_range("simulator.kidnap.pose.y", kidnap.pose.y, -1000.0, 1000.0);
    check.in_range("simulator.kidnap.pose.theta", kidnap.pose.theta, -2.0 * kPi, 2.0 * kPi);
    return issues;
}

std::vector<ConfigIssue> validate(const RobotSpec& robot, const SimulatorSettings& settings) {
    std::vector<ConfigIssue> issues = validate(robot);
    const std::vector<ConfigIssue> more = validate(settings);
    issues.insert(issues.end(), more.begin(), more.end());
    // A scan completes at the end of a control period (sensors.md), so its frame carries it.
    // Only an enabled scanner is held to it: its default period need not suit every run.
    const double periods = robot.laser_scanner.scan_period / settings.control_period;
    ConfigChecker check(issues);
    check.require(!robot.laser_scanner.enabled || !std::isfinite(periods)
                      || (std::abs(periods - std::round(periods)) <= 1e-9 * std::max(1.0, periods)
                          && std::round(periods) >= 1.0),
                  "simulator.laser_scanner.scan_period", robot.laser_scanner.scan_period,
                  "must be a whole number of control periods ("
                      + format_config_number(settings.control_period) + " s)");
    return issues;
}

struct Simulator::State {
    WorldSpec world;
    RobotSpec robot;
    SimulatorSettings settings;
    BeaconMap beacons_by_id;  // the world's beacons in the order the scanner reports them
    double dt = 0.01;
    int steps_per_period = 5;

    b2World physics{b2Vec2(0.0f, 0.0f)};
    b2Body* chassis = nullptr;
    DriveTrain drive_train;
    ExtraSensors extra;

    std::uint64_t step_count = 0;
    std::uint32_t sequence = 0;
    double next_ir_time = 0.0;
    std::array<std::uint16_t, 2> ir_adc{};
    std::array<double, 2> ir_distances{};
    // The realistic model's units as standard normal draws (n₁, n₂) per sensor, drawn at
    // each reset; the spreads scale them when used, so a changed spread applies at once.
    std::array<std::array<double, 2>, 2> ir_unit_draws{};
    double next_motion_sample_time = 0.0;  // gyroscope, accelerometers, compass
    double next_scan_time = 0.0;
    double next_laser_time = 0.0;
    bool displaced = false;  // the displacement event has happened
    bool kidnapped = false;  // the kidnap event has happened
    std::uint32_t teleports = 0;

    GaussianStream ir_front_noise{0, NoiseStream::IrFront};
    GaussianStream ir_rear_noise{0, NoiseStream::IrRear};
    GaussianStream slip_right{0, NoiseStream::SlipRight};
    GaussianStream slip_left{0, NoiseStream::SlipLeft};

    State(WorldSpec w, RobotSpec r, SimulatorSettings s)
        : world(std::move(w)),
          robot(std::move(r)),
          settings(s),
          beacons_by_id(sorted_by_id(world.beacons)),
          drive_train(robot),
          extra(0, robot) {
        dt = 1.0 / settings.physics_rate;
        steps_per_period =
            static_cast<int>(std::lround(settings.control_period * settings.physics_rate));
        physics.SetContinuousPhysics(false);  // 1 mm per step against 1 cm skins: no tunnelling
        physics.SetAllowSleeping(false);
        build_walls();
        if (world.map) {
            build_grid_body(physics, *world.map);  // after the walls: a fixed creation order
        }
    }

    double time() const { return static_cast<double>(step_count) * dt; }

    void build_walls() {
        b2BodyDef definition;  // static
        b2Body* walls = physics.CreateBody(&definition);
        for (const Wall& wall : world.walls) {
            b2EdgeShape edge;  // zero thickness: the beams reflect exactly on the wall's line
            edge.SetTwoSided(to_b2(wall.start), to_b2(wall.end));
            b2FixtureDef fixture;
            fixture.shape = &edge;
            fixture.friction = 0.3f;
            walls->CreateFixture(&fixture);
        }
    }

    void build_chassis(const Pose2& start) {
        if (chassis != nullptr) {
            physics.DestroyBody(chassis);
        }
        b2BodyDef definition;
        definition.type = b2_dynamicBody;
        definition.position = to_b2(start.x, start.y);
        definition.angle = static_cast<float>(start.theta);
        definition.allowSleep = false;
        chassis = physics.CreateBody(&definition);

        // Box2D rounds polygons with a skin of b2_polygonRadius; shrink the polygon by it so
        // the robot collides at the outline the spec gives.
        b2PolygonShape box;
        const auto skin = static_cast<double>(b2_polygonRadius);
        const auto front = static_cast<float>(robot.chassis_front - skin);
        const auto rear = static_cast<float>(robot.chassis_rear - skin);
        const auto half_width = static_cast<float>(robot.chassis_half_width - skin);
        const b2Vec2 corners[] = {
            {-rear, -half_width}, {front, -half_width}, {front, half_width}, {-rear, half_width}};
        box.Set(corners, 4);
        b2FixtureDef fixture;
        fixture.shape = &box;
        fixture.density = 1.0f;
        fixture.friction = 0.3f;
        chassis->CreateFixture(&fixture);

        // The NXT brick sits over the axle: put the centre of mass at the body origin (the
        // axle midpoint, which is also the pose the filter estimates).
        b2MassData mass;
        chassis->GetFixtureList()->GetMassData(&mass);
        const double scale = robot.mass / static_cast<double>(mass.mass);
        b2MassData placed;
        placed.mass = static_cast<float>(robot.mass);
        placed.center.SetZero();
        placed.I = static_cast<float>(static_cast<double>(mass.I) * scale);  // about the origin
        chassis->SetMassData(&placed);
    }

    void reseed(std::uint64_t seed) {
        ir_front_noise = GaussianStream(seed, NoiseStream::IrFront);
        ir_rear_noise = GaussianStream(seed, NoiseStream::IrRear);
        slip_right = GaussianStream(seed, NoiseStream::SlipRight);
        slip_left = GaussianStream(seed, NoiseStream::SlipLeft);
        draw_ir_units(seed);
    }

    // n₁ (the gain's) then n₂ (the offset's) from each sensor's own stream.
    void draw_ir_units(std::uint64_t seed) {
        const NoiseStream streams[] = {NoiseStream::IrUnitFront, NoiseStream::IrUnitRear};
        for (std::size_t s = 0; s < ir_unit_draws.size(); ++s) {
            GaussianStream stream(seed, streams[s]);
            ir_unit_draws[s][0] = truncated_normal(stream);
            ir_unit_draws[s][1] = truncated_normal(stream);
        }
    }

    // Sensor s's gain g = 1 + σ_g·n₁ and offset o = σ_o·n₂.
    IrUnit ir_unit(std::size_t s) const {
        return {1.0 + robot.ir_gain_spread * ir_unit_draws[s][0],
                robot.ir_offset_spread * ir_unit_draws[s][1]};
    }

    // The IR sensors sample every ir_period and hold the value: closest hit, then
    // (ideal) noise in metres and the characteristic curve (with its fold-back), or
    // (realistic) the sensor's own output and noise in counts; 10-bit conversion.
    void sample_ir() {
        GaussianStream* noise[] = {&ir_front_noise, &ir_rear_noise};
        const double output_noise =
            ir_output_noise_counts(robot.ir_curve, robot.ir_noise, robot.ir_noise_distance);
        const b2Vec2 look = chassis->GetWorldVector(b2Vec2(0.0f, -1.0f));  // the right side
        for (int sensor = 0; sensor < kIrSensorCount; ++sensor) {
            const auto s = static_cast<std::size_t>(sensor);
            const b2Vec2 mount =
                to_b2(robot.ir_mount.longitudinal(sensor), -robot.ir_mount.lateral_offset);
            const b2Vec2 origin = chassis->GetWorldPoint(mount);
            ir_distances[s] = cast_ir_ray(physics, chassis, origin, look, robot.ir_ray_length);
            if (robot.ir_model == IrSensorModel::Realistic) {
                const double n = robot.ir_noise > 0.0 ? noise[s]->next() : 0.0;
                ir_adc[s] =
                    realistic_ir_adc(robot.ir_curve, ir_unit(s), ir_distances[s], output_noise * n);
                continue;
            }
            const double measured =
                ir_distances[s] + (robot.ir_noise > 0.0 ? robot.ir_noise * noise[s]->next() : 0.0);
            ir_adc[s] =
                quantize_adc(adc_from_distance(measured, robot.ir_curve), robot.ir_curve.adc_max);
        }
    }

    void step() {
        if (time() + 1e-12 >= next_ir_time) {
            sample_ir();
            next_ir_time += robot.ir_period;
        }
        const MountMotion before = ExtraSensors::mount_motion(*chassis, robot);
        drive_train.drive(*chassis, dt, slip_right, slip_left);
        physics.Step(static_cast<float>(dt), kVelocityIterations, kPositionIterations);
        ++step_count;
        extra.accumulate(before, ExtraSensors::mount_motion(*chassis, robot), dt);
        sample_extra_sensors();
    }

    // The further lessons' sensors sample at the end of a physics step: the motion sensors
    // once per control period, the beacon scanner once per scan period.
    void sample_extra_sensors() {
        const double now = time();
        if (now + kTimeTolerance >= next_motion_sample_time) {
            extra.sample_motion_sensors(robot, world, *chassis, now);
            while (next_motion_sample_time <= now + kTimeTolerance) {
                next_motion_sample_time += settings.control_period;
            }
        }
        if (now + kTimeTolerance >= next_scan_time) {
            extra.scan_beacons(robot, beacons_by_id, physics, *chassis, now);
            while (next_scan_time <= now + kTimeTolerance) {
                next_scan_time += robot.beacon_scanner.period;
            }
        }
        // The schedule runs whether or not the laser is on, so scans stay at whole multiples
        // of scan_period (ends of control periods) even when it is switched on mid-run.
        if (now + kTimeTolerance >= next_laser_time) {
            extra.scan_laser(robot, physics, *chassis, now);
            while (next_laser_time <= now + kTimeTolerance) {
                next_laser_time += robot.laser_scanner.scan_period;
            }
        }
    }

    void restart(const Pose2& start, std::uint64_t seed) {
        build_chassis(start);
        drive_train = DriveTrain(robot);
        reseed(seed);
        extra = ExtraSensors(seed, robot);
        step_count = 0;
        sequence = 0;
        next_ir_time = 0.0;
        sample_ir();
        next_ir_time = robot.ir_period;
        next_motion_sample_time = 0.0;
        next_scan_time = 0.0;
        next_laser_time = 0.0;
        sample_extra_sensors();
        displaced = false;
        kidnapped = false;
        teleports = 0;
    }

    // The displacement and kidnap events (sensors.md) are due at the start of the first
    // control period whose end time is ≥ their time; both are teleports. When both are due
    // in the same period, the displacement comes first and the kidnap's absolute pose wins.
    bool due(bool enabled, bool happened, double event_time) const {
        return enabled && !happened
               && time() + settings.control_period + kTimeTolerance >= event_time;
    }
};

Simulator::Simulator(WorldSpec world, RobotSpec robot, SimulatorSettings settings,
                     std::uint64_t seed) {
    auto issues = validate(world);
    const auto more = validate(robot, settings);
    issues.insert(issues.end(), more.begin(), more.end());
    if (!issues.empty()) {
        throw invalid_configuration("simulator", issues);
    }
    const Pose2 start = world.start;
    state_ = std::make_unique<State>(std::move(world), std::move(robot), settings);
    state_->restart(start, seed);
}

Simulator::~Simulator() = default;

void Simulator::reset(const Pose2& start, std::uint64_t seed) {
    state_->restart(start, seed);
}

void Simulator::teleport(const Pose2& pose) {
    b2Body& chassis = *state_->chassis;
    chassis.SetTransform(to_b2(pose.x, pose.y), static_cast<float>(pose.theta));
    chassis.SetLinearVelocity(b2Vec2(0.0f, 0.0f));
    chassis.SetAngularVelocity(0.0f);
    ++state_->teleports;
}

void Simulator::set_wheel_command(const WheelSpeeds& command) {
    state_->drive_train.set_command(command);
}

void Simulator::set_robot(const RobotSpec& robot) {
    if (const auto issues = validate(robot, state_->settings); !issues.empty()) {
        throw invalid_configuration("simulator", issues);
    }
    state_->robot = robot;
    state_->drive_train.set_spec(robot);
}

void Simulator::step_physics() {
    state_->step();
}

void Simulator::step_control_period() {
    State& state = *state_;
    const auto& displacement = state.settings.displacement;
    if (state.due(displacement.enabled, state.displaced, displacement.time)) {
        const GroundTruth now = ground_truth();
        teleport({now.pose.x + displacement.dx, now.pose.y + displacement.dy,
                  now.pose.theta + displacement.dtheta});
        state.displaced = true;
    }
    const auto& kidnap = state.settings.kidnap;
    if (state.due(kidnap.enabled, state.kidnapped, kidnap.time)) {
        teleport(kidnap.pose);
        state.kidnapped = true;
    }
    for (int i = 0; i < state_->steps_per_period; ++i) {
        state_->step();
    }
    ++state_->sequence;
}

SensorFrame Simulator::sensor_frame() const {
    SensorFrame frame;
    frame.time = state_->time();
    frame.sequence = state_->sequence;
    frame.encoder_counts = state_->drive_train.encoder_counts();
    frame.ir_adc = state_->ir_adc;
    state_->extra.fill(frame, state_->robot, state_->settings.control_period);
    return frame;
}

GroundTruth Simulator::ground_truth() const {
    const b2Body& chassis = *state_->chassis;
    GroundTruth truth;
    truth.time = state_->time();
    const Vector2 position = from_b2(chassis.GetPosition());
    truth.pose = {position.x(), position.y(), wrap_angle(static_cast<double>(chassis.GetAngle()))};
    const Vector2 forward = from_b2(chassis.GetWorldVector(b2Vec2(1.0f, 0.0f)));
    truth.velocity = {from_b2(chassis.GetLinearVelocity()).dot(forward),
                      static_cast<double>(chassis.GetAngularVelocity())};
    truth.wheel_surface_speeds = state_->drive_train.surface_speeds();
    for (const b2ContactEdge* edge = chassis.GetContactList(); edge != nullptr; edge = edge->next) {
        truth.touching_wall = truth.touching_wall || edge->contact->IsTouching();
    }
    truth.ir_distances = state_->ir_distances;
    const GyroSpec& gyro = state_->robot.gyro;
    truth.gyro_bias_rate =
        gyro.enabled ? degrees_to_radians(state_->extra.gyro_bias() / gyro.counts_per_dps) : 0.0;
    truth.magnetic_disturbance =
        degrees_to_radians(magnetic_disturbance_deg(state_->world.magnetic, position));
    truth.teleports = state_->teleports;
    return truth;
}

std::array<IrUnit, 2> Simulator::ir_units() const {
    return {state_->ir_unit(0), state_->ir_unit(1)};
}

double Simulator::time() const {
    return state_->time();
}
const WorldSpec& Simulator::world() const {
    return state_->world;
}
const RobotSpec& Simulator::robot() const {
    return state_->robot;
}
const SimulatorSettings& Simulator::settings() const {
    return state_->settings;
}

}  // namespace legofeup::sim
