#pragma once
// Problems with what a user typed or a file contained, each with where it came from, and
// the exception that carries them. Messages read "file:line: key = value: reason".

#include <stdexcept>
#include <string>
#include <vector>

namespace legofeup::lessons {

struct InputProblem {
    std::string source;  ///< file name (or "--seed", "experiment c", …); may be empty
    int line = 0;        ///< 1-based line in `source`, 0 when not from a file line
    std::string key;     ///< the setting as the user writes it, e.g. "filter.q11"
    std::string value;   ///< the offending value as text (may be empty)
    std::string reason;

    std::string message() const;
};

class InputError : public std::runtime_error {
  public:
    /// Problems are kept in the order of their source and line (a document's problems are
    /// then listed top to bottom, whatever order they were found in).
    explicit InputError(std::vector<InputProblem> problems);
    const std::vector<InputProblem>& problems() const { return problems_; }
    /// Every problem's message, one per line.
    const char* what() const noexcept override;

  private:
    std::vector<InputProblem> problems_;
    std::string message_;
};

}  // namespace legofeup::lessons
