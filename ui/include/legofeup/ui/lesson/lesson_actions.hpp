#pragma once
// The File menu's lesson entries: Open lesson…, Save answers…, Open answers…, Export
// report…. Each asks for a path, has the lesson panel do the work, and says what it wrote or,
// in a message box, why not (a lesson or answers file with errors: every problem with its
// file:line). The report (an HTML page and a PDF laid out with cairo and pango) is written on
// a worker, so the window stays responsive; the report's contents are taken from the lesson
// panel at once, on the GUI thread, as they are when the user asks.

#include <QObject>
#include <QString>
#include <memory>

#include "legofeup/ui/background_task.hpp"

class QTimer;
class QWidget;

namespace legofeup::ui {

class LessonPanel;

class LessonActions : public QObject {
    Q_OBJECT

  public:
    LessonActions(LessonPanel& panel, QWidget* dialog_parent);
    /// Waits for a report being written (its files are not left half-written).
    ~LessonActions() override;

    /// Starts writing report.html and report.pdf into `directory` on a worker; done() or a
    /// warning box follow when it is written. Refused (false) while a report is being written.
    bool exportReportTo(const QString& directory);
    /// A report is being written.
    bool exporting() const { return export_job_ != nullptr; }

  public slots:
    void openLesson();
    void saveAnswers();
    void openAnswers();
    void exportReport();

  signals:
    /// A short note of what was done, for the status bar.
    void done(const QString& note);
    /// A report export finished: `problem` is empty, or says why nothing was written.
    void reportExported(const QString& problem);

  private:
    QString folder() const;
    void remember(const QString& path) const;
    void warn(const QString& title, const QString& error);
    void pollExport();

    LessonPanel& panel_;
    QWidget* dialog_parent_;
    std::unique_ptr<BackgroundTask<bool>> export_job_;
    QString export_directory_;
    QTimer* export_poll_ = nullptr;
};

}  // namespace legofeup::ui
