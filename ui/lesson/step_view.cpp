#include "legofeup/ui/lesson/step_view.hpp"

#include <QEvent>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTextDocument>
#include <QVBoxLayout>
#include <cmath>

#include "legofeup/ui/lesson/lesson_progress.hpp"
#include "legofeup/ui/lesson/shown_run.hpp"
#include "legofeup/ui/panels/message_line.hpp"

namespace legofeup::ui {
namespace {

QLabel* markdown_label(QWidget* parent, const QString& name) {
    auto* label = new QLabel(parent);
    label->setObjectName(name);
    label->setTextFormat(Qt::MarkdownText);
    label->setWordWrap(true);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::LinksAccessibleByMouse);
    label->setOpenExternalLinks(true);
    return label;
}

QLabel* heading(QWidget* parent, const QString& text) {
    auto* label = new QLabel(QStringLiteral("<b>%1</b>").arg(text.toHtmlEscaped()), parent);
    label->setContentsMargins(0, 8, 0, 0);
    return label;
}

/// Green and red that read on the window's background (light or dark theme).
QString outcome_colour(const QWidget& widget, bool passed) {
    const bool dark = widget.palette().color(QPalette::Window).lightness() < 128;
    if (passed) {
        return dark ? QStringLiteral("#7bd88f") : QStringLiteral("#1b6e32");
    }
    return dark ? QStringLiteral("#ff8a80") : QStringLiteral("#b3261e");
}

/// A check for students: what it means, and below it the condition on the metric — as
/// written before the run, with the run's value after it ("final_position_error_m = 0.41 >
/// 0.2").
QString check_line(const QString& mark, const lessons::MetricCheck& check, QString condition) {
    for (const QLatin1String suffix : {QLatin1String(": passed"), QLatin1String(": failed")}) {
        if (condition.endsWith(suffix)) {
            condition.chop(suffix.size());
        }
    }
    const QString description = check.description.empty()
                                    ? QString()
                                    : QString::fromStdString(check.description).toHtmlEscaped();
    return QStringLiteral("<p style=\"margin-bottom:6px\">%1 %2<br><code>%3</code></p>")
        .arg(mark, description, condition.toHtmlEscaped());
}

/// Room for a few lines of answer (more scroll), in the box's own font: large text makes
/// the box taller too (StepView::changeEvent).
void fit_answer_box(QPlainTextEdit& box) {
    constexpr int kLines = 5;
    const int margins =
        static_cast<int>(2 * box.document()->documentMargin()) + 2 * box.frameWidth();
    box.setFixedHeight(box.fontMetrics().lineSpacing() * kLines + margins);
}

}  // namespace

QString step_state_text(const LessonProgress& progress, const std::string& step_id) {
    switch (progress.state(step_id)) {
        case StepState::NotRun:
            return QObject::tr("○ not run");
        case StepState::Running:
            return QObject::tr("▶ running…");
        case StepState::Done: {
            const auto [passed, judged] = progress.checksPassed(step_id);
            QString text = judged == 0
                               ? QObject::tr("✓ done")
                               : QObject::tr("✓ done · checks %1/%2").arg(passed).arg(judged);
            if (const int not_judged = progress.checksNotJudged(step_id); not_judged > 0) {
                text += QObject::tr(" · %1 not judged").arg(not_judged);
            }
            return text;
        }
    }
    return {};
}

StepView::StepView(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    title_ = new QLabel(this);
    title_->setObjectName(QStringLiteral("stepTitle"));
    title_->setWordWrap(true);
    layout->addWidget(title_);
    state_ = new QLabel(this);
    state_->setObjectName(QStringLiteral("stepState"));
    layout->addWidget(state_);

    instructions_ = markdown_label(this, QStringLiteral("stepInstructions"));
    layout->addWidget(instructions_);
    layout->addWidget(heading(this, tr("What to observe")));
    observe_ = markdown_label(this, QStringLiteral("stepObserve"));
    layout->addWidget(observe_);

    run_ = new QPushButton(tr("Apply preset && run"), this);
    run_->setObjectName(QStringLiteral("applyAndRun"));
    run_->setToolTip(
        tr("Sets the configuration to this step's preset and starts a new run. Tune it as you "
           "like while it runs: the step counts as run when its routine finishes."));
    layout->addWidget(run_);
    connect(run_, &QPushButton::clicked, this, &StepView::applyAndRunRequested);
    note_ = new QLabel(this);
    note_->setObjectName(QStringLiteral("stepNote"));
    note_->setWordWrap(true);
    layout->addWidget(note_);

    layout->addWidget(heading(this, tr("Questions for your report")));
    questions_ = new QWidget(this);
    questions_layout_ = new QVBoxLayout(questions_);
    questions_layout_->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(questions_);

    layout->addWidget(heading(this, tr("Automatic checks")));
    checks_ = new QLabel(this);
    checks_->setObjectName(QStringLiteral("stepChecks"));
    checks_->setWordWrap(true);
    checks_->setTextFormat(Qt::RichText);
    checks_->setToolTip(
        tr("Judged on the run shown, from its own steps: tuned while it ran, paused or driven "
           "by keyboard for a while, it is the trajectory the window drew. legofeup-cli report "
           "re-runs a configuration in lockstep instead, and legofeup-cli grade does so on "
           "seeds the students never saw."));
    layout->addWidget(checks_);

    layout->addWidget(heading(this, tr("Expected conclusion")));
    locked_ = new QLabel(tr("Revealed when this step's run has finished. Write down what you "
                            "observed first."),
                         this);
    locked_->setObjectName(QStringLiteral("stepExpectationLocked"));
    locked_->setWordWrap(true);
    locked_->setForegroundRole(QPalette::PlaceholderText);
    layout->addWidget(locked_);
    expectation_ = markdown_label(this, QStringLiteral("stepExpectation"));
    expectation_->setVisible(false);
    layout->addWidget(expectation_);
    layout->addStretch(1);
}

