#include "legofeup/lessons/pgm_image.hpp"

#include <algorithm>
#include <optional>

#include "legofeup/lessons/input_error.hpp"
#include "text_file.hpp"

namespace legofeup::lessons {
namespace {

constexpr int kMaxPgmValue = 65535;          // the largest maxval PGM allows
constexpr long kNumberCap = 1'000'000'000L;  // larger numbers read as this: all too large
constexpr std::size_t kMaxWrittenDigits = 20;

bool is_space(char ch) {
    return ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r' || ch == '\v' || ch == '\f';
}

bool is_digit(char ch) {
    return ch >= '0' && ch <= '9';
}

/// A whole number of the file: its value (capped at kNumberCap) and its digits as written.
struct WholeNumber {
    long value = 0;
    std::string written;
};

/// Walks the text part of a PGM (the header, and the whole of a plain P2 file), counting
/// lines; comments run from '#' to the end of the line. The bytes may be only the first
/// part of the file (`more_follows`): reaching their end then means that the header goes
/// on beyond kMaxPgmHeaderBytes, which is refused.
class PgmText {
  public:
    PgmText(std::string_view bytes, std::string source, bool more_follows)
        : bytes_(bytes), source_(std::move(source)), more_follows_(more_follows) {}

    void skip_space_and_comments() {
        while (!past_end(position_)) {
            const char ch = bytes_[position_];
            if (ch == '#') {
                while (!past_end(position_) && bytes_[position_] != '\n') {
                    ++position_;
                }
            } else if (is_space(ch)) {
                line_ += ch == '\n' ? 1 : 0;
                ++position_;
            } else {
                return;
            }
        }
    }

    /// The next whole number, or nullopt (and nothing consumed) when there is none.
    std::optional<WholeNumber> number() {
        std::size_t end = position_;
        long value = 0;
        while (!past_end(end) && is_digit(bytes_[end])) {
            value = std::min(value * 10 + (bytes_[end] - '0'), kNumberCap);
            ++end;
        }
        if (end == position_ || (!past_end(end) && !is_space(bytes_[end]) && bytes_[end] != '#')) {
            return std::nullopt;
        }
        std::string written(bytes_.substr(position_, std::min(end - position_, kMaxWrittenDigits)));
        if (end - position_ > kMaxWrittenDigits) {
            written += "…";
        }
        position_ = end;
        return WholeNumber{value, std::move(written)};
    }

    /// What stands at the current position, for messages.
    std::string next_word() const {
        std::size_t end = position_;
        while (!past_end(end) && !is_space(bytes_[end]) && end - position_ < 12) {
            ++end;
        }
        if (end == position_) {
            return past_end(position_) ? "the end of the file" : "a blank";
        }
        std::string word(bytes_.substr(position_, end - position_));
        for (char& ch : word) {
            const auto code = static_cast<unsigned char>(ch);
            if (code < 0x20 || code >= 0x7f) {
                ch = '?';
            }
        }
        return "\"" + word + "\"";
    }

    [[noreturn]] void fail_header(const std::string& reason) const {
        throw InputError({{source_, line_, "PGM header", "", reason}});
    }

    bool at_end() const { return past_end(position_); }
    char peek() const { return bytes_[position_]; }
    void advance(std::size_t count) {
        for (std::size_t i = 0; i < count && !past_end(position_); ++i) {
            line_ += bytes_[position_] == '\n' ? 1 : 0;
            ++position_;
        }
    }
    std::size_t position() const { return position_; }
    int line() const { return line_; }
    const std::string& source() const { return source_; }

  private:
    /// Whether `index` is beyond the bytes; at the end of the file's first part, the
    /// header has not ended within it.
    bool past_end(std::size_t index) const {
        if (index < bytes_.size()) {
            return false;
        }
        if (more_follows_) {
            fail_header("does not end within the file's first "
                        + std::to_string(kMaxPgmHeaderBytes)
                        + " bytes (a header is the magic number, width, height and maxval, "
                          "with their comments)");
        }
        return true;
    }

