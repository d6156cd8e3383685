// Every message a refused control request can carry (docs/protocol.md, "Control stream")
// arrives whole: at most 95 bytes, so the reply's field never cuts it. Each is provoked with
// the arguments that make it longest (%.6g prints a double in at most 13 characters:
// -1.79769e+308) and matched against its whole pattern, end included, so a cut message, a
// changed wording or a byte that is not UTF-8 fails.

#include <gtest/gtest.h>

#include <limits>
#include <regex>

#include "legofeup/comms/control_client.hpp"
#include "support/test_server.hpp"

namespace legofeup {
namespace {

using comms::ControlOp;
using comms::ControlRequestPacket;
using comms::ControlResult;
using testing::loopback;

constexpr double kHuge = std::numeric_limits<double>::max();
/// A number as %.6g prints it.
const std::string kNumber = R"(-?[0-9]+(\.[0-9]+)?(e[-+][0-9]+)?)";

ControlRequestPacket placing(ControlOp op, const Pose2& pose) {
    ControlRequestPacket request;
    request.op = static_cast<std::uint8_t>(op);
    request.pose_given = true;
    request.pose = pose;
    return request;
}

ControlRequestPacket noise(const comms::NoiseSettings& settings) {
    ControlRequestPacket request;
    request.op = static_cast<std::uint8_t>(ControlOp::SetNoise);
    request.noise = settings;
    return request;
}

ControlRequestPacket time_scale(double scale) {
    ControlRequestPacket request;
    request.op = static_cast<std::uint8_t>(ControlOp::SetTimeScale);
    request.time_scale = scale;
    return request;
}

ControlRequestPacket unknown(std::uint8_t op) {
    ControlRequestPacket request;
    request.op = op;
    return request;
}

/// Sends the request and checks the refusal: its result, and a message that fits the field
/// and is exactly `pattern` (which spells its non-ASCII characters in UTF-8).
void expect_refusal(comms::ControlClient& control, const ControlRequestPacket& request,
                    ControlResult result, const std::string& pattern) {
    const comms::ControlReplyPacket reply = control.request(request);
    EXPECT_EQ(reply.result, result) << reply.message;
    EXPECT_LE(reply.message.size(), comms::kReplyMessageMaxBytes) << reply.message;
    EXPECT_TRUE(std::regex_match(reply.message, std::regex(pattern)))
        << "'" << reply.message << "' (" << reply.message.size() << " bytes) is not " << pattern;
}

void expect_placement_refusals(const sim::WorldSpec& world, const Pose2& near_an_obstacle,
                               const std::string& obstacle) {
    SCOPED_TRACE(world.name);
    const auto server = testing::start_test_server(20.0, {}, world);
    comms::ControlClient control(loopback(server->ports().control));
    const std::string number = kNumber;
    const std::string box =
        "(x|y) = " + number + " m: the chassis fits in " + number + " … " + number + " m";
    const std::string near = R"(pose \()" + number + ", " + number + R"(\) m is nearer than )"
                             + number + " m to " + obstacle;
    for (const auto& [op, name] :
         {std::pair{ControlOp::Teleport, "teleport"}, std::pair{ControlOp::Reset, "reset"}}) {
        const std::string prefix = std::string(name) + ": ";
        for (const Pose2 pose : {Pose2{-kHuge, -kHuge, 0.0}, Pose2{kHuge, 0.0, 0.0},
                                 Pose2{world.start.x, -kHuge, 0.0}}) {
            expect_refusal(control, placing(op, pose), ControlResult::Rejected, prefix + box);
        }
        expect_refusal(control, placing(op, near_an_obstacle), ControlResult::Rejected,
                       prefix + near);
    }
}

TEST(RefusalMessages, PlacementsInEveryBuiltInWorld) {
    // The standard arena and the beacon field have their walls on the box's edge only: a wall
    // inside one shows the "nearer than" message with the longest numbers a pose inside the
    // box can print.
    for (const char* name : {"standard_arena", "beacon_field"}) {
        const sim::WorldSpec* world = lessons::find_built_in_world(name);
        ASSERT_NE(world, nullptr) << name;
        sim::WorldSpec with_inner_wall = *world;
        with_inner_wall.walls.push_back({"inner", Vector2(0.0, -0.5), Vector2(0.0, 0.5)});
        expect_placement_refusals(with_inner_wall, Pose2{-1.23456789e-100, -1.23456789e-100, 0.0},
                                  "a wall");
    }
    const sim::WorldSpec* office = lessons::find_built_in_world("office");
    ASSERT_NE(office, nullptr);
    expect_placement_refusals(*office, Pose2{3.00000123456, 0.150000123456, 0.0},
                              "an occupied cell");
}

TEST(RefusalMessages, NoiseTimeScaleAndUnknownOps) {
    const auto server = testing::start_test_server(20.0);
    comms::ControlClient control(loopback(server->ports().control));
    const std::string number = kNumber;
    const std::string noise_field = "(wheel_diameter_ratio|wheel_base_ratio|slip_noise|ir_noise)";
    const std::string one = "set noise: " + noise_field + " = " + number + ": must be between "
                            + number + " and " + number;
    for (const comms::NoiseSettings settings :
         {comms::NoiseSettings{-kHuge, 1.0, 0.0, 0.0}, comms::NoiseSettings{1.0, -kHuge, 0.0, 0.0},
          comms::NoiseSettings{1.0, 1.0, -kHuge, 0.0},
          comms::NoiseSettings{1.0, 1.0, 0.0, -kHuge}}) {
        expect_refusal(control, noise(settings), ControlResult::Rejected, one);
    }
    expect_refusal(control, noise({-kHuge, -kHuge, -kHuge, -kHuge}), ControlResult::Rejected,
                   one + R"( \(and 3 more\))");

    const std::string scale =
        "set time scale: time_scale = " + number + ": must be 0 or between 0.05 and 1000";
    for (const double value : {-kHuge, kHuge, 0.01, 5000.0}) {
        expect_refusal(control, time_scale(value), ControlResult::Rejected, scale);
    }
    for (const std::uint8_t op : {std::uint8_t{0}, std::uint8_t{8}, std::uint8_t{255}}) {
        expect_refusal(control, unknown(op), ControlResult::UnknownOp, "unknown op [0-9]+");
    }
    // The refused requests changed nothing.
    const comms::ServerStatus status = control.status();
    EXPECT_EQ(status.noise, comms::NoiseSettings{});
    EXPECT_DOUBLE_EQ(status.time_scale, 20.0);
}

}  // namespace
}  // namespace legofeup
