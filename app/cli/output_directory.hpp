#pragma once
// Output folders. The files in them are written through legofeup::fileio::AtomicFile: each
// appears whole or not at all, and a file of the same name stays intact until the new one is.

#include <filesystem>
#include <iostream>

namespace legofeup::cli {

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
