// libFuzzer target for the IR calibration measurements reader (parse_ir_points_csv,
// docs/calibration.md): any bytes give measurements or an InputError; measurements that
// read are usable (A ≥ 0, D > 0, both finite).

#include <cmath>

#include "legofeup/lessons/calibration/ir_calibration.hpp"
#include "reader_fuzzing.hpp"

using namespace legofeup;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return fuzzing::fuzz_reader(data, size, [](std::string_view text) {
        for (const auto& point : lessons::parse_ir_points_csv(text, "points.csv")) {
            fuzzing::check(std::isfinite(point.adc) && point.adc >= 0.0);
            fuzzing::check(std::isfinite(point.distance) && point.distance > 0.0);
        }
    });
}
