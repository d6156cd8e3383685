#pragma once
// File ▸ Re-filter recorded run…: "what if" on identical noise. Pick a run log (recorded by
// File ▸ Record runs, or `legofeup-cli run --record`), change Q and R (prefilled with the
// recorded values, edited as in the configuration panel), and lessons::refilter replays the
// same raw readings through the loop with the recorded and with the new settings. The
// overlay shows the truth, the old and the new estimate, their position errors over time,
// and the old and new metrics side by side.

#include <QDialog>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "legofeup/lessons/config_schema.hpp"
#include "legofeup/lessons/recording/refilter.hpp"
#include "legofeup/lessons/recording/run_log.hpp"

class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QTimer;
class QTableWidget;

namespace legofeup::ui {

class RefilterJob;
class RunLogReadJob;
class RefilterPlots;
class Session;
class SettingEditor;

class RefilterDialog : public QDialog {
    Q_OBJECT

  public:
    /// Starts in the folder the session records into (if it does).
    explicit RefilterDialog(const Session& session, QWidget* parent = nullptr);
    /// Cancels a running replay and waits for its thread (it stops at its next step).
    ~RefilterDialog() override;

    /// Starts reading a run log (on a worker: a long log is tens of megabytes); when it is
    /// read, shows its recorded Q and R and replays it, and emits logOpened("") — or, when it
    /// does not read, keeps the log shown before and emits logOpened(the problem, file:line).
    void openLog(const QString& path);
    /// Starts replaying the log with the recorded and with the new settings (on a worker);
    /// both are shown, and refiltered() emitted, when it is done. Returns "" or why not.
    QString refilterNow();
    /// A log is being read or a replay is running (its outcome not shown yet).
    bool busy() const { return read_job_ != nullptr || job_ != nullptr; }

    /// The editor of filter.q11, q22, r11 or r22.
    SettingEditor* editor(const std::string& key) const;
    const lessons::RunConfig& newConfig() const { return new_config_; }
    const std::optional<lessons::RefilterResult>& result() const { return result_; }
    RefilterPlots& plots() const { return *plots_; }
    QTableWidget& metricsTable() const { return *metrics_; }

  signals:
    /// A log asked for by openLog() was read and is shown (`problem` empty), or was not.
    void logOpened(const QString& problem);
    /// A replay finished and its result (or its error) is shown.
    void refiltered();

  private:
    void chooseLog();
    /// Starts a replay of new_config_; when done, shows `message` or else `prefix` and the
    /// verdict.
    void startRefilter(const QString& prefix, const QString& message);
    void pollJob();
    /// Shows the log read_job_ read (or reports why not).
    void finishReading();
    void propose(SettingEditor& editor, const lessons::SettingValue& value, const QString& text);
    void resetToRecorded();
    void showMessage(const QString& text, bool error);

    QString folder_;
    std::shared_ptr<const lessons::RunLog> log_;  ///< shared with the running job
    std::vector<Wall> walls_;                     ///< the log's world, for the overlay
    lessons::RunConfig new_config_;
    std::optional<lessons::RefilterResult> result_;
    std::unique_ptr<RunLogReadJob> read_job_;
    QString reading_path_;  ///< the file read_job_ reads
    std::unique_ptr<RefilterJob> job_;
    QString done_prefix_;
    QString done_message_;

    QLineEdit* path_ = nullptr;
    QLabel* about_ = nullptr;
    std::map<std::string, SettingEditor*> editors_;
    QPushButton* run_ = nullptr;
    QPushButton* reset_ = nullptr;
    QLabel* message_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QTimer* poll_ = nullptr;
    RefilterPlots* plots_ = nullptr;
    QTableWidget* metrics_ = nullptr;
};

}  // namespace legofeup::ui
