#pragma once
// An output file that appears whole or not at all: written to `<path>.partial`, renamed over
// `<path>` on commit(). A failed or abandoned write never leaves a half file behind, and an
// existing file of the same name stays intact until the new one is complete.

#include <filesystem>
#include <fstream>
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

}  // namespace legofeup::cli
