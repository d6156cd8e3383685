#include "legofeup/ui/lesson/lesson_panel.hpp"

#include <QComboBox>
#include <QDateTime>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <array>
#include <exception>

#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/submission.hpp"
#include "legofeup/report/student_report.hpp"
#include "legofeup/ui/lesson/answers_store.hpp"
#include "legofeup/ui/lesson/lesson_progress.hpp"
#include "legofeup/ui/lesson/step_membership.hpp"
#include "legofeup/ui/lesson/step_run_tracker.hpp"
#include "legofeup/ui/lesson/step_view.hpp"
#include "legofeup/ui/session/session.hpp"
#include "legofeup/ui/window/app_settings.hpp"
#include "legofeup/ui/write_atomically.hpp"

namespace legofeup::ui {
namespace {

constexpr int kAutosaveDelayMs = 800;  // typing pauses this long before the answers are kept

/// How the lesson choice (and the preferences) name a built-in lesson: "builtin:<id>";
/// anything else is a lesson file's path, and "" (older preferences) the LegoFeup lesson.
const QString kBuiltInPrefix = QStringLiteral("builtin:");

QString built_in_key(const std::string& id) {
    return kBuiltInPrefix + QString::fromStdString(id);
}

/// One line per step: its state's mark, id and title, and once run the checks passed.
QString step_label(const lessons::LessonStep& step, const LessonProgress& progress) {
    static const std::array<QString, 3> kMarks = {QStringLiteral("○"), QStringLiteral("▶"),
                                                  QStringLiteral("✓")};
    const StepState state = progress.state(step.id);
    QString label = QStringLiteral("%1  %2) %3")
                        .arg(kMarks.at(static_cast<std::size_t>(state)),
                             QString::fromStdString(step.id), QString::fromStdString(step.title));
    if (const auto [passed, judged] = progress.checksPassed(step.id); judged > 0) {
        label += QObject::tr("  — checks %1/%2").arg(passed).arg(judged);
    }
    if (const int not_judged = progress.checksNotJudged(step.id); not_judged > 0) {
        label +=
            not_judged == 1
                ? QObject::tr("  — 1 check not judged without the true pose")
                : QObject::tr("  — %1 checks not judged without the true pose").arg(not_judged);
    }
    return label;
}

}  // namespace

LessonPanel::LessonPanel(Session& session, QWidget* parent) : QWidget(parent), session_(session) {
    auto* layout = new QVBoxLayout(this);

    auto* choice_row = new QHBoxLayout;
    lesson_choice_ = new QComboBox(this);
    lesson_choice_->setObjectName(QStringLiteral("lessonChoice"));
    lesson_choice_->setToolTip(tr("The built-in LegoFeup lesson, or a teacher's lesson file"));
    choice_row->addWidget(lesson_choice_, 1);
    auto* open = new QPushButton(tr("Open…"), this);
    open->setToolTip(tr("Open a teacher's lesson file (File ▸ Open lesson…)"));
    connect(open, &QPushButton::clicked, this, &LessonPanel::openLessonRequested);
    choice_row->addWidget(open);
    layout->addLayout(choice_row);

    lesson_title_ = new QLabel(this);
    lesson_title_->setObjectName(QStringLiteral("lessonTitle"));
    lesson_title_->setWordWrap(true);
    layout->addWidget(lesson_title_);

    auto* names = new QFormLayout;
    students_ = new QLineEdit(this);
    students_->setObjectName(QStringLiteral("studentNames"));
    students_->setPlaceholderText(tr("e.g. Ana Silva, Rui Costa"));
    names->addRow(tr("Students:"), students_);
    layout->addLayout(names);

    // Shown only when the configuration is not the selected step's: its runs count for none.
    configuration_owner_ = new QLabel(this);
    configuration_owner_->setObjectName(QStringLiteral("configurationOwner"));
    configuration_owner_->setWordWrap(true);
    configuration_owner_->hide();
    layout->addWidget(configuration_owner_);

    // The steps above, the selected one below; the students drag the divide as they like.
    auto* split = new QSplitter(Qt::Vertical, this);
    steps_ = new QListWidget(split);
    steps_->setObjectName(QStringLiteral("lessonSteps"));
    steps_->setWordWrap(true);
    steps_->setAlternatingRowColors(true);
    step_view_ = new StepView;
    auto* scroll = new QScrollArea(split);
    scroll->setObjectName(QStringLiteral("stepScroll"));
    scroll->setWidget(step_view_);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    split->addWidget(steps_);
    split->addWidget(scroll);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 4);
    split->setChildrenCollapsible(false);
    layout->addWidget(split, 1);

