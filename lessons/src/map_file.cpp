#include "legofeup/lessons/map_file.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <map>
#include <mutex>
#include <optional>

#include "built_in_resources.hpp"
#include "legofeup/core/config_issue.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "text_file.hpp"

namespace legofeup::lessons {
namespace {

constexpr double kMaxResolution = 10.0;   // m per pixel: anything coarser is a typo
constexpr double kMaxOriginOffset = 1e6;  // m
constexpr int kMaxPgmValue = 65535;       // the largest maxval PGM allows

// --- The YAML file --------------------------------------------------------------------------

// The fields ROS map_server requires (`mode` is optional).
constexpr const char* kRequiredKeys[] = {"image",           "resolution",  "origin",
                                         "occupied_thresh", "free_thresh", "negate"};

std::string number_text(double value) {
    return format_config_number(value);  // "%.6g", as every other message shows numbers
}

/// Reads the metadata, collecting every problem with its line (yaml-cpp marks are 0-based).
class MapYamlReader {
  public:
    explicit MapYamlReader(std::string source) : source_(std::move(source)) {}

    MapMetadata read(const YAML::Node& root) {
        MapMetadata map;
        if (!root.IsMap()) {
            problem(root, "", "",
                    std::string(root.IsNull() ? "the file is empty" : "not a map file")
                        + ": a map file is a YAML mapping with image, resolution, origin, "
                          "occupied_thresh, free_thresh and negate");
            return map;
        }
        std::map<std::string, int> seen;  // key → the line it was first written on
        for (const auto& entry : root) {
            const YAML::Node& key_node = entry.first;
            const YAML::Node& value = entry.second;
            const std::string key = key_node.IsScalar() ? key_node.Scalar() : std::string();
            const auto [first, inserted] = seen.emplace(key, line_of(key_node));
            if (!inserted) {
                problem(key_node, key, "",
                        "written twice (first on line " + std::to_string(first->second) + ")");
                continue;
            }
            if (key == "image") {
                read_image(value, map);
            } else if (key == "resolution") {
                read_resolution(value, map);
            } else if (key == "origin") {
                read_origin(value, map);
            } else if (key == "occupied_thresh") {
                occupied_ = threshold(value, key);
                map.occupied_thresh = occupied_.value_or(map.occupied_thresh);
            } else if (key == "free_thresh") {
                free_ = threshold(value, key);
                free_line_node_ = value;
                map.free_thresh = free_.value_or(map.free_thresh);
            } else if (key == "negate") {
                read_negate(value, map);
            } else if (key == "mode") {
                read_mode(value, map);
            } else {
                problem(key_node, key, "",
                        "unknown field (expected image, resolution, origin, occupied_thresh, "
                        "free_thresh, negate or mode)");
            }
        }
        for (const std::string key : kRequiredKeys) {
            if (!seen.contains(key)) {
                problems_.push_back({source_, 0, key, "",
                                     "missing (a map file needs image, resolution, origin, "
                                     "occupied_thresh, free_thresh and negate)"});
            }
        }
        check_thresholds();
        return map;
    }

    const std::vector<InputProblem>& problems() const { return problems_; }

  private:
    static int line_of(const YAML::Node& node) {
        const int line = node.Mark().line;
        return line >= 0 ? line + 1 : 0;
    }

    void problem(const YAML::Node& node, std::string key, std::string value, std::string reason) {
        problems_.push_back(
            {source_, line_of(node), std::move(key), std::move(value), std::move(reason)});
    }

    static std::string text_of(const YAML::Node& node) {
        return node.IsScalar() ? node.Scalar() : std::string();
    }

    /// A plain number (YAML's ".inf" and ".nan" read as non-finite and are refused).
    static std::optional<double> parse_number(const std::string& text) {
        std::string_view digits = text;
        if (digits.starts_with('+')) {
            digits.remove_prefix(1);
        }
        if (digits == ".inf" || digits == ".Inf" || digits == ".INF") {
            return INFINITY;
        }
        if (text == "-.inf" || text == "-.Inf" || text == "-.INF") {
            return -INFINITY;
        }
        if (digits == ".nan" || digits == ".NaN" || digits == ".NAN") {
            return NAN;
        }
        double value = 0.0;
        const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
        if (digits.empty() || result.ec != std::errc{}
            || result.ptr != digits.data() + digits.size()) {
            return std::nullopt;
        }
        return value;
    }

