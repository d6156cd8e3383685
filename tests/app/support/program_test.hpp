#pragma once
// Running the programs as a user does, from GoogleTest: each test gets its own directory
// under LEGOFEUP_TEST_TMP, and run() returns the exit code and what was printed.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace legofeup::testing {

struct Result {
    int exit_code;
    std::string out;
    std::string err;
};

inline std::string read_file(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

class ProgramTest : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = std::filesystem::path(LEGOFEUP_TEST_TMP) / info->name();
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }

    /// Runs `program arguments` through the shell, capturing stdout and stderr.
    Result run_program(const std::string& program, const std::string& arguments) const {
        const std::filesystem::path out = dir_ / "stdout.txt";
        const std::filesystem::path err = dir_ / "stderr.txt";
        const std::string command =
            program + " " + arguments + " > " + out.string() + " 2> " + err.string();
        const int status = std::system(command.c_str());
        return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(out), read_file(err)};
    }

    std::filesystem::path dir_;
};

}  // namespace legofeup::testing
