#include "document_reader.hpp"

#include <algorithm>

#include "toml_values.hpp"

namespace legofeup::lessons {

std::string joined(const std::vector<std::string>& words) {
    std::string text;
    for (const std::string& word : words) {
        text += (text.empty() ? "" : ", ") + word;
    }
    return text;
}

void DocumentReader::only_keys(const toml::table& table, const std::vector<std::string>& allowed,
                               const std::string& prefix) {
    for (const auto& [key, node] : table) {
        const std::string name(key.str());
        if (std::find(allowed.begin(), allowed.end(), name) != allowed.end()) {
            continue;
        }
        const std::string match = closest_match(name, allowed);
        problem(line_of(node), prefix + name, "",
                "unknown key"
                    + (match.empty() ? " (the keys here are: " + joined(allowed) + ")"
                                     : " (did you mean '" + match + "'?)"));
    }
}

std::string DocumentReader::text(const toml::table& table, const std::string& key,
                                 const std::string& prefix, const std::string& why) {
    const toml::node* node = table.get(key);
    if (node == nullptr) {
        problem(std::max(line_of(table), 1), prefix + key, "", "missing: " + why);
        return {};
    }
    const auto* text = node->as_string();
    if (text == nullptr) {
        problem(line_of(*node), prefix + key, node_text(*node), "must be a quoted text");
        return {};
    }
    if (text->get().find_first_not_of(" \t\r\n") == std::string::npos) {
        problem(line_of(*node), prefix + key, "", "must not be empty: " + why);
    }
    return text->get();
}

std::optional<std::string> DocumentReader::optional_text(const toml::table& table,
                                                         const std::string& key,
                                                         const std::string& prefix) {
    const toml::node* node = table.get(key);
    if (node == nullptr) {
        return std::nullopt;
    }
    if (const auto* text = node->as_string()) {
        return text->get();
    }
    problem(line_of(*node), prefix + key, node_text(*node), "must be a quoted text");
    return std::nullopt;
}

std::optional<std::int64_t> DocumentReader::integer(const toml::table& table,
                                                    const std::string& key,
                                                    const std::string& prefix, std::int64_t low,
                                                    std::int64_t high) {
    const toml::node* node = table.get(key);
    if (node == nullptr) {
        return std::nullopt;
    }
    const auto* integer = node->as_integer();
    if (integer == nullptr) {
        problem(line_of(*node), prefix + key, node_text(*node), "must be a whole number");
        return std::nullopt;
    }
    if (integer->get() < low || integer->get() > high) {
        problem(line_of(*node), prefix + key, node_text(*node),
                "must be between " + std::to_string(low) + " and " + std::to_string(high));
        return std::nullopt;
    }
    return integer->get();
}

std::vector<const toml::table*> DocumentReader::tables(const toml::table& table,
                                                       const std::string& key,
                                                       const std::string& prefix) {
    std::vector<const toml::table*> found;
    const toml::node* node = table.get(key);
    if (node == nullptr) {
        return found;
    }
    const auto* array = node->as_array();
    if (array == nullptr || !array->is_array_of_tables()) {
        problem(line_of(*node), prefix + key, "",
                "must be a list of tables, each starting with [[" + prefix + key + "]]");
        return found;
    }
    for (const toml::node& element : *array) {
        found.push_back(element.as_table());
    }
    return found;
}

const toml::table* DocumentReader::table(const toml::table& parent, const std::string& key,
                                         const std::string& prefix) {
    const toml::node* node = parent.get(key);
    if (node == nullptr) {
        return nullptr;
    }
    if (const auto* table = node->as_table()) {
        return table;
    }
    problem(line_of(*node), prefix + key, node_text(*node),
            "must be a table, starting with [" + prefix + key + "]");
    return nullptr;
}

void DocumentReader::problem(int line, std::string key, std::string value, std::string reason) {
    problems_.push_back({source_, line, std::move(key), std::move(value), std::move(reason)});
}

void DocumentReader::add(const InputError& error) {
    problems_.insert(problems_.end(), error.problems().begin(), error.problems().end());
}

void DocumentReader::throw_if_problems() {
    if (problems_.empty()) {
        return;
    }
    // The same problem can be found twice (a [base] setting that fails to resolve in every
    // step): report it once.
    std::vector<InputProblem> unique;
    for (InputProblem& problem : problems_) {
        const bool seen = std::any_of(unique.begin(), unique.end(), [&](const InputProblem& p) {
            return p.message() == problem.message();
        });
        if (!seen) {
            unique.push_back(std::move(problem));
        }
    }
    problems_.clear();
    throw InputError(std::move(unique));
}

}  // namespace legofeup::lessons
