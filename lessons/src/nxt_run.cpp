#include "legofeup/lessons/nxt_run.hpp"

#include "legofeup/comms/truth_receiver.hpp"
#include "legofeup/lessons/input_error.hpp"

namespace legofeup::lessons {
namespace {

/// An emulated brick's truth, matched by arrival rather than by time stamp: the brick's
/// frames carry the host's clock, the truth stream the simulator's. The newest truth is at
/// most one simulator period (10 ms in legofeup-nxt-emu) plus the downlink latency older
/// than the readings it is compared with — a few millimetres at the robot's speeds.
class LatestTruth final : public TruthSource {
  public:
    explicit LatestTruth(const comms::Endpoint& server) : receiver_(server) {}
    std::optional<GroundTruth> truth_at(double time) override {
        receiver_.poll();
        std::optional<GroundTruth> truth = receiver_.latest();
        if (truth) {
            truth->time = time;
        }
        return truth;
    }

  private:
    comms::TruthReceiver receiver_;
};

LinkState state_of(comms::nxt::LinkState state) {
    switch (state) {
        case comms::nxt::LinkState::Connecting:
            return LinkState::Connecting;
        case comms::nxt::LinkState::Connected:
            return LinkState::Connected;
        case comms::nxt::LinkState::Failed:
            return LinkState::Failed;
        case comms::nxt::LinkState::Disconnected:
            break;
    }
    return LinkState::Disconnected;
}

/// The NXT link's quality in the words every link shares.
LinkHealth health_of(const comms::nxt::LinkQuality& quality,
                     const comms::nxt::NxtLinkOptions& options) {
    LinkHealth health;
    health.state = state_of(quality.state);
    health.address = options.address.to_string();
    health.last_error = quality.last_error;
    health.frames = quality.cycles;
    health.timeouts = quality.timeouts;
    health.rejected_replies = quality.rejected_replies;
    health.invalid_readings = quality.invalid_ir_readings;
    health.last_cycle_seconds = quality.last_cycle_seconds;
    health.mean_cycle_seconds = quality.mean_cycle_seconds;
    health.max_cycle_seconds = quality.max_cycle_seconds;
    health.battery_millivolts = quality.battery_millivolts;
    return health;
}

class NxtRobotConnection final : public RobotConnection {
  public:
    explicit NxtRobotConnection(const NxtTarget& target) : target_(target), link_(target.link) {
        if (target.truth) {
            truth_.emplace(*target.truth);
        }
        link_.connect();
    }
    ~NxtRobotConnection() override { close(); }
    NxtRobotConnection(const NxtRobotConnection&) = delete;
    NxtRobotConnection& operator=(const NxtRobotConnection&) = delete;

    RobotLink& robot_link() override { return link_; }
    TruthSource* truth_source() override { return truth_ ? &*truth_ : nullptr; }
    void set_noise(const RobotNoise& /*noise*/) override {}
    void set_paused(bool paused) override { link_.set_paused(paused); }
    std::string teleport(const Pose2& /*pose*/) override {
        return describe() + " is not a simulator";
    }
    void close() override { link_.disconnect(); }
    std::string describe() const override {
        return "NXT at " + link_.options().address.to_string() + " ("
               + (link_.options().mode == comms::nxt::CycleMode::Relay ? "relay program"
                                                                       : "direct commands")
               + ")";
    }
    /// The brick has no truth of its own (an emulated one's comes from its simulator), no
    /// noise to set and nobody to lift it; its clock runs on; it has a battery and a cycle.
    LinkCapabilities capabilities() const override {
        LinkCapabilities can;
        can.ground_truth = truth_.has_value();
        can.robot_health = true;
        return can;
    }
    LinkHealth health() const override { return health_of(link_.quality(), link_.options()); }
    /// kind "nxt", the address, the cycle mode, the truth, the cycle's timing and counters
    /// and the battery.
    nlohmann::json summary() override {
        const LinkHealth q = health();
        nlohmann::json json = {
            {"kind", "nxt"},
            {"address", link_.options().address.to_string()},
            {"mode", link_.options().mode == comms::nxt::CycleMode::Relay ? "relay" : "direct"},
            {"truth", target_.truth ? target_.truth->to_string() : "unknown (real robot)"},
            {"cycles", q.frames},
            {"rate_hz", q.rate_hz()},
            {"mean_cycle_s", q.mean_cycle_seconds},
            {"max_cycle_s", q.max_cycle_seconds},
            {"timeouts", q.timeouts},
            {"rejected_replies", q.rejected_replies},
            {"invalid_ir_readings", q.invalid_readings},
            {"battery_mv", q.battery_millivolts ? nlohmann::json(*q.battery_millivolts) : nullptr},
        };
        return json;
    }

  private:
    NxtTarget target_;
    std::optional<LatestTruth> truth_;
    comms::nxt::NxtLink link_;
};

}  // namespace

NxtTarget parse_nxt_target(const std::string& link, bool relay, const std::string& truth_url) {
    NxtTarget target;
    try {
        target.link.address = comms::nxt::parse_transport_address(link);
    } catch (const std::invalid_argument& error) {
        throw InputError({{"", 0, "--link", link, error.what()}});
    }
    target.link.mode = relay ? comms::nxt::CycleMode::Relay : comms::nxt::CycleMode::DirectCommands;
    if (!truth_url.empty()) {
        const auto truth = comms::parse_udp_url(truth_url);
        if (!truth || truth->port == 0) {
            throw InputError({{"", 0, "--truth", truth_url,
                               "expected udp://a.b.c.d:port (an emulated brick's truth port, "
                               "printed by legofeup-nxt-emu)"}});
        }
        target.truth = *truth;
    }
    return target;
}

void apply_robot_profile(const RobotProfile& profile, NxtTarget& target) {
    comms::nxt::NxtWiring& wiring = target.link.wiring;
    wiring.right_motor = static_cast<std::uint8_t>(profile.right_motor_port);
    wiring.left_motor = static_cast<std::uint8_t>(profile.left_motor_port);
    wiring.front_ir = static_cast<std::uint8_t>(profile.front_ir_port);
    wiring.rear_ir = static_cast<std::uint8_t>(profile.rear_ir_port);
    wiring.reversed_motors = profile.reversed_motors;
    wiring.power_per_meter_per_second = profile.power_per_meter_per_second;
    if (!profile.relay_program.empty()) {
        target.link.relay_program = profile.relay_program;
    }
}

std::unique_ptr<RobotConnection> connect_nxt(const NxtTarget& target) {
    return std::make_unique<NxtRobotConnection>(target);
}

}  // namespace legofeup::lessons
