#include "legofeup/ui/refilter/refilter_dialog.hpp"

#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSplitter>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <array>
#include <exception>

#include "legofeup/lessons/config_schema.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/ui/panels/message_line.hpp"
#include "legofeup/ui/panels/setting_editor.hpp"
#include "legofeup/ui/refilter/refilter_job.hpp"
#include "legofeup/ui/refilter/refilter_metrics.hpp"
#include "legofeup/ui/refilter/refilter_plots.hpp"
#include "legofeup/ui/session/session.hpp"
#include "legofeup/ui/window/app_settings.hpp"

namespace legofeup::ui {
namespace {

// The settings a student changes to ask "what if": the process and the measurement noise.
constexpr std::array kTunedKeys = {"filter.q11", "filter.q22", "filter.r11", "filter.r22"};

}  // namespace

RefilterDialog::RefilterDialog(const Session& session, QWidget* parent) : QDialog(parent) {
    setWindowTitle(tr("Re-filter a recorded run"));
    setObjectName(QStringLiteral("refilterDialog"));
    folder_ = session.recordingDirectory();
    if (folder_.isEmpty()) {
        folder_ = preferences::kLessonFolder.read();
    }
    if (folder_.isEmpty()) {
        folder_ = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    }

    auto* layout = new QVBoxLayout(this);
    auto* file_row = new QHBoxLayout;
    file_row->addWidget(new QLabel(tr("Run log:"), this));
    path_ = new QLineEdit(this);
    path_->setObjectName(QStringLiteral("refilterLogPath"));
    path_->setReadOnly(true);
    path_->setPlaceholderText(tr("Choose a run recorded with File ▸ Record runs"));
    file_row->addWidget(path_, 1);
    auto* choose = new QPushButton(tr("Choose…"), this);
    choose->setAutoDefault(false);  // Enter belongs to the Q and R fields
    connect(choose, &QPushButton::clicked, this, &RefilterDialog::chooseLog);
    file_row->addWidget(choose);
    layout->addLayout(file_row);
    about_ = new QLabel(this);
    about_->setObjectName(QStringLiteral("refilterAbout"));
    about_->setWordWrap(true);
    layout->addWidget(about_);

    auto* top = new QHBoxLayout;
    auto* settings = new QGroupBox(tr("New Q and R (recorded values to start with)"), this);
    auto* form = new QFormLayout(settings);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    for (const char* key : kTunedKeys) {
        const lessons::Setting* setting = lessons::find_setting_by_key(key);
        auto* editor = new SettingEditor(*setting, settings);
        editor->setEnabled(false);
        editors_[key] = editor;
        form->addRow(setting_text(setting->label.text), editor);
        connect(editor, &SettingEditor::proposed, this,
                [this, editor](const lessons::SettingValue& value, const QString& text) {
                    propose(*editor, value, text);
                });
        connect(editor, &SettingEditor::unreadable, this,
                [this, editor](const QString& text, const QString& reason) {
                    editor->showValueOf(new_config_);
                    showMessage(
                        tr("Refused %1 = \"%2\": %3")
                            .arg(QString::fromStdString(editor->setting().key), text, reason),
                        true);
                });
    }
    auto* buttons = new QHBoxLayout;
    run_ = new QPushButton(tr("Re-filter"), this);
    run_->setObjectName(QStringLiteral("refilterRun"));
    run_->setAutoDefault(false);  // Enter in a field applies it (and re-filters) once
    run_->setEnabled(false);
    run_->setToolTip(
        tr("Replays the recorded raw readings with the recorded and with the new "
           "settings (the robot's motion stays as recorded)"));
    connect(run_, &QPushButton::clicked, this, [this] {
        if (const QString error = refilterNow(); !error.isEmpty()) {
            showMessage(error, true);
        }
    });
    // The replay runs on a RefilterJob's thread; this bar shows how far it is.
    progress_ = new QProgressBar(this);
    progress_->setObjectName(QStringLiteral("refilterProgress"));
    progress_->setRange(0, 100);
    progress_->setFormat(tr("Re-filtering… %p%"));
    progress_->setVisible(false);
    poll_ = new QTimer(this);
    poll_->setInterval(30);
    connect(poll_, &QTimer::timeout, this, &RefilterDialog::pollJob);
    reset_ = new QPushButton(tr("Recorded values"), this);
    reset_->setEnabled(false);
    reset_->setAutoDefault(false);
    connect(reset_, &QPushButton::clicked, this, [this] {
        resetToRecorded();
        if (const QString error = refilterNow(); !error.isEmpty()) {
            showMessage(error, true);
        }
    });
    buttons->addWidget(run_);
    buttons->addWidget(reset_);
    buttons->addWidget(progress_, 1);
    buttons->addStretch(1);
    form->addRow(buttons);
    top->addWidget(settings, 1);

    metrics_ = new QTableWidget(this);
    metrics_->setObjectName(QStringLiteral("refilterMetrics"));
    metrics_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    metrics_->setSelectionMode(QAbstractItemView::NoSelection);
    show_refilter_metrics(*metrics_, std::nullopt, std::nullopt);
    top->addWidget(metrics_, 1);
    layout->addLayout(top);

    message_ = new QLabel(this);
    message_->setObjectName(QStringLiteral("refilterMessage"));
    message_->setWordWrap(true);
    message_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(message_);

    plots_ = new RefilterPlots(this);
    plots_->setMinimumHeight(320);
    layout->addWidget(plots_, 1);
    resize(1280, 860);
}

RefilterDialog::~RefilterDialog() = default;

SettingEditor* RefilterDialog::editor(const std::string& key) const {
    const auto found = editors_.find(key);
    return found == editors_.end() ? nullptr : found->second;
}

void RefilterDialog::chooseLog() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Choose a recorded run"), folder_,
                                                      tr("Run logs (*.log);;All files (*)"));
    if (path.isEmpty()) {
        return;
    }
    folder_ = QFileInfo(path).absolutePath();
    // A log that does not read is worth a box: the user asked for it just now.
    connect(
        this, &RefilterDialog::logOpened, this,
        [this](const QString& problem) {
            if (problem.isEmpty()) {
                return;
            }
            QMessageBox box(QMessageBox::Warning, tr("The run log was not read"),
                            tr("The run log was not read"), QMessageBox::Ok, this);
            box.setObjectName(QStringLiteral("refilterProblem"));
            box.setInformativeText(problem);
            box.exec();
        },
        Qt::SingleShotConnection);
    openLog(path);
}

