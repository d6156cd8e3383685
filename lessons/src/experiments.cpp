#include "legofeup/lessons/experiments.hpp"

#include "config_reader.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup_experiments_resource.hpp"
#include "toml_values.hpp"

namespace legofeup::lessons {
namespace {

std::string text_field(const toml::table& table, const char* key, const std::string& source,
                       std::vector<InputProblem>& problems) {
    if (const auto* text = table[key].as_string()) {
        return text->get();
    }
    problems.push_back({source, line_of(table), key, "",
                        "every experiment needs a text `" + std::string(key) + "`"});
    return {};
}

}  // namespace

std::vector<Experiment> parse_experiments(std::string_view text, const std::string& source) {
    const toml::table root = parse_toml(text, source);
    RunConfig base;
    if (const auto* common = root["base"].as_table()) {
        apply_config_table(*common, source, base, {});
    }
    const auto* list = root["experiment"].as_array();
    if (list == nullptr || !list->is_array_of_tables()) {
        throw InputError({{source, 0, "experiment", "", "no [[experiment]] tables"}});
    }
    std::vector<Experiment> experiments;
    std::vector<InputProblem> problems;
    for (const auto& node : *list) {
        const toml::table& table = *node.as_table();
        Experiment experiment;
        experiment.id = text_field(table, "id", source, problems);
        experiment.title = text_field(table, "title", source, problems);
        experiment.instructions = text_field(table, "instructions", source, problems);
        experiment.expectation = text_field(table, "expectation", source, problems);
        experiment.config = base;
        if (const auto* overlay = table["config"].as_table()) {
            try {
                apply_config_table(*overlay, source, experiment.config, {});
            } catch (const InputError& error) {
                problems.insert(problems.end(), error.problems().begin(), error.problems().end());
            }
        }
        experiments.push_back(std::move(experiment));
    }
    if (!problems.empty()) {
        throw InputError(std::move(problems));
    }
    return experiments;
}

const std::vector<Experiment>& legofeup_experiments() {
    static const std::vector<Experiment> experiments =
        parse_experiments(resources::kLegoFeupExperiments, "experiments/legofeup.toml (built in)");
    return experiments;
}

const Experiment* find_experiment(std::string_view id) {
    for (const Experiment& experiment : legofeup_experiments()) {
        if (experiment.id == id) {
            return &experiment;
        }
    }
    return nullptr;
}

}  // namespace legofeup::lessons
