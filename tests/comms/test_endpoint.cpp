// Endpoints: parsing "a.b.c.d[:port]" and "udp://a.b.c.d[:port]", formatting, loopback.

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <string_view>

#include "legofeup/comms/endpoint.hpp"
#include "legofeup/comms/protocol.hpp"

namespace legofeup::comms {
namespace {

constexpr std::uint16_t kOtherPort = 4321;

void expect_endpoint(const std::optional<Endpoint>& parsed, std::uint32_t address,
                     std::uint16_t port, std::string_view text) {
    ASSERT_TRUE(parsed.has_value()) << '"' << text << '"';
    EXPECT_EQ(parsed->address, address) << '"' << text << '"';
    EXPECT_EQ(parsed->port, port) << '"' << text << '"';
}

TEST(Endpoint, ParsesAddressAndPort) {
    expect_endpoint(parse_endpoint("127.0.0.1:5600", kOtherPort), 0x7F000001, 5600,
                    "127.0.0.1:5600");
    expect_endpoint(parse_endpoint("0.0.0.0:0", kOtherPort), 0, 0, "0.0.0.0:0");
    expect_endpoint(parse_endpoint("255.255.255.255:65535", kOtherPort), 0xFFFFFFFF, 65535,
                    "255.255.255.255:65535");
    // Each octet lands in its own byte (host order: a is the most significant).
    expect_endpoint(parse_endpoint("192.168.1.20:40000", kOtherPort), 0xC0A80114, 40000,
                    "192.168.1.20:40000");
    expect_endpoint(parse_endpoint("1.2.3.4:1", kOtherPort), 0x01020304, 1, "1.2.3.4:1");
}

TEST(Endpoint, AddressAloneTakesTheDefaultPort) {
    expect_endpoint(parse_endpoint("10.0.0.2", kOtherPort), 0x0A000002, kOtherPort, "10.0.0.2");
    expect_endpoint(parse_endpoint("10.0.0.2", kDefaultControlPort), 0x0A000002,
                    kDefaultControlPort, "10.0.0.2");
    expect_endpoint(parse_endpoint("10.0.0.2", 0), 0x0A000002, 0, "10.0.0.2");
}

TEST(Endpoint, UdpUrls) {
    expect_endpoint(parse_udp_url("udp://127.0.0.1"), 0x7F000001, 5600, "udp://127.0.0.1");
    EXPECT_EQ(kDefaultRobotPort, 5600);
    expect_endpoint(parse_udp_url("udp://127.0.0.1:5600"), 0x7F000001, 5600,
                    "udp://127.0.0.1:5600");
    expect_endpoint(parse_udp_url("udp://10.0.0.2:7000"), 0x0A000002, 7000, "udp://10.0.0.2:7000");
    expect_endpoint(parse_udp_url("udp://0.0.0.0:0"), 0, 0, "udp://0.0.0.0:0");
}

TEST(Endpoint, RejectsMalformedEndpoints) {
    constexpr std::string_view kBad[] = {
        "",                                // nothing
        "localhost:5600",                  // names are not resolved
        "localhost",                       //
        "1.2.3:4",                         // three octets
        "1.2.3",                           //
        "1.2.3.4.5",                       // five octets
        "1.2.3.4.5:6",                     //
        "256.0.0.1",                       // octet out of range
        "1.2.3.256:80",                    //
        "1.2.3.4:65536",                   // port out of range
        "1.2.3.4:99999",                   //
        "1.2.3.4:-1",                      // signs
        "1.2.3.4:+5",                      //
        "-1.2.3.4",                        //
        "+1.2.3.4",                        //
        " 1.2.3.4",                        // spaces
        "1.2.3.4 ",                        //
        "1.2.3.4: 80",                     //
        "1.2.3.4 :80",                     //
        "1. 2.3.4",                        //
        "1.2.3.4:",                        // empty port
        ":5600",                           // empty address
        "1..2.3",                          // empty octet
        ".1.2.3",                          //
        "1.2.3.",                          //
        "1.2.3.4:5:6",                     // two ports
        "1.2.3.4:0x10",                    // not decimal
        "1.2.3.4:1e3",                     //
        "0x7f.0.0.1",                      //
        "http://1.2.3.4",                  // another scheme
        "udp://1.2.3.4",                   // a URL is not an endpoint
        "udp://",                          //
        "01234.1.1.1",                     // octet too long and too large
        "1.2.3.4:000005600",               // port too long
        "[::1]:5600",                      // IPv6
        "::1",                             //
        "1.2.3.4/24",                      // a network, not an address
        std::string_view("1.2.3.4\0", 8),  // a NUL inside
    };
    for (const std::string_view text : kBad) {
        EXPECT_FALSE(parse_endpoint(text, kOtherPort).has_value())
            << '"' << std::string(text) << '"';
        // And the same behind the URL scheme.
        const std::string url = "udp://" + std::string(text);
        EXPECT_FALSE(parse_udp_url(url).has_value()) << '"' << url << '"';
    }
}

TEST(Endpoint, RejectsMalformedUrls) {
    constexpr std::string_view kBad[] = {
        "",
        "udp://",
        "udp:/127.0.0.1",
        "udp:127.0.0.1",
        "udp//127.0.0.1",
        "127.0.0.1:5600",  // no scheme
        "127.0.0.1",
        "http://1.2.3.4",
        "tcp://127.0.0.1:5600",
        " udp://127.0.0.1",
        "udp://localhost:5600",
        "udp://127.0.0.1:",
        "udp://127.0.0.1:65536",
        "udp://127.0.0.1/",
    };
    for (const std::string_view url : kBad) {
        EXPECT_FALSE(parse_udp_url(url).has_value()) << '"' << std::string(url) << '"';
    }
}

TEST(Endpoint, Formats) {
    EXPECT_EQ((Endpoint{0x7F000001, 5600}).to_string(), "127.0.0.1:5600");
    EXPECT_EQ((Endpoint{0, 0}).to_string(), "0.0.0.0:0");
    EXPECT_EQ((Endpoint{0xFFFFFFFF, 65535}).to_string(), "255.255.255.255:65535");
    EXPECT_EQ((Endpoint{0xC0A80114, 40000}).to_string(), "192.168.1.20:40000");
    EXPECT_EQ((Endpoint{0x0A000002, 7}).to_string(), "10.0.0.2:7");
    EXPECT_EQ(Endpoint{}.to_string(), "127.0.0.1:0");  // the default is the loopback address
}

TEST(Endpoint, FormattedEndpointsParseBack) {
    std::mt19937 rng(5600);
    std::uniform_int_distribution<std::uint32_t> address(0, 0xFFFFFFFF);
    std::uniform_int_distribution<int> port(0, 65535);
    for (int i = 0; i < 2000; ++i) {
        const Endpoint endpoint{address(rng), static_cast<std::uint16_t>(port(rng))};
        const std::string text = endpoint.to_string();
        const auto parsed = parse_endpoint(text, kOtherPort);
        ASSERT_TRUE(parsed.has_value()) << text;
        EXPECT_EQ(*parsed, endpoint) << text;
        const auto from_url = parse_udp_url("udp://" + text);
        ASSERT_TRUE(from_url.has_value()) << text;
        EXPECT_EQ(*from_url, endpoint) << text;
    }
}

TEST(Endpoint, Equality) {
    EXPECT_EQ((Endpoint{0x7F000001, 5600}), (Endpoint{0x7F000001, 5600}));
    EXPECT_NE((Endpoint{0x7F000001, 5600}), (Endpoint{0x7F000001, 5601}));
    EXPECT_NE((Endpoint{0x7F000001, 5600}), (Endpoint{0x7F000002, 5600}));
}

TEST(Endpoint, LoopbackIsExactly127Slash8) {
    EXPECT_TRUE((Endpoint{0x7F000001, 0}).is_loopback());
    EXPECT_TRUE((Endpoint{0x7F000000, 0}).is_loopback());
    EXPECT_TRUE((Endpoint{0x7FFFFFFF, 0}).is_loopback());
    EXPECT_TRUE((Endpoint{0x7F0A0B0C, 5600}).is_loopback());
    EXPECT_TRUE(Endpoint{}.is_loopback());
    EXPECT_FALSE((Endpoint{0x7EFFFFFF, 0}).is_loopback());  // 126.255.255.255
    EXPECT_FALSE((Endpoint{0x80000000, 0}).is_loopback());  // 128.0.0.0
    EXPECT_FALSE((Endpoint{0, 0}).is_loopback());           // 0.0.0.0
    EXPECT_FALSE((Endpoint{0x0100007F, 0}).is_loopback());  // 127.0.0.1 byte-swapped
    EXPECT_FALSE((Endpoint{0xFFFFFFFF, 0}).is_loopback());
    EXPECT_FALSE((Endpoint{0xC0A80114, 0}).is_loopback());
    for (std::uint32_t first = 0; first < 256; ++first) {
        const Endpoint endpoint{(first << 24) | 0x00010203U, 1};
        EXPECT_EQ(endpoint.is_loopback(), first == 127) << first;
    }
    const auto parsed = parse_endpoint("127.1.2.3:9", kOtherPort);
    ASSERT_TRUE(parsed.has_value());
    EXPECT_TRUE(parsed->is_loopback());
    const auto other = parse_endpoint("10.0.0.127", kOtherPort);
    ASSERT_TRUE(other.has_value());
    EXPECT_FALSE(other->is_loopback());
}

}  // namespace
}  // namespace legofeup::comms
