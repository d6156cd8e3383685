#pragma once
// Reading the tables of a lesson or submission document: typed values, required texts and
// unknown keys, every problem collected with its line instead of stopping at the first.
// Private to lessons/.

#include <toml++/toml.h>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "legofeup/lessons/input_error.hpp"

namespace legofeup::lessons {

/// "a, b, c": a list for messages.
std::string joined(const std::vector<std::string>& words);

class DocumentReader {
  public:
    explicit DocumentReader(std::string source) : source_(std::move(source)) {}

    const std::string& source() const { return source_; }

    /// Reports every key of `table` not in `allowed`, named `prefix` + key.
    void only_keys(const toml::table& table, const std::vector<std::string>& allowed,
                   const std::string& prefix);

    /// The text at `key`; "" with a problem if it is missing (and `why` is not empty: the
    /// reason it is needed), empty or not a text. `prefix` names the table in messages.
    std::string text(const toml::table& table, const std::string& key, const std::string& prefix,
                     const std::string& why);
    /// An optional text: nothing if absent, a problem if it is not a text.
    std::optional<std::string> optional_text(const toml::table& table, const std::string& key,
                                             const std::string& prefix);
    /// An optional whole number in [low, high].
    std::optional<std::int64_t> integer(const toml::table& table, const std::string& key,
                                        const std::string& prefix, std::int64_t low,
                                        std::int64_t high);
    /// The tables of an array of tables ([[key]]); a problem if `key` is something else.
    std::vector<const toml::table*> tables(const toml::table& table, const std::string& key,
                                           const std::string& prefix);
    /// A table ([key]); nullptr if absent, with a problem if `key` is something else.
    const toml::table* table(const toml::table& parent, const std::string& key,
                             const std::string& prefix);

    void problem(int line, std::string key, std::string value, std::string reason);
    void add(const InputError& error);

    std::size_t problem_count() const { return problems_.size(); }
    /// Throws InputError with every problem found (each once), if there were any.
    void throw_if_problems();

  private:
    std::string source_;
    std::vector<InputProblem> problems_;
};

}  // namespace legofeup::lessons
