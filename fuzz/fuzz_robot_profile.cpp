// libFuzzer target for the robot-profile reader (parse_robot_profile, docs/calibration.md):
// any bytes give a profile or an InputError; one that reads writes out (robot_profile_to_toml)
// to a document that reads back to the same document.

#include "legofeup/lessons/robot_profile.hpp"
#include "reader_fuzzing.hpp"

using namespace legofeup;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return fuzzing::fuzz_reader(data, size, [](std::string_view text) {
        const lessons::RobotProfile profile = lessons::parse_robot_profile(text, "robot.toml");
        const std::string written = lessons::robot_profile_to_toml(profile);
        std::string again;
        try {
            again = lessons::robot_profile_to_toml(
                lessons::parse_robot_profile(written, "written.toml"));
        } catch (const lessons::InputError&) {
            fuzzing::check(false);  // the reader refuses what the writer wrote
        }
        fuzzing::check(again == written);
    });
}
