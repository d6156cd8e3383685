#include "mailboxes.hpp"

namespace legofeup::nxtemu {

void Mailboxes::write(std::uint8_t box, std::span<const std::uint8_t> message) {
    auto& queue = queues_.at(box);
    if (queue.size() == kMessagesPerQueue) {
        queue.pop_front();  // the firmware bumps the read index: the oldest is lost
    }
    queue.emplace_back(message.begin(), message.end());
}

std::optional<std::vector<std::uint8_t>> Mailboxes::read(std::uint8_t box, bool remove) {
    auto& queue = queues_.at(box);
    if (queue.empty()) {
        return std::nullopt;
    }
    std::vector<std::uint8_t> message = queue.front();
    if (remove) {
        queue.pop_front();
    }
    return message;
}

void Mailboxes::clear() {
    for (auto& queue : queues_) {
        queue.clear();
    }
}

}  // namespace legofeup::nxtemu
