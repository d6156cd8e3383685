#pragma once
// The ground-truth stream's subscribers: up to kMax addresses, each kept for kLease after
// its last TruthSubscribe (clients renew about every second).

#include <chrono>
#include <vector>

#include "legofeup/comms/endpoint.hpp"

namespace legofeup::simserver {

class TruthSubscribers {
  public:
    static constexpr std::size_t kMax = 8;
    static constexpr std::chrono::seconds kLease{5};

    enum class Outcome { Added, Renewed, Full };
    /// Adds `from` (if there is room) or renews its lease.
    Outcome subscribe(const comms::Endpoint& from, std::chrono::steady_clock::time_point now);
    void unsubscribe(const comms::Endpoint& from);
    void expire(std::chrono::steady_clock::time_point now);

    template <typename Send>
    void for_each(Send&& send) const {
        for (const Subscriber& subscriber : subscribers_) {
            send(subscriber.address);
        }
    }
    std::size_t size() const { return subscribers_.size(); }

  private:
    struct Subscriber {
        comms::Endpoint address;
        std::chrono::steady_clock::time_point until;
    };
    std::vector<Subscriber> subscribers_;
};

}  // namespace legofeup::simserver
