// Where Reset and Teleport may put the robot (docs/protocol.md, "Where the robot may be
// put"), over loopback. The limits are computed here from the rule as the document states
// it (the walls' and the map's bounding box, less the chassis' reach; no wall and no occupied
// cell nearer than the reach), not taken from the server's code.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <regex>
#include <string>
#include <utility>

#include "legofeup/comms/control_client.hpp"
#include "legofeup/comms/link_error.hpp"
#include "legofeup/comms/truth_receiver.hpp"
#include "support/test_server.hpp"

namespace legofeup {
namespace {

using namespace std::chrono_literals;
using comms::ControlClient;
using testing::loopback;
using testing::start_test_server;

constexpr double kPi = 3.14159265358979323846;
/// How far inside or outside a limit the poses below lie, m.
constexpr double kMargin = 1e-6;

/// The chassis' reach as the document defines it: the corner of the chassis rectangle
/// farthest from the axle, sqrt(max(front, rear)² + half_width²).
double documented_reach(const sim::RobotSpec& robot) {
    const double along = std::max(robot.chassis_front, robot.chassis_rear);
    return std::sqrt(along * along + robot.chassis_half_width * robot.chassis_half_width);
}

struct Box {
    double low_x;
    double high_x;
    double low_y;
    double high_y;
};

/// The walls' end points' bounding box and the map's extent (origin + size, no yaw in the
/// built-in worlds), shrunk by the reach.
Box documented_box(const sim::WorldSpec& world, double reach) {
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    Box box{kInfinity, -kInfinity, kInfinity, -kInfinity};
    const auto include = [&](double x, double y) {
        box = {std::min(box.low_x, x), std::max(box.high_x, x), std::min(box.low_y, y),
               std::max(box.high_y, y)};
    };
    for (const Wall& wall : world.walls) {
        include(wall.start.x(), wall.start.y());
        include(wall.end.x(), wall.end.y());
    }
    if (world.map) {
        const OccupancyGrid& map = *world.map;
        include(map.origin().x, map.origin().y);
        include(map.origin().x + map.width() * map.resolution(),
                map.origin().y + map.height() * map.resolution());
    }
    return {box.low_x + reach, box.high_x - reach, box.low_y + reach, box.high_y - reach};
}

bool refused(ControlClient& control, const Pose2& pose, const std::string& expected_part) {
    try {
        control.teleport(pose);
    } catch (const comms::LinkError& error) {
        EXPECT_NE(std::string(error.what()).find(expected_part), std::string::npos) << error.what();
        return true;
    }
    return false;
}

TEST(Placement, TheStandardArenasLimitsAreTheDocumentedRule) {
    const sim::WorldSpec& arena = lessons::built_in_world();
    const double reach = documented_reach(sim::RobotSpec{});
    const Box box = documented_box(arena, reach);
    // The numbers docs/protocol.md and docs/arena.md print: a reach of 0.106301458 m and
    // limits of ±1.10369854 m.
    EXPECT_NEAR(reach, 0.106301458, 1e-9);
    for (const double limit : {-box.low_x, box.high_x, -box.low_y, box.high_y}) {
        EXPECT_NEAR(limit, 1.10369854, 1e-8);
    }

    const auto server = start_test_server(20.0);
    ControlClient control(loopback(server->ports().control));
    const double in_low_x = box.low_x + kMargin;
    const double in_high_x = box.high_x - kMargin;
    const double in_low_y = box.low_y + kMargin;
    const double in_high_y = box.high_y - kMargin;
    // Just inside every corner and the middle of every side, at any heading.
    for (const double heading : {0.0, 1.0, -2.5, kPi}) {
        for (const Pose2 pose :
             {Pose2{in_low_x, in_low_y, heading}, Pose2{in_high_x, in_low_y, heading},
              Pose2{in_high_x, in_high_y, heading}, Pose2{in_low_x, in_high_y, heading},
              Pose2{in_low_x, 0.0, heading}, Pose2{in_high_x, 0.0, heading},
              Pose2{0.0, in_low_y, heading}, Pose2{0.0, in_high_y, heading}}) {
            EXPECT_NO_THROW(control.teleport(pose)) << pose.x << ", " << pose.y;
        }
    }
    EXPECT_NO_THROW(control.reset(1, Pose2{in_high_x, in_low_y, 0.5}));
    // Just outside every side: refused, and the message gives the limits.
    for (const Pose2 pose :
         {Pose2{box.low_x - kMargin, 0.0, 0.0}, Pose2{box.high_x + kMargin, 0.0, 0.0}}) {
        EXPECT_TRUE(refused(control, pose, "x = ")) << pose.x;
    }
    for (const Pose2 pose :
         {Pose2{0.0, box.low_y - kMargin, 0.0}, Pose2{0.0, box.high_y + kMargin, 0.0}}) {
        EXPECT_TRUE(refused(control, pose, "the chassis fits in -1.10369854 … 1.10369854 m"))
            << pose.y;
    }
    EXPECT_THROW(control.reset(1, Pose2{box.high_x + kMargin, 0.0, 0.0}), comms::LinkError);

    // The last accepted pose is where the robot is: the truth stream says so.
    const Pose2 corner{in_high_x, in_high_y, 1.0};
    const comms::ServerStatus moved = control.teleport(corner);
    const double after = static_cast<double>(moved.steps + 1) * moved.control_period;
    comms::TruthReceiver truth(loopback(server->ports().truth));
    std::optional<GroundTruth> seen;
    for (int i = 0; i < 100 && !(seen && seen->time >= after); ++i) {
        truth.poll(20ms);
        seen = truth.latest();
    }
    ASSERT_TRUE(seen && seen->time >= after);
    EXPECT_NEAR(seen->pose.x, corner.x, 1e-4);  // Box2D keeps positions in floats
    EXPECT_NEAR(seen->pose.y, corner.y, 1e-4);
    EXPECT_NEAR(seen->pose.theta, corner.theta, 1e-4);
    EXPECT_FALSE(seen->touching_wall);
}

/// What a refusal prints: "...: x = VALUE m: the chassis fits in LOW … HIGH m".
struct Printed {
    double value;
    double low;
    double high;
};

Printed printed_refusal(ControlClient& control, const Pose2& pose) {
    const comms::ControlReplyPacket reply = control.request([&] {
        comms::ControlRequestPacket request;
        request.op = static_cast<std::uint8_t>(comms::ControlOp::Teleport);
        request.pose = pose;
        return request;
    }());
    std::smatch numbers;
    if (!std::regex_search(reply.message, numbers,
                           std::regex("[xy] = (\\S+) m: the chassis fits in (\\S+) … (\\S+) m$"))) {
        ADD_FAILURE() << "not a refusal naming the limits: '" << reply.message << "'";
        return {};
    }
    return {std::stod(numbers[1].str()), std::stod(numbers[2].str()), std::stod(numbers[3].str())};
}

// A client (or a person) that takes the limits of a refusal at their word is not refused: they
// are rounded towards the inside (to 9 digits). In a world whose walls span 0 … 2 m the low
// limit is r = 0.10630145813 m, which to the nearest (0.106301458) would lie outside. And a
// refused coordinate a hair outside prints outside the printed limits, not equal to them.
TEST(Placement, TheLimitsARefusalPrintsAreAccepted) {
    sim::WorldSpec shifted = lessons::built_in_world();
    shifted.walls = {{"south", Vector2(0.0, 0.0), Vector2(2.0, 0.0)},
                     {"north", Vector2(0.0, 2.0), Vector2(2.0, 2.0)}};
    const double reach = documented_reach(sim::RobotSpec{});
    ASSERT_LT(std::stod("0.106301458"), documented_box(shifted, reach).low_x);  // the premise
    for (const sim::WorldSpec& world : {lessons::built_in_world(), shifted}) {
        SCOPED_TRACE(world.walls.front().name);
        const Box box = documented_box(world, reach);
        const double middle_x = 0.5 * (box.low_x + box.high_x);
        const double middle_y = 0.5 * (box.low_y + box.high_y);
        const auto server = start_test_server(20.0, {}, world);
        ControlClient control(loopback(server->ports().control));
        const Printed x = printed_refusal(control, Pose2{box.high_x + 1e-10, middle_y, 0.0});
        const Printed y = printed_refusal(control, Pose2{middle_x, box.low_y - 1e-10, 0.0});
        EXPECT_NEAR(x.low, box.low_x, 1e-8);
        EXPECT_NEAR(y.high, box.high_y, 1e-8);
        EXPECT_GT(x.value, x.high);
        EXPECT_LT(y.value, y.low);
        for (const Pose2 pose : {Pose2{x.low, middle_y, 0.0}, Pose2{x.high, middle_y, 0.0},
                                 Pose2{middle_x, y.low, 0.0}, Pose2{middle_x, y.high, 0.0}}) {
            EXPECT_NO_THROW(control.teleport(pose)) << pose.x << ", " << pose.y;
        }
    }
}

// A world that is a map alone (the office): its extent is the map's, and no occupied cell of
// the map the simulator uses (as built) may come nearer than the reach.
TEST(Placement, AMapOnlyWorldKeepsTheChassisClearOfItsOccupiedCells) {
    const sim::WorldSpec* office = lessons::find_built_in_world("office");
    ASSERT_NE(office, nullptr);
    ASSERT_TRUE(office->walls.empty());
    ASSERT_TRUE(office->map);
    const OccupancyGrid& map = *office->map;
    const double reach = documented_reach(sim::RobotSpec{});
    const Box box = documented_box(*office, reach);
    // docs/arena.md: 12 m × 8 m from the origin, so x 0.106301458 … 11.8936985 and
    // y 0.106301458 … 7.89369854.
    EXPECT_NEAR(box.low_x, 0.106301458, 1e-9);
    EXPECT_NEAR(box.high_x, 11.8936985, 1e-7);
    EXPECT_NEAR(box.low_y, 0.106301458, 1e-9);
    EXPECT_NEAR(box.high_y, 7.89369854, 1e-8);
    // The premise: at x = 1 m the outer wall along y = 0 is rows 0-4 of 0.02 m cells, so its
    // face is y = 0.10 m, with nothing else occupied within a reach above it.
    ASSERT_DOUBLE_EQ(map.resolution(), 0.02);
    const double face = 0.10;
    for (int col = 40; col <= 60; ++col) {
        ASSERT_TRUE(map.occupied({col, 4})) << col;
        for (int row = 5; row <= 20; ++row) {
            ASSERT_FALSE(map.occupied({col, row})) << col << ", " << row;
        }
    }

    const auto server = start_test_server(20.0, {}, *office);
    ControlClient control(loopback(server->ports().control));
    EXPECT_NO_THROW(control.reset(3, office->start));
    EXPECT_NO_THROW(control.teleport(Pose2{9.9, 0.8, 0.0}));  // the twin hall
    EXPECT_NO_THROW(control.teleport(Pose2{1.0, face + reach + kMargin, 2.0}));
    EXPECT_TRUE(refused(control, Pose2{1.0, face + reach - kMargin, 2.0}, "an occupied cell"));
    EXPECT_TRUE(refused(control, Pose2{3.0, 0.15, 0.0}, "an occupied cell"));  // in the box
    EXPECT_TRUE(refused(control, Pose2{3.0, 0.025, 0.0}, "y = 0.025 m"));      // in the wall
    EXPECT_TRUE(refused(control, Pose2{30.0, 0.8, 0.0}, "x = 30 m"));          // off the map
}

// A wall inside the box: the chassis keeps clear of it too, its ends included.
TEST(Placement, AWallInsideTheArenaKeepsTheChassisClear) {
    sim::WorldSpec world = lessons::built_in_world();
    world.walls.push_back({"inner", Vector2(0.0, -0.5), Vector2(0.0, 0.5)});
    const double reach = documented_reach(sim::RobotSpec{});
    const auto server = start_test_server(20.0, {}, world);
    ControlClient control(loopback(server->ports().control));
    EXPECT_NO_THROW(control.teleport(Pose2{reach + kMargin, 0.0, 0.0}));
    EXPECT_NO_THROW(control.teleport(Pose2{-reach - kMargin, 0.3, 0.0}));
    EXPECT_TRUE(refused(control, Pose2{reach - kMargin, 0.0, 0.0}, "to a wall"));
    EXPECT_NO_THROW(control.teleport(Pose2{0.0, 0.5 + reach + kMargin, 0.0}));  // past its end
    EXPECT_TRUE(refused(control, Pose2{0.05, 0.55, 0.0}, "to a wall"));  // 0.0707 m from the end
    EXPECT_THROW(control.reset(1, Pose2{0.0, 0.0, 0.0}), comms::LinkError);
}

}  // namespace
}  // namespace legofeup
