// libFuzzer target for the lesson reader (parse_lesson, docs/lessons.md): a colleague's
// lesson opened in the GUI gives a lesson or an InputError, whatever its bytes.

#include "legofeup/lessons/lesson.hpp"
#include "reader_fuzzing.hpp"

using namespace legofeup;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return fuzzing::fuzz_reader(
        data, size, [](std::string_view text) { lessons::parse_lesson(text, "lesson.toml", {}); });
}
