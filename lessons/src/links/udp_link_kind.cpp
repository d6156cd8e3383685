// The registry's "udp" entry: a simulator server (legofeup-sim, or the GUI's embedded one)
// at udp://a.b.c.d:port, its truth and control streams on the next two ports unless
// --truth-port and --control-port say otherwise (docs/protocol.md).
#include <utility>

#include "built_in_link_kinds.hpp"
#include "legofeup/lessons/udp_run.hpp"

namespace legofeup::lessons {
namespace {

class UdpLinkPlan final : public LinkPlan {
  public:
    explicit UdpLinkPlan(UdpTarget target) : target_(std::move(target)) {}

    std::string describe() const override { return "udp://" + target_.robot.to_string(); }
    void apply_profile(const RobotProfile& /*profile*/) override {}  // no wiring to set
    std::unique_ptr<RobotConnection> connect(const ResolvedRun& run) const override {
        return std::make_unique<UdpRobotConnection>(run, target_);
    }

  private:
    UdpTarget target_;
};

bool takes_udp(std::string_view address) {
    return address.starts_with("udp://");
}

std::unique_ptr<LinkPlan> plan_udp(const LinkRequest& request) {
    return std::make_unique<UdpLinkPlan>(
        parse_udp_target(request.address, request.truth_port, request.control_port));
}

void refuse_no_udp_options(const LinkRequest& /*request*/) {
    // --truth-port and --control-port default to 0 and mean nothing to the other kinds.
}

}  // namespace

const LinkKind& udp_link_kind() {
    static const LinkKind kind{"udp", "udp://a.b.c.d:port (a simulator server's robot port)",
                               &takes_udp, &plan_udp, &refuse_no_udp_options};
    return kind;
}

}  // namespace legofeup::lessons
