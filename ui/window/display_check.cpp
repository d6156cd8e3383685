#include "legofeup/ui/window/display_check.hpp"

#include <QObject>

namespace legofeup::ui {
namespace {

/// The platforms Qt will try: the -platform argument's (QGuiApplication takes -platform and
/// --platform), else QT_QPA_PLATFORM's, else X11's and Wayland's.
QStringList platforms_asked(const QStringList& arguments, const QProcessEnvironment& environment) {
    QString asked = environment.value(QStringLiteral("QT_QPA_PLATFORM"));
    for (qsizetype i = 1; i + 1 < arguments.size(); ++i) {
        if (arguments[i] == QLatin1String("-platform")
            || arguments[i] == QLatin1String("--platform")) {
            asked = arguments[i + 1];
        }
    }
    QStringList names;
    for (const QString& entry : asked.split(QLatin1Char(';'))) {
        if (const QString name = entry.section(QLatin1Char(':'), 0, 0).trimmed();  // vnc:size=…
            !name.isEmpty()) {
            names << name;
        }
    }
    return names.isEmpty() ? QStringList{QStringLiteral("xcb"), QStringLiteral("wayland")} : names;
}

/// The variable a platform needs to find its display; "" for one that needs none.
QString display_variable(const QString& platform) {
    if (platform == QLatin1String("xcb")) {
        return QStringLiteral("DISPLAY");
    }
    if (platform.startsWith(QLatin1String("wayland"))) {
        return QStringLiteral("WAYLAND_DISPLAY");
    }
    return {};
}

}  // namespace

QString missing_display(const QStringList& arguments, const QProcessEnvironment& environment) {
    QStringList unset;
    for (const QString& platform : platforms_asked(arguments, environment)) {
        const QString variable = display_variable(platform);
        if (variable.isEmpty() || !environment.value(variable).isEmpty()) {
            return {};
        }
        if (!unset.contains(variable)) {
            unset << variable;
        }
    }
    // Only DISPLAY and WAYLAND_DISPLAY are ever asked for: one or both.
    const QString reason = unset.size() == 1
                               ? QObject::tr("%1 is unset").arg(unset.constFirst())
                               : QObject::tr("%1 and %2 are unset").arg(unset[0], unset[1]);
    return QObject::tr(
               "legofeup: there is no display to open the window on (%1): run the "
               "lessons without a window with legofeup-cli (e.g. legofeup-cli run "
               "--experiment f), or give the window a virtual display with xvfb-run "
               "legofeup.")
        .arg(reason);
}

}  // namespace legofeup::ui
