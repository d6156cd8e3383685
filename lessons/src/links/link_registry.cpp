#include "legofeup/lessons/links/link_registry.hpp"

#include <array>

#include "built_in_link_kinds.hpp"
#include "legofeup/lessons/input_error.hpp"

namespace legofeup::lessons {

std::span<const LinkKind* const> built_in_links() {
    static const std::array<const LinkKind*, 2> kinds = {&udp_link_kind(), &nxt_link_kind()};
    return kinds;
}

const LinkKind* link_kind_for(std::string_view address) {
    for (const LinkKind* kind : built_in_links()) {
        if (kind->takes(address)) {
            return kind;
        }
    }
    return nullptr;
}

std::string link_forms() {
    std::string forms = std::string(kLockstepLink) + " (the simulator inside the program)";
    for (const LinkKind* kind : built_in_links()) {
        forms += "; ";
        forms += kind->forms;
    }
    return forms;
}

std::unique_ptr<LinkPlan> plan_link(const LinkRequest& request) {
    const LinkKind* chosen = link_kind_for(request.address);
    if (chosen == nullptr && request.address != kLockstepLink) {
        throw InputError({{"", 0, "--link", request.address, "expected one of: " + link_forms()}});
    }
    for (const LinkKind* kind : built_in_links()) {
        if (kind != chosen) {
            kind->refuse_own_options(request);
        }
    }
    return chosen != nullptr ? chosen->plan(request) : nullptr;
}

}  // namespace legofeup::lessons
