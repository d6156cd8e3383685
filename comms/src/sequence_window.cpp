#include "legofeup/comms/sequence_window.hpp"

namespace legofeup::comms {
namespace {

/// Serial-number arithmetic (RFC 1982): how far `a` is ahead of `b`, negative if behind,
/// correct across the wrap from 2³² − 1 to 0 as long as the two are < 2³¹ apart.
std::int32_t ahead_of(std::uint32_t a, std::uint32_t b) {
    return static_cast<std::int32_t>(a - b);
}

}  // namespace

Arrival SequenceWindow::classify(std::uint32_t sequence) {
    if (!started_) {
        started_ = true;
        history_ = 0;
        newest_ = sequence;
        seen_ = 1;
        ++counts_.accepted;
        return Arrival::New;
    }
    if (ahead_of(sequence, newest_) > 0) {
        const std::uint32_t advance = sequence - newest_;
        counts_.missing += advance - 1;  // the numbers skipped over, until they turn up
        seen_ = advance >= kWindow ? 0 : seen_ << advance;
        seen_ |= 1;
        history_ = advance >= kWindow - history_ ? kWindow : history_ + advance;
        newest_ = sequence;
        ++counts_.accepted;
        return Arrival::New;
    }
    const std::uint32_t age = newest_ - sequence;
    if (age < kWindow) {
        const std::uint64_t bit = std::uint64_t{1} << age;
        if ((seen_ & bit) != 0) {
            ++counts_.duplicate;
            return Arrival::Duplicate;
        }
        seen_ |= bit;
        if (age <= history_) {
            --counts_.missing;  // it was counted missing when newer ones overtook it
        }  // (older than the stream's first packet: it was never counted missing)
    }
    // Older than the window: a packet this late is counted late; whether it was counted
    // missing can no longer be told, so missing keeps it (lost for the stream's purpose).
    ++counts_.late;
    return Arrival::Late;
}

}  // namespace legofeup::comms