    tracker_ = new StepRunTracker(session_, this);
    autosave_ = new QTimer(this);
    autosave_->setSingleShot(true);
    autosave_->setInterval(kAutosaveDelayMs);
    connect(autosave_, &QTimer::timeout, this, [this] { store_answers(*progress_); });

    connect(lesson_choice_, &QComboBox::activated, this, [this](int index) {
        const QString file = lesson_choice_->itemData(index).toString();
        if (file == lesson_file_) {
            return;
        }
        if (file.startsWith(kBuiltInPrefix)) {
            useBuiltInLesson(file.mid(kBuiltInPrefix.size()));
        } else if (const QString error = openLesson(file); !error.isEmpty()) {
            emit note(error);
        }
    });
    connect(steps_, &QListWidget::currentRowChanged, this, &LessonPanel::stepChosen);
    connect(students_, &QLineEdit::textEdited, this, [this](const QString& text) {
        progress_->setStudents(text.toStdString());
        answersEdited();
    });
    connect(step_view_, &StepView::answerEdited, this,
            [this](const QString& question, const QString& text) {
                progress_->setAnswer(step_view_->stepId(), question.toStdString(),
                                     text.toStdString());
                answersEdited();
            });
    connect(step_view_, &StepView::applyAndRunRequested, this, &LessonPanel::applyAndRun);
    connect(&session_, &Session::configChanged, this, &LessonPanel::refreshConfigurationOwner);

    const auto refresh_step = [this](const QString& id) {
        refreshList();
        if (id.toStdString() == step_view_->stepId()) {
            step_view_->refresh(*progress_);
        }
    };
    connect(tracker_, &StepRunTracker::stepStarted, this, [this, refresh_step](const QString& id) {
        progress_->markRunning(id.toStdString());
        refresh_step(id);
    });
    connect(tracker_, &StepRunTracker::stepAbandoned, this,
            [this, refresh_step](const QString& id) {
                progress_->markAbandoned(id.toStdString());
                refresh_step(id);
            });
    connect(tracker_, &StepRunTracker::outcomeReady, this,
            [this, refresh_step](const report::StepOutcome& outcome) {
                const QString id = QString::fromStdString(outcome.step_id);
                progress_->setOutcome(outcome);
                refresh_step(id);
                const auto [passed, judged] = progress_->checksPassed(outcome.step_id);
                const int not_judged = progress_->checksNotJudged(outcome.step_id);
                emit note(not_judged == 0
                              ? tr("Step %1 done: %2 of %3 checks passed on the run shown; its "
                                   "conclusion is shown.")
                                    .arg(id)
                                    .arg(passed)
                                    .arg(judged)
                              : tr("Step %1 done: %2 of %3 checks passed on the run shown, %4 not "
                                   "judged without the true pose; its conclusion is shown.")
                                    .arg(id)
                                    .arg(passed)
                                    .arg(judged)
                                    .arg(not_judged));
                emit stepOutcomeShown(id);
            });

    // The lesson used last, if it still reads; otherwise the built-in one.
    const QString last = preferences::kLessonFile.read();
    if (last.startsWith(kBuiltInPrefix)) {
        useBuiltInLesson(last.mid(kBuiltInPrefix.size()));
    } else if (last.isEmpty() || !openLesson(last).isEmpty()) {
        useBuiltInLesson();
    }
}

LessonPanel::~LessonPanel() {
    saveAnswersNow();
}

void LessonPanel::saveAnswersNow() const {
    autosave_->stop();
    if (progress_ != nullptr) {
        store_answers(*progress_);
    }
}

void LessonPanel::answersEdited() {
    autosave_->start();
}

