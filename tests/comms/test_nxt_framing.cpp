// NXT framing (framing.cpp) and the fd stream under it (fd_stream.cpp), over a socketpair:
// the length prefix, frames split into single bytes, lengths 0 and 65, a timeout in the
// middle of a frame, the other end closing, writes to a closed peer, resynchronising.

#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>
#include <thread>

#include "legofeup/comms/nxt/framing.hpp"
#include "nxt_test_support.hpp"

namespace legofeup::comms::nxt {
namespace {

using namespace std::chrono_literals;
using namespace test_support;

TEST(NxtFraming, PrefixIsTheLengthLittleEndian) {
    expect_bytes(frame_telegram(Bytes{0x00, 0x0D}), {0x02, 0x00, 0x00, 0x0D});
    Bytes largest(64, 0xAA);
    const Bytes frame = frame_telegram(largest);
    ASSERT_EQ(frame.size(), 66U);
    EXPECT_EQ(frame[0], 0x40);
    EXPECT_EQ(frame[1], 0x00);
    EXPECT_EQ(Bytes(frame.begin() + 2, frame.end()), largest);
}

TEST(NxtFraming, EmptyAndOversizedTelegramsCannotBeFramed) {
    EXPECT_EQ(message_of<std::invalid_argument>([] { frame_telegram(Bytes{}); }),
              "NXT telegram of 0 bytes cannot be framed: expected 1..64");
    EXPECT_EQ(message_of<std::invalid_argument>([] { frame_telegram(Bytes(65, 0)); }),
              "NXT telegram of 65 bytes cannot be framed: expected 1..64");
}

TEST(NxtFraming, TelegramsCrossBothWays) {
    SocketPair pair;
    const Bytes request = {0x00, 0x06, 0x02};
    write_telegram(*pair.left, request);
    expect_bytes(read_telegram(*pair.right, in_ms(1000)), request);
    const Bytes reply(25, 0x5A);
    write_telegram(*pair.right, reply);
    expect_bytes(read_telegram(*pair.left, in_ms(1000)), reply);
}

TEST(NxtFraming, SeveralTelegramsInOneWriteArriveInOrder) {
    SocketPair pair;
    const std::vector<Telegram> telegrams = {{0x80, 0x04, 1}, {0x00, 0x06, 2}, Bytes(64, 7)};
    write_telegrams(*pair.left, telegrams);
    for (const Telegram& telegram : telegrams) {
        expect_bytes(read_telegram(*pair.right, in_ms(1000)), telegram);
    }
    EXPECT_FALSE(pair.right->wait_readable(in_ms(20)));  // nothing more
}

TEST(NxtFraming, ABadTelegramInABatchSendsNothing) {
    SocketPair pair;
    const std::vector<Telegram> telegrams = {{0x00, 0x0D}, Bytes(65, 0)};
    EXPECT_THROW(write_telegrams(*pair.left, telegrams), std::invalid_argument);
    EXPECT_FALSE(pair.right->wait_readable(in_ms(50)));
    write_telegrams(*pair.left, {});  // nothing to send is not an error
    EXPECT_FALSE(pair.right->wait_readable(in_ms(20)));
}

TEST(NxtFraming, AFrameSplitIntoSingleBytesIsReassembled) {
    SocketPair pair;
    Bytes telegram(40);
    for (std::size_t i = 0; i < telegram.size(); ++i) {
        telegram[i] = static_cast<std::uint8_t>(i * 7);
    }
    const Bytes frame = frame_telegram(telegram);
    std::thread writer([&] {
        for (const std::uint8_t byte : frame) {
            pair.left->write_all(Bytes{byte});
            std::this_thread::sleep_for(1ms);
        }
    });
    const Telegram received = read_telegram(*pair.right, in_ms(5000));
    writer.join();
    expect_bytes(received, telegram);
}

TEST(NxtFraming, LengthZeroIsAFramingError) {
    SocketPair pair;
    pair.left->write_all(Bytes{0x00, 0x00, 0x00, 0x0D});
    EXPECT_EQ(message_of<FramingError>([&] { read_telegram(*pair.right, in_ms(1000)); }),
              "right: frame length 0, expected 1..64 — the stream is out of step, or the other "
              "end is not an NXT brick");
}

TEST(NxtFraming, LengthAboveSixtyFourIsAFramingError) {
    SocketPair pair;
    Bytes frame = {0x41, 0x00};
    frame.resize(2 + 65, 0x00);
    pair.left->write_all(frame);
    const std::string message =
        message_of<FramingError>([&] { read_telegram(*pair.right, in_ms(1000)); });
    EXPECT_EQ(message.rfind("right: frame length 65, expected 1..64", 0), 0U) << message;
    pair.left->write_all(Bytes{0xFF, 0xFF});
    pair.right->discard_pending();
    pair.left->write_all(Bytes{0xFF, 0xFF});
    EXPECT_THROW(read_telegram(*pair.right, in_ms(1000)), FramingError);  // 65535
    EXPECT_THROW(read_telegram(*pair.right, in_ms(50)), LinkError);       // a timeout: one base
}

TEST(NxtFraming, NothingArrivingIsATimeoutAndTheStreamStaysUsable) {
    SocketPair pair;
    const auto start = ByteStream::Clock::now();
    EXPECT_EQ(message_of<StreamTimeout>([&] { read_telegram(*pair.right, in_ms(100)); }),
              "right: no data before the deadline (0 of 2 bytes arrived)");
    EXPECT_GE(ByteStream::Clock::now() - start, 95ms);
    write_telegram(*pair.left, Bytes{0x00, 0x0B});
    expect_bytes(read_telegram(*pair.right, in_ms(1000)), {0x00, 0x0B});
}

TEST(NxtFraming, ATimeoutInTheMiddleOfAFrame) {
    SocketPair pair;
    pair.left->write_all(Bytes{0x05, 0x00, 0x00, 0x13});  // 5 announced, 2 sent
    EXPECT_EQ(message_of<StreamTimeout>([&] { read_telegram(*pair.right, in_ms(100)); }),
              "right: no data before the deadline (2 of 5 bytes arrived)");
    // The caller resynchronises: drop what is left, then the next frame reads cleanly.
    pair.left->write_all(Bytes{0x0A, 0x00});
    pair.right->discard_pending();
    write_telegram(*pair.left, Bytes{0x02, 0x0D, 0x00, 1, 2, 3, 4});
    expect_bytes(read_telegram(*pair.right, in_ms(1000)), {0x02, 0x0D, 0x00, 1, 2, 3, 4});
}

TEST(NxtFraming, DeadlineInThePastStillReadsWhatIsThere) {
    SocketPair pair;
    write_telegram(*pair.left, Bytes{0x00, 0x0D});
    ASSERT_TRUE(pair.right->wait_readable(in_ms(1000)));
    expect_bytes(read_telegram(*pair.right, ByteStream::Clock::now() - 1s), {0x00, 0x0D});
}

TEST(NxtFraming, PeerCloseIsStreamClosed) {
    SocketPair pair;
    pair.left.reset();
    EXPECT_TRUE(pair.right->wait_readable(in_ms(1000)));  // a close is news to read
    EXPECT_EQ(message_of<StreamClosed>([&] { read_telegram(*pair.right, in_ms(1000)); }),
              "right: closed by the other end");
}

TEST(NxtFraming, PeerCloseMidFrameDeliversNothingHalfRead) {
    SocketPair pair;
    pair.left->write_all(Bytes{0x03, 0x00, 0x00});
    pair.left->close();
    EXPECT_THROW(read_telegram(*pair.right, in_ms(1000)), StreamClosed);
}

TEST(NxtFraming, BytesSentBeforeACloseStillArrive) {
    SocketPair pair;
    write_telegram(*pair.left, Bytes{0x02, 0x0B, 0x00, 0x40, 0x1F});
    pair.left.reset();
    expect_bytes(read_telegram(*pair.right, in_ms(1000)), {0x02, 0x0B, 0x00, 0x40, 0x1F});
    EXPECT_THROW(read_telegram(*pair.right, in_ms(1000)), StreamClosed);
}

TEST(NxtFraming, WritingToAClosedPeerIsStreamClosedNotSigpipe) {
    SocketPair pair;
    pair.right.reset();
    // Without MSG_NOSIGNAL the kernel would raise SIGPIPE here and end the test program.
    const auto error = caught<StreamClosed>([&] {
        for (int i = 0; i < 100; ++i) {
            write_telegram(*pair.left, Bytes(64, 0x11));
        }
    });
    ASSERT_TRUE(error.has_value());
    EXPECT_EQ(std::string(error->what()), "left: write failed: Broken pipe");
}

TEST(NxtFraming, AClosedStreamRefusesEverything) {
    SocketPair pair;
    pair.right->close();
    pair.right->close();  // twice is harmless
    EXPECT_EQ(message_of<StreamClosed>([&] { read_telegram(*pair.right, in_ms(100)); }),
              "right: the stream was closed");
    EXPECT_THROW(write_telegram(*pair.right, Bytes{0x00, 0x0D}), StreamClosed);
    EXPECT_TRUE(pair.right->wait_readable(in_ms(100)));  // the next read reports it at once
    pair.right->discard_pending();
    EXPECT_EQ(pair.right->describe(), "right");
}

TEST(NxtFraming, ALargeWriteWaitsForTheReader) {
    // More than a socket buffer holds: write_all must wait for room, not fail or drop.
    SocketPair pair;
    const std::size_t frames = 20000;
    std::thread writer([&] {
        std::vector<Telegram> batch(frames, Bytes(64, 0x33));
        write_telegrams(*pair.left, batch);
    });
    std::size_t received = 0;
    for (; received < frames; ++received) {
        if (read_telegram(*pair.right, in_ms(5000)).size() != 64) {
            break;
        }
    }
    writer.join();
    EXPECT_EQ(received, frames);
}

}  // namespace
}  // namespace legofeup::comms::nxt
