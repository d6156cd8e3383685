// NXT transports (transport_address.cpp, tcp_*, serial_transport.cpp, pseudo_terminal.cpp,
// bluetooth_transport.cpp): address parsing with its exact messages, a TCP listener and
// client exchanging telegrams, refused and timed-out connects naming the address, a
// pseudo-terminal served like an emulated brick on /dev/rfcomm0, and a bt: connect on a
// machine without Bluetooth failing quickly and clearly.

#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <stdexcept>
#include <string>

#include "legofeup/comms/nxt/framing.hpp"
#include "legofeup/comms/nxt/transport.hpp"
#include "nxt_test_support.hpp"

namespace legofeup::comms::nxt {
namespace {

using namespace std::chrono_literals;
using namespace test_support;

constexpr std::uint32_t kLoopback = INADDR_LOOPBACK;

// --- Addresses ------------------------------------------------------------------------------

TEST(NxtTransportAddress, ParsesTheThreeKinds) {
    const TransportAddress bt = parse_transport_address("bt:00:16:53:01:02:03");
    EXPECT_EQ(bt.kind, TransportKind::Bluetooth);
    EXPECT_EQ(bt.target, "00:16:53:01:02:03");
    EXPECT_EQ(parse_transport_address("bt:00:16:53:0a:bc:Ef").target, "00:16:53:0A:BC:EF");

    const TransportAddress serial = parse_transport_address("serial:/dev/rfcomm0");
    EXPECT_EQ(serial.kind, TransportKind::Serial);
    EXPECT_EQ(serial.target, "/dev/rfcomm0");

    const TransportAddress tcp = parse_transport_address("tcp:127.0.0.1:7000");
    EXPECT_EQ(tcp.kind, TransportKind::Tcp);
    EXPECT_EQ(tcp.target, "127.0.0.1");
    EXPECT_EQ(tcp.port, 7000);
    EXPECT_EQ(parse_transport_address("tcp:localhost:1").port, 1);
    EXPECT_EQ(parse_transport_address("tcp:brick-bridge.lab:65535").target, "brick-bridge.lab");
}

TEST(NxtTransportAddress, ToStringGivesTheTextBack) {
    for (const std::string text : {"bt:00:16:53:01:02:03", "serial:/dev/rfcomm0",
                                   "serial:/dev/pts/7", "tcp:127.0.0.1:7000", "tcp:localhost:1"}) {
        EXPECT_EQ(parse_transport_address(text).to_string(), text);
    }
}

std::string refusal(const std::string& text) {
    return message_of<std::invalid_argument>([&] { parse_transport_address(text); });
}

TEST(NxtTransportAddress, BadBluetoothAddresses) {
    EXPECT_EQ(refusal("bt:00:16:53:0G:00:01"),
              "bt:00:16:53:0G:00:01: 'G' is not a hex digit; expected bt:XX:XX:XX:XX:XX:XX");
    EXPECT_EQ(refusal("bt:00-16-53-01-02-03"),
              "bt:00-16-53-01-02-03: '-' where a ':' belongs; expected bt:XX:XX:XX:XX:XX:XX");
    const std::string six_bytes =
        ": a Bluetooth address has 6 bytes; expected bt:XX:XX:XX:XX:XX:XX (an NXT's starts "
        "00:16:53)";
    EXPECT_EQ(refusal("bt:00:16:53:01:02"), "bt:00:16:53:01:02" + six_bytes);
    EXPECT_EQ(refusal("bt:00:16:53:01:02:03:04"), "bt:00:16:53:01:02:03:04" + six_bytes);
    EXPECT_EQ(refusal("bt:"), "bt:" + six_bytes);
}

TEST(NxtTransportAddress, BadSerialAndTcpAddresses) {
    EXPECT_EQ(refusal("serial:"),
              "serial:: no device path; expected serial:/dev/rfcomm0 (or another tty)");
    EXPECT_EQ(refusal("tcp:localhost"),
              "tcp:localhost: no port; expected tcp:HOST:PORT, e.g. tcp:127.0.0.1:7000");
    EXPECT_EQ(refusal("tcp::7000"),
              "tcp::7000: no host; expected tcp:HOST:PORT, e.g. tcp:127.0.0.1:7000");
    EXPECT_EQ(refusal("tcp:localhost:abc"),
              "tcp:localhost:abc: port 'abc' is not a number; expected tcp:HOST:PORT");
    EXPECT_EQ(refusal("tcp:localhost:"),
              "tcp:localhost:: port '' is not a number; expected tcp:HOST:PORT");
    EXPECT_EQ(refusal("tcp:localhost:+7"),
              "tcp:localhost:+7: port '+7' is not a number; expected tcp:HOST:PORT");
    EXPECT_EQ(refusal("tcp:localhost:0"), "tcp:localhost:0: port 0 is not in 1..65535");
    EXPECT_EQ(refusal("tcp:localhost:65536"), "tcp:localhost:65536: port 65536 is not in 1..65535");
    EXPECT_EQ(refusal("tcp:localhost:99999999999"),
              "tcp:localhost:99999999999: port 99999999999 is not in 1..65535");
}

TEST(NxtTransportAddress, MissingOrUnknownPrefix) {
    const std::string forms = "expected bt:XX:XX:XX:XX:XX:XX, serial:/dev/rfcomm0 or tcp:HOST:PORT";
    EXPECT_EQ(refusal(""), "empty brick address; " + forms);
    EXPECT_EQ(refusal("/dev/rfcomm0"), "/dev/rfcomm0: no transport prefix; " + forms
                                           + "; for a device write serial:/dev/rfcomm0");
    EXPECT_EQ(refusal("00:16:53:01:02:03"),
              "00:16:53:01:02:03: no transport prefix; " + forms
                  + "; for a Bluetooth address write bt:00:16:53:01:02:03");
    EXPECT_EQ(refusal("127.0.0.1:7000"), "127.0.0.1:7000: no transport prefix; " + forms
                                             + "; for a host and port write tcp:127.0.0.1:7000");
    EXPECT_EQ(refusal("brick"), "brick: no transport prefix; " + forms);
    EXPECT_EQ(refusal("usb:1"), "usb:1: unknown transport 'usb'; " + forms);
    EXPECT_EQ(refusal("udp://127.0.0.1:5600"),
              "udp://127.0.0.1:5600: unknown transport 'udp'; " + forms);
}

// --- TCP ------------------------------------------------------------------------------------

TransportAddress tcp_loopback(std::uint16_t port) {
    return parse_transport_address("tcp:127.0.0.1:" + std::to_string(port));
}

TEST(NxtTcpTransport, ClientAndListenerExchangeTelegrams) {
    TcpListener listener(kLoopback, 0);
    ASSERT_NE(listener.port(), 0);
    const auto client = open_transport(tcp_loopback(listener.port()), 2s);
    const auto server = listener.accept(2s);
    ASSERT_NE(server, nullptr);
    EXPECT_EQ(client->describe(), "tcp:127.0.0.1:" + std::to_string(listener.port()));
    EXPECT_EQ(server->describe().rfind("tcp:127.0.0.1:", 0), 0U) << server->describe();

    write_telegram(*client, encode_keep_alive(true));
    expect_bytes(read_telegram(*server, in_ms(2000)), {0x00, 0x0D});
    write_telegram(*server, encode_keep_alive_reply(status::kOk, 600000));
    EXPECT_EQ(decode_keep_alive_reply(read_telegram(*client, in_ms(2000))), 600000U);

    client->close();
    EXPECT_THROW(read_telegram(*server, in_ms(2000)), StreamClosed);
}

TEST(NxtTcpTransport, AcceptWithNoClientTimesOutWithNull) {
    TcpListener listener(kLoopback, 0);
    const auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(listener.accept(100ms), nullptr);
    EXPECT_GE(std::chrono::steady_clock::now() - start, 95ms);
}

TEST(NxtTcpTransport, ListeningOnAPortInUseSaysSo) {
    TcpListener first(kLoopback, 0);
    const std::string message =
        message_of<LinkError>([&] { TcpListener second(kLoopback, first.port()); });
    EXPECT_EQ(message, "cannot listen on tcp:127.0.0.1:" + std::to_string(first.port())
                           + ": Address already in use — is another emulator running? Choose "
                             "another port, or 0 for any free one");
}

TEST(NxtTcpTransport, ARefusedConnectNamesTheAddress) {
    std::uint16_t port = 0;
    {
        TcpListener listener(kLoopback, 0);  // a port that was free a moment ago…
        port = listener.port();
    }  // …and is closed now
    EXPECT_EQ(message_of<LinkError>([&] { open_transport(tcp_loopback(port), 2s); }),
              "tcp:127.0.0.1:" + std::to_string(port)
                  + ": connection refused — is the emulated brick (or the bridge) running and "
                    "listening on port "
                  + std::to_string(port) + "?");
}

TEST(NxtTcpTransport, AConnectThatHangsTimesOut) {
    // A listener with a full accept queue drops new SYNs, so a connect to it hangs — on
    // loopback, like a brick that does not answer.
    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    ASSERT_GE(fd, 0);
    sockaddr_in local{};
    local.sin_family = AF_INET;
    local.sin_addr.s_addr = htonl(kLoopback);
    ASSERT_EQ(::bind(fd, reinterpret_cast<const sockaddr*>(&local), sizeof local), 0);
    ASSERT_EQ(::listen(fd, 0), 0);
    socklen_t length = sizeof local;
    ::getsockname(fd, reinterpret_cast<sockaddr*>(&local), &length);
    const std::uint16_t port = ntohs(local.sin_port);
    std::vector<std::unique_ptr<ByteStream>> queued;
    std::string message;
    const auto start = std::chrono::steady_clock::now();
    for (int attempt = 0; attempt < 4 && message.find("timed out") == std::string::npos;
         ++attempt) {
        try {
            queued.push_back(open_transport(tcp_loopback(port), 300ms));  // fills the queue
        } catch (const LinkError& error) {
            message = error.what();
        }
    }
    ::close(fd);
    EXPECT_EQ(message, "tcp:127.0.0.1:" + std::to_string(port)
                           + ": connect timed out after 300 ms — is the host reachable and the "
                             "port open?");
    EXPECT_LT(std::chrono::steady_clock::now() - start, 3s);
}

// --- Serial and pseudo-terminals ------------------------------------------------------------

TransportAddress serial(const std::string& path) {
    return parse_transport_address("serial:" + path);
}

TEST(NxtSerialTransport, AMissingDeviceSaysWhatToDo) {
    EXPECT_EQ(message_of<LinkError>([] { open_transport(serial("/dev/rfcomm9"), 1s); }),
              "serial:/dev/rfcomm9: No such file or directory — bind it first: rfcomm bind 9 "
              "<address>");
    EXPECT_EQ(message_of<LinkError>([] { open_transport(serial("/tmp/no-such-tty"), 1s); }),
              "serial:/tmp/no-such-tty: No such file or directory — check the device path (ls "
              "/dev/rfcomm* /dev/tty*)");
}

TEST(NxtSerialTransport, ANonTerminalIsRefused) {
    EXPECT_EQ(message_of<LinkError>([] { open_transport(serial("/dev/null"), 1s); }),
              "serial:/dev/null: not a terminal (Inappropriate ioctl for device) — expected a "
              "tty such as /dev/rfcomm0");
}

TEST(NxtPseudoTerminal, ASerialClientAndTheMasterExchangeTelegrams) {
    PseudoTerminal pty;
    EXPECT_EQ(pty.slave_path().rfind("/dev/pts/", 0), 0U) << pty.slave_path();
    const auto master = pty.take_master();
    EXPECT_THROW(pty.take_master(), std::logic_error);
    EXPECT_EQ(master->describe(), "pty:" + pty.slave_path());

    const auto client = open_transport(serial(pty.slave_path()), 1s);
    EXPECT_EQ(client->describe(), "serial:" + pty.slave_path());
    // Nothing sent yet: both ends time out. (A raw tty's read() returns 0 when it has no
    // data; that must not be taken for the end of the stream.)
    EXPECT_THROW(read_telegram(*client, in_ms(50)), StreamTimeout);
    EXPECT_THROW(read_telegram(*master, in_ms(50)), StreamTimeout);
    write_telegram(*client, encode_get_output_state(2));
    expect_bytes(read_telegram(*master, in_ms(2000)), {0x00, 0x06, 0x02});
    OutputStateReply reply;
    reply.state.port = 2;
    reply.rotation_count = -720;
    write_telegram(*master, encode_output_state_reply(status::kOk, reply));
    EXPECT_EQ(decode_output_state_reply(read_telegram(*client, in_ms(2000))), reply);
}

TEST(NxtPseudoTerminal, RawModeCarriesEveryByteValueUnchanged) {
    // Line endings, ^C, ^D, XON/XOFF, DEL: a cooked tty would translate or swallow these.
    PseudoTerminal pty;
    const auto master = pty.take_master();
    const auto client = open_transport(serial(pty.slave_path()), 1s);
    for (int first = 0; first < 256; first += 64) {
        Bytes telegram(64);
        for (std::size_t i = 0; i < telegram.size(); ++i) {
            telegram[i] = static_cast<std::uint8_t>(first + static_cast<int>(i));
        }
        write_telegram(*client, telegram);
        expect_bytes(read_telegram(*master, in_ms(2000)), telegram);
        write_telegram(*master, telegram);
        expect_bytes(read_telegram(*client, in_ms(2000)), telegram);
    }
}

TEST(NxtPseudoTerminal, AClientLeavingDoesNotBreakTheMasterForTheNext) {
    PseudoTerminal pty;
    const auto master = pty.take_master();
    {
        const auto first = open_transport(serial(pty.slave_path()), 1s);
        write_telegram(*first, encode_keep_alive(true));
        expect_bytes(read_telegram(*master, in_ms(2000)), {0x00, 0x0D});
    }  // the first client goes away
    // The master only sees silence — no hang-up, no EIO.
    EXPECT_FALSE(master->wait_readable(in_ms(50)));
    EXPECT_THROW(read_telegram(*master, in_ms(50)), StreamTimeout);
    // A reply nobody will read is left in the slave's queue…
    write_telegram(*master, encode_keep_alive_reply(status::kOk, 1));

    const auto second = open_transport(serial(pty.slave_path()), 1s);
    // …and the next client does not get it: it starts with an empty queue.
    EXPECT_FALSE(second->wait_readable(in_ms(50)));
    write_telegram(*second, encode_get_battery_level());
    expect_bytes(read_telegram(*master, in_ms(2000)), {0x00, 0x0B});
    write_telegram(*master, encode_battery_level_reply(status::kOk, 7400));
    EXPECT_EQ(decode_battery_level_reply(read_telegram(*second, in_ms(2000))), 7400);
}

TEST(NxtPseudoTerminal, TheMasterGoingAwayClosesTheClient) {
    PseudoTerminal pty;
    auto master = pty.take_master();
    const auto client = open_transport(serial(pty.slave_path()), 1s);
    master.reset();
    const std::string message =
        message_of<StreamClosed>([&] { read_telegram(*client, in_ms(2000)); });
    // Linux reports the hang-up as EIO; other systems as end of file.
    const std::string where = "serial:" + pty.slave_path() + ": ";
    EXPECT_TRUE(message == where + "the other end hung up (Input/output error)"
                || message == where + "closed by the other end")
        << message;
}

// --- Bluetooth ------------------------------------------------------------------------------

TEST(NxtBluetoothTransport, ConnectWithoutABrickFailsQuicklyAndNamesTheAddress) {
    // This machine has no Bluetooth adapter (and may not have the kernel's Bluetooth support
    // at all); either way the user must learn which address failed and what to check.
    const auto address = parse_transport_address("bt:00:16:53:01:02:03");
    const auto start = std::chrono::steady_clock::now();
    const std::string message = message_of<LinkError>([&] { open_transport(address, 2s); });
    EXPECT_LT(std::chrono::steady_clock::now() - start, 3s);
    EXPECT_EQ(message.rfind("bt:00:16:53:01:02:03: ", 0), 0U) << message;
    const bool explained = message.find("Address family not supported") != std::string::npos
                           || message.find("no Bluetooth") != std::string::npos
                           || message.find("timed out after 2 s") != std::string::npos
                           || message.find("No such device") != std::string::npos;
    EXPECT_TRUE(explained) << message;
    EXPECT_NE(message.find("bluetoothctl"), std::string::npos) << message;
}

}  // namespace
}  // namespace legofeup::comms::nxt
