#pragma once
// Output files and folders. An output file appears whole or not at all: written to
// `<path>.partial`, renamed over
// `<path>` on commit(). A failed or abandoned write never leaves a half file behind, and an
// existing file of the same name stays intact until the new one is complete.

#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <utility>

namespace legofeup::cli {

class AtomicFile {
  public:
    explicit AtomicFile(std::filesystem::path path)
        : path_(std::move(path)), partial_(path_.string() + ".partial"), out_(partial_) {}
    ~AtomicFile() {
        if (!committed_) {
            out_.close();
            std::error_code ignored;
            std::filesystem::remove(partial_, ignored);
        }
    }
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    std::ostream& stream() { return out_; }
    bool good() const { return out_.good(); }
    const std::filesystem::path& path() const { return path_; }

    /// Closes and renames into place. Throws std::runtime_error naming the file on failure.
    void commit() {
        out_.close();
        if (!out_) {
            throw std::runtime_error("cannot write " + path_.string());
        }
        std::filesystem::rename(partial_, path_);
        committed_ = true;
    }

  private:
    std::filesystem::path path_;
    std::filesystem::path partial_;
    std::ofstream out_;
    bool committed_ = false;
};

/// Creates an output directory (and its parents). On failure says why on stderr and returns
/// false: the caller exits with kExitOutputFailed.
inline bool create_output_directory(const std::filesystem::path& directory) {
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error) {
        std::cerr << "error: cannot create " << directory.string() << ": " << error.message()
                  << '\n';
        return false;
    }
    return true;
}

}  // namespace legofeup::cli
