#pragma once
// Pictures for the documentation, taken by the tests that fill the dialogs in: with
// LEGOFEUP_SCREENSHOTS=DIR set, save_screenshot() writes the widget to DIR/<name>.png
// (docs/images holds the chosen ones). Without it, nothing happens.

#include <QDir>
#include <QString>
#include <QWidget>

namespace legofeup::ui::testing {

inline void save_screenshot(QWidget& widget, const char* name) {
    const QString directory = qEnvironmentVariable("LEGOFEUP_SCREENSHOTS");
    if (!directory.isEmpty()) {
        widget.grab().save(QDir(directory).filePath(QLatin1String(name) + ".png"));
    }
}

}  // namespace legofeup::ui::testing
