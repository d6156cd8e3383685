// open_transport(): from a parsed address to a connected stream.

#include <stdexcept>

#include "transports.hpp"

namespace legofeup::comms::nxt {

std::unique_ptr<ByteStream> open_transport(const TransportAddress& address,
                                           std::chrono::milliseconds timeout) {
    switch (address.kind) {
        case TransportKind::Bluetooth:
            return detail::open_bluetooth(address, timeout);
        case TransportKind::Serial:
            // Opened non-blocking, a tty never waits for its line: nothing to time out.
            return detail::open_serial(address);
        case TransportKind::Tcp:
            return detail::open_tcp(address, timeout);
    }
    throw std::invalid_argument("open_transport: unknown transport kind");
}

}  // namespace legofeup::comms::nxt
