#include "kinematic_world.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace legofeup::testing {

Pose2 integrate_arc(const Pose2& pose, double v, double w, double dt) {
    if (std::abs(w) < 1e-12) {
        return {pose.x + v * dt * std::cos(pose.theta), pose.y + v * dt * std::sin(pose.theta),
                pose.theta};
    }
    const double radius = v / w;
    const double theta_end = pose.theta + w * dt;
    return {pose.x + radius * (std::sin(theta_end) - std::sin(pose.theta)),
            pose.y - radius * (std::cos(theta_end) - std::cos(pose.theta)), theta_end};
}

KinematicRobot::KinematicRobot(const Pose2& start, const KinematicRobotParams& params,
                               unsigned seed)
    : pose_(start), params_(params), rng_(seed) {}

void KinematicRobot::drive(const WheelSpeeds& wheels, double dt) {
    const double rolled_right = wheels.right * dt;  // distance each tyre's surface turns
    const double rolled_left = wheels.left * dt;
    // The encoders count the wheels' rotation, degrees: rolled distance / circumference · 360.
    // Slip never reaches them.
    const double pi = std::numbers::pi;
    wheel_degrees_[0] +=
        rolled_right / (pi * params_.right_wheel_diameter) * params_.counts_per_turn;
    wheel_degrees_[1] += rolled_left / (pi * params_.left_wheel_diameter) * params_.counts_per_turn;
    // The ground distances: rolled + ε, ε ~ N(0, slip_noise²·|rolled|) per wheel.
    double right = rolled_right;
    double left = rolled_left;
    if (params_.slip_noise > 0.0) {
        std::normal_distribution<double> unit(0.0, 1.0);
        right += unit(rng_) * params_.slip_noise * std::sqrt(std::abs(rolled_right));
        left += unit(rng_) * params_.slip_noise * std::sqrt(std::abs(rolled_left));
    }
    const double v = 0.5 * (right + left) / dt;
    const double w = (right - left) / (params_.wheel_base * dt);
    pose_ = integrate_arc(pose_, v, w, dt);
}

void KinematicRobot::drive(const VelocityCommand& command, double dt) {
    const double half = 0.5 * params_.wheel_base * command.w;
    drive(WheelSpeeds{command.v + half, command.v - half}, dt);
}

std::array<std::int32_t, 2> KinematicRobot::encoder_counts() const {
    return {static_cast<std::int32_t>(std::floor(wheel_degrees_[0])),
            static_cast<std::int32_t>(std::floor(wheel_degrees_[1]))};
}

double ray_distance(const Vector2& origin, const Vector2& direction,
                    const std::vector<Wall>& walls) {
    // Solve origin + t·direction = start + s·(end − start) for t ≥ 0, s ∈ [0, 1] by Cramer's
    // rule on the 2×2 system [direction, −(end − start)]·[t, s]ᵀ = start − origin.
    double best = std::numeric_limits<double>::infinity();
    for (const Wall& wall : walls) {
        const Vector2 edge = wall.end - wall.start;
        const Vector2 rhs = wall.start - origin;
        const double det = direction.x() * (-edge.y()) - direction.y() * (-edge.x());
        if (std::abs(det) < 1e-15) {
            continue;
        }
        const double t = (rhs.x() * (-edge.y()) - rhs.y() * (-edge.x())) / det;
        const double s = (direction.x() * rhs.y() - direction.y() * rhs.x()) / det;
        if (t >= 0.0 && s >= 0.0 && s <= 1.0 && t < best) {
            best = t;
        }
    }
    return best;
}

std::array<double, 2> true_ir_distances(const Pose2& pose, const std::vector<Wall>& walls,
                                        double lateral_offset, double front, double rear) {
    const double c = std::cos(pose.theta);
    const double s = std::sin(pose.theta);
    // Robot frame → world: (a, b) ↦ p + a·(c, s) + b·(−s, c). Sensors at (front|rear, −e),
    // looking along the robot's −y axis, i.e. the world direction (s, −c).
    const auto origin = [&](double along) {
        return Vector2(pose.x + along * c + lateral_offset * s,
                       pose.y + along * s - lateral_offset * c);
    };
    const Vector2 look(s, -c);
    return {ray_distance(origin(front), look, walls), ray_distance(origin(rear), look, walls)};
}

std::uint16_t gp2d120_adc(double distance_m) {
    if (!std::isfinite(distance_m)) {
        return 0;
    }
    const double adc = 2914.0 / (distance_m * 100.0 + 1.0) - 5.0;
    return static_cast<std::uint16_t>(std::lround(std::fmax(0.0, std::fmin(1023.0, adc))));
}

std::vector<RunRecord> run_closed_loop(LegoFeupLoop& loop, KinematicRobot& robot,
                                       const std::vector<Wall>& walls, double duration,
                                       double period, double ir_noise_sd, unsigned noise_seed) {
    std::mt19937_64 rng(noise_seed);
    std::normal_distribution<double> unit(0.0, 1.0);
    std::vector<RunRecord> records;
    const auto steps = static_cast<int>(std::lround(duration / period));
    records.reserve(static_cast<std::size_t>(steps));
    for (int k = 0; k < steps; ++k) {
        SensorFrame frame;
        frame.time = k * period;
        frame.sequence = static_cast<std::uint32_t>(k);
        frame.encoder_counts = robot.encoder_counts();
        const auto distances = true_ir_distances(robot.pose(), walls);
        for (std::size_t i = 0; i < 2; ++i) {
            const double measured = distances[i] + ir_noise_sd * unit(rng);
            frame.ir_adc[i] = gp2d120_adc(measured);
        }
        const LoopSnapshot& snapshot = loop.step(frame);
        records.push_back({robot.pose(), snapshot});
        robot.drive(snapshot.wheels, period);
    }
    return records;
}

}  // namespace legofeup::testing
