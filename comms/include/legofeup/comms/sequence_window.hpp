#pragma once
// Classifies the sequence numbers arriving on one stream, like IPsec's anti-replay window:
// new (newer than all before), duplicate (already seen) or late (older, unseen: reordered).
// Gaps count as missing until a late packet fills them. Over a lossy link with duplicates
// and reordering, missing = lost, duplicate = duplicated and late = reordered exactly, as
// long as no packet is held back more than kWindow sequence numbers.

#include <cstdint>

namespace legofeup::comms {

enum class Arrival : std::uint8_t { New, Duplicate, Late };

struct SequenceCounts {
    std::uint64_t accepted = 0;
    std::uint64_t duplicate = 0;
    std::uint64_t late = 0;
    std::uint64_t missing = 0;
};

class SequenceWindow {
  public:
    static constexpr std::uint32_t kWindow = 64;

    Arrival classify(std::uint32_t sequence);
    /// Forget the stream (a new peer); the counts are kept.
    void restart() { started_ = false; }

    const SequenceCounts& counts() const { return counts_; }
    std::uint32_t newest() const { return newest_; }
    bool started() const { return started_; }

  private:
    bool started_ = false;
    /// How many numbers before newest_ belong to this stream (at most kWindow): a late
    /// packet within them was counted missing, one before the stream's first was not.
    std::uint32_t history_ = 0;
    std::uint32_t newest_ = 0;
    std::uint64_t seen_ = 0;  ///< bit i: newest_ − i was received
    SequenceCounts counts_;
};

}  // namespace legofeup::comms
