#pragma once
// Reading a whole text file for the parsers of lessons/ (configurations, worlds, profiles,
// lessons, submissions, run logs, shards). Private to lessons/.

#include <filesystem>
#include <string>

namespace legofeup::lessons {

/// The whole of a text file; InputError "cannot open the <what> file" if it cannot be read.
std::string read_text_file(const std::filesystem::path& path, const std::string& what);

}  // namespace legofeup::lessons
