#pragma once
// The firmware's 20 message queues (c_cmd.c: MESSAGE_QUEUE_COUNT, MESSAGES_PER_QUEUE): 0–9
// are the program's inboxes, 10–19 its outboxes ("response mailboxes"). Each holds 5
// messages; a sixth pushes the oldest out. Private to nxtemu.

#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <vector>

#include "legofeup/comms/nxt/telegram.hpp"

namespace legofeup::nxtemu {

class Mailboxes {
  public:
    static constexpr std::size_t kMessagesPerQueue = 5;

    /// Appends a message (NUL included); drops the oldest when the queue is full.
    /// `box` < comms::nxt::kMailboxCount.
    void write(std::uint8_t box, std::span<const std::uint8_t> message);
    /// The oldest message, taken out when `remove`; nullopt when the queue is empty.
    std::optional<std::vector<std::uint8_t>> read(std::uint8_t box, bool remove);
    bool empty(std::uint8_t box) const { return queues_.at(box).empty(); }
    void clear();

  private:
    std::array<std::deque<std::vector<std::uint8_t>>, comms::nxt::kMailboxCount> queues_;
};

}  // namespace legofeup::nxtemu