void StepView::showStep(const lessons::LessonStep& step, const LessonProgress& progress) {
    step_id_ = step.id;
    // <big> is relative to the widget's font, so the title follows View ▸ Large text.
    title_->setText(QStringLiteral("<big><b>%1) %2</b></big>")
                        .arg(QString::fromStdString(step.id).toHtmlEscaped(),
                             QString::fromStdString(step.title).toHtmlEscaped()));
    instructions_->setText(QString::fromStdString(step.instructions));
    observe_->setText(QString::fromStdString(step.observe));
    note_->clear();
    rebuildQuestions(step, progress);
    refresh(progress);
}

void StepView::rebuildQuestions(const lessons::LessonStep& step, const LessonProgress& progress) {
    while (QLayoutItem* item = questions_layout_->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    answers_.clear();
    if (step.questions.empty()) {
        questions_layout_->addWidget(new QLabel(tr("No questions in this step."), questions_));
    }
    for (const lessons::LessonQuestion& question : step.questions) {
        QLabel* text =
            markdown_label(questions_, QString::fromStdString("question." + question.id));
        text->setText(QString::fromStdString(question.text));
        questions_layout_->addWidget(text);
        text->show();  // at once, not when the layout next runs (a step shown mid-frame)
        auto* box = new QPlainTextEdit(questions_);
        box->setObjectName(QString::fromStdString("answer." + question.id));
        box->setPlaceholderText(tr("Your answer…"));
        box->setPlainText(QString::fromStdString(progress.answer(step.id, question.id)));
        fit_answer_box(*box);
        box->setTabChangesFocus(true);
        questions_layout_->addWidget(box);
        box->show();
        answers_[question.id] = box;
        connect(box, &QPlainTextEdit::textChanged, this, [this, box, id = question.id] {
            emit answerEdited(QString::fromStdString(id), box->toPlainText());
        });
    }
}

void StepView::refresh(const LessonProgress& progress) {
    const lessons::LessonStep* step = progress.lesson().find_step(step_id_);
    if (step == nullptr) {
        return;
    }
    state_->setText(step_state_text(progress, step_id_));
    const report::StepOutcome* outcome = progress.outcome(step_id_);

    QString text;
    if (step->checks.empty()) {
        text = tr("None in this step.");
    } else if (outcome == nullptr) {
        for (const lessons::MetricCheck& check : step->checks) {
            text +=
                check_line(QStringLiteral("○"), check, QString::fromStdString(check.expression));
        }
        text += tr("<p><i>Checked once the run has finished.</i></p>");
    } else {
        for (const lessons::CheckResult& result : outcome->checks) {
            if (truth_missing(result, outcome->metrics)) {
                // Nothing measured it: say why rather than fail it (or judge another run).
                text += check_line(QStringLiteral("<b>%1</b>").arg(tr("— not judged")),
                                   result.check, QString::fromStdString(result.check.expression));
                text += QStringLiteral("<p style=\"margin-top:0\"><i>%1</i></p>")
                            .arg(tr("This check needs the true pose, which the NXT does not "
                                    "give: only a simulator knows where the robot really is.")
                                     .toHtmlEscaped());
                continue;
            }
            const QString mark = QStringLiteral("<span style=\"color:%1\"><b>%2</b></span>")
                                     .arg(outcome_colour(*this, result.passed),
                                          result.passed ? tr("✓ passed") : tr("✗ failed"));
            text += check_line(mark, result.check, QString::fromStdString(result.message));
        }
        text +=
            QStringLiteral("<p><i>%1</i></p>").arg(tr("Judged on the run shown.").toHtmlEscaped());
    }
    checks_->setText(text);

    const bool revealed = progress.revealed(step_id_);
    expectation_->setText(revealed ? QString::fromStdString(step->expectation) : QString());
    expectation_->setVisible(revealed);
    locked_->setVisible(!revealed);
}

void StepView::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange) {
        for (auto& [id, box] : answers_) {
            fit_answer_box(*box);
        }
    }
}

void StepView::setNote(const QString& text, bool error) {
    show_message_line(*note_, text, error);
}

QString StepView::instructions() const {
    QTextDocument document;
    document.setMarkdown(instructions_->text() + QStringLiteral("\n\n") + observe_->text());
    return document.toPlainText();
}

bool StepView::expectationShown() const {
    return !expectation_->isHidden() && !expectation_->text().isEmpty();
}

QPlainTextEdit* StepView::answerBox(const std::string& question_id) const {
    const auto found = answers_.find(question_id);
    return found == answers_.end() ? nullptr : found->second;
}

}  // namespace legofeup::ui
