#pragma once
// Whether the window can be opened here, asked before QApplication is made: without a display
// Qt's xcb platform aborts the program (SIGABRT, "could not connect to display"), where the
// user needs one sentence saying what to do instead.

#include <QProcessEnvironment>
#include <QString>
#include <QStringList>

namespace legofeup::ui {

/// "" when Qt can be expected to open its platform, else the one sentence legofeup prints.
/// The platform is the one asked for (-platform NAME, or QT_QPA_PLATFORM, a list separated by
/// ';'), else Qt's choice on Linux, X11 or Wayland. xcb needs DISPLAY, wayland needs
/// WAYLAND_DISPLAY; any other (offscreen for tests and screenshots, minimal, vnc, eglfs, …)
/// needs no display and is taken as given.
QString missing_display(const QStringList& arguments, const QProcessEnvironment& environment);

}  // namespace legofeup::ui
