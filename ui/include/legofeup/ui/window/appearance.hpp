#pragma once
// The application's look: light, dark or the system's theme (Fusion with a palette, so every
// widget follows), and the projector's "large text".

#include <QString>

class QApplication;

namespace legofeup::ui {

enum class Theme { System, Light, Dark };

Theme theme_from_name(const QString& name);
QString theme_name(Theme theme);

/// Applies `theme` and the text size (1: normal; large text is kLargeTextScale) to the
/// whole application. Views that draw their own text also get setTextScale().
void apply_appearance(QApplication& app, Theme theme, double text_scale);

inline constexpr double kLargeTextScale = 1.6;

}  // namespace legofeup::ui
