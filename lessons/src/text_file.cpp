#include "text_file.hpp"

#include <algorithm>
#include <fstream>
#include <system_error>

#include "legofeup/lessons/input_error.hpp"

namespace legofeup::lessons {
namespace {

constexpr std::size_t kReadChunk = 64 * 1024;

InputError file_problem(const std::filesystem::path& path, const std::string& reason) {
    return InputError({{path.string(), 0, "", "", reason}});
}

InputError too_large(const std::filesystem::path& path, const TextFileKind& kind,
                     const std::string& size) {
    return file_problem(path, "the file is " + size + ": " + kind.name + " files may be at most "
                                  + std::to_string(kind.max_bytes / kMiB) + " MiB ("
                                  + std::to_string(kind.max_bytes) + " bytes)");
}

std::ifstream open_file(const std::filesystem::path& path, const TextFileKind& kind) {
    const std::string cannot_open = std::string("cannot open the ") + kind.name + " file";
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) {
        throw file_problem(path, cannot_open + ": it is a directory");
    }
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw file_problem(path, cannot_open);
    }
    return file;
}

/// Appends what is left of `file` to `bytes`, until `bytes` holds `limit` bytes.
void read_up_to(std::ifstream& file, std::string& bytes, std::size_t limit) {
    while (bytes.size() < limit && file) {
        const std::size_t start = bytes.size();
        const std::size_t wanted = std::min(kReadChunk, limit - start);
        bytes.resize(start + wanted);
        file.read(bytes.data() + start, static_cast<std::streamsize>(wanted));
        bytes.resize(start + static_cast<std::size_t>(file.gcount()));
    }
}

}  // namespace

std::string read_text_file(const std::filesystem::path& path, const TextFileKind& kind) {
    std::ifstream file = open_file(path, kind);
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(path, error);  // none for a pipe
    if (!error && size > kind.max_bytes) {
        throw too_large(path, kind, std::to_string(size) + " bytes");
    }
    std::string text;
    if (!error) {
        text.reserve(size);
    }
    read_up_to(file, text, kind.max_bytes + 1);  // one byte more tells a pipe that is too long
    if (text.size() > kind.max_bytes) {
        throw too_large(path, kind, "more than " + std::to_string(kind.max_bytes) + " bytes");
    }
    return text;
}

FilePrefix read_file_prefix(const std::filesystem::path& path, const TextFileKind& kind,
                            std::size_t max_bytes) {
    std::ifstream file = open_file(path, kind);
    FilePrefix prefix;
    read_up_to(file, prefix.bytes, max_bytes);
    prefix.whole_file = file.peek() == std::ifstream::traits_type::eof();
    return prefix;
}

}  // namespace legofeup::lessons
