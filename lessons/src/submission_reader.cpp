// Reading a submission (docs/lessons.md): its answers must fit the lesson's steps and
// questions, and its tuning the lesson's [grading] tunable list.
#include <algorithm>

#include "config_reader.hpp"
#include "document_reader.hpp"
#include "legofeup/lessons/submission.hpp"
#include "text_file.hpp"
#include "toml_values.hpp"
#include "tuning_settings.hpp"

namespace legofeup::lessons {
namespace {

const std::vector<std::string> kSubmissionKeys = {"lesson", "students", "answers", "tuning"};

class SubmissionReader {
  public:
    SubmissionReader(const std::string& source, const Lesson& lesson)
        : doc_(source), lesson_(lesson) {}

    Submission read(const toml::table& root) {
        Submission submission;
        submission.source = doc_.source();
        doc_.only_keys(root, kSubmissionKeys, "");
        submission.lesson =
            doc_.text(root, "lesson", "", "the id of the lesson it answers, e.g. \"legofeup\"");
        if (!submission.lesson.empty() && submission.lesson != lesson_.id) {
            doc_.problem(line_of(*root.get("lesson")), "lesson", "\"" + submission.lesson + "\"",
                         "this submission is for another lesson (expected \"" + lesson_.id + "\")");
        }
        submission.students = doc_.text(root, "students", "", "who hands it in");
        if (const toml::table* answers = doc_.table(root, "answers", "")) {
            submission.answers = read_answers(*answers);
        }
        read_tuning(root, submission);
        doc_.throw_if_problems();
        return submission;
    }

  private:
    std::map<std::string, std::map<std::string, std::string>> read_answers(
        const toml::table& answers) {
        std::map<std::string, std::map<std::string, std::string>> result;
        for (const auto& [step_key, step_node] : answers) {
            const std::string step_id(step_key.str());
            const LessonStep* step = lesson_.find_step(step_id);
            if (step == nullptr) {
                std::vector<std::string> ids;
                for (const LessonStep& s : lesson_.steps) {
                    ids.push_back(s.id);
                }
                doc_.problem(line_of(step_node), "answers." + step_id, "",
                             "no such step in lesson \"" + lesson_.id
                                 + "\" (its steps: " + joined(ids) + ")");
                continue;
            }
            const auto* table = step_node.as_table();
            if (table == nullptr) {
                doc_.problem(line_of(step_node), "answers." + step_id, node_text(step_node),
                             "must be a table [answers." + step_id + "] of answers");
                continue;
            }
            for (const auto& [question_key, answer] : *table) {
                read_answer(*step, std::string(question_key.str()), answer, result[step_id]);
            }
        }
        return result;
    }

    void read_answer(const LessonStep& step, const std::string& question_id,
                     const toml::node& answer, std::map<std::string, std::string>& answers) {
        const std::string key = "answers." + step.id + "." + question_id;
        const bool asked =
            std::any_of(step.questions.begin(), step.questions.end(),
                        [&](const LessonQuestion& question) { return question.id == question_id; });
        if (!asked) {
            std::vector<std::string> ids;
            for (const LessonQuestion& question : step.questions) {
                ids.push_back(question.id);
            }
            doc_.problem(
                line_of(answer), key, "",
                "step " + step.id + " has no such question (its questions: " + joined(ids) + ")");
            return;
        }
        if (const auto* text = answer.as_string()) {
            answers[question_id] = text->get();
        } else {
            doc_.problem(line_of(answer), key, node_text(answer), "must be a quoted text");
        }
    }

    void read_tuning(const toml::table& root, Submission& submission) {
        const toml::table* tuning = doc_.table(root, "tuning", "");
        const LessonStep* graded =
            lesson_.grading ? lesson_.find_step(lesson_.grading->step) : nullptr;
        if (graded == nullptr) {
            if (tuning != nullptr && !tuning->empty()) {
                doc_.problem(line_of(*tuning), "tuning", "",
                             "lesson \"" + lesson_.id + "\" grades no step, so it takes no tuning");
            }
            return;
        }
        submission.tuned = graded->config;
        if (tuning == nullptr) {
            return;
        }
        const std::size_t problems_before = doc_.problem_count();
        const std::set<std::string> keys = tuned_keys(*tuning);
        if (doc_.problem_count() != problems_before) {
            return;
        }
        try {
            apply_config_table(*tuning, doc_.source(), submission.tuned, {});
            resolve(submission.tuned);
        } catch (const InputError& error) {
            doc_.add(error);
            return;
        }
        submission.tuning_toml = settings_to_toml(submission.tuned, keys);
    }

    // The settings [tuning] sets, each checked against the lesson's tunable list.
    std::set<std::string> tuned_keys(const toml::table& tuning) {
        std::set<std::string> keys;
        const auto check = [&](const std::string& key, const toml::node& node) {
            if (is_tunable(key, *lesson_.grading)) {
                keys.insert(key);
            } else {
                doc_.problem(line_of(node), "tuning." + key, node_text(node),
                             "lesson \"" + lesson_.id + "\" lets students tune only: "
                                 + joined(lesson_.grading->tunable));
            }
        };
        for (const auto& [name, node] : tuning) {
            if (const auto* section = node.as_table()) {
                for (const auto& [inner, inner_node] : *section) {
                    check(std::string(name.str()) + "." + std::string(inner.str()), inner_node);
                }
            } else {
                check(std::string(name.str()), node);
            }
        }
        return keys;
    }

    DocumentReader doc_;
    const Lesson& lesson_;
};

}  // namespace

Submission parse_submission(std::string_view text, const std::string& source,
                            const Lesson& lesson) {
    return SubmissionReader(source, lesson).read(parse_toml(text, source));
}

Submission load_submission_file(const std::filesystem::path& path, const Lesson& lesson) {
    return parse_submission(read_text_file(path, kSubmissionFile), path.string(), lesson);
}

}  // namespace legofeup::lessons
