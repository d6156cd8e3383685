#pragma once
// What the File menu does: configurations in and out (the CLI's TOML), plots and the trace
// exported, the run recorded. Each asks for a path, then reports what it wrote or why not.

#include <QObject>

class QWidget;

namespace legofeup::ui {

class PlotsPanel;
class Session;

class FileActions : public QObject {
    Q_OBJECT

  public:
    FileActions(Session& session, PlotsPanel& plots, QWidget* dialog_parent);

  public slots:
    void loadConfig();
    void saveConfig();
    void exportPlots();
    void exportTrace();
    /// On: asks for a folder and records the runs there; off: stops recording.
    void setRecording(bool on);

  signals:
    void recordingChanged(bool on);
    /// A short note of what was done, for the status bar.
    void done(const QString& note);

  private:
    void report(const QString& title, const QString& error);

    Session& session_;
    PlotsPanel& plots_;
    QWidget* dialog_parent_;
};

}  // namespace legofeup::ui
