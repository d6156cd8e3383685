// The registry's "nxt" entry in a build without the NXT (LEGOFEUP_WITH_NXT=OFF): it still
// knows an NXT's addresses (nxt_link_text.hpp), so that they, --relay and --truth are
// refused with the reason rather than taken for something else.
#include <string>

#include "built_in_link_kinds.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/nxt_link_text.hpp"

namespace legofeup::lessons {
namespace {

std::unique_ptr<LinkPlan> refuse_nxt(const LinkRequest& request) {
    throw InputError({{"", 0, "--link", request.address, std::string(kNoNxtSupport)}});
}

void refuse_options_in_this_build(const LinkRequest& request) {
    refuse_nxt_options(request, kNoNxtSupport);
}

}  // namespace

const LinkKind& nxt_link_kind() {
    static const LinkKind kind{"nxt", "bt:…, serial:… or tcp:… (a LEGO NXT; not in this build)",
                               &is_nxt_link, &refuse_nxt, &refuse_options_in_this_build};
    return kind;
}

}  // namespace legofeup::lessons
