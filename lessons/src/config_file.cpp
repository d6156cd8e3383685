#include "legofeup/lessons/config_file.hpp"

#include <algorithm>
#include <set>
#include <sstream>

#include "config_reader.hpp"
#include "legofeup/lessons/config_schema.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "text_file.hpp"
#include "toml_values.hpp"

namespace legofeup::lessons {
namespace {

const char* type_reason(SettingType type) {
    switch (type) {
        case SettingType::Real:
            return "must be a number";
        case SettingType::Integer:
            return "must be a whole number";
        case SettingType::Boolean:
            return "must be true or false";
        case SettingType::Text:
            return "must be a quoted text";
        case SettingType::Point:
            return "must be a point [x, y]";
        case SettingType::Choice:
            return "must be one of the listed words";
    }
    return "has the wrong type";
}

std::optional<SettingValue> convert(const Setting& setting, const toml::node& node) {
    switch (setting.type) {
        case SettingType::Real:
            if (auto number = number_of(node)) {
                return *number;
            }
            break;
        case SettingType::Integer:
            if (const auto* integer = node.as_integer()) {
                return integer->get();
            }
            break;
        case SettingType::Boolean:
            if (const auto* flag = node.as_boolean()) {
                return flag->get();
            }
            break;
        case SettingType::Text:
        case SettingType::Choice:
            if (const auto* text = node.as_string()) {
                return text->get();
            }
            break;
        case SettingType::Point:
            if (auto p = point_of(node)) {
                return *p;
            }
            break;
    }
    return std::nullopt;
}

class TableReader {
  public:
    TableReader(std::string source, std::filesystem::path base, RunConfig& config)
        : source_(std::move(source)), base_(std::move(base)), config_(config) {}

    void read(const toml::table& root) {
        for (const auto& [key, node] : root) {
            const std::string name(key.str());
            if (const auto* section = node.as_table()) {
                if (!known_section(name)) {
                    problem(line_of(node), "[" + name + "]", "",
                            "unknown section" + suggestion(name, sections()));
                    continue;
                }
                for (const auto& [inner_key, inner_node] : *section) {
                    read_setting(name + "." + std::string(inner_key.str()), inner_node);
                }
            } else {
                read_setting(name, node);
            }
        }
    }

    std::vector<InputProblem>& problems() { return problems_; }

  private:
    void read_setting(const std::string& key, const toml::node& node) {
        const int line = line_of(node);
        const Setting* setting = find_setting_by_key(key);
        if (setting == nullptr) {
            problem(line, key, "", "unknown setting" + suggestion(key, keys()));
            return;
        }
        std::optional<SettingValue> value = convert(*setting, node);
        if (!value) {
            problem(line, key, node_text(node), type_reason(setting->type));
            return;
        }
        if (setting->type == SettingType::Choice) {
            const auto& word = std::get<std::string>(*value);
            if (std::find(setting->choices.begin(), setting->choices.end(), word)
                == setting->choices.end()) {
                std::string list;
                for (const std::string& choice : setting->choices) {
                    list += (list.empty() ? "" : ", ") + choice;
                }
                problem(line, key, node_text(node), "must be one of: " + list);
                return;
            }
        }
        if (setting->type == SettingType::Integer) {
            const std::int64_t number = std::get<std::int64_t>(*value);
            const bool laps = key == "laps";
            if (number < (laps ? 1 : 0) || (laps && number > 1000)) {
                problem(line, key, node_text(node),
                        laps ? "must be between 1 and 1000" : "must not be negative");
                return;
            }
            if (number > setting->integer_max) {
                problem(line, key, node_text(node),
                        "must be at most " + std::to_string(setting->integer_max));
                return;
            }
        }
        if (setting->built_in_files) {
            // A file: relative to this configuration's directory, unless a built-in's name.
            const std::string& text = std::get<std::string>(*value);
            const auto& built_in = setting->built_in_files();
            std::filesystem::path path(text);
            if (std::find(built_in.begin(), built_in.end(), text) == built_in.end() && !path.empty()
                && path.is_relative() && !base_.empty()) {
                path = base_ / path;
            }
            value = path.string();
        }
        setting->set(config_, *value);
        config_.origins[setting->field] = {source_, line, key};
    }

    void problem(int line, std::string key, std::string value, std::string reason) {
        problems_.push_back({source_, line, std::move(key), std::move(value), std::move(reason)});
    }

    static std::vector<std::string> keys() {
        std::vector<std::string> all;
        for (const Setting& setting : run_settings()) {
            all.push_back(setting.key);
        }
        return all;
    }