    std::optional<double> finite_number(const YAML::Node& node, const std::string& key) {
        const auto value = node.IsScalar() ? parse_number(node.Scalar()) : std::nullopt;
        if (!value || !std::isfinite(*value)) {
            problem(node, key, text_of(node), "must be a finite number");
            return std::nullopt;
        }
        return value;
    }

    void read_image(const YAML::Node& node, MapMetadata& map) {
        map.image_line = line_of(node);
        if (!node.IsScalar() || node.Scalar().empty()) {
            problem(node, "image", text_of(node),
                    "must name the PGM image (a path relative to this file)");
            return;
        }
        map.image = node.Scalar();
    }

    void read_resolution(const YAML::Node& node, MapMetadata& map) {
        const auto value = finite_number(node, "resolution");
        if (!value) {
            return;
        }
        if (!(*value > 0.0 && *value <= kMaxResolution)) {
            problem(node, "resolution", node.Scalar(),
                    "must be greater than 0 and at most " + number_text(kMaxResolution)
                        + " m per pixel");
            return;
        }
        map.resolution = *value;
    }

    void read_origin(const YAML::Node& node, MapMetadata& map) {
        if (!node.IsSequence() || node.size() != 3) {
            problem(node, "origin", text_of(node),
                    "must be [x, y, yaw]: the lower-left corner in metres and the map's "
                    "rotation in radians");
            return;
        }
        const char* names[] = {"origin x", "origin y", "origin yaw"};
        double parts[3] = {0.0, 0.0, 0.0};
        bool ok = true;
        for (std::size_t i = 0; i < 3; ++i) {
            const auto value = finite_number(node[i], names[i]);
            ok = ok && value.has_value();
            parts[i] = value.value_or(0.0);
        }
        if (!ok) {
            return;
        }
        if (std::abs(parts[0]) > kMaxOriginOffset || std::abs(parts[1]) > kMaxOriginOffset) {
            problem(node, "origin",
                    "[" + number_text(parts[0]) + ", " + number_text(parts[1]) + ", "
                        + number_text(parts[2]) + "]",
                    "x and y must be within ±" + number_text(kMaxOriginOffset) + " m");
            return;
        }
        map.origin = {parts[0], parts[1], parts[2]};
    }

    std::optional<double> threshold(const YAML::Node& node, const std::string& key) {
        const auto value = finite_number(node, key);
        if (value && !(*value >= 0.0 && *value <= 1.0)) {
            problem(node, key, node.Scalar(), "must be between 0 and 1 (an occupancy probability)");
            return std::nullopt;
        }
        return value;
    }

    void read_negate(const YAML::Node& node, MapMetadata& map) {
        const std::string text = text_of(node);
        if (text == "0" || text == "false") {
            map.negate = false;
        } else if (text == "1" || text == "true") {
            map.negate = true;
        } else {
            problem(node, "negate", text, "must be 0 (black is occupied) or 1 (white is occupied)");
        }
    }

    void read_mode(const YAML::Node& node, MapMetadata& map) {
        const std::string text = text_of(node);
        if (text == "trinary") {
            map.mode = MapMode::Trinary;
        } else if (text == "scale") {
            map.mode = MapMode::Scale;
        } else if (text == "raw") {
            problem(node, "mode", text,
                    "is not supported: raw pixel values have no thresholds, and the map here "
                    "is free / occupied / unknown (use trinary or scale)");
        } else {
            problem(node, "mode", text, "must be trinary or scale");
        }
    }

    // free_thresh < occupied_thresh, reported at free_thresh's line (when both are valid).
    void check_thresholds() {
        if (free_ && occupied_ && *free_ >= *occupied_) {
            problem(free_line_node_, "free_thresh", number_text(*free_),
                    "must be below occupied_thresh (" + number_text(*occupied_)
                        + "): between the two a cell is unknown");
        }
    }