void RefilterDialog::openLog(const QString& path) {
    job_.reset();  // a replay of the log being replaced: cancelled and joined
    read_job_ = std::make_unique<RunLogReadJob>(path.toStdString());
    reading_path_ = path;
    showMessage(tr("Reading %1…").arg(path), false);
    progress_->setRange(0, 0);  // reading has no progress to show: a busy bar
    progress_->setVisible(true);
    poll_->start();
}

void RefilterDialog::finishReading() {
    std::optional<RunLogReadJob::Outcome> outcome = read_job_->take();
    read_job_.reset();
    progress_->setRange(0, 100);
    progress_->setVisible(false);
    if (!outcome->result) {  // InputError: file:line and the reason
        const QString problem = QString::fromStdString(outcome->error);
        poll_->stop();
        showMessage(tr("The run log was not read: %1").arg(problem), true);
        emit logOpened(problem);
        return;
    }
    const lessons::RunLog& log = *outcome->result->log;
    path_->setText(reading_path_);
    QStringList about_parts = {
        QString::fromStdString(log.header.title), tr("seed %1").arg(log.header.seed),
        tr("%1 steps").arg(log.records.size()), QString::fromStdString(log.header.link),
        tr("recorded by %1").arg(QString::fromStdString(log.header.program))};
    about_parts.removeAll(QString());
    QString about = about_parts.join(QStringLiteral(" · "));
    for (const std::string& note : log.notes) {
        about += QStringLiteral("\n") + QString::fromStdString(note);
    }
    about_->setText(about);
    walls_ = std::move(outcome->result->walls);
    log_ = std::move(outcome->result->log);
    result_.reset();
    plots_->clear();
    show_refilter_metrics(*metrics_, std::nullopt, std::nullopt);
    for (auto& [key, editor] : editors_) {
        editor->setEnabled(true);
    }
    run_->setEnabled(true);
    reset_->setEnabled(true);
    resetToRecorded();
    // The recorded run at once (both replays the same), ready for the first "what if".
    startRefilter({}, tr("The recorded run. Change Q or R and press Enter: it is re-filtered "
                         "at once."));
    emit logOpened(QString());
}

