#pragma once
// Running the programs as a user does, from GoogleTest: each test gets its own directory
// under LEGOFEUP_TEST_TMP, and run() returns the exit code and what was printed. Servers
// (legofeup-sim, legofeup-nxt-emu) run in the background and are stopped after the test.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

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

    /// Runs `program arguments` through the shell, capturing stdout and stderr (in
    /// `<prefix>stdout.txt` and `<prefix>stderr.txt`: runs at the same time need their own
    /// prefixes).
    Result run_program(const std::string& program, const std::string& arguments,
                       const std::string& prefix = "") const {
        const std::filesystem::path out = dir_ / (prefix + "stdout.txt");
        const std::filesystem::path err = dir_ / (prefix + "stderr.txt");
        const std::string command =
            program + " " + arguments + " > " + out.string() + " 2> " + err.string();
        const int status = std::system(command.c_str());
        return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(out), read_file(err)};
    }

    /// Writes `text` to the file `name` in the test's directory; its path.
    std::filesystem::path write_file(const std::string& name, const std::string& text) const {
        const std::filesystem::path path = dir_ / name;
        std::ofstream(path, std::ios::binary) << text;
        return path;
    }

    /// Starts `program arguments` in the background, its output in `<name>.log`; the test's
    /// end stops it.
    void start_in_background(const std::string& program, const std::string& arguments,
                             const std::string& name) {
        const std::filesystem::path pid = dir_ / (name + ".pid");
        const std::string command = program + " " + arguments + " > "
                                    + (dir_ / (name + ".log")).string() + " 2>&1 & echo $! > "
                                    + pid.string();
        std::system(command.c_str());
        background_.push_back(pid);
    }

    /// Waits until `path` exists (a server's ready file); false after `patience`.
    static bool wait_for_file(const std::filesystem::path& path,
                              std::chrono::milliseconds patience) {
        const auto give_up = std::chrono::steady_clock::now() + patience;
        while (!std::filesystem::exists(path)) {
            if (std::chrono::steady_clock::now() > give_up) {
                return false;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        return true;
    }

    void TearDown() override {
        for (const std::filesystem::path& pid : background_) {
            std::system(("kill $(cat " + pid.string() + ") 2>/dev/null").c_str());
        }
    }

    std::filesystem::path dir_;

  private:
    std::vector<std::filesystem::path> background_;
};

}  // namespace legofeup::testing
