// Reading a lesson document (docs/lessons.md) into a Lesson, collecting every problem.
#include <algorithm>
#include <cctype>
#include <map>

#include "config_reader.hpp"
#include "document_reader.hpp"
#include "legofeup/lessons/config_schema.hpp"
#include "legofeup/lessons/lesson.hpp"
#include "metric_check.hpp"
#include "text_file.hpp"
#include "toml_values.hpp"

namespace legofeup::lessons {
namespace {

const std::vector<std::string> kLessonKeys = {"id", "title", "goals", "base", "step", "grading"};
const std::vector<std::string> kStepKeys = {"id",          "title",    "instructions", "observe",
                                            "expectation", "question", "check",        "config"};
const std::vector<std::string> kQuestionKeys = {"id", "text"};
const std::vector<std::string> kCheckKeys = {"expression", "description"};
const std::vector<std::string> kGradingKeys = {"step", "seeds", "first_seed", "tunable", "check"};

bool is_identifier(const std::string& id) {
    return !id.empty() && std::all_of(id.begin(), id.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
    });
}

// Every configuration section ("filter") and key ("filter.q11"): what `tunable` may list.
std::vector<std::string> tunable_names() {
    std::vector<std::string> names;
    for (const Setting& setting : run_settings()) {
        const std::string section = setting.section();
        if (!section.empty() && std::find(names.begin(), names.end(), section) == names.end()) {
            names.push_back(section);
        }
        names.push_back(setting.key);
    }
    return names;
}

class LessonReader {
  public:
    LessonReader(const std::string& source, std::filesystem::path base_directory)
        : doc_(source), base_directory_(std::move(base_directory)) {}

    Lesson read(const toml::table& root) {
        Lesson lesson;
        lesson.source = doc_.source();
        doc_.only_keys(root, kLessonKeys, "");
        lesson.id = read_id(root, "", "the lesson's short name, e.g. \"legofeup\"");
        lesson.title = doc_.text(root, "title", "", "the lesson's title");
        lesson.goals = doc_.text(root, "goals", "", "what students learn (Markdown)");
        const RunConfig base = base_config(root);
        const auto steps = doc_.tables(root, "step", "");
        if (steps.empty() && root.get("step") == nullptr) {
            doc_.problem(1, "step", "", "a lesson needs at least one [[step]]");
        }
        std::map<std::string, int> step_ids;
        for (const toml::table* table : steps) {
            lesson.steps.push_back(read_step(*table, base, step_ids));
        }
        if (const toml::table* grading = doc_.table(root, "grading", "")) {
            lesson.grading = read_grading(*grading, lesson);
        }
        doc_.throw_if_problems();
        return lesson;
    }

  private:
    RunConfig base_config(const toml::table& root) {
        RunConfig base;
        if (const toml::table* overlay = doc_.table(root, "base", "")) {
            try {
                apply_config_table(*overlay, doc_.source(), base, base_directory_);
            } catch (const InputError& error) {
                doc_.add(error);
                base_ok_ = false;
            }
        }
        return base;
    }

    // An id: letters, digits, '-' and '_' (submissions and reports name it), unique among
    // `seen` (id → line) when given.
    std::string read_id(const toml::table& table, const std::string& prefix, const std::string& why,
                        std::map<std::string, int>* seen = nullptr, const std::string& what = "") {
        const std::string id = doc_.text(table, "id", prefix, why);
        if (id.empty()) {
            return id;
        }
        const int line = line_of(*table.get("id"));
        if (!is_identifier(id)) {
            doc_.problem(line, prefix + "id", "\"" + id + "\"",
                         "use letters, digits, '-' and '_' only");
        } else if (seen != nullptr) {
            if (const auto [first, fresh] = seen->emplace(id, line); !fresh) {
                doc_.problem(line, prefix + "id", "\"" + id + "\"",
                             "duplicate " + what + " (first used on line "
                                 + std::to_string(first->second) + ")");
            }
        }
        return id;
    }

    LessonStep read_step(const toml::table& table, const RunConfig& base,
                         std::map<std::string, int>& step_ids) {
        const std::string prefix = "step.";
        doc_.only_keys(table, kStepKeys, prefix);
        LessonStep step;
        step.id =
            read_id(table, prefix, "every step needs an id, e.g. \"a\"", &step_ids, "step id");
        step.title = doc_.text(table, "title", prefix, "every step needs a title");
        step.instructions =
            doc_.text(table, "instructions", prefix, "what the student does (Markdown)");
        step.observe = doc_.text(table, "observe", prefix, "what to watch while it runs");
        step.expectation =
            doc_.text(table, "expectation", prefix, "the conclusion the step should lead to");
        step.questions = read_questions(table);
        step.checks = read_checks(table, prefix);
        step.config = base;
        bool config_ok = base_ok_;
        if (const toml::table* overlay = doc_.table(table, "config", prefix)) {
            try {
                apply_config_table(*overlay, doc_.source(), step.config, base_directory_);
            } catch (const InputError& error) {
                doc_.add(error);
                config_ok = false;
            }
        }
        if (config_ok) {
            try {
                resolve(step.config);  // a preset that would not run is a bad lesson
            } catch (const InputError& error) {
                doc_.add(error);
            }
        }
        return step;
    }

