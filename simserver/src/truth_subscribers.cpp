#include "truth_subscribers.hpp"

#include <algorithm>

namespace legofeup::simserver {

TruthSubscribers::Outcome TruthSubscribers::subscribe(const comms::Endpoint& from,
                                                      std::chrono::steady_clock::time_point now) {
    const auto it = std::find_if(subscribers_.begin(), subscribers_.end(),
                                 [&](const Subscriber& s) { return s.address == from; });
    if (it != subscribers_.end()) {
        it->until = now + kLease;
        return Outcome::Renewed;
    }
    if (subscribers_.size() >= kMax) {
        return Outcome::Full;
    }
    subscribers_.push_back({from, now + kLease});
    return Outcome::Added;
}

void TruthSubscribers::unsubscribe(const comms::Endpoint& from) {
    std::erase_if(subscribers_, [&](const Subscriber& s) { return s.address == from; });
}

void TruthSubscribers::expire(std::chrono::steady_clock::time_point now) {
    std::erase_if(subscribers_, [&](const Subscriber& s) { return s.until <= now; });
}

}  // namespace legofeup::simserver
