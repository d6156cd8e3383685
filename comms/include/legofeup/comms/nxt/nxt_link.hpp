#pragma once
// The loop's link to a LEGO NXT running the standard firmware (docs/nxt.md): encoder counts
// and IR A/D values in, wheel speeds out. To the loop it is a RobotLink like the simulator.
//
// Cycle design for Bluetooth, where every change of direction costs ≈30 ms:
//  - Motor commands never wait: send_command() writes the two SETOUTPUTSTATEs at once, as
//    "no reply" commands.
//  - Direct commands (stock firmware, nothing on the brick): each cycle is ONE write of
//    GETOUTPUTSTATE × 2 and GETINPUTVALUES × 2 and ONE read of the four replies — two
//    direction changes per cycle, not eight. One batch is in flight at a time.
//  - Relay (resources/nxt/legofeup_relay.nxc running on the brick): the program packs the
//    counts and A/D values into one mailbox message; each cycle is one MESSAGEREAD. Two are
//    kept in flight, sent min_period apart, so a cycle costs a period, not a round trip.
// The period is what the link sustains: next_frame() returns as soon as the cycle's replies
// are in (never sooner than min_period after the previous frame). The frame's time is the
// host's clock when the readings arrived, so the loop sees the real, varying period.
//
// Safety: any error, timeout or disconnect tries to stop both motors, records why in
// quality(), and leaves the link closed; connect() opens it again. The destructor stops the
// motors.

#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "legofeup/comms/nxt/byte_stream.hpp"
#include "legofeup/comms/nxt/telegram.hpp"
#include "legofeup/comms/nxt/transport.hpp"
#include "legofeup/core/robot_link.hpp"

namespace legofeup::comms::nxt {

enum class CycleMode {
    DirectCommands,  ///< stock firmware only
    Relay,           ///< the relay program on the brick, read with MESSAGEREAD
};

/// Which NXT ports the robot uses and how wheel speeds become motor power.
struct NxtWiring {
    std::uint8_t right_motor = 2;  ///< output port of wheel 1 (right): 0 = A, 1 = B, 2 = C
    std::uint8_t left_motor = 1;   ///< output port of wheel 2 (left)
    std::uint8_t front_ir = 0;     ///< input port of IR sensor 1 (front): 0 = port 1
    std::uint8_t rear_ir = 1;      ///< input port of IR sensor 2 (rear)
    bool reversed_motors = false;  ///< motors mounted so that positive power drives backwards
    /// Motor power per m/s of wheel speed, for speed-regulated outputs. The firmware's
    /// regulation aims for about 10 °/s per unit of power, so for a 43.2 mm wheel
    /// 1 m/s = 2653 °/s ≈ 265 power units; calibrate it (docs/nxt.md).
    double power_per_meter_per_second = 265.3;
};

struct NxtLinkOptions {
    TransportAddress address;
    NxtWiring wiring;
    CycleMode mode = CycleMode::DirectCommands;
    std::chrono::milliseconds connect_timeout{8000};
    /// A cycle whose replies are not all in by then is a timeout (a missing frame).
    std::chrono::milliseconds reply_timeout{400};
    /// This many timeouts in a row mean the brick is gone: stop and close.
    int max_consecutive_timeouts = 5;
    /// The loop never runs faster than this: 25 Hz, above what the relay needs to reach
    /// (20 Hz) and below what Bluetooth sustains with two reads in flight.
    std::chrono::milliseconds min_period{40};
    std::chrono::seconds keep_alive_interval{30};
    std::chrono::seconds battery_interval{10};
    std::string relay_program = "legofeup.rxe";
    std::uint8_t relay_mailbox = 10;  ///< the program's response mailbox (MAILBOX1 + 10)
};

enum class LinkState { Disconnected, Connecting, Connected, Failed };
const char* to_string(LinkState state);

/// For the GUI's status bar and the CLI's summary: how well the link keeps up.
struct LinkQuality {
    LinkState state = LinkState::Disconnected;
    std::string last_error;                 ///< why it failed or closed (empty if it did not)
    std::uint64_t cycles = 0;               ///< frames delivered
    std::uint64_t timeouts = 0;             ///< cycles whose replies did not come in time
    std::uint64_t rejected_replies = 0;     ///< malformed replies or error statuses
    std::uint64_t invalid_ir_readings = 0;  ///< readings the brick flagged not valid
    double last_cycle_seconds = 0.0;
    double mean_cycle_seconds = 0.0;  ///< mean interval between frames since connect
    double max_cycle_seconds = 0.0;
    std::optional<int> battery_millivolts;  ///< last GETBATTERYLEVEL
    /// Cycles per second (1 / mean cycle time), 0 before the first frame.
    double rate_hz() const { return mean_cycle_seconds > 0 ? 1.0 / mean_cycle_seconds : 0.0; }
};

class NxtLink final : public RobotLink {
  public:
    explicit NxtLink(NxtLinkOptions options);
    ~NxtLink() override;
    NxtLink(const NxtLink&) = delete;
    NxtLink& operator=(const NxtLink&) = delete;

