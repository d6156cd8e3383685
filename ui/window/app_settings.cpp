#include "legofeup/ui/window/app_settings.hpp"

#include <QDir>
#include <QFileInfo>

namespace legofeup::ui {

QString last_config_path() {
    return QFileInfo(QSettings().fileName()).dir().filePath(QStringLiteral("last-config.toml"));
}

}  // namespace legofeup::ui
