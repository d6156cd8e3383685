#pragma once
// Reading a whole text file for the parsers of lessons/ (configurations, worlds, profiles,
// lessons, submissions, run logs, shards, maps, measurements). Private to lessons/.

#include <cstddef>
#include <filesystem>
#include <string>

namespace legofeup::lessons {

inline constexpr std::size_t kMiB = 1024 * 1024;

/// A kind of file the readers take whole, and the largest one of it they read: far above
/// any real file of the kind, so that a wrong file (a disk image, a video, /dev/zero) is
/// refused, naming its size, before it fills the memory.
struct TextFileKind {
    const char* name;       ///< in messages: "cannot open the <name> file"
    std::size_t max_bytes;  ///< a larger file is refused without being read
};

// The kinds, with their limits (docs/configuration.md, "File sizes", lists them).
// A TOML or YAML document a person writes: the largest that ship are 15 KB.
inline constexpr TextFileKind kConfigurationFile{"configuration", 16 * kMiB};
inline constexpr TextFileKind kLessonFile{"lesson", 16 * kMiB};
inline constexpr TextFileKind kSubmissionFile{"submission", 16 * kMiB};
inline constexpr TextFileKind kWorldFile{"world", 16 * kMiB};
inline constexpr TextFileKind kRobotProfileFile{"robot profile", 16 * kMiB};
inline constexpr TextFileKind kMapFile{"map", 16 * kMiB};
inline constexpr TextFileKind kMeasurementsFile{"measurements", 16 * kMiB};
/// An hour at 20 steps a second with the laser scan is about 150 MB (2 KB a record).
inline constexpr TextFileKind kRunLogFile{"run log", 1024 * kMiB};
/// A Monte Carlo shard holds one record per run and the per-step sums: tens of MB.
inline constexpr TextFileKind kShardFile{"shard", 256 * kMiB};
/// A map image, read once its header has accepted its size (pgm_image.cpp): a plain (P2)
/// 4096 × 4096 image of five-digit values and their blanks is 96 MiB.
inline constexpr TextFileKind kMapImageFile{"map image", 128 * kMiB};

/// The whole of a text file. InputError naming the file: "cannot open the <kind> file" if it
/// cannot be read (": it is a directory" for one), "the file is N bytes: <kind> files may be
/// at most M MiB (B bytes)" when it is larger than kind.max_bytes (a regular file's size is
/// checked before anything is read; a pipe is read up to the limit).
std::string read_text_file(const std::filesystem::path& path, const TextFileKind& kind);

/// At most the first `max_bytes` bytes of a file (a header to check before the rest is
/// read); InputError as read_text_file if it cannot be read.
struct FilePrefix {
    std::string bytes;
    bool whole_file = false;  ///< the file ends within `bytes`
};
FilePrefix read_file_prefix(const std::filesystem::path& path, const TextFileKind& kind,
                            std::size_t max_bytes);

}  // namespace legofeup::lessons
