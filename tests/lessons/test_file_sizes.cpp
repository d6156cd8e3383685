// The readers refuse a file larger than its kind may be before reading it, naming the file,
// its size and the limit (docs/configuration.md, "File sizes"): a wrong file — a disk image
// named as a run log, /dev/zero as a configuration — is an error, not the memory filled.
// The large files here are sparse: they take no disk space, and reading one whole would
// take seconds and gigabytes, so a reader that reads before it checks fails loudly.

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

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
#include "scratch_dir_test_support.hpp"

namespace legofeup::lessons {
namespace {

using namespace scratch_testing;

constexpr std::uintmax_t kMiB = 1024 * 1024;

/// What `read` throws for `path`, or "(no error)".
std::string read_message_of(const std::function<void(const fs::path&)>& read,
                            const fs::path& path) {
    try {
        read(path);
    } catch (const InputError& error) {
        return error.what();
    }
    return "(no error)";
}

/// A file of `size` zero bytes that takes no disk space.
fs::path sparse_file(const std::string& name, std::uintmax_t size) {
    const fs::path path = temp_dir() / name;
    write_file(path, "");
    fs::resize_file(path, size);
    return path;
}

struct Reader {
    const char* kind;  ///< as the message names it
    std::uintmax_t limit;
    std::function<void(const fs::path&)> read;
};

// Every reader of a file a user hands in, with the limit docs/configuration.md gives.
const std::vector<Reader>& readers() {
    static const std::vector<Reader> all = {
        {"configuration", 16 * kMiB, [](const fs::path& p) { load_config_file(p, {}); }},
        {"lesson", 16 * kMiB, [](const fs::path& p) { load_lesson_file(p); }},
        {"submission", 16 * kMiB,
         [](const fs::path& p) { load_submission_file(p, legofeup_lesson()); }},
        {"world", 16 * kMiB, [](const fs::path& p) { load_world_file(p); }},
        {"robot profile", 16 * kMiB, [](const fs::path& p) { load_robot_profile(p.string()); }},
        {"map", 16 * kMiB, [](const fs::path& p) { load_map_file(p); }},
        {"measurements", 16 * kMiB, [](const fs::path& p) { read_ir_points_csv(p.string()); }},
        {"run log", 1024 * kMiB, [](const fs::path& p) { load_run_log(p); }},
        {"shard", 256 * kMiB, [](const fs::path& p) { analysis::read_shard_file(p); }},
    };
    return all;
}

TEST(FileSizes, AFileOneByteAboveItsKindsLimitIsRefusedUnread) {
    for (const Reader& reader : readers()) {
        const fs::path path = sparse_file("too_large", reader.limit + 1);
        EXPECT_EQ(read_message_of(reader.read, path),
                  path.string() + ": the file is " + std::to_string(reader.limit + 1) + " bytes: "
                      + reader.kind + " files may be at most " + std::to_string(reader.limit / kMiB)
                      + " MiB (" + std::to_string(reader.limit) + " bytes)")
            << reader.kind;
        fs::remove(path);  // sparse, but it looks like gigabytes to anyone listing /tmp
    }
}

TEST(FileSizes, AFileAtTheLimitIsReadAndParsed) {
    // 16 MiB of zero bytes is no TOML: the parser's error, not the size's.
    const fs::path path = sparse_file("at_limit.toml", 16 * kMiB);
    const std::string message = read_message_of(readers().front().read, path);
    EXPECT_EQ(message.find("may be at most"), std::string::npos) << message;
    EXPECT_EQ(message.rfind(path.string() + ":1: ", 0), 0U) << message;
    fs::remove(path);
}

TEST(FileSizes, AStreamWithoutASizeIsReadUpToTheLimit) {
    // /dev/zero has no size to check first: read up to the limit and one byte more.
    EXPECT_EQ(read_message_of(readers().front().read, "/dev/zero"),
              "/dev/zero: the file is more than 16777216 bytes: configuration files may be at "
              "most 16 MiB (16777216 bytes)");
}

TEST(FileSizes, ADirectoryIsNamedAsOne) {
    const fs::path dir = temp_dir();
    for (const Reader& reader : readers()) {
        EXPECT_EQ(read_message_of(reader.read, dir),
                  dir.string() + ": cannot open the " + reader.kind + " file: it is a directory");
    }
}

TEST(FileSizes, AMapImageWhoseHeaderFitsButWhoseFileIsTooLargeIsRefusedUnread) {
    // A 4000 × 4000 header is accepted; the file behind it is 200 MB, above the 128 MiB a
    // map image may be (its pixels would be 16 MB).
    const fs::path dir = temp_dir();
    write_file(dir / "map.yaml",
               "image: map.pgm\nresolution: 0.05\norigin: [0, 0, 0]\noccupied_thresh: 0.65\n"
               "free_thresh: 0.196\nnegate: 0\n");
    write_file(dir / "map.pgm", "P5\n4000 4000\n255\n");
    fs::resize_file(dir / "map.pgm", 200'000'000);
    EXPECT_EQ(read_message_of([](const fs::path& p) { load_map_file(p); }, dir / "map.yaml"),
              (dir / "map.pgm").string()
                  + ": the file is 200000000 bytes: map image files may be at most 128 MiB "
                    "(134217728 bytes)");
    fs::remove(dir / "map.pgm");
}

}  // namespace
}  // namespace legofeup::lessons
