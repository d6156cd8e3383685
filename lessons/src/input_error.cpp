#include "legofeup/lessons/input_error.hpp"

#include <algorithm>
#include <map>
#include <utility>

namespace legofeup::lessons {
namespace {

// Groups problems by source (in the order the sources first appear) and sorts each group
// by line, so a file's problems read top to bottom.
std::vector<InputProblem> in_source_order(std::vector<InputProblem> problems) {
    std::map<std::string, std::size_t> first_seen;
    for (const InputProblem& problem : problems) {
        first_seen.emplace(problem.source, first_seen.size());
    }
    std::stable_sort(problems.begin(), problems.end(),
                     [&](const InputProblem& a, const InputProblem& b) {
                         return std::pair(first_seen.at(a.source), a.line)
                                < std::pair(first_seen.at(b.source), b.line);
                     });
    return problems;
}

std::string join(const std::vector<InputProblem>& problems) {
    std::string text;
    for (const InputProblem& problem : problems) {
        text += (text.empty() ? "" : "\n") + problem.message();
    }
    return text;
}

}  // namespace

std::string InputProblem::message() const {
    std::string text;
    if (!source.empty()) {
        text += source + (line > 0 ? ":" + std::to_string(line) : "") + ": ";
    }
    if (!key.empty()) {
        text += key + (value.empty() ? "" : " = " + value) + ": ";
    }
    return text + reason;
}

InputError::InputError(std::vector<InputProblem> problems)
    : std::runtime_error(""), problems_(in_source_order(std::move(problems))) {
    message_ = join(problems_);
}

const char* InputError::what() const noexcept {
    return message_.c_str();
}

}  // namespace legofeup::lessons
