// libFuzzer target for the shard reader (parse_shard_file, docs/analysis.md): a damaged or
// foreign shard gives a shard or an InputError, whatever its bytes.

#include "legofeup/lessons/analysis/shard_file.hpp"
#include "reader_fuzzing.hpp"

using namespace legofeup;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return fuzzing::fuzz_reader(data, size, [](std::string_view text) {
        const lessons::analysis::ShardFile shard =
            lessons::analysis::parse_shard_file(std::string(text), "shard.json");
        fuzzing::check(shard.shard.index >= 1 && shard.shard.index <= shard.shard.count);
    });
}
