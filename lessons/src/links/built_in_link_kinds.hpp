#pragma once
// The entries of built_in_links(), each defined in its own file: udp_link_kind.cpp, and
// nxt_link_kind.cpp in a build with the NXT or no_nxt_link_kind.cpp in one without.

#include <string>
#include <string_view>

#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/links/link_kind.hpp"

namespace legofeup::lessons {

const LinkKind& udp_link_kind();
const LinkKind& nxt_link_kind();

/// The nxt entry's refuse_own_options in both builds: --relay and --truth, refused for any
/// other link with `why` (only an NXT takes them; or this build has no NXT).
inline void refuse_nxt_options(const LinkRequest& request, std::string_view why) {
    if (request.relay) {
        throw InputError({{"", 0, "--relay", "", std::string(why)}});
    }
    if (!request.truth_url.empty()) {
        throw InputError({{"", 0, "--truth", request.truth_url, std::string(why)}});
    }
}

}  // namespace legofeup::lessons
