#pragma once
// Saving what a calibration found into a robot profile (lessons/robot_profile.hpp): the file
// is read first when it exists, so the values the calibration did not touch stay as they
// were, then written atomically.

#include <QString>
#include <functional>

#include "legofeup/lessons/calibration/umbmark.hpp"
#include "legofeup/lessons/robot_profile.hpp"

class QLabel;
class QWidget;

namespace legofeup::ui {

/// Reads the profile at `path` (the defaults if there is no such file), lets `change` edit
/// it and saves it. Returns why it failed (the file's problems, one per line), or "".
QString update_profile(const QString& path,
                       const std::function<void(lessons::RobotProfile&)>& change);

/// UMBmark's corrected wheel diameters and wheel base into the profile, with the Codo
/// derived from them.
void apply_umbmark(lessons::RobotProfile& profile, const lessons::UmbmarkResult& result);

/// Asks where to save a profile, starting at `suggested` (the run's profile, if any).
/// Returns the path, or "" when cancelled.
QString ask_profile_path(QWidget* parent, const QString& suggested);

/// update_profile() and its outcome told: "Saved to …" after the `result`, or why not in
/// `message`. Returns success.
bool save_and_report(const QString& path, const std::function<void(lessons::RobotProfile&)>& change,
                     QLabel& result, QLabel& message);

/// A calibration dialog's labels: the result (`lines` high, so it never resizes the dialog)
/// and the message line for problems (in a warning colour).
QLabel* result_label(const QString& text, const char* name, int lines, QWidget* parent);
QLabel* message_label(const char* name, QWidget* parent);

}  // namespace legofeup::ui
