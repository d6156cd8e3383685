#pragma once
// Opening a byte stream to a brick from an address the user typed:
//   bt:XX:XX:XX:XX:XX:XX   BlueZ RFCOMM socket, channel 1 (the NXT's serial port profile)
//   serial:/dev/rfcomm0    any tty, opened in raw mode (e.g. a bound rfcomm device)
//   tcp:HOST:PORT          an emulator or a bridge (IPv4 address or host name)
// and the server ends the emulated brick listens on (TCP and pseudo-terminals).

#include <chrono>
#include <memory>
#include <string>

#include "legofeup/comms/nxt/byte_stream.hpp"

namespace legofeup::comms::nxt {

enum class TransportKind { Bluetooth, Serial, Tcp };

struct TransportAddress {
    TransportKind kind = TransportKind::Tcp;
    std::string target;             ///< bt: "00:16:53:01:02:03"; serial: path; tcp: host
    std::uint16_t port = 0;         ///< tcp only
    std::string to_string() const;  ///< back to "bt:…", "serial:…", "tcp:host:port"
};

/// Parses an address; throws std::invalid_argument saying what is wrong and what is expected
/// ("bt:00:16:53:0G:00:01: 'G' is not a hex digit; expected bt:XX:XX:XX:XX:XX:XX").
TransportAddress parse_transport_address(const std::string& text);

/// Connects. A connect that does not complete within `timeout` is abandoned (BlueZ connects
/// can hang). Throws LinkError naming the address, the system's reason and what to try
/// ("is the brick on and paired? bluetoothctl pair 00:16:53:…").
std::unique_ptr<ByteStream> open_transport(const TransportAddress& address,
                                           std::chrono::milliseconds timeout);

/// A byte stream over an already open file descriptor (sockets, ttys, pty masters); owns
/// and closes it. For servers and tests.
std::unique_ptr<ByteStream> stream_from_fd(int fd, std::string description);

/// Puts a tty (or pty) into raw mode: no echo, no line discipline, 8 data bits.
void make_raw_tty(int fd, const std::string& path);

/// A listening TCP socket on loopback (or any address when asked); port 0 picks a free one.
class TcpListener {
  public:
    TcpListener(std::uint32_t address, std::uint16_t port);
    ~TcpListener();
    TcpListener(const TcpListener&) = delete;
    TcpListener& operator=(const TcpListener&) = delete;
    std::uint16_t port() const { return port_; }
    /// The next client, or nullptr if none came before `timeout`.
    std::unique_ptr<ByteStream> accept(std::chrono::milliseconds timeout);

  private:
    int fd_ = -1;
    std::uint16_t port_ = 0;
};

/// A pseudo-terminal pair in raw mode: the emulator serves the master; clients open
/// slave_path() as they would /dev/rfcomm0.
class PseudoTerminal {
  public:
    PseudoTerminal();
    ~PseudoTerminal();
    PseudoTerminal(const PseudoTerminal&) = delete;
    PseudoTerminal& operator=(const PseudoTerminal&) = delete;
    const std::string& slave_path() const { return slave_path_; }
    /// The master end as a stream (once). While no client has the slave open, reads time out.
    std::unique_ptr<ByteStream> take_master();

  private:
    int master_fd_ = -1;
    int keep_slave_fd_ = -1;  ///< held open so the master never sees a hang-up between clients
    std::string slave_path_;
};

}  // namespace legofeup::comms::nxt
