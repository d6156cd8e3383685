#include "legofeup/ui/lesson/lesson_actions.hpp"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QStandardPaths>
#include <QThread>
#include <QTimer>
#include <filesystem>

#include "legofeup/report/student_report.hpp"
#include "legofeup/ui/lesson/lesson_panel.hpp"
#include "legofeup/ui/lesson/lesson_progress.hpp"
#include "legofeup/ui/window/app_settings.hpp"

namespace legofeup::ui {
namespace {

const QString kTomlFilter = QObject::tr("TOML files (*.toml);;All files (*)");

}  // namespace

LessonActions::LessonActions(LessonPanel& panel, QWidget* dialog_parent)
    : QObject(dialog_parent), panel_(panel), dialog_parent_(dialog_parent) {
    export_poll_ = new QTimer(this);
    export_poll_->setInterval(30);
    connect(export_poll_, &QTimer::timeout, this, &LessonActions::pollExport);
}

LessonActions::~LessonActions() {
    if (export_job_) {
        while (!export_job_->finished()) {  // writing cannot be cut short without a torn file
            QThread::msleep(5);
        }
    }
}

QString LessonActions::folder() const {
    // The folder used last, else Documents, else home (a fresh account may have no Documents).
    for (const QString& candidate :
         {preferences::kLessonFolder.read(),
          QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation)}) {
        if (!candidate.isEmpty() && QFileInfo(candidate).isDir()) {
            return candidate;
        }
    }
    return QDir::homePath();
}

void LessonActions::remember(const QString& path) const {
    const QFileInfo info(path);
    preferences::kLessonFolder.write(info.isDir() ? info.absoluteFilePath() : info.absolutePath());
}

void LessonActions::warn(const QString& title, const QString& error) {
    QMessageBox box(QMessageBox::Warning, title, title, QMessageBox::Ok, dialog_parent_);
    box.setObjectName(QStringLiteral("lessonProblem"));
    box.setInformativeText(error);
    box.setTextInteractionFlags(Qt::TextSelectableByMouse);
    box.exec();
}

void LessonActions::openLesson() {
    const QString path = QFileDialog::getOpenFileName(dialog_parent_, tr("Open a lesson"), folder(),
                                                      tr("Lessons (*.toml);;All files (*)"));
    if (path.isEmpty()) {
        return;
    }
    remember(path);
    if (const QString error = panel_.openLesson(path); !error.isEmpty()) {
        warn(tr("The lesson was not opened; the current lesson stays"), error);
        return;
    }
    emit done(tr("Opened the lesson %1").arg(path));
}

void LessonActions::saveAnswers() {
    const std::string& id = panel_.progress().lesson().id;
    const QString path = QFileDialog::getSaveFileName(
        dialog_parent_, tr("Save your answers"),
        QDir(folder()).filePath(QString::fromStdString(id) + QStringLiteral("-answers.toml")),
        kTomlFilter);
    if (path.isEmpty()) {
        return;
    }
    remember(path);
    if (const QString error = panel_.saveAnswers(path); !error.isEmpty()) {
        warn(tr("The answers were not saved"), error);
        return;
    }
    emit done(tr("Saved the answers to %1").arg(path));
}

void LessonActions::openAnswers() {
    const QString path = QFileDialog::getOpenFileName(dialog_parent_, tr("Open saved answers"),
                                                      folder(), kTomlFilter);
    if (path.isEmpty()) {
        return;
    }
    remember(path);
    if (const QString error = panel_.openAnswers(path); !error.isEmpty()) {
        warn(tr("The answers were not opened"), error);
    }
}

void LessonActions::exportReport() {
    const QString directory = QFileDialog::getExistingDirectory(
        dialog_parent_, tr("Export the report (report.html and report.pdf) into"), folder());
    if (directory.isEmpty()) {
        return;
    }
    remember(directory);
    exportReportTo(directory);
}

bool LessonActions::exportReportTo(const QString& directory) {
    if (export_job_) {
        return false;
    }
    export_directory_ = directory;
    export_job_ = std::make_unique<BackgroundTask<bool>>(
        [report = panel_.reportNow(),
         path = std::filesystem::path(directory.toStdString())](const TaskProgress&) {
            report::write_report(report, path);
            return true;
        });
    emit done(tr("Writing the report into %1…").arg(directory));
    export_poll_->start();
    return true;
}

void LessonActions::pollExport() {
    if (!export_job_ || !export_job_->finished()) {
        return;
    }
    export_poll_->stop();
    const std::optional<BackgroundTask<bool>::Outcome> outcome = export_job_->take();
    export_job_.reset();
    const QString problem =
        outcome && outcome->result ? QString() : QString::fromStdString(outcome->error);
    emit reportExported(problem);
    if (!problem.isEmpty()) {
        warn(tr("The report was not exported"), problem);
        return;
    }
    emit done(tr("Wrote report.html and report.pdf into %1").arg(export_directory_));
}

}  // namespace legofeup::ui
