#include "text_file.hpp"

#include <fstream>
#include <sstream>

#include "legofeup/lessons/input_error.hpp"

namespace legofeup::lessons {

std::string read_text_file(const std::filesystem::path& path, const std::string& what) {
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw InputError({{path.string(), 0, "", "", "cannot open the " + what + " file"}});
    }
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

}  // namespace legofeup::lessons
