#include "nxt_choice.hpp"

#include <utility>

#include "legofeup/lessons/nxt_run.hpp"

namespace legofeup::cli {
namespace {

class LessonsNxtChoice final : public NxtChoice {
  public:
    explicit LessonsNxtChoice(lessons::NxtTarget target) : target_(std::move(target)) {}

    std::string address() const override { return target_.link.address.to_string(); }
    void apply_profile(const lessons::RobotProfile& profile) override {
        lessons::apply_robot_profile(profile, target_);
    }
    std::unique_ptr<lessons::RobotConnection> connect() const override {
        return lessons::connect_nxt(target_);
    }
    nlohmann::json to_json() const override {
        return {
            {"kind", "nxt"},
            {"address", address()},
            {"mode", target_.link.mode == comms::nxt::CycleMode::Relay ? "relay" : "direct"},
            {"truth", target_.truth ? target_.truth->to_string() : "unknown (real robot)"},
        };
    }

  private:
    lessons::NxtTarget target_;
};

}  // namespace

std::unique_ptr<NxtChoice> choose_nxt(const RunOptions& options) {
    if (!lessons::is_nxt_link(options.link)) {
        return nullptr;
    }
    return std::make_unique<LessonsNxtChoice>(
        lessons::parse_nxt_target(options.link, options.relay, options.truth_url));
}

}  // namespace legofeup::cli
