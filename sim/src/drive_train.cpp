#include "drive_train.hpp"

#include <algorithm>
#include <cmath>

#include "box2d_convert.hpp"
#include "legofeup/core/angles.hpp"

namespace legofeup::sim {
namespace {

constexpr double kGravity = 9.81;      // m/s²
constexpr int kContactIterations = 4;  // sequential-impulse passes over the two tyres
constexpr int kRight = 0;
constexpr int kLeft = 1;

/// ⌊turns · counts_per_turn⌋ of a wheel turned `degrees`, wrapped to 32 bits as the NXT's
/// SLONG counters do. Computed as ⌊degrees · (counts_per_turn / 360)⌋: the factor is exactly
/// 1, 2 or ½ for 360, 720 or 180 counts, so the NXT's 360 counts are ⌊degrees⌋ bit for bit.
std::int32_t encoder_count(double degrees, double counts_per_turn) {
    const auto count = static_cast<std::int64_t>(std::floor(degrees * (counts_per_turn / 360.0)));
    return static_cast<std::int32_t>(static_cast<std::uint32_t>(count));
}

double cross(const Vector2& a, const Vector2& b) {
    return a.x() * b.y() - a.y() * b.x();
}

// Impulse accumulated along one direction at one contact, clamped to ±limit in total.
struct ContactRow {
    Vector2 arm;        // contact point relative to the centre of mass, world frame
    Vector2 direction;  // unit direction of the impulse
    double target;      // desired velocity of the contact point along `direction`, m/s
    double limit;       // friction limit of the accumulated impulse, N·s
    double accumulated = 0.0;
};

}  // namespace

void DriveTrain::set_spec(const RobotSpec& spec) {
    spec_ = spec;
    radius_ = {0.5 * spec.right_wheel_diameter(), 0.5 * spec.left_wheel_diameter()};
}

void DriveTrain::set_command(const WheelSpeeds& command) {
    const double nominal_radius = 0.5 * spec_.wheel_diameter;
    const double max_rate = spec_.max_motor_rpm * 2.0 * kPi / 60.0;
    target_rate_[kRight] = std::clamp(command.right / nominal_radius, -max_rate, max_rate);
    target_rate_[kLeft] = std::clamp(command.left / nominal_radius, -max_rate, max_rate);
}

void DriveTrain::stop_motors() {
    target_rate_ = {0.0, 0.0};
    rate_ = {0.0, 0.0};
}

std::array<std::int32_t, 2> DriveTrain::encoder_counts() const {
    return {encoder_count(wheel_degrees_[kRight], spec_.counts_per_turn),
            encoder_count(wheel_degrees_[kLeft], spec_.counts_per_turn)};
}

WheelSpeeds DriveTrain::surface_speeds() const {
    return {rate_[kRight] * radius_[kRight], rate_[kLeft] * radius_[kLeft]};
}

void DriveTrain::drive(b2Body& chassis, double dt, GaussianStream& slip_right,
                       GaussianStream& slip_left) {
    // 1. Motors: exact discretisation of τ·ω̇ = ω_target − ω over dt.
    const double decay =
        spec_.motor_time_constant > 0.0 ? std::exp(-dt / spec_.motor_time_constant) : 0.0;
    for (int i : {kRight, kLeft}) {
        const auto w = static_cast<std::size_t>(i);
        rate_[w] = target_rate_[w] + (rate_[w] - target_rate_[w]) * decay;
        wheel_degrees_[w] += radians_to_degrees(rate_[w] * dt);  // encoders count rotation
    }

    // 2. Where each tyre wants to go: its surface speed, plus random slip whose variance
    //    grows with the distance rolled (σ² = slip_noise²·|distance| per step).
    std::array<double, 2> ground_speed{};
    GaussianStream* slip[] = {&slip_right, &slip_left};
    for (int i : {kRight, kLeft}) {
        const auto w = static_cast<std::size_t>(i);
        const double rolled = rate_[w] * radius_[w] * dt;
        const double slip_distance =
            spec_.slip_noise > 0.0
                ? spec_.slip_noise * std::sqrt(std::abs(rolled)) * slip[w]->next()
                : 0.0;
        ground_speed[w] = (rolled + slip_distance) / dt;
    }

    // 3. Tyre contacts as velocity constraints solved by sequential impulses: the contact
    //    point's forward velocity should equal the tyre's ground speed, its sideways
    //    velocity zero; each accumulated impulse is limited by μ·N·dt.
    const double mass = static_cast<double>(chassis.GetMass());
    const Vector2 local_centre = from_b2(chassis.GetLocalCenter());
    const double inertia =
        static_cast<double>(chassis.GetInertia()) - mass * local_centre.squaredNorm();
    const double normal_force = spec_.wheel_load * mass * kGravity / 2.0;  // per driven wheel
    const double limit = spec_.traction * normal_force * dt;
    const double half_base = 0.5 * spec_.wheel_base * spec_.wheel_base_ratio;  // actual b/2
    const Vector2 forward = from_b2(chassis.GetWorldVector(b2Vec2(1.0f, 0.0f)));
    const Vector2 left = from_b2(chassis.GetWorldVector(b2Vec2(0.0f, 1.0f)));
    const Vector2 centre = from_b2(chassis.GetWorldCenter());

    std::array<ContactRow, 4> rows{};
    for (int i : {kRight, kLeft}) {
        const double side = i == kRight ? -half_base : half_base;
        const Vector2 contact = from_b2(chassis.GetWorldPoint(to_b2(0.0, side)));
        const Vector2 arm = contact - centre;
        rows[static_cast<std::size_t>(2 * i)] = {arm, forward,
                                                 ground_speed[static_cast<std::size_t>(i)], limit};
        rows[static_cast<std::size_t>(2 * i + 1)] = {arm, left, 0.0, limit};
    }

    Vector2 velocity = from_b2(chassis.GetLinearVelocity());
    double omega = static_cast<double>(chassis.GetAngularVelocity());
    for (int iteration = 0; iteration < kContactIterations; ++iteration) {
        for (ContactRow& row : rows) {
            // Velocity of the contact point: v + ω × r, along the row's direction.
            const Vector2 point_velocity = velocity + omega * Vector2(-row.arm.y(), row.arm.x());
            const double along = point_velocity.dot(row.direction);
            const double arm_cross = cross(row.arm, row.direction);
            const double effective_mass = 1.0 / (1.0 / mass + arm_cross * arm_cross / inertia);
            const double wanted = (row.target - along) * effective_mass;
            const double total = std::clamp(row.accumulated + wanted, -row.limit, row.limit);
            const double impulse = total - row.accumulated;
            row.accumulated = total;
            velocity += impulse / mass * row.direction;
            omega += impulse * arm_cross / inertia;
        }
    }
    chassis.SetLinearVelocity(to_b2(velocity));
    chassis.SetAngularVelocity(static_cast<float>(omega));
}

}  // namespace legofeup::sim
