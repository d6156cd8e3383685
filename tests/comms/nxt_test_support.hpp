#pragma once
// Helpers for the NXT codec and transport tests: byte dumps, exceptions with their messages,
// deadlines and a connected pair of streams.

#include <gtest/gtest.h>
#include <sys/socket.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "legofeup/comms/nxt/byte_stream.hpp"
#include "legofeup/comms/nxt/transport.hpp"

namespace legofeup::comms::nxt::test_support {

using Bytes = std::vector<std::uint8_t>;

inline std::string hex(std::span<const std::uint8_t> bytes) {
    std::string text;
    for (const std::uint8_t byte : bytes) {
        char cell[4];
        std::snprintf(cell, sizeof cell, "%02X ", static_cast<unsigned>(byte));
        text += cell;
    }
    return text;
}

/// Compares byte for byte and shows both in hex on failure.
inline void expect_bytes(std::span<const std::uint8_t> actual, const Bytes& expected) {
    EXPECT_EQ(Bytes(actual.begin(), actual.end()), expected)
        << "actual:   " << hex(actual) << "\nexpected: " << hex(expected);
}

/// Bytes from a string literal's characters (no NUL added).
inline Bytes text_bytes(const std::string& text) {
    return Bytes(text.begin(), text.end());
}

/// The exception of type E that `function` throws, or nullopt (a test failure) if it throws
/// none. Any other exception type escapes and fails the test with its message.
template <typename E, typename Function>
std::optional<E> caught(Function&& function) {
    try {
        std::forward<Function>(function)();
    } catch (const E& error) {
        return error;
    }
    ADD_FAILURE() << "no exception was thrown";
    return std::nullopt;
}

template <typename E, typename Function>
std::string message_of(Function&& function) {
    const auto error = caught<E>(std::forward<Function>(function));
    return error ? std::string(error->what()) : std::string("<no exception>");
}

inline ByteStream::Clock::time_point in_ms(int milliseconds) {
    return ByteStream::Clock::now() + std::chrono::milliseconds(milliseconds);
}

/// Two connected stream sockets (AF_UNIX), each end a stream.
struct SocketPair {
    SocketPair() {
        int fds[2] = {-1, -1};
        EXPECT_EQ(::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds), 0);
        left = stream_from_fd(fds[0], "left");
        right = stream_from_fd(fds[1], "right");
    }
    std::unique_ptr<ByteStream> left;
    std::unique_ptr<ByteStream> right;
};

}  // namespace legofeup::comms::nxt::test_support
