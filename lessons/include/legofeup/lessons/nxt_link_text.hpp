#pragma once
// The link texts that name a LEGO NXT ("bt:…", "serial:…", "tcp:…", docs/nxt.md), known to
// every build: one built without the NXT (LEGOFEUP_WITH_NXT=OFF) still recognises them, to
// refuse them with kNoNxtSupport rather than take them for something else.

#include <array>
#include <string_view>

namespace legofeup::lessons {

/// The schemes of an NXT's transports: Bluetooth RFCOMM, a serial port, TCP.
inline constexpr std::array<std::string_view, 3> kNxtLinkSchemes = {"bt:", "serial:", "tcp:"};

/// True for the link texts that name an NXT.
constexpr bool is_nxt_link(std::string_view text) {
    for (const std::string_view scheme : kNxtLinkSchemes) {
        if (text.starts_with(scheme)) {
            return true;
        }
    }
    return false;
}

/// Why a build without the NXT refuses an NXT link or option (the reason of an InputError).
inline constexpr std::string_view kNoNxtSupport =
    "this build has no NXT support (built with LEGOFEUP_WITH_NXT=OFF)";

}  // namespace legofeup::lessons
