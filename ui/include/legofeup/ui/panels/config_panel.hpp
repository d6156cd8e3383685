#pragma once
// The configuration panel: every setting of a run (the one settings table the TOML files and
// the CLI use), grouped as the lesson talks about them — Q and R first. Entries apply live
// while the robot runs where the loop allows it (the others are marked "next start"); an entry
// the session refuses is undone and the reason shown, never clamped.

#include <QWidget>
#include <map>
#include <string>

#include "legofeup/core/lesson_filters_config.hpp"

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
    /// Whether the setting's row is enabled: the current localisation uses it
    /// (setting_relevance.hpp). False for an unknown key.
    bool isRelevant(const std::string& key) const;

  private:
    void refresh();
    /// Greys the rows (and pages) of settings `localisation` does not use.
    void showRelevance(Localisation localisation);
    void showMessage(const QString& text, bool error);

    Session& session_;
    QLabel* message_ = nullptr;
    bool message_is_error_ = false;
    QToolBox* pages_ = nullptr;
    std::map<std::string, SettingEditor*> editors_;
    struct Row {
        QWidget* label = nullptr;
        QWidget* field = nullptr;
        int page = 0;
    };
    std::map<std::string, Row> rows_;
};

}  // namespace legofeup::ui