    std::string_view bytes_;
    std::string source_;
    bool more_follows_;
    std::size_t position_ = 0;
    int line_ = 1;
};

WholeNumber header_number(PgmText& text, const char* what) {
    text.skip_space_and_comments();
    const std::string found = text.next_word();
    auto number = text.number();
    if (!number) {
        text.fail_header(std::string("expected the ") + what + " (a whole number), found " + found);
    }
    return std::move(*number);
}

/// The width or the height: at least 1 (the largest is checked with the other side).
WholeNumber side_number(PgmText& text, const char* what) {
    WholeNumber side = header_number(text, what);
    if (side.value < 1) {
        text.fail_header(std::string("the ") + what + " " + side.written + " must be at least 1");
    }
    return side;
}

/// What the header says: the format, the size and the maxval.
struct PgmHeader {
    bool binary = true;  ///< P5 (else P2)
    int width = 0;
    int height = 0;
    int max_value = 255;
};

/// Reads the header up to its maxval, refusing an image too large before anything else.
PgmHeader read_header(std::string_view bytes, PgmText& text) {
    const std::string magic(bytes.substr(0, 2));
    if (magic != "P5" && magic != "P2") {
        const bool other_netpbm =
            magic.size() == 2 && magic[0] == 'P' && magic[1] >= '1' && magic[1] <= '7';
        text.fail_header(other_netpbm
                             ? "this is a Netpbm " + magic
                                   + " image; a map is a greyscale PGM (P5 binary or P2 plain)"
                             : "not a PGM image: the file must start with P5 (binary) or P2 "
                               "(plain)");
    }
    text.advance(2);
    if (text.at_end() || (!is_space(text.peek()) && text.peek() != '#')) {
        text.fail_header("a blank must follow " + magic);
    }
    const WholeNumber width = side_number(text, "width");
    const WholeNumber height = side_number(text, "height");
    // The size, from the header alone: no pixel is read (nor allocated) for a refused image.
    if (width.value > kMaxMapImageSide || height.value > kMaxMapImageSide) {
        const std::string side = std::to_string(kMaxMapImageSide);
        text.fail_header("the image is " + width.written + "×" + height.written
                         + " pixels, larger than a map image may be (at most " + side + "×" + side
                         + ")");
    }
    const WholeNumber max_value = header_number(text, "maxval");
    if (max_value.value < 1 || max_value.value > kMaxPgmValue) {
        text.fail_header("the maxval " + max_value.written + " must be between 1 and "
                         + std::to_string(kMaxPgmValue));
    }
    return {magic == "P5", static_cast<int>(width.value), static_cast<int>(height.value),
            static_cast<int>(max_value.value)};
}

std::string pixel_name(const GreyImage& image, std::size_t index) {
    const auto width = static_cast<std::size_t>(image.width);
    return "pixel (column " + std::to_string(index % width) + ", row "
           + std::to_string(index / width) + ")";
}

std::string pixel_count_text(const GreyImage& image) {
    return std::to_string(image.width) + "×" + std::to_string(image.height) + " = "
           + std::to_string(static_cast<std::size_t>(image.width)
                            * static_cast<std::size_t>(image.height))
           + " pixels";
}

// P5: after maxval one whitespace byte, then width·height samples of 1 byte (maxval < 256)
// or 2 bytes, most significant first.
void read_binary_raster(std::string_view bytes, PgmText& text, GreyImage& image) {
    if (text.at_end() || !is_space(text.peek())) {
        text.fail_header("a single blank must follow the maxval, then the pixels");
    }
    text.advance(1);
    const std::size_t sample_size = image.max_value < 256 ? 1 : 2;
    const std::size_t available = bytes.size() - text.position();
    const std::size_t expected = image.pixels.size();
    if (available != expected * sample_size) {
        const std::string found = std::to_string(available / sample_size)
                                  + (available % sample_size != 0 ? " and a half" : "");
        throw InputError({{text.source(), 0, "", "",
                           "expected " + pixel_count_text(image) + " ("
                               + std::to_string(sample_size * 8) + "-bit), found " + found}});
    }
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data() + text.position());
    for (std::size_t i = 0; i < expected; ++i) {
        const unsigned value =
            sample_size == 1 ? data[i] : (unsigned{data[2 * i]} << 8U) | data[2 * i + 1];
        if (value > static_cast<unsigned>(image.max_value)) {
            throw InputError({{text.source(), 0, pixel_name(image, i), std::to_string(value),
                               "above the maxval " + std::to_string(image.max_value)}});
        }
        image.pixels[i] = static_cast<std::uint16_t>(value);
    }
}

// P2: width·height decimal numbers separated by blanks (comments allowed).
void read_plain_raster(PgmText& text, GreyImage& image) {
    const std::size_t expected = image.pixels.size();
    std::size_t count = 0;
    while (true) {
        text.skip_space_and_comments();
        if (text.at_end()) {
            break;
        }
        const std::string found = text.next_word();
        const auto value = text.number();
        if (!value) {
            throw InputError({{text.source(), text.line(),
                               count < expected ? pixel_name(image, count) : "after the pixels",
                               found, "not a whole number"}});
        }
        if (count < expected) {
            if (value->value > image.max_value) {
                throw InputError(
                    {{text.source(), text.line(), pixel_name(image, count), value->written,
                      "above the maxval " + std::to_string(image.max_value)}});
            }
            image.pixels[count] = static_cast<std::uint16_t>(value->value);
        }
        ++count;
    }
    if (count != expected) {
        throw InputError(
            {{text.source(), 0, "", "",
              "expected " + pixel_count_text(image) + ", found " + std::to_string(count)}});
    }
}

}  // namespace

GreyImage parse_pgm(std::string_view bytes, const std::string& source) {
    PgmText text(bytes, source, false);
    const PgmHeader header = read_header(bytes, text);
    GreyImage image{header.width, header.height, header.max_value, {}};
    // The header has accepted the size: at most kMaxMapImageSide² pixels.
    image.pixels.assign(
        static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height), 0);
    if (header.binary) {
        read_binary_raster(bytes, text, image);
    } else {
        read_plain_raster(text, image);
    }
    return image;
}

GreyImage read_pgm_file(const std::filesystem::path& path) {
    const std::string source = path.string();
    const FilePrefix first = read_file_prefix(path, kMapImageFile, kMaxPgmHeaderBytes);
    if (first.whole_file) {
        return parse_pgm(first.bytes, source);
    }
    PgmText header_text(first.bytes, source, true);
    read_header(first.bytes, header_text);  // throws for an image too large or malformed
    return parse_pgm(read_text_file(path, kMapImageFile), source);
}

}  // namespace legofeup::lessons