void LessonPanel::setLesson(lessons::Lesson lesson, const QString& file) {
    saveAnswersNow();  // the previous lesson's answers stay with it
    const QString keep_step = currentStep();
    progress_ = std::make_unique<LessonProgress>(std::move(lesson));
    restore_answers(*progress_);
    lesson_file_ = file;
    preferences::kLessonFile.write(file);

    const QSignalBlocker blocker(lesson_choice_);
    lesson_choice_->clear();
    // Every built-in lesson (lessons::built_in_lessons(), in its order), then the file.
    for (const lessons::BuiltInLesson& built_in : lessons::built_in_lessons()) {
        lesson_choice_->addItem(tr("%1 (built-in)").arg(QString::fromStdString(built_in.title)),
                                built_in_key(built_in.id));
    }
    if (!file.startsWith(kBuiltInPrefix)) {
        lesson_choice_->addItem(QFileInfo(file).fileName(), file);
        lesson_choice_->setItemData(lesson_choice_->count() - 1, file, Qt::ToolTipRole);
    }
    lesson_choice_->setCurrentIndex(std::max(0, lesson_choice_->findData(file)));
    lesson_title_->setText(
        QStringLiteral("<b>%1</b>")
            .arg(QString::fromStdString(progress_->lesson().title).toHtmlEscaped()));
    lesson_title_->setToolTip(QString::fromStdString(progress_->lesson().goals));
    students_->setText(QString::fromStdString(progress_->students()));

    {
        const QSignalBlocker list_blocker(steps_);
        steps_->clear();
        for (const lessons::LessonStep& step : progress_->lesson().steps) {
            auto* item = new QListWidgetItem(steps_);
            item->setData(Qt::UserRole, QString::fromStdString(step.id));
        }
    }
    refreshList();
    emit lessonChanged();
    if (!showStep(keep_step) && !progress_->lesson().steps.empty()) {
        showStep(QString::fromStdString(progress_->lesson().steps.front().id));
    }
}

void LessonPanel::refreshList() {
    int height = 2 * steps_->frameWidth();
    for (int row = 0; row < steps_->count(); ++row) {
        const lessons::LessonStep& step =
            progress_->lesson().steps.at(static_cast<std::size_t>(row));
        QListWidgetItem* item = steps_->item(row);
        item->setText(step_label(step, *progress_));
        item->setToolTip(step_state_text(*progress_, step.id));
        item->setData(Qt::AccessibleDescriptionRole, item->toolTip());
        height += steps_->sizeHintForRow(row);
    }
    // Every step in sight (up to a dozen or so); a longer lesson scrolls.
    steps_->setMinimumHeight(std::min(height, 14 * steps_->fontMetrics().lineSpacing()));
}

void LessonPanel::stepChosen(int row) {
    if (row < 0 || row >= static_cast<int>(progress_->lesson().steps.size())) {
        return;
    }
    const lessons::LessonStep& step = progress_->lesson().steps[static_cast<std::size_t>(row)];
    step_view_->showStep(step, *progress_);
    tracker_->setStep(progress_->sharedLesson(), step.id);
    refreshConfigurationOwner();
    step_view_->setNote(
        session_.running()
            ? tr("A run is going: it counts for the step that was shown when it started.")
            : tr("Apply preset & run starts this step. You may tune it while it runs."));
}

void LessonPanel::refreshConfigurationOwner() {
    const lessons::LessonStep* shown = progress_->lesson().find_step(step_view_->stepId());
    const std::vector<std::string> differing =
        shown == nullptr ? std::vector<std::string>{}
                         : experiment_differences(session_.config(), *shown);
    configuration_owner_->setVisible(!differing.empty());
    if (differing.empty()) {
        configuration_owner_->clear();
        return;
    }
    QStringList keys;
    for (const std::string& key : differing) {
        keys << QString::fromStdString(key);
    }
    const QString id = QString::fromStdString(shown->id);
    const StepOfConfiguration own =
        step_of_configuration(session_.config(), {&progress_->lesson()});
    configuration_owner_->setText(
        own.step != nullptr
            ? tr("The configuration is step %1's, not step %2's (it differs from its preset in "
                 "%3): its runs count for no step while step %2 is shown.")
                  .arg(QString::fromStdString(own.step->id), id, keys.join(QStringLiteral(", ")))
            : tr("Own configuration: it differs from step %1's preset in %2, so its runs count "
                 "for no step. Apply preset & run runs step %1.")
                  .arg(id, keys.join(QStringLiteral(", "))));
}

bool LessonPanel::showStepOfConfiguration(const QString& preferred) {
    const lessons::RunConfig& config = session_.config();
    if (const lessons::LessonStep* step = progress_->lesson().find_step(preferred.toStdString());
        step != nullptr && is_step_configuration(config, *step)) {
        return showStep(preferred);
    }
    // This lesson first, then the built-in ones (the same one once).
    std::vector<const lessons::Lesson*> candidates = {&progress_->lesson()};
    for (const lessons::BuiltInLesson& built_in : lessons::built_in_lessons()) {
        if (built_in_key(built_in.id) != lesson_file_) {
            candidates.push_back(lessons::find_built_in_lesson(built_in.id));
        }
    }
    const StepOfConfiguration found = step_of_configuration(config, candidates);
    if (found.step == nullptr) {
        showStep(preferred);  // or the step shown stays; either says "own configuration"
        return false;
    }
    if (found.lesson != &progress_->lesson()) {
        useBuiltInLesson(QString::fromStdString(found.lesson->id));
    }
    return showStep(QString::fromStdString(found.step->id));
}

