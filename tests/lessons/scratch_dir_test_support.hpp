// A scratch directory per process and test (ctest runs tests in parallel processes) and
// writing a file into it, for the tests that read files from disk.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace legofeup::lessons::scratch_testing {

namespace fs = std::filesystem;

/// <tmp>/legofeup_lessons_tests_<pid>/<suite>.<test>, created.
inline fs::path temp_dir() {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path dir = fs::temp_directory_path()
                         / ("legofeup_lessons_tests_" + std::to_string(::getpid()))
                         / (std::string(test->test_suite_name()) + "." + test->name());
    fs::create_directories(dir);
    return dir;
}

/// Writes `bytes` as they are, creating the file's directories.
inline void write_file(const fs::path& path, const std::string& bytes) {
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << bytes;
}

}  // namespace legofeup::lessons::scratch_testing
