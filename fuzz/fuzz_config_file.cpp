// libFuzzer target for the run-configuration reader (apply_config_toml, docs/configuration.md):
// any bytes give a configuration or an InputError; one that reads writes out (config_to_toml)
// to a document that reads back to the same document, as config_to_toml promises.

#include "legofeup/lessons/config_file.hpp"
#include "reader_fuzzing.hpp"

using namespace legofeup;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return fuzzing::fuzz_reader(data, size, [](std::string_view text) {
        lessons::RunConfig config;
        lessons::apply_config_toml(text, "config.toml", config, {});
        const std::string written = lessons::config_to_toml(config, "fuzzed");
        lessons::RunConfig again;
        try {
            lessons::apply_config_toml(written, "written.toml", again, {});
        } catch (const lessons::InputError&) {
            fuzzing::check(false);  // the reader refuses what the writer wrote
        }
        fuzzing::check(lessons::config_to_toml(again, "fuzzed") == written);
    });
}
