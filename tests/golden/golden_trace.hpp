// The golden run: experiment f, seed 1, in lockstep, as `legofeup-cli run -e f --seed 1`
// runs it, and the fingerprint of its trace that tests/golden/experiment_f_seed1.hash pins
// (docs/experiments.md, "Golden trace").
//
// The fingerprint, every hash FNV-1a 64 (trace_hash_test_support.hpp):
//   trace     the bytes of trace.csv exactly as the CLI writes them;
//   bits      the IEEE-754 bit patterns (8 bytes each, least significant first) of each
//             step's true pose, estimate, covariance (upper triangle) and dead-reckoning
//             pose, and the frame's encoder counts and IR A/D values (4 and 2 bytes): a
//             change below trace.csv's 9 significant digits shows here;
//   rows      the number of rows after the header;
//   column c  the cells of column c, each followed by '\n': which columns changed tells
//             whether the simulator (x_true…), the odometry (x_odo…) or the filter moved.
#pragma once

#include <cstdint>
#include <map>
#include <string>

namespace legofeup::lessons::golden_testing {

struct TraceFingerprint {
    std::uint64_t trace = 0;
    std::uint64_t bits = 0;
    std::uint64_t rows = 0;
    std::map<std::string, std::uint64_t> columns;  ///< by column name

    bool operator==(const TraceFingerprint&) const = default;
};

/// Runs the golden run; its trace.csv text and its fingerprint.
TraceFingerprint golden_run_fingerprint(std::string* trace_csv = nullptr);

/// The hashes and row and column counts of a trace's text; `bits` is left 0.
TraceFingerprint text_fingerprint(const std::string& trace_csv);

/// The pinned file's text: a comment naming what it pins and the renew command, then one
/// `name value` line per hash (hashes as 16 hexadecimal digits).
std::string to_pinned_text(const TraceFingerprint& fingerprint);
/// Reads what to_pinned_text wrote (lines starting with '#' are comments). Throws
/// std::runtime_error naming `file`:line, the line and what is wrong with it.
TraceFingerprint parse_pinned_text(const std::string& text, const std::string& file);

/// What differs between the pinned and the computed fingerprint, in words: the hashes old →
/// new, the rows, and the columns that changed, appeared or disappeared. Empty when equal.
std::string describe_change(const TraceFingerprint& pinned, const TraceFingerprint& now);

/// The one command that renews the pinned file.
inline constexpr const char* kRenewCommand = "scripts/renew-golden.sh";

}  // namespace legofeup::lessons::golden_testing
