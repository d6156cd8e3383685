#include "legofeup/comms/sequence_window.hpp"

namespace legofeup::comms {

Arrival SequenceWindow::classify(std::uint32_t sequence) {
    if (!started_) {
        started_ = true;
        newest_ = sequence;
        seen_ = 1;
        ++counts_.accepted;
        return Arrival::New;
    }
    if (sequence > newest_) {
        const std::uint32_t advance = sequence - newest_;
        counts_.missing += advance - 1;  // the numbers skipped over, until they turn up
        seen_ = advance >= kWindow ? 0 : seen_ << advance;
        seen_ |= 1;
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
        --counts_.missing;  // it was counted missing when newer ones overtook it
    }
    // Older than the window: a packet this late is counted late; whether it was counted
    // missing can no longer be told, so missing keeps it (lost for the stream's purpose).
    ++counts_.late;
    return Arrival::Late;
}

}  // namespace legofeup::comms
