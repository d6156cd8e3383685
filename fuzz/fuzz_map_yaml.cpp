// libFuzzer target for a map's YAML file (parse_map_yaml, docs/maps.md; the image it names
// has its own target, fuzz_pgm_image): any bytes give metadata or an InputError; metadata
// that reads is usable (a positive finite resolution, thresholds ordered within [0, 1]).

#include <cmath>

#include "legofeup/lessons/map_file.hpp"
#include "reader_fuzzing.hpp"

using namespace legofeup;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return fuzzing::fuzz_reader(data, size, [](std::string_view text) {
        const lessons::MapMetadata map = lessons::parse_map_yaml(text, "map.yaml");
        fuzzing::check(std::isfinite(map.resolution) && map.resolution > 0.0);
        fuzzing::check(0.0 <= map.free_thresh && map.free_thresh < map.occupied_thresh
                       && map.occupied_thresh <= 1.0);
        fuzzing::check(!map.image.empty());
    });
}
