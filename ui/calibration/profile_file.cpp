#include "legofeup/ui/calibration/profile_file.hpp"

#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <cmath>
#include <exception>

#include "legofeup/lessons/input_error.hpp"

namespace legofeup::ui {

QString update_profile(const QString& path,
                       const std::function<void(lessons::RobotProfile&)>& change) {
    if (path.trimmed().isEmpty()) {
        return QObject::tr("No profile file given.");
    }
    const std::string file = path.toStdString();
    try {
        lessons::RobotProfile profile;
        if (QFileInfo::exists(path)) {
            profile = lessons::load_robot_profile(file);
        }
        change(profile);
        lessons::save_robot_profile(file, profile);
    } catch (const lessons::InputError& error) {
        return QObject::tr("The profile was not saved:\n%1").arg(QString::fromUtf8(error.what()));
    } catch (const std::exception& error) {
        return QObject::tr("The profile was not saved: %1").arg(QString::fromUtf8(error.what()));
    }
    return {};
}

void apply_umbmark(lessons::RobotProfile& profile, const lessons::UmbmarkResult& result) {
    profile.right_wheel_diameter = result.right_wheel_diameter;
    profile.left_wheel_diameter = result.left_wheel_diameter;
    profile.wheel_base = result.wheel_base;
    lessons::derive_codo(profile);
    // Encoders other than the NXT's 360 counts a turn: UMBmark's Codo overrides the derived.
    const auto differs = [](double a, double b) { return std::abs(a - b) > 1e-9 * std::abs(b); };
    if (differs(profile.codo_right, result.codo_right)
        || differs(profile.codo_left, result.codo_left)) {
        profile.codo_right = result.codo_right;
        profile.codo_left = result.codo_left;
    }
}

QString ask_profile_path(QWidget* parent, const QString& suggested) {
    return QFileDialog::getSaveFileName(
        parent, QObject::tr("Save to robot profile"),
        suggested.isEmpty() ? QStringLiteral("robot.toml") : suggested,
        QObject::tr("Robot profiles (*.toml);;All files (*)"), nullptr,
        QFileDialog::DontConfirmOverwrite);  // the profile is updated, not replaced
}

bool save_and_report(const QString& path, const std::function<void(lessons::RobotProfile&)>& change,
                     QLabel& result, QLabel& message) {
    const QString error = update_profile(path, change);
    message.setText(error);
    if (error.isEmpty()) {
        result.setText(result.text() + QObject::tr("\nSaved to %1.").arg(path));
    }
    return error.isEmpty();
}

QLabel* result_label(const QString& text, const char* name, int lines, QWidget* parent) {
    auto* label = new QLabel(text, parent);
    label->setObjectName(QLatin1String(name));
    label->setWordWrap(true);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    label->setMinimumHeight(label->fontMetrics().lineSpacing() * lines + 4);
    return label;
}

QLabel* message_label(const char* name, QWidget* parent) {
    QLabel* label = result_label({}, name, 2, parent);
    QPalette warning = label->palette();
    warning.setColor(QPalette::WindowText, QColor(0xc6, 0x28, 0x28));
    label->setPalette(warning);
    return label;
}

}  // namespace legofeup::ui
