#include "legofeup/ui/window/start_up.hpp"

#include <QFile>
#include <QFileInfo>
#include <QObject>

#include "legofeup/lessons/config_file.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/ui/lesson/lesson_panel.hpp"
#include "legofeup/ui/window/app_settings.hpp"

namespace legofeup::ui {

StartConfig initial_config(const StartOptions& options) {
    StartConfig start;
    if (!options.experiment.isEmpty()) {
        // read_command_line() has refused an unknown one.
        start.config = lessons::find_experiment(options.experiment.toStdString())->config;
        return start;
    }
    const QString path = options.config.isEmpty() ? last_config_path() : options.config;
    if (!QFileInfo::exists(path)) {
        if (!options.config.isEmpty()) {
            start.refusal = QObject::tr("legofeup: --config = %1: no such file").arg(path);
            return start;
        }
        start.config = lessons::find_experiment("f")->config;
        return start;
    }
    try {
        lessons::RunConfig config = lessons::load_config_file(path.toStdString(), {});
        lessons::resolve(config);
        start.config = std::move(config);
    } catch (const lessons::InputError& error) {
        if (!options.config.isEmpty()) {
            start.refusal = QObject::tr("legofeup: %1").arg(QString::fromUtf8(error.what()));
            return start;
        }
        // The last configuration no longer loads (edited by hand?): keep it for the user to
        // repair, start from experiment f, and say so.
        const QString kept = path + QStringLiteral(".bad");
        QFile::remove(kept);
        QFile::rename(path, kept);
        start.notes << QObject::tr("The last configuration did not load and was kept as %1:\n%2")
                           .arg(kept, QString::fromUtf8(error.what()));
        start.config = lessons::find_experiment("f")->config;
    }
    return start;
}

LinkChoice initial_link(const StartOptions& options) {
    LinkChoice link = saved_link_choice();
    if (options.speed > 0.0) {
        link.speed = options.speed;
    }
    return link;
}

bool show_initial_step(LessonPanel& panel, const StartOptions& options) {
    if (options.experiment.isEmpty()) {
        // --config: the step the file is; else the step shown last, if the configuration
        // used last is still its.
        return panel.showStepOfConfiguration(
            options.config.isEmpty() ? preferences::kExperiment.read() : QString());
    }
    // "<lesson>:<step>", or a … h of the LegoFeup lesson.
    const qsizetype colon = options.experiment.indexOf(QLatin1Char(':'));
    panel.useBuiltInLesson(colon > 0 ? options.experiment.left(colon)
                                     : QString::fromStdString(lessons::legofeup_lesson().id));
    return panel.showStepOfConfiguration(options.experiment.mid(colon + 1));
}

}  // namespace legofeup::ui