    std::vector<LessonQuestion> read_questions(const toml::table& step) {
        const std::string prefix = "step.question.";
        std::vector<LessonQuestion> questions;
        std::map<std::string, int> ids;
        for (const toml::table* table : doc_.tables(step, "question", "step.")) {
            doc_.only_keys(*table, kQuestionKeys, prefix);
            LessonQuestion question;
            question.id = read_id(*table, prefix, "every question needs an id, e.g. \"q1\"", &ids,
                                  "question id in this step");
            question.text = doc_.text(*table, "text", prefix, "the question (Markdown)");
            questions.push_back(std::move(question));
        }
        return questions;
    }

    std::vector<MetricCheck> read_checks(const toml::table& parent,
                                         const std::string& parent_prefix) {
        const std::string prefix = parent_prefix + "check.";
        std::vector<MetricCheck> checks;
        for (const toml::table* table : doc_.tables(parent, "check", parent_prefix)) {
            doc_.only_keys(*table, kCheckKeys, prefix);
            const std::string expression =
                doc_.text(*table, "expression", prefix,
                          "the condition on a metric, e.g. \"final_position_error_m > 0.2\"");
            const std::string description =
                doc_.text(*table, "description", prefix, "what the check means, for students");
            if (expression.empty()) {
                continue;
            }
            const int line = line_of(*table->get("expression"));
            ParsedCheck parsed = parse_check_expression(expression);
            if (!parsed.problem.empty()) {
                doc_.problem(line, prefix + "expression", "\"" + expression + "\"", parsed.problem);
                continue;
            }
            parsed.check.description = description;
            parsed.check.source = doc_.source() + ":" + std::to_string(line);
            parsed.check.line = line;
            checks.push_back(std::move(parsed.check));
        }
        return checks;
    }

    GradingSpec read_grading(const toml::table& table, const Lesson& lesson) {
        const std::string prefix = "grading.";
        doc_.only_keys(table, kGradingKeys, prefix);
        GradingSpec spec;
        spec.step = doc_.text(table, "step", prefix, "the id of the step students tune");
        if (!spec.step.empty() && lesson.find_step(spec.step) == nullptr) {
            std::vector<std::string> ids;
            for (const LessonStep& step : lesson.steps) {
                ids.push_back(step.id);
            }
            doc_.problem(line_of(*table.get("step")), prefix + "step", "\"" + spec.step + "\"",
                         "no step with this id (the steps are: " + joined(ids) + ")");
        }
        spec.seeds = static_cast<int>(doc_.integer(table, "seeds", prefix, 1, 100000).value_or(20));
        spec.first_seed = static_cast<std::uint64_t>(
            doc_.integer(table, "first_seed", prefix, 0, std::int64_t{1} << 62).value_or(1));
        spec.tunable = read_tunable(table);
        spec.checks = read_checks(table, prefix);
        return spec;
    }

    std::vector<std::string> read_tunable(const toml::table& grading) {
        std::vector<std::string> tunable;
        const toml::node* node = grading.get("tunable");
        if (node == nullptr) {
            return tunable;
        }
        const auto* list = node->as_array();
        if (list == nullptr) {
            doc_.problem(line_of(*node), "grading.tunable", node_text(*node),
                         "must be a list of texts, e.g. [\"filter\", \"initial.var_x\"]");
            return tunable;
        }
        const std::vector<std::string> allowed = tunable_names();
        for (const toml::node& element : *list) {
            const auto* name = element.as_string();
            if (name == nullptr) {
                doc_.problem(line_of(element), "grading.tunable", node_text(element),
                             "must be a quoted configuration section or key");
                continue;
            }
            if (std::find(allowed.begin(), allowed.end(), name->get()) == allowed.end()) {
                const std::string match = closest_match(name->get(), allowed);
                doc_.problem(line_of(element), "grading.tunable", node_text(element),
                             "not a configuration section or key"
                                 + (match.empty() ? std::string(" (docs/configuration.md)")
                                                  : " (did you mean '" + match + "'?)"));
                continue;
            }
            tunable.push_back(name->get());
        }
        return tunable;
    }

    DocumentReader doc_;
    std::filesystem::path base_directory_;
    bool base_ok_ = true;
};

}  // namespace

Lesson parse_lesson(std::string_view text, const std::string& source,
                    const std::filesystem::path& base_directory) {
    return LessonReader(source, base_directory).read(parse_toml(text, source));
}

Lesson load_lesson_file(const std::filesystem::path& path) {
    return parse_lesson(read_text_file(path, kLessonFile), path.string(), path.parent_path());
}

}  // namespace legofeup::lessons
