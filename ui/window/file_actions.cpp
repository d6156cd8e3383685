#include "legofeup/ui/window/file_actions.hpp"

#include <QFileDialog>
#include <QInputDialog>
#include <QMessageBox>
#include <QStandardPaths>

#include "legofeup/ui/plots/plots_panel.hpp"
#include "legofeup/ui/session/session.hpp"

namespace legofeup::ui {
namespace {

const QString kTomlFilter = QObject::tr("Run configurations (*.toml);;All files (*)");

QString documents() {
    return QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
}

}  // namespace

FileActions::FileActions(Session& session, PlotsPanel& plots, QWidget* dialog_parent)
    : QObject(dialog_parent), session_(session), plots_(plots), dialog_parent_(dialog_parent) {}

void FileActions::report(const QString& title, const QString& error) {
    if (error.isEmpty()) {
        return;
    }
    QMessageBox::warning(dialog_parent_, title, error);
}

void FileActions::loadConfig() {
    const QString path = QFileDialog::getOpenFileName(
        dialog_parent_, tr("Load a run configuration"), documents(), kTomlFilter);
    if (path.isEmpty()) {
        return;
    }
    const QStringList problems = session_.loadConfig(path);
    report(tr("The configuration was not loaded"), problems.join('\n'));
    if (problems.isEmpty()) {
        emit done(tr("Loaded %1").arg(path));
    }
}

void FileActions::saveConfig() {
    const QString path =
        QFileDialog::getSaveFileName(dialog_parent_, tr("Save the run configuration"),
                                     documents() + QStringLiteral("/legofeup.toml"), kTomlFilter);
    if (path.isEmpty()) {
        return;
    }
    const QString error = session_.saveConfig(path);
    report(tr("The configuration was not saved"), error);
    if (error.isEmpty()) {
        emit done(tr("Saved %1 (legofeup-cli run --config reads it)").arg(path));
    }
}

void FileActions::exportPlots() {
    const QStringList formats = {tr("PNG, SVG and PDF"), QStringLiteral("PNG"),
                                 QStringLiteral("SVG"), QStringLiteral("PDF")};
    bool ok = false;
    const QString format = QInputDialog::getItem(dialog_parent_, tr("Export the plots"),
                                                 tr("Format:"), formats, 0, false, &ok);
    if (!ok) {
        return;
    }
    const QString directory =
        QFileDialog::getExistingDirectory(dialog_parent_, tr("Export the plots into"), documents());
    if (directory.isEmpty()) {
        return;
    }
    ExportFormats chosen = kAllExportFormats;
    if (format == QLatin1String("PNG")) {
        chosen = ExportFormat::Png;
    } else if (format == QLatin1String("SVG")) {
        chosen = ExportFormat::Svg;
    } else if (format == QLatin1String("PDF")) {
        chosen = ExportFormat::Pdf;
    }
    const ExportResult result = plots_.exportPlots(directory, chosen);
    report(tr("The plots were not all exported"), result.error);
    emit done(tr("Wrote %n plot file(s) into %1", nullptr, static_cast<int>(result.files.size()))
                  .arg(directory));
}

void FileActions::exportTrace() {
    const QString path = QFileDialog::getSaveFileName(dialog_parent_, tr("Export the trace"),
                                                      documents() + QStringLiteral("/trace.csv"),
                                                      tr("CSV files (*.csv);;All files (*)"));
    if (path.isEmpty()) {
        return;
    }
    const QString error = session_.exportTrace(path);
    report(tr("The trace was not exported"), error);
    if (error.isEmpty()) {
        emit done(tr("Wrote %1").arg(path));
    }
}

void FileActions::setRecording(bool on) {
    if (!on) {
        session_.setRecordingDirectory({});
        emit recordingChanged(false);
        emit done(tr("Recording stopped"));
        return;
    }
    const QString directory =
        QFileDialog::getExistingDirectory(dialog_parent_, tr("Record the runs into"), documents());
    const QString error =
        directory.isEmpty() ? QString() : session_.setRecordingDirectory(directory);
    report(tr("Not recording"), error);
    const bool recording = !session_.recordingDirectory().isEmpty();
    emit recordingChanged(recording);
    if (recording) {
        emit done(
            tr("Recording into %1: config.toml now, trace.csv as the run goes").arg(directory));
    }
}

}  // namespace legofeup::ui
