#pragma once
// One lesson step as the students read it on the projector: what to do and what to observe
// (Markdown), the button that applies the step's preset and runs it, the questions with a box
// for each answer, the automatic checks (their outcome once the run finished), and the
// expected conclusion — hidden until the step has run, then revealed.

#include <QString>
#include <QWidget>
#include <map>
#include <string>

#include "legofeup/lessons/lesson.hpp"

class QLabel;
class QPlainTextEdit;
class QPushButton;
class QVBoxLayout;

namespace legofeup::ui {

class LessonProgress;

class StepView : public QWidget {
    Q_OBJECT

  public:
    explicit StepView(QWidget* parent = nullptr);

    /// Shows `step` (its answers as `progress` has them) and its state.
    void showStep(const lessons::LessonStep& step, const LessonProgress& progress);
    /// Shows the state, the checks and the conclusion as `progress` has them now.
    void refresh(const LessonProgress& progress);
    /// A line under the button: what was applied, or why not.
    void setNote(const QString& text, bool error = false);

    const std::string& stepId() const { return step_id_; }
    /// What the students read (instructions and what to observe), as plain text.
    QString instructions() const;
    bool expectationShown() const;
    QPlainTextEdit* answerBox(const std::string& question_id) const;

  signals:
    void applyAndRunRequested();
    void answerEdited(const QString& question_id, const QString& text);

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void rebuildQuestions(const lessons::LessonStep& step, const LessonProgress& progress);

    std::string step_id_;
    QLabel* title_ = nullptr;
    QLabel* state_ = nullptr;
    QLabel* instructions_ = nullptr;
    QLabel* observe_ = nullptr;
    QPushButton* run_ = nullptr;
    QLabel* note_ = nullptr;
    QWidget* questions_ = nullptr;
    QVBoxLayout* questions_layout_ = nullptr;
    std::map<std::string, QPlainTextEdit*> answers_;
    QLabel* checks_ = nullptr;
    QLabel* expectation_ = nullptr;
    QLabel* locked_ = nullptr;
};

/// "✓ Done · checks 2/3", "▶ Running…" — a step's state in a few characters, for the list.
QString step_state_text(const LessonProgress& progress, const std::string& step_id);

}  // namespace legofeup::ui
