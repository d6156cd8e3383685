#include "legofeup/ui/lesson/lesson_actions.hpp"

#include <QApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QStandardPaths>

#include "legofeup/ui/lesson/lesson_panel.hpp"
#include "legofeup/ui/lesson/lesson_progress.hpp"
#include "legofeup/ui/window/app_settings.hpp"

namespace legofeup::ui {
namespace {

const QString kTomlFilter = QObject::tr("TOML files (*.toml);;All files (*)");

}  // namespace

LessonActions::LessonActions(LessonPanel& panel, QWidget* dialog_parent)
    : QObject(dialog_parent), panel_(panel), dialog_parent_(dialog_parent) {}

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
    QApplication::setOverrideCursor(Qt::WaitCursor);
    const QString error = panel_.exportReport(directory);
    QApplication::restoreOverrideCursor();
    if (!error.isEmpty()) {
        warn(tr("The report was not exported"), error);
        return;
    }
    emit done(tr("Wrote report.html and report.pdf into %1").arg(directory));
}

}  // namespace legofeup::ui
