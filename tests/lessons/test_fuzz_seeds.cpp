// The seed corpora of the readers' fuzz targets (fuzz/corpus/<target>/) are valid files of
// their kind, read by the same entry point the target feeds: libFuzzer then starts from
// inputs that reach past the first check. A seed that stops reading (a format changed, a
// lesson's step renamed) fails here, naming it and the reader's message.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "legofeup/lessons/analysis/shard_file.hpp"
#include "legofeup/lessons/calibration/ir_calibration.hpp"
#include "legofeup/lessons/config_file.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/lesson.hpp"
#include "legofeup/lessons/map_file.hpp"
#include "legofeup/lessons/recording/run_log.hpp"
#include "legofeup/lessons/robot_profile.hpp"
#include "legofeup/lessons/submission.hpp"
#include "legofeup/lessons/world_file.hpp"

namespace legofeup::lessons {
namespace {

namespace fs = std::filesystem;

const fs::path kFuzzDir = fs::path(LEGOFEUP_SOURCE_DIR) / "fuzz";

struct Target {
    const char* name;
    std::function<void(const std::string& text)> read;  ///< as fuzz/<name>.cpp reads
};

const std::vector<Target>& targets() {
    static const std::vector<Target> all = {
        {"fuzz_config_file",
         [](const std::string& text) {
             RunConfig config;
             apply_config_toml(text, "config.toml", config, {});
         }},
        {"fuzz_lesson", [](const std::string& text) { parse_lesson(text, "lesson.toml", {}); }},
        {"fuzz_submission",
         [](const std::string& text) {
             parse_submission(text, "student.toml", legofeup_lesson());
         }},
        {"fuzz_world_file",
         [](const std::string& text) { parse_world(text, "world.toml", kFuzzDir / "world_map"); }},
        {"fuzz_map_yaml", [](const std::string& text) { parse_map_yaml(text, "map.yaml"); }},
        {"fuzz_pgm_image", [](const std::string& text) { parse_pgm(text, "map.pgm"); }},
        {"fuzz_run_log", [](const std::string& text) { parse_run_log(text, "run.log"); }},
        {"fuzz_robot_profile",
         [](const std::string& text) { parse_robot_profile(text, "robot.toml"); }},
        {"fuzz_shard_file",
         [](const std::string& text) { analysis::parse_shard_file(text, "shard.json"); }},
        {"fuzz_ir_points",
         [](const std::string& text) { parse_ir_points_csv(text, "points.csv"); }},
    };
    return all;
}

std::string read_bytes(const fs::path& path) {
    // Through rdbuf, not istreambuf_iterator: GCC 12 at -O3 reports a null dereference
    // inside the iterator's inlined streambuf calls (a false positive).
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

TEST(FuzzSeeds, EveryReaderTargetHasSeedsAndEachSeedReads) {
    for (const Target& target : targets()) {
        const fs::path corpus = kFuzzDir / "corpus" / target.name;
        ASSERT_TRUE(fs::is_directory(corpus)) << corpus;
        int seeds = 0;
        for (const fs::directory_entry& seed : fs::directory_iterator(corpus)) {
            ++seeds;
            try {
                target.read(read_bytes(seed.path()));
            } catch (const InputError& error) {
                ADD_FAILURE() << seed.path() << " does not read:\n" << error.what();
            }
        }
        EXPECT_GE(seeds, 1) << corpus;
    }
}

TEST(FuzzSeeds, TheSeedsTellAReaderThatAcceptsEverythingFromOneThatReads) {
    // The premise of the test above: the readers it runs do refuse a file of another kind.
    for (const Target& target : targets()) {
        EXPECT_THROW(target.read("\x01 not a file of any kind"), InputError) << target.name;
    }
}

}  // namespace
}  // namespace legofeup::lessons
