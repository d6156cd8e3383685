#pragma once
// Shared by the calibration tests: a scratch directory per test and the message of an
// InputError a call throws.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "legofeup/lessons/input_error.hpp"

namespace legofeup::testing {

/// A fresh directory for the running test, removed with the fixture.
class ScratchDirectory : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = std::filesystem::temp_directory_path() / "legofeup_calibration_tests"
               / (std::string(info->test_suite_name()) + "." + info->name());
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& text) const {
        const std::filesystem::path path = dir_ / name;
        std::ofstream(path, std::ios::binary) << text;
        return path.string();
    }

    std::filesystem::path dir_;
};

inline std::string read_text(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    // Through rdbuf, not istreambuf_iterator: GCC 12 at -O3 reports a null dereference
    // inside the iterator's inlined streambuf calls (a false positive).
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

/// What `call` throws as an InputError, or "" (and a test failure) when it throws nothing.
inline std::string input_error_of(const std::function<void()>& call) {
    try {
        call();
    } catch (const lessons::InputError& error) {
        return error.what();
    }
    ADD_FAILURE() << "no InputError was thrown";
    return {};
}

}  // namespace legofeup::testing
