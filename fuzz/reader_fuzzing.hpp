#pragma once
// What the fuzz targets of the file readers share (one target per reader of a file a user
// hands in: docs/architecture.md, "Files users hand in"). A reader answers bad input with
// an InputError, the "file:line: key = value: reason" error the programs print and go on
// after (a batch grading a folder catches InputError alone); every problem in it has a
// reason. Anything else (another exception escaping LLVMFuzzerTestOneInput, a crash, a
// sanitizer report, a failed check) is a bug, and libFuzzer stops with its input.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "legofeup/lessons/input_error.hpp"

namespace legofeup::fuzzing {

/// Stops the fuzzer (abort: libFuzzer keeps the input) when `condition` is false.
inline void check(bool condition) {
    if (!condition) {
        std::abort();
    }
}

/// Runs `read` on the input as text; an InputError is an answer, checked to be a clear one.
template <typename Read>
int fuzz_reader(const std::uint8_t* data, std::size_t size, Read read) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        read(text);
    } catch (const lessons::InputError& error) {
        check(!error.problems().empty());
        for (const lessons::InputProblem& problem : error.problems()) {
            check(!problem.reason.empty());
        }
    }
    return 0;
}

}  // namespace legofeup::fuzzing
