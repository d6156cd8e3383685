#include "relay_program.hpp"

#include <string>
#include <vector>

#include "legofeup/comms/nxt/relay_message.hpp"

namespace legofeup::nxtemu {
namespace {

namespace nxt = comms::nxt;

/// NXC's Off(): power 0, MOTORON | BRAKE, running — the motor holds still, braked.
nxt::OutputState braked(std::uint8_t port) {
    nxt::OutputState state;
    state.port = port;
    state.mode = nxt::kModeMotorOn | nxt::kModeBrake;
    state.run_state = nxt::kRunStateRunning;
    return state;
}

}  // namespace

void RelayProgram::start(double now, ProgramDevices& devices) {
    const BrickWiring& wiring = devices.options.wiring;
    for (const std::uint8_t port : {wiring.front_ir, wiring.rear_ir}) {
        devices.inputs.set_mode(port, nxt::kSensorLightInactive, nxt::kSensorModeRaw, now);
    }
    running_ = true;
    next_tick_ = now + kSensorSettle;
    last_read_ = now;
    motors_stopped_ = false;
    sequence_ = 0;
}

void RelayProgram::run_until(double now, ProgramDevices& devices) {
    if (!running_ || now < next_tick_) {
        return;
    }
    if (now - next_tick_ > kPeriod) {
        next_tick_ = now;  // late: one tick now, not a burst of stale ones
    }
    while (next_tick_ <= now) {
        tick(next_tick_, devices);
        next_tick_ += kPeriod;
    }
}

void RelayProgram::tick(double time, ProgramDevices& devices) {
    const BrickWiring& wiring = devices.options.wiring;
    // 1. The previous message: still there means the host has not read it. Take it out, so
    //    the queue never holds more than the newest one.
    if (devices.mailboxes.empty(kResponseMailbox)) {
        last_read_ = time;
    } else {
        while (devices.mailboxes.read(kResponseMailbox, true)) {
        }
    }
    // 2. Safety: a host that reads nothing for 500 ms is gone; the wheels must not run on.
    if (time - last_read_ >= kSilenceStop) {
        if (!motors_stopped_) {
            ++devices.counters.relay_safety_stops;
            motors_stopped_ = true;
        }
        devices.outputs.set(wiring.right_motor, braked(wiring.right_motor));
        devices.outputs.set(wiring.left_motor, braked(wiring.left_motor));
    } else {
        motors_stopped_ = false;
    }
    // 3. The new message.
    sequence_ = (sequence_ + 1) % nxt::kRelaySequenceModulus;
    const nxt::InputValues front = devices.inputs.values(wiring.front_ir, time);
    const nxt::InputValues rear = devices.inputs.values(wiring.rear_ir, time);
    nxt::RelayReading reading;
    reading.sequence = sequence_;
    reading.right_count = devices.outputs.reply(wiring.right_motor).rotation_count;
    reading.left_count = devices.outputs.reply(wiring.left_motor).rotation_count;
    reading.front_raw = front.raw;
    reading.rear_raw = rear.raw;
    reading.front_valid = front.valid;
    reading.rear_valid = rear.valid;
    reading.battery_millivolts = devices.options.battery_millivolts;
    const std::string text = nxt::format_relay_message(reading);
    std::vector<std::uint8_t> message(text.begin(), text.end());
    message.push_back(0);
    devices.mailboxes.write(kResponseMailbox, message);
    ++devices.counters.relay_messages;
}

}  // namespace legofeup::nxtemu
