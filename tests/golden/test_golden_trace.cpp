// Golden determinism: the trace of experiment f, seed 1, run in lockstep in-process, must be
// the one pinned in tests/golden/experiment_f_seed1.hash, hash for hash. Two runs of one
// build agreeing (tests/lessons/test_run_outputs.cpp) does not show that a new compiler,
// libm, Box2D or optimisation level left every trajectory alone; this does, as Box2D's own
// determinism test pins its hash. golden_trace.hpp says what is hashed (FNV-1a 64 of
// trace.csv's bytes as `legofeup-cli run -e f --seed 1` writes them, and of the bit patterns
// of the poses and covariances the CSV rounds to 9 digits).
//
// When a change is meant to move the trajectories, renew the pinned file with
//     scripts/renew-golden.sh
// (it builds this test, rewrites the file and prints the old and new hashes) and commit the
// file with the change. docs/experiments.md, "Golden trace", says the same.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "golden_trace.hpp"
#include "trace_hash_test_support.hpp"

namespace legofeup::lessons::golden_testing {
namespace {

using hash_testing::fnv1a_64;

std::string read_text(const char* path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw std::runtime_error(std::string("cannot read ") + path);
    }
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(GoldenTrace, ExperimentFSeed1IsThePinnedTrace) {
    std::string csv;
    const TraceFingerprint now = golden_run_fingerprint(&csv);
    ASSERT_EQ(now.trace, fnv1a_64(csv));
    ASSERT_GT(now.rows, 1000u);  // a whole run of experiment f, not an empty trace

    const TraceFingerprint pinned =
        parse_pinned_text(read_text(LEGOFEUP_GOLDEN_FILE), LEGOFEUP_GOLDEN_FILE);
    EXPECT_TRUE(pinned == now)
        << "The trace of experiment f, seed 1 is not the pinned one (" << LEGOFEUP_GOLDEN_FILE
        << "):\n"
        << describe_change(pinned, now)
        << "This build computes other trajectories than the build that pinned them: a change "
           "of the code's arithmetic, of its order of operations, of the compiler or its flags, "
           "of libm or of Box2D. If the change is meant, renew the pinned file with "
        << kRenewCommand
        << " and commit it with the change; if not, find what moved (the changed columns say "
           "whether the simulator's truth, the odometry or the filter did).";
}

// The hash is FNV-1a 64 as published (Fowler–Noll–Vo test vectors), so that anyone can
// recompute the pinned trace hash from the CLI's trace.csv with another implementation.
TEST(GoldenTrace, HashIsFnv1a64) {
    EXPECT_EQ(fnv1a_64(""), 0xcbf29ce484222325ULL);
    EXPECT_EQ(fnv1a_64("a"), 0xaf63dc4c8601ec8cULL);
    EXPECT_EQ(fnv1a_64("foobar"), 0x85944171f73967e8ULL);
}

constexpr const char* kSmallTrace = "t,x_true,x_est\n0.05,1,1.1\n0.1,2,2.1\n";

TEST(GoldenTrace, PinnedTextReadsBackWhatWasWritten) {
    TraceFingerprint fingerprint = text_fingerprint(kSmallTrace);
    fingerprint.bits = 0x0123456789abcdefULL;
    EXPECT_EQ(fingerprint.rows, 2u);
    EXPECT_EQ(fingerprint.columns.size(), 3u);
    EXPECT_EQ(fingerprint.columns.at("x_true"), fnv1a_64("1\n2\n"));
    EXPECT_EQ(parse_pinned_text(to_pinned_text(fingerprint), "pinned.hash"), fingerprint);
}

TEST(GoldenTrace, UnreadablePinnedTextNamesTheFileLineAndValue) {
    const auto message_of = [](const std::string& text) {
        try {
            parse_pinned_text(text, "pinned.hash");
        } catch (const std::runtime_error& error) {
            return std::string(error.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message_of("# comment\ntrace 12345\nbits 0000000000000000\nrows 1\n"),
              "pinned.hash:2: \"12345\" is not a hash (16 lower-case hexadecimal digits)");
    EXPECT_EQ(message_of("trace 0000000000000000\nbits 0000000000000000\nrows 1\nsum 7\n"),
              "pinned.hash:4: \"sum 7\": expected \"trace <hash>\", \"bits <hash>\", "
              "\"rows <count>\" or \"column <name> <hash>\"");
    EXPECT_EQ(message_of("trace 0000000000000000\nrows 1\n"),
              "pinned.hash: the trace, bits and rows lines are all required");
}

TEST(GoldenTrace, ChangeNamesTheHashesRowsAndColumnsThatMoved) {
    const TraceFingerprint pinned = text_fingerprint(kSmallTrace);
    EXPECT_EQ(describe_change(pinned, pinned), "");

    // One estimate moved: the trace hash and the x_est column, nothing else.
    const TraceFingerprint estimate = text_fingerprint("t,x_true,x_est\n0.05,1,1.1\n0.1,2,2.2\n");
    const std::string change = describe_change(pinned, estimate);
    EXPECT_NE(change.find("trace.csv hash: "), std::string::npos) << change;
    EXPECT_NE(change.find("columns changed: x_est\n"), std::string::npos) << change;
    EXPECT_EQ(change.find("rows"), std::string::npos) << change;
    EXPECT_EQ(change.find("x_true"), std::string::npos) << change;

    // A longer run with a renamed column.
    const TraceFingerprint longer =
        text_fingerprint("t,x_true,x_odo\n0.05,1,1.1\n0.1,2,2.1\n0.15,3,3.1\n");
    const std::string other = describe_change(pinned, longer);
    EXPECT_NE(other.find("rows: 2 -> 3\n"), std::string::npos) << other;
    EXPECT_NE(other.find("columns changed: t x_true\n"), std::string::npos) << other;
    EXPECT_NE(other.find("columns no longer written: x_est\n"), std::string::npos) << other;
    EXPECT_NE(other.find("columns new: x_odo\n"), std::string::npos) << other;
}

}  // namespace
}  // namespace legofeup::lessons::golden_testing
