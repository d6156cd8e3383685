#pragma once
// Occupancy-grid map files in the ROS map_server convention (paper 001 stores its map with
// map_server): a YAML file with the metadata and a PGM image with one pixel per cell.
//
//   image: office.pgm          # relative to the YAML file (or absolute)
//   resolution: 0.05           # m per pixel
//   origin: [0.0, 0.0, 0.0]    # x, y (m), yaw (rad) of the lower-left pixel's lower-left corner
//   occupied_thresh: 0.65      # p > this: occupied
//   free_thresh: 0.196         # p < this: free (in between: unknown)
//   negate: 0                  # 1: p = value/maxval instead of (maxval − value)/maxval
//   mode: trinary              # optional; "scale" reads the same, "raw" is refused
//
// The image's first row is the top of the map; OccupancyGrid's row 0 is the bottom, so rows
// are flipped on reading (the image itself is read by pgm_image.hpp). docs/maps.md
// describes the format and the maps that ship.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "legofeup/core/occupancy_grid.hpp"
#include "legofeup/lessons/pgm_image.hpp"

namespace legofeup::lessons {

/// How pixel values become cell states (ROS map_server's `mode`).
enum class MapMode : std::uint8_t {
    Trinary,  ///< the thresholds give free / occupied / unknown
    Scale,    ///< ROS keeps in-between values as probabilities; here they are Unknown
};

/// The YAML file's contents.
struct MapMetadata {
    std::filesystem::path image;  ///< as written; relative paths are from the YAML's directory
    int image_line = 0;           ///< where `image` was written (for the image's problems)
    double resolution = 0.05;     ///< m per pixel
    Pose2 origin;                 ///< x, y, yaw of the grid's lower-left corner in the world
    double occupied_thresh = 0.65;
    double free_thresh = 0.196;
    bool negate = false;
    MapMode mode = MapMode::Trinary;
};

/// Parses the YAML text; throws InputError naming every problem with its line and field.
MapMetadata parse_map_yaml(std::string_view text, const std::string& source);

/// The state of one pixel: occupancy p = (max − v)/max, or v/max when negated; occupied
/// when p > occupied_thresh, free when p < free_thresh, unknown otherwise.
CellState cell_state_of(const MapMetadata& map, int max_value, int value);

/// The grid of an image under its metadata: rows flipped (image row 0 is the top).
OccupancyGrid occupancy_from_image(const MapMetadata& map, const GreyImage& image);

/// Reads the YAML file and the image it names. Problems of either file are reported with
/// the file (and line) they are in; a missing image is reported at the YAML's `image` line.
OccupancyGrid load_map_file(const std::filesystem::path& yaml);

/// The maps built into the programs (resources/maps/): "standard_arena" and "office".
const std::vector<std::string>& built_in_map_names();

/// A built-in map by its name, or by its path under resources/ ("maps/office.yaml");
/// nullptr when there is none. Each is read once and shared.
std::shared_ptr<const OccupancyGrid> find_built_in_map(std::string_view name_or_path);

/// A built-in map's name, or else a YAML file on disk.
std::shared_ptr<const OccupancyGrid> load_map(const std::string& name_or_path);

}  // namespace legofeup::lessons
