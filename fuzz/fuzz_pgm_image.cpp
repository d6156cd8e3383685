// libFuzzer target for a map's PGM image (parse_pgm, docs/maps.md): any bytes give an image
// or an InputError. An image that reads holds width·height pixels, none above its maxval,
// within the size limit, and written again as a binary P5 it reads back to the same pixels
// (whichever of P5 and P2 it came as).

#include <algorithm>

#include "legofeup/lessons/pgm_image.hpp"
#include "reader_fuzzing.hpp"

using namespace legofeup;

namespace {

std::string as_p5(const lessons::GreyImage& image) {
    std::string bytes = "P5\n" + std::to_string(image.width) + " " + std::to_string(image.height)
                        + "\n" + std::to_string(image.max_value) + "\n";
    for (const std::uint16_t value : image.pixels) {
        if (image.max_value > 255) {
            bytes += static_cast<char>(value >> 8U);
        }
        bytes += static_cast<char>(value & 0xffU);
    }
    return bytes;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return fuzzing::fuzz_reader(data, size, [](std::string_view bytes) {
        const lessons::GreyImage image = lessons::parse_pgm(bytes, "map.pgm");
        fuzzing::check(image.width >= 1 && image.width <= lessons::kMaxMapImageSide);
        fuzzing::check(image.height >= 1 && image.height <= lessons::kMaxMapImageSide);
        fuzzing::check(image.pixels.size()
                       == static_cast<std::size_t>(image.width)
                              * static_cast<std::size_t>(image.height));
        fuzzing::check(std::all_of(image.pixels.begin(), image.pixels.end(),
                                   [&](std::uint16_t value) { return value <= image.max_value; }));
        lessons::GreyImage again;
        try {
            again = lessons::parse_pgm(as_p5(image), "written.pgm");
        } catch (const lessons::InputError&) {
            fuzzing::check(false);
        }
        fuzzing::check(again.width == image.width && again.height == image.height
                       && again.max_value == image.max_value && again.pixels == image.pixels);
    });
}