    static std::vector<std::string> sections() {
        std::set<std::string> unique;
        for (const Setting& setting : run_settings()) {
            if (!setting.section().empty()) {
                unique.insert(setting.section());
            }
        }
        return {unique.begin(), unique.end()};
    }

    static bool known_section(const std::string& name) {
        const auto all = sections();
        return std::find(all.begin(), all.end(), name) != all.end();
    }

    static std::string suggestion(const std::string& word, const std::vector<std::string>& all) {
        const std::string match = closest_match(word, all);
        return match.empty() ? std::string() : " (did you mean '" + match + "'?)";
    }

    std::string source_;
    std::filesystem::path base_;
    RunConfig& config_;
    std::vector<InputProblem> problems_;
};

}  // namespace

std::string closest_match(const std::string& word, const std::vector<std::string>& candidates) {
    // Levenshtein distance, case-insensitive.
    const auto distance = [](const std::string& a, const std::string& b) {
        std::vector<std::size_t> row(b.size() + 1);
        for (std::size_t j = 0; j <= b.size(); ++j) {
            row[j] = j;
        }
        for (std::size_t i = 1; i <= a.size(); ++i) {
            std::size_t diagonal = row[0];
            row[0] = i;
            for (std::size_t j = 1; j <= b.size(); ++j) {
                const std::size_t above = row[j];
                const bool same = std::tolower(static_cast<unsigned char>(a[i - 1]))
                                  == std::tolower(static_cast<unsigned char>(b[j - 1]));
                row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0U : 1U)});
                diagonal = above;
            }
        }
        return row[b.size()];
    };
    std::string best;
    std::size_t best_distance = 4;
    for (const std::string& candidate : candidates) {
        const std::size_t d = distance(word, candidate);
        if (d < best_distance) {
            best_distance = d;
            best = candidate;
        }
    }
    return best;
}

void apply_config_table(const toml::table& root, const std::string& source, RunConfig& config,
                        const std::filesystem::path& base_directory) {
    RunConfig updated = config;
    TableReader reader(source, base_directory, updated);
    reader.read(root);
    if (!reader.problems().empty()) {
        throw InputError(std::move(reader.problems()));
    }
    config = std::move(updated);
}

toml::table parse_toml(std::string_view text, const std::string& source) {
    try {
        return toml::parse(text, source);
    } catch (const toml::parse_error& error) {
        throw InputError({{source, static_cast<int>(error.source().begin.line), "", "",
                           std::string(error.description())}});
    }
}

void apply_config_toml(std::string_view text, const std::string& source, RunConfig& config,
                       const std::filesystem::path& base_directory) {
    apply_config_table(parse_toml(text, source), source, config, base_directory);
}

RunConfig load_config_file(const std::filesystem::path& path, const RunConfig& base) {
    RunConfig config = base;
    apply_config_toml(read_text_file(path, kConfigurationFile), path.string(), config,
                      path.parent_path());
    return config;
}

std::string config_to_toml(const RunConfig& config, std::string_view title) {
    std::ostringstream out;
    out << "# " << title << "\n"
        << "# LegoFeup Lab run configuration. Units are SI (m, s, rad) unless a key ends\n"
        << "# in _deg. Any key left out keeps its default.\n";
    std::string current_section = "(none)";
    for (const Setting& setting : run_settings()) {
        const std::string section = setting.section();
        if (section != current_section) {
            out << "\n";
            if (!section.empty()) {
                out << "[" << section << "]\n";
            }
            current_section = section;
        }
        const bool set = !setting.is_set || setting.is_set(config);
        out << (set ? "" : "# ") << setting.name() << " = "
            << format_setting_value(setting.get(config)) << "  # " << setting.file_comment()
            << "\n";
    }
    return out.str();
}

RunConfig compose_config(const ConfigSources& sources) {
    RunConfig config;
    if (!sources.experiment.empty()) {
        const Experiment* experiment = find_experiment(sources.experiment);
        if (experiment == nullptr) {
            throw InputError({{"", 0, "--experiment", sources.experiment,
                               "unknown experiment (choose a … h, or <lesson>:<step> of another "
                               "built-in lesson, e.g. beacons:a; `legofeup-cli lesson show "
                               "beacons` lists the steps)"}});
        }
        config = experiment->config;
    }
    if (!sources.config_file.empty()) {
        config = load_config_file(sources.config_file, config);
    }
    if (sources.seed) {
        config.seed = *sources.seed;
        config.origins["seed"] = {"--seed", 0, "seed"};
    }
    return config;
}

}  // namespace legofeup::lessons
