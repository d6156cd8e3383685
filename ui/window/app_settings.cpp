#include "legofeup/ui/window/app_settings.hpp"

#include <QDir>
#include <QFileInfo>
#include <algorithm>

#include "legofeup/ui/session/nxt_connection.hpp"

namespace legofeup::ui {

QString last_config_path() {
    return QFileInfo(QSettings().fileName()).dir().filePath(QStringLiteral("last-config.toml"));
}

LinkChoice saved_link_choice() {
    LinkChoice choice;
    choice.kind = static_cast<LinkKind>(
        std::clamp(preferences::kLinkKind.read(), 0, static_cast<int>(LinkKind::Nxt)));
    if (choice.kind == LinkKind::Nxt && !nxt_supported()) {
        choice.kind = LinkKind::Embedded;  // saved by a build with the NXT
    }
    choice.address = preferences::kLinkAddress.read();
    // A speed edited by hand into something the simulator refuses: the default instead.
    if (const double speed = preferences::kSimulatorSpeed.read(); is_simulator_speed(speed)) {
        choice.speed = speed;
    }
    choice.nxt_address = preferences::kNxtAddress.read();
    choice.relay = preferences::kNxtRelay.read();
    choice.robot_profile = preferences::kNxtProfile.read();
    choice.emulated = preferences::kNxtEmulated.read();
    return choice;
}

void save_link_choice(const LinkChoice& choice) {
    preferences::kLinkKind.write(static_cast<int>(choice.kind));
    preferences::kLinkAddress.write(choice.address);
    preferences::kSimulatorSpeed.write(choice.speed);
    preferences::kNxtAddress.write(choice.nxt_address);
    preferences::kNxtRelay.write(choice.relay);
    preferences::kNxtProfile.write(choice.robot_profile);
    preferences::kNxtEmulated.write(choice.emulated);
}

QStringList with_recent_robot(QStringList recent, const QString& address) {
    const QString trimmed = address.trimmed();
    if (trimmed.isEmpty()) {
        return recent;
    }
    recent.removeAll(trimmed);
    recent.prepend(trimmed);
    while (recent.size() > kMaxRecentRobots) {
        recent.removeLast();
    }
    return recent;
}

void remember_robot(const QString& address) {
    preferences::kRecentRobots.write(with_recent_robot(preferences::kRecentRobots.read(), address));
}

}  // namespace legofeup::ui
