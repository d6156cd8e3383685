// libFuzzer target for the run-log reader (parse_run_log, docs/recording.md): a cut,
// garbled or foreign log gives a log or an InputError, whatever its bytes; a log that reads
// has steps that follow each other, and says why when it did not end normally.

#include "legofeup/lessons/recording/run_log.hpp"
#include "reader_fuzzing.hpp"

using namespace legofeup;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return fuzzing::fuzz_reader(data, size, [](std::string_view text) {
        const lessons::RunLog log = lessons::parse_run_log(std::string(text), "run.log");
        for (std::size_t i = 1; i < log.records.size(); ++i) {
            fuzzing::check(log.records[i].step == log.records[i - 1].step + 1);
        }
        fuzzing::check(log.ended || !log.notes.empty());
    });
}
