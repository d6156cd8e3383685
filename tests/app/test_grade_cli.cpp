// legofeup-cli grade as a teacher runs it: one submission to JSON, a folder to CSV.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/program_test.hpp"

namespace {

namespace fs = std::filesystem;

using legofeup::testing::read_file;
using legofeup::testing::Result;

constexpr const char* kGoodSubmission = R"(lesson = "legofeup"
students = "Ana Silva, Rui Costa"

[answers.a]
q1 = "The ellipse keeps growing."
)";

constexpr const char* kOdometryOnly = R"(lesson = "legofeup"
students = "Eva"

[tuning.filter]
wall_updates = false
)";

// Line 4 sets a key outside what the lesson lets students tune.
constexpr const char* kCheating = R"(lesson = "legofeup"
students = "Max"
[tuning.simulator]
ir_noise = 0.0
)";

class GradeCli : public legofeup::testing::ProgramTest {
  protected:
    Result grade(const std::string& arguments) const {
        return run_program(LEGOFEUP_CLI, "grade --seeds 3 --laps 1 " + arguments);
    }
    fs::path write(const fs::path& path, const std::string& text) const {
        fs::create_directories(path.parent_path());
        std::ofstream(path) << text;
        return path;
    }
};

TEST_F(GradeCli, OneSubmissionGivesTheSameJsonEveryTime) {
    const fs::path file = write(dir_ / "ana.toml", kGoodSubmission);
    const Result first = grade("--submission " + file.string());
    ASSERT_EQ(first.exit_code, 0) << first.err;
    const nlohmann::json json = nlohmann::json::parse(first.out);
    EXPECT_EQ(json["lesson"], "legofeup");
    EXPECT_EQ(json["step"], "f");
    EXPECT_EQ(json["students"], "Ana Silva, Rui Costa");
    EXPECT_EQ(json["per_seed"].size(), 3u);
    EXPECT_TRUE(json["passed"].get<bool>()) << json["summary"];
    EXPECT_NE(first.err.find("PASS"), std::string::npos);  // the summary for people

    const Result again = grade("--jobs 1 --submission " + file.string());
    EXPECT_EQ(again.out, first.out);  // deterministic, whatever the number of jobs
}

TEST_F(GradeCli, APoorTuningFailsAndSaysWhichCheck) {
    const fs::path file = write(dir_ / "eva.toml", kOdometryOnly);
    const fs::path out = dir_ / "eva.json";
    const Result result = grade("--submission " + file.string() + " --out " + out.string());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.out.rfind("FAIL", 0), 0u) << result.out;
    const nlohmann::json json = nlohmann::json::parse(read_file(out));
    EXPECT_FALSE(json["passed"].get<bool>());
    EXPECT_LT(json["checks_passed"].get<int>(), json["checks_total"].get<int>());
}

TEST_F(GradeCli, AMalformedSubmissionIsRejectedWithItsLine) {
    const fs::path file = write(dir_ / "max.toml", kCheating);
    const Result result = grade("--submission " + file.string());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.err.find("max.toml:4"), std::string::npos) << result.err;
    EXPECT_TRUE(result.out.empty());
}

TEST_F(GradeCli, AFolderGivesOneRowEachAndAnErrorRowDoesNotStopTheBatch) {
    const fs::path folder = dir_ / "submissions";
    write(folder / "a_ana.toml", kGoodSubmission);
    write(folder / "b_max.toml", kCheating);
    write(folder / "c_eva.toml", kOdometryOnly);
    write(folder / "notes.txt", "not a submission");
    const fs::path csv = dir_ / "results.csv";
    const Result result = grade("--submissions " + folder.string() + " --out " + csv.string()
                                + " --details " + (dir_ / "details").string());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_NE(result.out.find("3 submissions: 2 graded (1 passed), 1 with errors"),
              std::string::npos)
        << result.out;

    std::istringstream rows(read_file(csv));
    std::string header, ana, max, eva, extra;
    std::getline(rows, header);
    std::getline(rows, ana);
    std::getline(rows, max);
    std::getline(rows, eva);
    EXPECT_FALSE(std::getline(rows, extra));
    EXPECT_EQ(header.rfind("submission,students,status,passed", 0), 0u);
    EXPECT_EQ(ana.rfind("a_ana.toml,\"Ana Silva, Rui Costa\",graded,yes", 0), 0u) << ana;
    EXPECT_EQ(max.rfind("b_max.toml,,error", 0), 0u) << max;
    EXPECT_NE(max.find("b_max.toml:4"), std::string::npos) << max;
    EXPECT_EQ(eva.rfind("c_eva.toml,Eva,graded,no", 0), 0u) << eva;
    EXPECT_TRUE(fs::exists(dir_ / "details" / "a_ana.json"));

    // Two shards together hold exactly the rows of the whole batch.
    std::string sharded;
    for (const char* shard : {"1/2", "2/2"}) {
        const fs::path part = dir_ / (std::string("shard") + shard[0] + ".csv");
        ASSERT_EQ(grade("--submissions " + folder.string() + " --shard " + shard + " --out "
                        + part.string())
                      .exit_code,
                  0);
        std::istringstream lines(read_file(part));
        std::string line;
        std::getline(lines, line);  // header
        while (std::getline(lines, line)) {
            sharded += line + "\n";
        }
    }
    for (const std::string& row : {ana, max, eva}) {
        EXPECT_NE(sharded.find(row + "\n"), std::string::npos) << row;
    }
    EXPECT_EQ(sharded.size(), ana.size() + max.size() + eva.size() + 3);
}

TEST_F(GradeCli, NeedsExactlyOneOfSubmissionOrFolder) {
    const Result none = grade("");
    EXPECT_EQ(none.exit_code, 1);
    EXPECT_NE(none.err.find("--submission"), std::string::npos);
    const Result folder_without_out = grade("--submissions " + dir_.string());
    EXPECT_EQ(folder_without_out.exit_code, 1);
    EXPECT_NE(folder_without_out.err.find("--out"), std::string::npos);
    const Result bad_shard = grade("--submissions " + dir_.string() + " --shard 3/2 --out x.csv");
    EXPECT_EQ(bad_shard.exit_code, 1);
    EXPECT_NE(bad_shard.err.find("--shard"), std::string::npos) << bad_shard.err;
}

}  // namespace
