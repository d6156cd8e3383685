// The registry's "nxt" entry in a build with the NXT: a LEGO NXT, real or emulated, at
// bt:XX:XX:XX:XX:XX:XX, serial:DEVICE or tcp:HOST:PORT, with --relay for the relay program
// and --truth for an emulated brick's ground truth (docs/nxt.md).
#include <utility>

#include "built_in_link_kinds.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/nxt_run.hpp"

namespace legofeup::lessons {
namespace {

class NxtLinkPlan final : public LinkPlan {
  public:
    explicit NxtLinkPlan(NxtTarget target) : target_(std::move(target)) {}

    std::string describe() const override { return target_.link.address.to_string(); }
    void apply_profile(const RobotProfile& profile) override {
        apply_robot_profile(profile, target_);
    }
    std::unique_ptr<RobotConnection> connect(const ResolvedRun& /*run*/) const override {
        return connect_nxt(target_);  // the run's robot is the brick's own
    }

  private:
    NxtTarget target_;
};

std::unique_ptr<LinkPlan> plan_nxt(const LinkRequest& request) {
    return std::make_unique<NxtLinkPlan>(
        parse_nxt_target(request.address, request.relay, request.truth_url));
}

void refuse_options_for_other_links(const LinkRequest& request) {
    refuse_nxt_options(request, "only applies to an NXT link (--link bt:…, serial:… or tcp:…)");
}

}  // namespace

const LinkKind& nxt_link_kind() {
    static const LinkKind kind{"nxt",
                               "bt:XX:XX:XX:XX:XX:XX, serial:DEVICE or tcp:HOST:PORT (a LEGO NXT)",
                               &is_nxt_link, &plan_nxt, &refuse_options_for_other_links};
    return kind;
}

}  // namespace legofeup::lessons
