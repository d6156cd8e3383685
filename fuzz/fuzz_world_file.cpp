// libFuzzer target for the world reader (parse_world, docs/configuration.md): any bytes give
// a world or an InputError. Relative paths in a world are read from fuzz/world_map/, which
// holds a small valid map (map.yaml, map.pgm: 4 × 3 cells of 0.25 m, the second column
// occupied), so the seeds' [map] file = "map.yaml" reaches the map's reading and the
// start-in-a-wall check too; the map's own readers have their own targets.

#include "legofeup/lessons/world_file.hpp"
#include "reader_fuzzing.hpp"

using namespace legofeup;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return fuzzing::fuzz_reader(data, size, [](std::string_view text) {
        lessons::parse_world(text, "world.toml", LEGOFEUP_FUZZ_WORLD_MAP_DIR);
    });
}
