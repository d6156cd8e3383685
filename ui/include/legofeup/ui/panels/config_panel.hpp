#pragma once
// The configuration panel: every setting of a run, built from the one settings table the TOML
// files and the CLI use (lessons/config_schema.hpp): its pages, each row's label and help, the
// rows a run does not use greyed, and the settings that wait for the next start marked so.
// An entry the session refuses is undone and the reason shown, never clamped.

#include <QWidget>
#include <map>
#include <string>

namespace legofeup::lessons {
struct RunConfig;
struct Setting;
}  // namespace legofeup::lessons

class QLabel;
class QToolBox;

namespace legofeup::ui {

class Session;
class SettingEditor;

class ConfigPanel : public QWidget {
    Q_OBJECT

  public:
    explicit ConfigPanel(Session& session, QWidget* parent = nullptr);

    /// The editor of the setting with this TOML key, or nullptr.
    SettingEditor* editor(const std::string& key) const;
    /// The message last shown (what was applied, or why an entry was refused).
    QString message() const;
    bool messageIsError() const { return message_is_error_; }
    /// Whether the setting's row is enabled: the current configuration uses it
    /// (Setting::used_by). False for an unknown key.
    bool isRelevant(const std::string& key) const;

  private:
    void refresh();
    /// Greys the rows (and pages) of settings a run of `config` does not use.
    void showRelevance(const lessons::RunConfig& config);
    void showMessage(const QString& text, bool error);

    Session& session_;
    QLabel* message_ = nullptr;
    bool message_is_error_ = false;
    QToolBox* pages_ = nullptr;
    std::map<std::string, SettingEditor*> editors_;
    struct Row {
        const lessons::Setting* setting = nullptr;
        QWidget* label = nullptr;
        QWidget* field = nullptr;
        int page = 0;
    };
    std::map<std::string, Row> rows_;
};

}  // namespace legofeup::ui
