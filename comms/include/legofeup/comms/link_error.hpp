#pragma once
// A link that cannot do its job (no server, robot held by another client, request refused).
// The message says what was tried and what to do about it.

#include <stdexcept>

namespace legofeup::comms {

class LinkError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

}  // namespace legofeup::comms
