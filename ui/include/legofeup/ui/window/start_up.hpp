#pragma once
// What the window starts with, from the command line (command_line.hpp) and the preferences:
// the configuration (--config, --experiment, the last one used, or experiment f), the link
// (with --speed) and the lesson step the run belongs to.

#include <QString>
#include <QStringList>
#include <optional>

#include "legofeup/lessons/run_config.hpp"
#include "legofeup/ui/session/session.hpp"
#include "legofeup/ui/window/command_line.hpp"

namespace legofeup::ui {

class LessonPanel;

struct StartConfig {
    std::optional<lessons::RunConfig> config;  ///< nullopt: refused, `refusal` says why
    QString refusal;                           ///< "legofeup: <file:line and reason>"
    QStringList notes;                         ///< for the status line once the window shows
};

/// The configuration to start with: --config's (a file that does not load is refused),
/// --experiment's, the last one used (one that no longer loads is kept as .bad and noted),
/// or experiment f.
StartConfig initial_config(const StartOptions& options);

/// The link used last, at --speed if it is given.
LinkChoice initial_link(const StartOptions& options);

/// Shows the lesson and step the first run belongs to: --experiment's (its lesson, LegoFeup
/// for a … h); else the step shown last if the configuration is its, else the step the
/// configuration came from (LessonPanel::showStepOfConfiguration); a configuration that is
/// no step's is shown as the students' own. False in that last case.
bool show_initial_step(LessonPanel& panel, const StartOptions& options);

}  // namespace legofeup::ui
