#include "output_ports.hpp"

#include <algorithm>
#include <cmath>

namespace legofeup::nxtemu {
namespace {

namespace nxt = comms::nxt;

/// Adds `delta` to a 32-bit counter with the firmware's wrap-around (SLONG arithmetic).
std::int32_t advanced(std::int32_t count, std::int64_t delta) {
    return static_cast<std::int32_t>(static_cast<std::uint32_t>(count)
                                     + static_cast<std::uint32_t>(delta));
}

}  // namespace

void OutputPorts::set(std::uint8_t port, const nxt::OutputState& state) {
    Port& p = ports_.at(port);
    p.set = state;
    p.set.port = port;
    if ((state.mode & nxt::kModeMotorOn) != 0) {
        // UPDATE_SPEED, then UPDATE_MODE: run state and power, then the regulation. RUNNING
        // with power 0 is the firmware's HOLD: running, braked at speed 0.
        p.run_state = state.run_state;
        p.power = state.run_state == nxt::kRunStateIdle ? std::int8_t{0} : state.power;
        p.regulated = (state.mode & nxt::kModeRegulated) != 0
                      && state.regulation == nxt::kRegulationMotorSpeed;
    } else {
        // No MOTORON: the driver goes idle (coast, or brake with BRAKE — both stop here).
        p.run_state = nxt::kRunStateIdle;
        p.power = 0;
        p.regulated = false;
    }
    // UPDATE_TACHO_LIMIT: 0 runs forever; otherwise the limit is added to the target, in the
    // direction of the power (so a second limit of the same size goes twice as far).
    if (state.tacho_limit == 0) {
        p.run_forever = true;
    } else {
        p.run_forever = false;
        const auto limit = static_cast<std::int64_t>(state.tacho_limit);
        p.target += p.power > 0 ? limit : -limit;
    }
}

void OutputPorts::reset_position(std::uint8_t port, bool relative) {
    Port& p = ports_.at(port);
    if (relative) {
        p.block_tacho_count = 0;
    } else {
        p.rotation_count = 0;
    }
}

void OutputPorts::reset_all() {
    ports_ = {};  // coast, regulation off, run forever, every counter and target 0
}

void OutputPorts::update(const std::array<double, kOutputCount>& counts) {
    for (std::size_t i = 0; i < kOutputCount; ++i) {
        const auto whole = static_cast<std::int64_t>(std::floor(counts.at(i)));
        const std::int64_t delta = have_counts_ ? whole - last_whole_counts_.at(i) : 0;
        last_whole_counts_.at(i) = whole;
        Port& p = ports_.at(i);
        p.tacho_count = advanced(p.tacho_count, delta);
        p.block_tacho_count = advanced(p.block_tacho_count, delta);
        p.rotation_count = advanced(p.rotation_count, delta);
        if (p.run_forever && moving(p)) {
            p.target = p.tacho_count;  // a later limit counts from here
        }
        apply_tacho_limit(p);
    }
    have_counts_ = true;
}

void OutputPorts::apply_tacho_limit(Port& p) const {
    if (p.run_forever || !moving(p)) {
        return;
    }
    const bool reached =
        (p.power > 0 && p.tacho_count >= p.target) || (p.power < 0 && p.tacho_count <= p.target);
    if (reached) {
        // The run state at the limit is IDLE: the driver lets the motor coast (it overshoots).
        p.run_state = nxt::kRunStateIdle;
        p.regulated = false;
    }
}

bool OutputPorts::moving(const Port& p) {
    const bool running = p.run_state == nxt::kRunStateRunning || p.run_state == nxt::kRunStateRampUp
                         || p.run_state == nxt::kRunStateRampDown;
    return running && p.power != 0;
}

double OutputPorts::speed(const Port& p) const {
    if (!moving(p)) {
        return 0.0;
    }
    // The battery limits what full power (100 % PWM) can do, regulated or not.
    const double full =
        model_.max_degrees_per_second * model_.battery_volts / MotorModel::kNominalVolts;
    if (p.regulated) {
        return std::clamp(MotorModel::kRegulatedDegreesPerPower * p.power, -full, full);
    }
    return p.power / 100.0 * full;
}

nxt::OutputStateReply OutputPorts::reply(std::uint8_t port) const {
    const Port& p = ports_.at(port);
    nxt::OutputStateReply reply;
    reply.state = p.set;
    reply.state.port = port;
    reply.state.run_state = p.run_state;  // the IO map shows the driver's run state
    reply.tacho_count = p.tacho_count;
    reply.block_tacho_count = p.block_tacho_count;
    reply.rotation_count = p.rotation_count;
    return reply;
}

std::array<double, kOutputCount> OutputPorts::speeds() const {
    std::array<double, kOutputCount> result{};
    for (std::size_t i = 0; i < kOutputCount; ++i) {
        result.at(i) = speed(ports_.at(i));
    }
    return result;
}

}  // namespace legofeup::nxtemu
