#pragma once
// The Lesson dock: the lesson (the built-in LegoFeup one, or a teacher's file), the students'
// names, the steps with where each stands (not run, running, done with its checks passed),
// and the selected step (StepView): its texts, "Apply preset & run", the questions and their
// answers, the checks and — once it has run — the expected conclusion.
//
// The answers are never lost: they are kept with the preferences as they are typed and come
// back at the next start. Saving them (a submission) and exporting the report go through
// paths here; the File menu's dialogs are in LessonActions.

#include <QString>
#include <QWidget>
#include <memory>

#include "legofeup/lessons/lesson.hpp"
#include "legofeup/report/student_report.hpp"

class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QTimer;

namespace legofeup::ui {

class LessonProgress;
class Session;
class StepRunTracker;
class StepView;

class LessonPanel : public QWidget {
    Q_OBJECT

  public:
    /// Starts with the lesson used last (or the built-in one) and its saved answers.
    explicit LessonPanel(Session& session, QWidget* parent = nullptr);
    ~LessonPanel() override;

    const LessonProgress& progress() const { return *progress_; }
    StepView& stepView() const { return *step_view_; }
    const StepRunTracker& tracker() const { return *tracker_; }

    /// Shows step `id` without touching the configuration. False for an unknown id.
    bool showStep(const QString& id);
    /// Shows the step the session's configuration is (step_membership.hpp): `preferred` of this
    /// lesson if it is that step's, else the step it came from — of this lesson or another
    /// built-in one, switching to it. False when it is no step's: `preferred` (or the step
    /// shown) is shown with the note that the configuration is the students' own and its runs
    /// count for no step.
    bool showStepOfConfiguration(const QString& preferred);
    /// Shows step `id` and applies its preset (no run). False for an unknown id or a refused
    /// preset (the note says why).
    bool selectStep(const QString& id);
    QString currentStep() const;
    /// The selected step's instructions and what to observe, as plain text.
    QString instructions() const;

    /// Reads a teacher's lesson and switches to it. Returns "" or every problem (file:line,
    /// reason); on error the current lesson stays.
    QString openLesson(const QString& path);
    /// Switches to the built-in lesson `id` (lessons::built_in_lessons(): "legofeup",
    /// "beacons", …); an unknown id gives the LegoFeup lesson.
    void useBuiltInLesson(const QString& id = QStringLiteral("legofeup"));

    /// Writes the submission (names, answers, the graded step's tuning as the configuration
    /// has it now). Returns "" or why not.
    QString saveAnswers(const QString& path) const;
    /// Reads a submission of this lesson: names and answers (and the tuning, applied to the
    /// configuration). Returns "" or every problem (file:line).
    QString openAnswers(const QString& path);
    /// Writes report.html and report.pdf into `directory`. Returns "" or why not.
    /// The student's report as it stands now (steps run, checks, answers), stamped with the
    /// local time: a copy, to be written anywhere, on any thread.
    report::StudentReport reportNow() const;
    QString exportReport(const QString& directory) const;
    /// Keeps the names and answers with the preferences now (they are also kept as typed).
    void saveAnswersNow() const;

  public slots:
    /// Applies the selected step's preset and starts a new run.
    void applyAndRun();

  signals:
    /// The "Open…" button: File ▸ Open lesson… asks for the file.
    void openLessonRequested();
    void lessonChanged();
    void stepApplied(const QString& id);
    /// A step's run finished and its outcome (checks, conclusion) is shown.
    void stepOutcomeShown(const QString& id);
    /// Something worth a line in the status bar.
    void note(const QString& text);

  private:
    void setLesson(lessons::Lesson lesson, const QString& file);
    void refreshList();
    void stepChosen(int row);
    void answersEdited();
    /// Says, when it is so, that the configuration is not the shown step's.
    void refreshConfigurationOwner();

    Session& session_;
    std::unique_ptr<LessonProgress> progress_;
    QString lesson_file_;  ///< "builtin:<id>" for a built-in lesson, else the file's path
    StepRunTracker* tracker_ = nullptr;
    QComboBox* lesson_choice_ = nullptr;
    QLabel* lesson_title_ = nullptr;
    QLineEdit* students_ = nullptr;
    QLabel* configuration_owner_ = nullptr;
    QListWidget* steps_ = nullptr;
    StepView* step_view_ = nullptr;
    QTimer* autosave_ = nullptr;
};

}  // namespace legofeup::ui
