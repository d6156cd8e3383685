#pragma once
// File ▸ Re-filter recorded run…: "what if" on identical noise. Pick a run log (recorded by
// File ▸ Record runs, or `legofeup-cli run --record`), change Q and R (prefilled with the
// recorded values, edited as in the configuration panel), and lessons::refilter replays the
// same raw readings through the loop with the recorded and with the new settings. The
// overlay shows the truth, the old and the new estimate, their position errors over time,
// and the old and new metrics side by side.

#include <QDialog>
#include <map>
#include <optional>
#include <string>

#include "legofeup/lessons/config_schema.hpp"
#include "legofeup/lessons/recording/refilter.hpp"
#include "legofeup/lessons/recording/run_log.hpp"

class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;

namespace legofeup::ui {

class RefilterPlots;
class Session;
class SettingEditor;

class RefilterDialog : public QDialog {
    Q_OBJECT

  public:
    /// Starts in the folder the session records into (if it does).
    explicit RefilterDialog(const Session& session, QWidget* parent = nullptr);

    /// Reads a run log and shows its recorded Q and R. Returns "" or the problem (file:line);
    /// on error the log shown before stays.
    QString openLog(const QString& path);
    /// Replays the log with the recorded and with the new settings and shows both. Returns ""
    /// or why not.
    QString refilterNow();

    /// The editor of filter.q11, q22, r11 or r22.
    SettingEditor* editor(const std::string& key) const;
    const lessons::RunConfig& newConfig() const { return new_config_; }
    const std::optional<lessons::RefilterResult>& result() const { return result_; }
    RefilterPlots& plots() const { return *plots_; }
    QTableWidget& metricsTable() const { return *metrics_; }

  private:
    void chooseLog();
    void propose(SettingEditor& editor, const lessons::SettingValue& value, const QString& text);
    void resetToRecorded();
    void showMessage(const QString& text, bool error);

    QString folder_;
    std::optional<lessons::RunLog> log_;
    lessons::RunConfig new_config_;
    std::optional<lessons::RefilterResult> result_;

    QLineEdit* path_ = nullptr;
    QLabel* about_ = nullptr;
    std::map<std::string, SettingEditor*> editors_;
    QPushButton* run_ = nullptr;
    QPushButton* reset_ = nullptr;
    QLabel* message_ = nullptr;
    RefilterPlots* plots_ = nullptr;
    QTableWidget* metrics_ = nullptr;
};

}  // namespace legofeup::ui