bool LessonPanel::showStep(const QString& id) {
    const auto& steps = progress_->lesson().steps;
    for (std::size_t row = 0; row < steps.size(); ++row) {
        if (QString::fromStdString(steps[row].id) == id) {
            steps_->setCurrentRow(static_cast<int>(row));  // shows it (currentRowChanged)
            if (step_view_->stepId() != steps[row].id) {
                stepChosen(static_cast<int>(row));
            }
            return true;
        }
    }
    return false;
}

bool LessonPanel::selectStep(const QString& id) {
    if (!showStep(id)) {
        return false;
    }
    const lessons::LessonStep* step = progress_->lesson().find_step(id.toStdString());
    const QStringList problems = session_.setConfig(step->config);
    if (!problems.isEmpty()) {
        step_view_->setNote(tr("The preset was refused:\n%1").arg(problems.join('\n')), true);
        return false;
    }
    step_view_->setNote(session_.running()
                            ? tr("Preset %1 applied: Q, R and the noise take effect now, the "
                                 "rest at the next start.")
                                  .arg(id)
                            : tr("Preset %1 applied. Press Start.").arg(id));
    emit stepApplied(id);
    return true;
}

void LessonPanel::applyAndRun() {
    const QString id = currentStep();
    if (id.isEmpty() || !selectStep(id)) {
        return;
    }
    session_.start();
    step_view_->setNote(tr("Running step %1 from its preset. The step counts as run when its "
                           "routine finishes.")
                            .arg(id));
}

QString LessonPanel::currentStep() const {
    return QString::fromStdString(step_view_->stepId());
}

QString LessonPanel::instructions() const {
    return step_view_->instructions();
}

QString LessonPanel::openLesson(const QString& path) {
    try {
        setLesson(lessons::load_lesson_file(path.toStdString()),
                  QFileInfo(path).absoluteFilePath());
    } catch (const std::exception& error) {  // InputError: file:line and reason per problem
        return QString::fromUtf8(error.what());
    }
    emit note(tr("Lesson \"%1\" opened from %2")
                  .arg(QString::fromStdString(progress_->lesson().title), path));
    return {};
}

void LessonPanel::useBuiltInLesson(const QString& id) {
    const lessons::Lesson* lesson = lessons::find_built_in_lesson(id.toStdString());
    if (lesson == nullptr) {
        lesson = &lessons::legofeup_lesson();  // an id from an older version: the first one
    }
    setLesson(*lesson, built_in_key(lesson->id));
}

QString LessonPanel::saveAnswers(const QString& path) const {
    const lessons::Submission submission = progress_->submission(session_.config());
    return write_atomically(path,
                            QByteArray::fromStdString(lessons::submission_to_toml(submission)));
}

QString LessonPanel::openAnswers(const QString& path) {
    lessons::Submission submission;
    try {
        submission = lessons::load_submission_file(path.toStdString(), progress_->lesson());
    } catch (const std::exception& error) {
        return QString::fromUtf8(error.what());
    }
    progress_->takeAnswers(submission.students, submission.answers);
    students_->setText(QString::fromStdString(progress_->students()));
    if (const lessons::LessonStep* step = progress_->lesson().find_step(step_view_->stepId())) {
        step_view_->showStep(*step, *progress_);
    }
    saveAnswersNow();
    QString done =
        tr("Answers of %1 opened from %2").arg(QString::fromStdString(submission.students), path);
    if (!submission.tuning_toml.empty() && progress_->lesson().grading) {
        // The tuning is the graded step's: apply it as the step's configuration.
        const QString graded = QString::fromStdString(progress_->lesson().grading->step);
        if (session_.setConfig(submission.tuned).isEmpty()) {
            showStep(graded);
            done += tr("; the tuning of step %1 is applied").arg(graded);
        }
    }
    emit note(done);
    return {};
}

report::StudentReport LessonPanel::reportNow() const {
    const QString created =
        QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm"));
    return progress_->report(created.toStdString());
}

QString LessonPanel::exportReport(const QString& directory) const {
    try {
        report::write_report(reportNow(), directory.toStdString());
    } catch (const std::exception& error) {
        return QString::fromUtf8(error.what());
    }
    return {};
}

}  // namespace legofeup::ui