void RefilterDialog::resetToRecorded() {
    if (!log_) {
        return;
    }
    new_config_ = log_->config;
    for (auto& [key, editor] : editors_) {
        editor->showValueOf(new_config_);
    }
}

void RefilterDialog::propose(SettingEditor& editor, const lessons::SettingValue& value,
                             const QString& text) {
    lessons::RunConfig changed = new_config_;
    const QString key = QString::fromStdString(editor.setting().key);
    try {
        editor.setting().set(changed, value);
        changed.origins[editor.setting().field] = {"the re-filter dialog", 0, editor.setting().key};
        lessons::resolve(changed);  // refused as the configuration panel refuses it
    } catch (const lessons::InputError& error) {
        editor.showValueOf(new_config_);
        showMessage(tr("Refused %1 = %2:\n%3").arg(key, text, QString::fromUtf8(error.what())),
                    true);
        return;
    } catch (const std::exception& error) {
        editor.showValueOf(new_config_);
        showMessage(tr("Refused %1 = %2: %3").arg(key, text, QString::fromUtf8(error.what())),
                    true);
        return;
    }
    new_config_ = std::move(changed);
    editor.showValueOf(new_config_);  // the slider follows a typed value
    // Replaying takes a moment on the job's thread: the answer to "what if" comes when done.
    startRefilter(tr("%1 = %2: re-filtered. ").arg(key, text), {});
}

QString RefilterDialog::refilterNow() {
    if (read_job_) {
        return tr("The run log is still being read.");
    }
    if (!log_) {
        return tr("Choose a run log first.");
    }
    startRefilter({}, {});
    return {};
}

void RefilterDialog::startRefilter(const QString& prefix, const QString& message) {
    job_.reset();  // a replay of settings since replaced: cancelled and joined
    job_ = std::make_unique<RefilterJob>(log_, new_config_);
    done_prefix_ = prefix;
    done_message_ = message;
    progress_->setValue(0);
    progress_->setVisible(true);
    poll_->start();
}

void RefilterDialog::pollJob() {
    if (read_job_) {
        if (read_job_->finished()) {
            finishReading();
        }
        return;
    }
    if (!job_) {
        poll_->stop();
        return;
    }
    progress_->setValue(static_cast<int>(job_->progress() * 100.0));
    std::optional<RefilterJob::Outcome> outcome = job_->take();
    if (!outcome) {
        return;
    }
    job_.reset();
    poll_->stop();
    progress_->setVisible(false);
    if (!outcome->result) {
        showMessage(QString::fromStdString(outcome->error), true);
        emit refiltered();
        return;
    }
    result_ = std::move(outcome->result);
    plots_->showResult(*result_, walls_);
    show_refilter_metrics(*metrics_, result_->old_metrics, result_->new_metrics);
    const QString verdict =
        result_->reproduces_recording()
            ? tr(
                "Same raw readings, two tunings. The replay with the recorded settings "
                "reproduces the recorded estimate exactly.")
            : tr("Same raw readings, two tunings. The replay with the recorded settings "
                 "differs from the recorded estimate by up to %1 (the settings were "
                 "changed during the recorded run).")
                  .arg(result_->old_replay_deviation, 0, 'g', 3);
    showMessage(done_message_.isEmpty() ? done_prefix_ + verdict : done_message_, false);
    emit refiltered();
}

void RefilterDialog::showMessage(const QString& text, bool error) {
    show_message_line(*message_, text, error);
}

}  // namespace legofeup::ui
