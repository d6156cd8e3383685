// The sequence window: new, duplicate and late arrivals and the missing count, case by case
// and over a simulated lossy channel whose drops, duplicates and reorders are counted.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "legofeup/comms/sequence_window.hpp"

namespace legofeup::comms {
namespace {

void expect_counts(const SequenceWindow& window, std::uint64_t accepted, std::uint64_t duplicate,
                   std::uint64_t late, std::uint64_t missing) {
    const SequenceCounts& counts = window.counts();
    EXPECT_EQ(counts.accepted, accepted);
    EXPECT_EQ(counts.duplicate, duplicate);
    EXPECT_EQ(counts.late, late);
    EXPECT_EQ(counts.missing, missing);
}

TEST(SequenceWindow, StartsEmpty) {
    const SequenceWindow window;
    EXPECT_FALSE(window.started());
    expect_counts(window, 0, 0, 0, 0);
    EXPECT_EQ(SequenceWindow::kWindow, 64U);
}

TEST(SequenceWindow, InOrderPacketsAreAllNew) {
    SequenceWindow window;
    for (std::uint32_t sequence = 0; sequence < 1000; ++sequence) {
        ASSERT_EQ(window.classify(sequence), Arrival::New) << sequence;
        EXPECT_EQ(window.newest(), sequence);
    }
    EXPECT_TRUE(window.started());
    expect_counts(window, 1000, 0, 0, 0);
}

TEST(SequenceWindow, FirstPacketAtAnArbitrarySequence) {
    for (const std::uint32_t first : {0U, 1U, 452U, 123456789U, 0xFFFFFFF0U}) {
        SequenceWindow window;
        EXPECT_EQ(window.classify(first), Arrival::New) << first;
        EXPECT_TRUE(window.started());
        EXPECT_EQ(window.newest(), first);
        expect_counts(window, 1, 0, 0, 0);  // nothing before the first counts as missing
        EXPECT_EQ(window.classify(first + 1), Arrival::New);
        EXPECT_EQ(window.classify(first), Arrival::Duplicate);
        expect_counts(window, 2, 1, 0, 0);
    }
}

TEST(SequenceWindow, Duplicates) {
    SequenceWindow window;
    EXPECT_EQ(window.classify(10), Arrival::New);
    EXPECT_EQ(window.classify(10), Arrival::Duplicate);  // the newest itself
    EXPECT_EQ(window.classify(11), Arrival::New);
    EXPECT_EQ(window.classify(12), Arrival::New);
    EXPECT_EQ(window.classify(11), Arrival::Duplicate);
    EXPECT_EQ(window.classify(10), Arrival::Duplicate);
    EXPECT_EQ(window.classify(12), Arrival::Duplicate);
    EXPECT_EQ(window.newest(), 12U);
    expect_counts(window, 3, 4, 0, 0);
}

TEST(SequenceWindow, GapsCountAsMissing) {
    SequenceWindow window;
    EXPECT_EQ(window.classify(0), Arrival::New);
    EXPECT_EQ(window.classify(5), Arrival::New);  // 1–4 skipped
    expect_counts(window, 2, 0, 0, 4);
    EXPECT_EQ(window.classify(6), Arrival::New);
    EXPECT_EQ(window.classify(8), Arrival::New);  // 7 skipped
    expect_counts(window, 4, 0, 0, 5);
    EXPECT_EQ(window.newest(), 8U);
}

TEST(SequenceWindow, LateArrivalTakesItsNumberOffTheMissing) {
    SequenceWindow window;
    EXPECT_EQ(window.classify(0), Arrival::New);
    EXPECT_EQ(window.classify(2), Arrival::New);
    expect_counts(window, 2, 0, 0, 1);
    EXPECT_EQ(window.classify(1), Arrival::Late);
    expect_counts(window, 2, 0, 1, 0);
    EXPECT_EQ(window.newest(), 2U);  // a late packet does not move the window
    // Once seen, the late one is a duplicate.
    EXPECT_EQ(window.classify(1), Arrival::Duplicate);
    expect_counts(window, 2, 1, 1, 0);

    // Several holes filled in any order.
    EXPECT_EQ(window.classify(10), Arrival::New);  // 3–9 missing
    expect_counts(window, 3, 1, 1, 7);
    for (const std::uint32_t sequence : {9U, 3U, 6U}) {
        EXPECT_EQ(window.classify(sequence), Arrival::Late) << sequence;
    }
    expect_counts(window, 3, 1, 4, 4);
    EXPECT_EQ(window.classify(6), Arrival::Duplicate);
    EXPECT_EQ(window.classify(4), Arrival::Late);
    expect_counts(window, 3, 2, 5, 3);
}

TEST(SequenceWindow, EdgeOfTheWindow) {
    // 63 behind the newest is still inside the 64-packet window…
    SequenceWindow window;
    EXPECT_EQ(window.classify(0), Arrival::New);
    EXPECT_EQ(window.classify(63), Arrival::New);
    expect_counts(window, 2, 0, 0, 62);
    EXPECT_EQ(window.classify(0), Arrival::Duplicate);
    EXPECT_EQ(window.classify(1), Arrival::Late);
    expect_counts(window, 2, 1, 1, 61);

    // …64 behind is outside: counted late, and it stays missing.
    SequenceWindow outside;
    EXPECT_EQ(outside.classify(0), Arrival::New);
    EXPECT_EQ(outside.classify(65), Arrival::New);
    expect_counts(outside, 2, 0, 0, 64);
    EXPECT_EQ(outside.classify(2), Arrival::Late);  // age 63: inside
    expect_counts(outside, 2, 0, 1, 63);
    EXPECT_EQ(outside.classify(1), Arrival::Late);  // age 64: outside
    expect_counts(outside, 2, 0, 2, 63);
}

TEST(SequenceWindow, JumpBeyondTheWindow) {
    SequenceWindow window;
    for (std::uint32_t sequence = 0; sequence < 10; ++sequence) {
        EXPECT_EQ(window.classify(sequence), Arrival::New);
    }
    EXPECT_EQ(window.classify(200), Arrival::New);  // 10–199 skipped: 190
    expect_counts(window, 11, 0, 0, 190);
    EXPECT_EQ(window.newest(), 200U);
    // The bits of the old packets are gone: nothing inside the new window was seen.
    EXPECT_EQ(window.classify(199), Arrival::Late);
    EXPECT_EQ(window.classify(137), Arrival::Late);  // age 63
    expect_counts(window, 11, 0, 2, 188);
    // Older than the window: late, and missing keeps them (whether received or not).
    EXPECT_EQ(window.classify(136), Arrival::Late);  // age 64
    EXPECT_EQ(window.classify(9), Arrival::Late);    // received before the jump
    EXPECT_EQ(window.classify(50), Arrival::Late);
    expect_counts(window, 11, 0, 5, 188);
    EXPECT_EQ(window.classify(200), Arrival::Duplicate);
    EXPECT_EQ(window.classify(201), Arrival::New);
    expect_counts(window, 12, 1, 5, 188);
}

// Serial-number arithmetic (RFC 1982, docs/protocol.md): a stream may wrap past 2³² − 1.
TEST(SequenceWindow, WrapsPastTheLargestSequence) {
    SequenceWindow window;
    for (std::uint32_t sequence = 0xFFFFFFFCU; sequence != 3U; ++sequence) {
        ASSERT_EQ(window.classify(sequence), Arrival::New) << sequence;
    }
    EXPECT_EQ(window.newest(), 2U);
    expect_counts(window, 7, 0, 0, 0);
    EXPECT_EQ(window.classify(0xFFFFFFFFU), Arrival::Duplicate);  // 3 behind 2
    EXPECT_EQ(window.classify(0xFFFFFFFCU), Arrival::Duplicate);
    expect_counts(window, 7, 2, 0, 0);
}

TEST(SequenceWindow, GapsAndLateArrivalsAcrossTheWrap) {
    SequenceWindow window;
    EXPECT_EQ(window.classify(0xFFFFFFFDU), Arrival::New);
    EXPECT_EQ(window.classify(2U), Arrival::New);  // FFFFFFFE, FFFFFFFF, 0, 1 skipped
    expect_counts(window, 2, 0, 0, 4);
    EXPECT_EQ(window.classify(0xFFFFFFFFU), Arrival::Late);
    EXPECT_EQ(window.classify(0U), Arrival::Late);
    expect_counts(window, 2, 0, 2, 2);
    EXPECT_EQ(window.classify(0U), Arrival::Duplicate);
    EXPECT_EQ(window.classify(0xFFFFFFFDU), Arrival::Duplicate);
    expect_counts(window, 2, 2, 2, 2);
}

TEST(SequenceWindow, NewerMeansLessThanHalfTheNumberSpaceAhead) {
    // 2³¹ − 1 ahead is newer…
    SequenceWindow ahead;
    EXPECT_EQ(ahead.classify(10), Arrival::New);
    EXPECT_EQ(ahead.classify(10 + 0x7FFFFFFFU), Arrival::New);
    expect_counts(ahead, 2, 0, 0, 0x7FFFFFFEULL);
    // …2³¹ ahead is older: far outside the window, counted late.
    SequenceWindow half;
    EXPECT_EQ(half.classify(10), Arrival::New);
    EXPECT_EQ(half.classify(10 + 0x80000000U), Arrival::Late);
    expect_counts(half, 1, 0, 1, 0);
    EXPECT_EQ(half.newest(), 10U);
    // 0xFFFFFFFF right after 0 is one behind, not 2³² − 1 ahead.
    SequenceWindow behind;
    EXPECT_EQ(behind.classify(0), Arrival::New);
    EXPECT_EQ(behind.classify(0xFFFFFFFFU), Arrival::Late);
    expect_counts(behind, 1, 0, 1, 0);
}

// The stream runs on for more than 2³¹ numbers past its first packet (3.4 years of 20 Hz,
// or a few large jumps, each < 2³¹ and so newer): a packet reordered inside the window
// must still take its number off the missing.
TEST(SequenceWindow, LateArrivalFarIntoALongStream) {
    SequenceWindow window;
    EXPECT_EQ(window.classify(0), Arrival::New);
    EXPECT_EQ(window.classify(0x7FFFFFF0U), Arrival::New);
    EXPECT_EQ(window.classify(0x80000010U), Arrival::New);
    expect_counts(window, 3, 0, 0, 0x8000000EULL);
    EXPECT_EQ(window.classify(0x80000005U), Arrival::Late);  // 11 behind the newest
    expect_counts(window, 3, 0, 1, 0x8000000DULL);
}

TEST(SequenceWindow, RestartForgetsTheStreamButKeepsTheCounts) {
    SequenceWindow window;
    EXPECT_EQ(window.classify(100), Arrival::New);
    EXPECT_EQ(window.classify(103), Arrival::New);  // 101, 102 missing
    EXPECT_EQ(window.classify(103), Arrival::Duplicate);
    EXPECT_EQ(window.classify(101), Arrival::Late);
    expect_counts(window, 2, 1, 1, 1);

    window.restart();
    EXPECT_FALSE(window.started());
    expect_counts(window, 2, 1, 1, 1);

    // A new peer starting lower: new, not late; no gap to the old stream.
    EXPECT_EQ(window.classify(5), Arrival::New);
    EXPECT_TRUE(window.started());
    EXPECT_EQ(window.newest(), 5U);
    expect_counts(window, 3, 1, 1, 1);
    // Its own numbers are classified afresh; the old stream's 103 is not "seen".
    EXPECT_EQ(window.classify(5), Arrival::Duplicate);
    EXPECT_EQ(window.classify(7), Arrival::New);
    EXPECT_EQ(window.classify(6), Arrival::Late);
    expect_counts(window, 4, 2, 2, 1);
    EXPECT_EQ(window.classify(103), Arrival::New);  // far ahead of 7: 95 skipped
    expect_counts(window, 5, 2, 2, 96);

    // Restarting at a higher number adds no missing either.
    window.restart();
    EXPECT_EQ(window.classify(100000), Arrival::New);
    expect_counts(window, 6, 2, 2, 96);
}

// A packet numbered below the first one the window saw was reordered with it: it is late,
// and it was never counted missing, so missing must not change (docs/protocol.md: "when
// one of them turns up late it is taken off again" — only numbers counted missing).
TEST(SequenceWindow, OlderThanTheFirstPacketIsLateWithoutTouchingMissing) {
    SequenceWindow window;
    EXPECT_EQ(window.classify(1), Arrival::New);  // packets 0 and 1 swapped on the way
    EXPECT_EQ(window.classify(0), Arrival::Late);
    expect_counts(window, 1, 0, 1, 0);
    EXPECT_EQ(window.classify(2), Arrival::New);
    expect_counts(window, 2, 0, 1, 0);
}

TEST(SequenceWindow, OlderThanTheFirstPacketAfterARestart) {
    SequenceWindow window;
    EXPECT_EQ(window.classify(0), Arrival::New);
    EXPECT_EQ(window.classify(3), Arrival::New);  // 1, 2 missing (really lost)
    expect_counts(window, 2, 0, 0, 2);
    window.restart();
    EXPECT_EQ(window.classify(11), Arrival::New);  // the new peer's 10 and 11 swapped
    EXPECT_EQ(window.classify(10), Arrival::Late);
    expect_counts(window, 3, 0, 1, 2);  // the old stream's two losses stay counted
}

// --- A lossy channel ---------------------------------------------------------------------------

struct Delivery {
    std::uint32_t sequence;
    Arrival expected;
};

/// What the channel did, counted as it did it.
struct ChannelLog {
    std::vector<Delivery> deliveries;
    std::uint64_t sent = 0;        ///< distinct packets delivered in order
    std::uint64_t dropped = 0;     ///< lost for good
    std::uint64_t duplicated = 0;  ///< extra copies delivered
    std::uint64_t reordered = 0;   ///< held back and delivered after a newer packet
    std::uint32_t numbers = 0;     ///< sequence numbers used
    std::uint32_t largest_hold = 0;
};

/// Sends `body` packets through a channel that drops 30 %, duplicates 10 % (the copy right
/// behind the original) and reorders 10 % by one (the packet is held and delivered right
/// after the next packet actually delivered). The first packet and a short tail go through
/// unharmed: the window starts at the first packet it receives (a loss before it cannot
/// be seen), and a loss after the last delivered packet leaves no gap to see either.
ChannelLog simulate_channel(std::uint64_t seed, std::uint32_t first, std::uint32_t body,
                            std::uint32_t tail) {
    std::mt19937_64 rng(seed);
    std::bernoulli_distribution drop(0.30);
    std::bernoulli_distribution duplicate(0.10);
    std::bernoulli_distribution reorder(0.10);

    ChannelLog log;
    bool holding = false;
    std::uint32_t held = 0;
    const auto deliver = [&](std::uint32_t sequence) {
        log.deliveries.push_back({sequence, Arrival::New});
        ++log.sent;
    };
    const auto release_held = [&](std::uint32_t newest) {
        if (holding) {
            log.largest_hold = std::max(log.largest_hold, newest - held);
            log.deliveries.push_back({held, Arrival::Late});
            holding = false;
        }
    };

    std::uint32_t sequence = first;
    deliver(sequence++);  // the clean head
    for (std::uint32_t i = 0; i < body; ++i, ++sequence) {
        if (drop(rng)) {
            ++log.dropped;
            continue;
        }
        if (!holding && reorder(rng)) {
            holding = true;
            held = sequence;
            ++log.reordered;
            continue;
        }
        deliver(sequence);
        if (duplicate(rng)) {
            log.deliveries.push_back({sequence, Arrival::Duplicate});
            ++log.duplicated;
        }
        release_held(sequence);
    }
    for (std::uint32_t i = 0; i < tail; ++i, ++sequence) {
        deliver(sequence);
        release_held(sequence);
    }
    log.numbers = sequence - first;
    return log;
}

TEST(SequenceWindow, LossyChannelCountsExactlyWhatTheChannelDid) {
    for (const std::uint64_t seed : {1ULL, 2ULL, 3ULL, 4ULL, 20240501ULL, 0xC0FFEEULL}) {
        SCOPED_TRACE(seed);
        // Some streams start just before the wrap past 2³² − 1 and cross it.
        const std::uint32_t first = seed % 2 == 0
                                        ? static_cast<std::uint32_t>(seed * 7919U) % 100000U
                                        : 0xFFFFFFFFU - static_cast<std::uint32_t>(seed % 5000U);
        const ChannelLog log = simulate_channel(seed, first, 10000, 5);

        // The channel really was as lossy as intended: 30 % of 10 000 dropped (σ ≈ 46), about
        // 0.7 · 0.1 of them held back and 0.7 · 0.9 · 0.1 duplicated (σ ≈ 25 each).
        EXPECT_GT(log.dropped, 2800U);
        EXPECT_LT(log.dropped, 3200U);
        EXPECT_GT(log.reordered, 500U);
        EXPECT_LT(log.reordered, 800U);
        EXPECT_GT(log.duplicated, 500U);
        EXPECT_LT(log.duplicated, 800U);
        // The window's promise holds only while no packet is held back 64 numbers or more.
        ASSERT_LT(log.largest_hold, SequenceWindow::kWindow);
        ASSERT_EQ(log.sent + log.reordered + log.dropped, log.numbers);

        SequenceWindow window;
        for (std::size_t i = 0; i < log.deliveries.size(); ++i) {
            const Delivery& delivery = log.deliveries[i];
            ASSERT_EQ(window.classify(delivery.sequence), delivery.expected)
                << "delivery " << i << ", sequence " << delivery.sequence;
        }
        const SequenceCounts& counts = window.counts();
        EXPECT_EQ(counts.accepted, log.sent);
        EXPECT_EQ(counts.duplicate, log.duplicated);
        EXPECT_EQ(counts.late, log.reordered);
        EXPECT_EQ(counts.missing, log.dropped);
        EXPECT_EQ(window.newest(), first + log.numbers - 1);
    }
}

TEST(SequenceWindow, LossyChannelWithoutItsTailLeavesTheLastLossesUnseen) {
    // The tail matters: without it, drops after the last delivered packet leave no gap, so
    // missing can be less than the drops but never more.
    const ChannelLog log = simulate_channel(7, 0, 10000, 0);
    SequenceWindow window;
    for (const Delivery& delivery : log.deliveries) {
        window.classify(delivery.sequence);
    }
    EXPECT_LE(window.counts().missing, log.dropped);
    EXPECT_EQ(window.counts().missing, static_cast<std::uint64_t>(window.newest()) + 1
                                           - window.counts().accepted - window.counts().late);
}

}  // namespace
}  // namespace legofeup::comms
