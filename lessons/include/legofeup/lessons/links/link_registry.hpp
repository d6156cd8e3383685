#pragma once
// Every kind of link, in one explicit list (as built_in_lessons() lists the lessons):
// udp (a simulator server, docs/protocol.md) and nxt (a LEGO NXT, docs/nxt.md). In a build
// without the NXT (LEGOFEUP_WITH_NXT=OFF) the nxt entry is still there, so that an NXT
// address is recognised, and refuses it with the reason. The CLI and the GUI both plan
// their links here. Adding a kind: its own files (a LinkKind, a LinkPlan, a RobotConnection)
// and one line in built_in_links().
//
// "lockstep" is no link: the in-process simulator, stepped by the loop itself
// (lockstep_run.hpp); plan_link() checks its options and returns no plan for it.

#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "legofeup/lessons/links/link_kind.hpp"

namespace legofeup::lessons {

inline constexpr std::string_view kLockstepLink = "lockstep";

/// The registry, in the order the help and the errors list it.
std::span<const LinkKind* const> built_in_links();

/// The kind that takes `address`, or null when none does.
const LinkKind* link_kind_for(std::string_view address);

/// "lockstep (…); udp://a.b.c.d:port (…); bt:XX:XX:XX:XX:XX:XX, serial:DEVICE or
/// tcp:HOST:PORT (a LEGO NXT)": every address there is, for help texts and errors.
std::string link_forms();

/// The plan for `request`, or null for lockstep. Throws InputError naming the option and
/// its value: an address no kind takes (the message lists every form), an address its kind
/// finds malformed, or an option of another kind's.
std::unique_ptr<LinkPlan> plan_link(const LinkRequest& request);

}  // namespace legofeup::lessons
