#pragma once
// The editor of one setting of the configuration panel, made from its entry in the settings
// table (lessons/config_schema.hpp): a number field (with a decade slider for variances), a
// check box, a choice, a point or a text. It proposes values; the session decides.

#include <QWidget>

#include "legofeup/lessons/config_schema.hpp"

class QLineEdit;

namespace legofeup::ui {

class LogSlider;

/// A text of the settings table (a label, help, page title) in the user's language: the
/// table's English is the source text, kSettingTextContext its context.
QString setting_text(const char* source);

class SettingEditor : public QWidget {
    Q_OBJECT

  public:
    SettingEditor(const lessons::Setting& setting, QWidget* parent = nullptr);

    const lessons::Setting& setting() const { return setting_; }
    /// Shows the value `config` has (after a change elsewhere, or to undo a refused entry).
    void showValueOf(const lessons::RunConfig& config);
    /// Whether this setting is a variance (Q, R, P0): those get the decade slider.
    static bool isVariance(const lessons::Setting& setting);

  signals:
    /// The user entered a value. `text` is what was typed, for messages.
    void proposed(const lessons::SettingValue& value, const QString& text);
    /// The user typed something that is not a value of this setting's type.
    void unreadable(const QString& text, const QString& reason);

  private:
    void buildNumber(bool integer);
    void buildPoint();
    void buildText();
    void buildBoolean();
    void buildChoice();
    void numberEntered(QLineEdit* field, bool integer);

    const lessons::Setting& setting_;
    QList<QLineEdit*> fields_;
    LogSlider* slider_ = nullptr;
};

}  // namespace legofeup::ui
