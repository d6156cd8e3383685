// A build without the NXT (LEGOFEUP_WITH_NXT=OFF): an NXT link, --relay or --truth is bad
// input, refused like any other, with the reason.
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/nxt_link_text.hpp"
#include "nxt_choice.hpp"

namespace legofeup::cli {

std::unique_ptr<NxtChoice> choose_nxt(const RunOptions& options) {
    const std::string reason(lessons::kNoNxtSupport);
    if (lessons::is_nxt_link(options.link)) {
        throw lessons::InputError({{"", 0, "--link", options.link, reason}});
    }
    if (options.relay) {
        throw lessons::InputError({{"", 0, "--relay", "", reason}});
    }
    if (!options.truth_url.empty()) {
        throw lessons::InputError({{"", 0, "--truth", options.truth_url, reason}});
    }
    return nullptr;
}

}  // namespace legofeup::cli