    std::string source_;
    std::optional<double> occupied_;
    std::optional<double> free_;
    YAML::Node free_line_node_;
    std::vector<InputProblem> problems_;
};

// --- The PGM image --------------------------------------------------------------------------

bool is_space(char ch) {
    return ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r' || ch == '\v' || ch == '\f';
}

bool is_digit(char ch) {
    return ch >= '0' && ch <= '9';
}

/// Walks the text part of a PGM (the header, and the whole of a plain P2 file), counting
/// lines; comments run from '#' to the end of the line.
class PgmText {
  public:
    PgmText(std::string_view bytes, std::string source)
        : bytes_(bytes), source_(std::move(source)) {}

    void skip_space_and_comments() {
        while (position_ < bytes_.size()) {
            const char ch = bytes_[position_];
            if (ch == '#') {
                while (position_ < bytes_.size() && bytes_[position_] != '\n') {
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
    std::optional<long> number() {
        std::size_t end = position_;
        long value = 0;
        while (end < bytes_.size() && is_digit(bytes_[end])) {
            value = std::min(value * 10 + (bytes_[end] - '0'), 1'000'000'000L);
            ++end;
        }
        if (end == position_
            || (end < bytes_.size() && !is_space(bytes_[end]) && bytes_[end] != '#')) {
            return std::nullopt;
        }
        position_ = end;
        return value;
    }

    /// What stands at the current position, for messages.
    std::string next_word() const {
        std::size_t end = position_;
        while (end < bytes_.size() && !is_space(bytes_[end]) && end - position_ < 12) {
            ++end;
        }
        if (end == position_) {
            return position_ >= bytes_.size() ? "the end of the file" : "a blank";
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

    bool at_end() const { return position_ >= bytes_.size(); }
    char peek() const { return bytes_[position_]; }
    void advance(std::size_t count) {
        for (std::size_t i = 0; i < count && position_ < bytes_.size(); ++i) {
            line_ += bytes_[position_] == '\n' ? 1 : 0;
            ++position_;
        }
    }
    std::size_t position() const { return position_; }
    int line() const { return line_; }
    const std::string& source() const { return source_; }

  private:
    std::string_view bytes_;
    std::string source_;
    std::size_t position_ = 0;
    int line_ = 1;
};

int header_number(PgmText& text, const char* what, long low, long high) {
    text.skip_space_and_comments();
    const std::string found = text.next_word();
    const auto value = text.number();
    if (!value) {
        text.fail_header(std::string("expected the ") + what + " (a whole number), found " + found);
    }
    if (*value < low || *value > high) {
        text.fail_header(std::string("the ") + what + " " + std::to_string(*value)
                         + " must be between " + std::to_string(low) + " and "
                         + std::to_string(high));
    }
    return static_cast<int>(*value);
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
            if (*value > image.max_value) {
                throw InputError(
                    {{text.source(), text.line(), pixel_name(image, count), std::to_string(*value),
                      "above the maxval " + std::to_string(image.max_value)}});
            }
            image.pixels[count] = static_cast<std::uint16_t>(*value);
        }
        ++count;
    }
    if (count != expected) {
        throw InputError(
            {{text.source(), 0, "", "",
              "expected " + pixel_count_text(image) + ", found " + std::to_string(count)}});
    }
}

// --- Reading a map from files or from the built-in resources --------------------------------

/// Reads a file's bytes, or nullopt when it does not exist (disk or built-in resources).
using FileSource = std::function<std::optional<std::string>(const std::filesystem::path&)>;

std::optional<std::string> read_from_disk(const std::filesystem::path& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
        return std::nullopt;
    }
    return read_text_file(path, kMapImageFile);
}

std::optional<std::string> read_built_in(const std::filesystem::path& path) {
    const auto contents = built_in_resource(path.lexically_normal().generic_string());
    return contents ? std::optional<std::string>(*contents) : std::nullopt;
}

OccupancyGrid read_map(std::string_view yaml_text, const std::filesystem::path& yaml_path,
                       const std::string& yaml_source, const FileSource& files) {
    const MapMetadata map = parse_map_yaml(yaml_text, yaml_source);
    const std::filesystem::path image_path =
        map.image.is_absolute() ? map.image : yaml_path.parent_path() / map.image;
    const std::optional<std::string> bytes = files(image_path);
    if (!bytes) {
        throw InputError({{yaml_source, map.image_line, "image", map.image.string(),
                           "cannot read the image " + image_path.lexically_normal().string()}});
    }
    const std::string image_source =
        yaml_source.ends_with(" (built in)")
            ? image_path.lexically_normal().generic_string() + " (built in)"
            : image_path.string();
    return occupancy_from_image(map, parse_pgm(*bytes, image_source));
}

}  // namespace

MapMetadata parse_map_yaml(std::string_view text, const std::string& source) {
    YAML::Node root;
    try {
        root = YAML::Load(std::string(text));
    } catch (const YAML::Exception& error) {
        throw InputError({{source, error.mark.line >= 0 ? error.mark.line + 1 : 0, "", "",
                           "not valid YAML: " + error.msg}});
    }
    MapYamlReader reader(source);
    MapMetadata map = reader.read(root);
    if (!reader.problems().empty()) {
        throw InputError(reader.problems());
    }
    return map;
}

GreyImage parse_pgm(std::string_view bytes, const std::string& source) {
    PgmText text(bytes, source);
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
    GreyImage image;
    image.width = header_number(text, "width", 1, kMaxMapImageSide);
    image.height = header_number(text, "height", 1, kMaxMapImageSide);
    image.max_value = header_number(text, "maxval", 1, kMaxPgmValue);
    image.pixels.assign(
        static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height), 0);
    if (magic == "P5") {
        read_binary_raster(bytes, text, image);
    } else {
        read_plain_raster(text, image);
    }
    return image;
}

CellState cell_state_of(const MapMetadata& map, int max_value, int value) {
    // The occupancy probability, as ROS map_server computes it.
    const double p = static_cast<double>(map.negate ? value : max_value - value) / max_value;
    if (p > map.occupied_thresh) {
        return CellState::Occupied;
    }
    if (p < map.free_thresh) {
        return CellState::Free;
    }
    return CellState::Unknown;
}

OccupancyGrid occupancy_from_image(const MapMetadata& map, const GreyImage& image) {
    std::vector<CellState> cells(image.pixels.size());
    for (int row = 0; row < image.height; ++row) {
        const int image_row = image.height - 1 - row;  // the image's first row is the top
        for (int column = 0; column < image.width; ++column) {
            cells[static_cast<std::size_t>(row) * static_cast<std::size_t>(image.width)
                  + static_cast<std::size_t>(column)] =
                cell_state_of(map, image.max_value, image.at(column, image_row));
        }
    }
    return {image.width, image.height, map.resolution, map.origin, std::move(cells)};
}

OccupancyGrid load_map_file(const std::filesystem::path& yaml) {
    return read_map(read_text_file(yaml, kMapFile), yaml, yaml.string(), read_from_disk);
}

const std::vector<std::string>& built_in_map_names() {
    static const std::vector<std::string> names = {"standard_arena", "office", "office_as_built"};
    return names;
}

std::shared_ptr<const OccupancyGrid> find_built_in_map(std::string_view name_or_path) {
    std::string path(name_or_path);
    if (std::find(built_in_map_names().begin(), built_in_map_names().end(), path)
        != built_in_map_names().end()) {
        path = "maps/" + path + ".yaml";
    }
    const auto yaml = built_in_resource(path);
    if (!yaml) {
        return nullptr;
    }
    // Each built-in map is read once; worlds and filters share it.
    static std::mutex mutex;
    static std::map<std::string, std::shared_ptr<const OccupancyGrid>> cache;
    const std::lock_guard lock(mutex);
    auto& entry = cache[path];
    if (!entry) {
        entry = std::make_shared<const OccupancyGrid>(
            read_map(*yaml, path, path + " (built in)", read_built_in));
    }
    return entry;
}

std::shared_ptr<const OccupancyGrid> load_map(const std::string& name_or_path) {
    const auto& names = built_in_map_names();
    if (std::find(names.begin(), names.end(), name_or_path) != names.end()) {
        return find_built_in_map(name_or_path);
    }
    return std::make_shared<const OccupancyGrid>(load_map_file(name_or_path));
}

}  // namespace legofeup::lessons