    /// Opens the transport, checks the brick answers (KEEPALIVE, GETBATTERYLEVEL), sets the
    /// IR ports to raw A/D, resets both motors' RotationCount, starts the relay program in
    /// relay mode and waits for its first message. Throws LinkError saying what failed.
    void connect();
    /// Uses an already open stream (tests, emulators in the same process), then as connect().
    void connect(std::unique_ptr<ByteStream> stream);
    /// Stops the motors (coast to a standstill, then brake), stops the relay program and
    /// closes. Never throws.
    void disconnect();
    bool connected() const;

    /// One cycle: the replies of the oldest request in flight. nullopt on a timeout or a
    /// rejected reply (the loop predicts without a frame). Throws LinkError when the link
    /// fails (closed, or max_consecutive_timeouts): the motors have been told to stop and
    /// quality() says why. Throws LinkError if called while not connected.
    std::optional<SensorFrame> next_frame() override;
    /// Converts (V1, V2) m/s to speed-regulated motor power and sends it at once, no reply.
    /// Ignored while paused or not connected.
    void send_command(const WheelSpeeds& command) override;
    /// Both motors off now (best effort, no reply), e.g. on a stop button.
    void stop_motors();
    /// Paused: motors stopped and wheel commands ignored; frames keep coming.
    void set_paused(bool paused);

    /// A copy, from any thread.
    LinkQuality quality() const;
    const NxtLinkOptions& options() const { return options_; }

  private:
    using Clock = std::chrono::steady_clock;
    /// A cycle's request on its way: what replies it owes, in order.
    struct InFlight {
        Clock::time_point sent;
        std::vector<Opcode> replies;
    };

    void open_session();
    Telegram exchange(const Telegram& request, std::chrono::milliseconds timeout);
    void send_read_request();
    std::optional<SensorFrame> receive_cycle();
    SensorFrame frame_from_direct(std::span<const Telegram> replies);
    std::optional<SensorFrame> frame_from_relay(const Telegram& reply);
    void drain_owed_replies();
    void on_timeout(const std::string& what);
    [[noreturn]] void fail(const std::string& why);
    void send_stop_best_effort() noexcept;
    std::vector<Telegram> motor_commands(const WheelSpeeds& speeds) const;
    void set_state(LinkState state, const std::string& error = {});

    NxtLinkOptions options_;
    std::unique_ptr<ByteStream> stream_;
    std::vector<InFlight> in_flight_;  ///< oldest first
    std::size_t owed_replies_ = 0;     ///< replies of timed-out requests still to come
    bool paused_ = false;
    Clock::time_point next_read_at_;  ///< when the pipeline may take another read
    Clock::time_point connected_at_;
    Clock::time_point last_frame_at_;
    Clock::time_point first_frame_at_;
    Clock::time_point next_keep_alive_;
    Clock::time_point next_battery_;
    std::uint32_t next_sequence_ = 0;
    int consecutive_timeouts_ = 0;

    mutable std::mutex quality_mutex_;
    LinkQuality quality_;
};

}  // namespace legofeup::comms::nxt
