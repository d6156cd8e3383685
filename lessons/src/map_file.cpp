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

// --- Reading a map from files or from the built-in resources --------------------------------

/// Reads the image at a path, or nullopt when there is none (on disk or among the built-in
/// resources); `source` names it in messages.
using ImageSource = std::function<std::optional<GreyImage>(const std::filesystem::path& path,
                                                           const std::string& source)>;

// On disk, the image's path is its source in messages.
std::optional<GreyImage> read_from_disk(const std::filesystem::path& path, const std::string&) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
        return std::nullopt;
    }
    return read_pgm_file(path);  // the header first: a huge image is refused unread
}

std::optional<GreyImage> read_built_in(const std::filesystem::path& path,
                                       const std::string& source) {
    const auto contents = built_in_resource(path.lexically_normal().generic_string());
    return contents ? std::optional<GreyImage>(parse_pgm(*contents, source)) : std::nullopt;
}

OccupancyGrid read_map(std::string_view yaml_text, const std::filesystem::path& yaml_path,
                       const std::string& yaml_source, const ImageSource& images) {
    const MapMetadata map = parse_map_yaml(yaml_text, yaml_source);
    const std::filesystem::path image_path =
        map.image.is_absolute() ? map.image : yaml_path.parent_path() / map.image;
    const std::string image_source =
        yaml_source.ends_with(" (built in)")
            ? image_path.lexically_normal().generic_string() + " (built in)"
            : image_path.string();
    const std::optional<GreyImage> image = images(image_path, image_source);
    if (!image) {
        throw InputError({{yaml_source, map.image_line, "image", map.image.string(),
                           "cannot read the image " + image_path.lexically_normal().string()}});
    }
    return occupancy_from_image(map, *image);
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
