// libFuzzer target for the submission reader (parse_submission against the built-in
// LegoFeup lesson, docs/grading.md): a student's file gives a submission or an InputError,
// whatever its bytes; one that reads writes out (submission_to_toml) to a document that
// reads back to the same document.

#include "legofeup/lessons/submission.hpp"
#include "reader_fuzzing.hpp"

using namespace legofeup;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const lessons::Lesson& lesson = lessons::legofeup_lesson();
    return fuzzing::fuzz_reader(data, size, [&](std::string_view text) {
        const std::string written =
            lessons::submission_to_toml(lessons::parse_submission(text, "student.toml", lesson));
        std::string again;
        try {
            again = lessons::submission_to_toml(
                lessons::parse_submission(written, "written.toml", lesson));
        } catch (const lessons::InputError&) {
            fuzzing::check(false);  // the reader refuses what the writer wrote
        }
        fuzzing::check(again == written);
    });
}
