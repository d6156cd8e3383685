#pragma once
// PGM images, the pixels of an occupancy-grid map (map_file.hpp; docs/maps.md): binary (P5,
// 8 or 16 bits per pixel, most significant byte first) or plain (P2, decimal numbers), with
// '#' comments in the header. Row 0 is the top row, as stored.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace legofeup::lessons {

/// Images may be at most this many pixels wide and high.
inline constexpr int kMaxMapImageSide = 4096;

/// A file's header must end within its first this many bytes (a header is a few short
/// lines: magic number, width, height, maxval and their comments).
inline constexpr std::size_t kMaxPgmHeaderBytes = 64 * 1024;

/// A grey image as stored: row 0 is the top row, values 0 … max_value.
struct GreyImage {
    int width = 0;
    int height = 0;
    int max_value = 255;
    std::vector<std::uint16_t> pixels;  ///< row-major, width·height values

    std::uint16_t at(int column, int row) const {
        return pixels[static_cast<std::size_t>(row) * static_cast<std::size_t>(width)
                      + static_cast<std::size_t>(column)];
    }
};

/// Parses a PGM image; throws InputError ("<source>:<line>: PGM header: …", "<source>:
/// expected … pixels, found …") on anything malformed or larger than kMaxMapImageSide ×
/// kMaxMapImageSide. The size is checked from the header, before any pixel is read.
GreyImage parse_pgm(std::string_view bytes, const std::string& source);

/// Reads a PGM file header first: its first kMaxPgmHeaderBytes bytes, whose header must
/// accept the image's size before the rest of the file is read (a 20000 × 20000 image is
/// refused, naming its size, without reading its 400 MB). Problems as parse_pgm's, with
/// the path as their source.
GreyImage read_pgm_file(const std::filesystem::path& path);

}  // namespace legofeup::lessons
