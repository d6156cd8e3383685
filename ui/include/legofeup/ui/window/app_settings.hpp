#pragma once
// Every persisted preference in one typed place: its key, its default and its type together
// (docs/architecture.md). Stored with QSettings (~/.config/LegoFeup/LegoFeup Lab.conf); the
// last configuration itself is a TOML file beside it (last_config_path()).

#include <QSettings>
#include <QString>
#include <QStringList>
#include <QVariant>

#include "legofeup/ui/session/session.hpp"

namespace legofeup::ui {

template <class T>
struct Preference {
    const char* key;
    T fallback;

    T read() const {
        const QVariant value = QSettings().value(QLatin1String(key));
        return value.isValid() && value.canConvert<T>() ? value.value<T>() : fallback;
    }
    void write(const T& value) const { QSettings().setValue(QLatin1String(key), value); }
};

namespace preferences {

inline const Preference<QByteArray> kWindowGeometry{"window/geometry", {}};
inline const Preference<QByteArray> kWindowState{"window/state", {}};
inline const Preference<bool> kLargeText{"view/largeText", false};
/// "system", "light" or "dark".
inline const Preference<QString> kTheme{"view/theme", QStringLiteral("system")};
/// 0: 1σ, 1: 95 %, 2: 99 % (EllipseConfidence).
inline const Preference<int> kEllipseConfidence{"view/ellipseConfidence", 0};
inline const Preference<bool> kFollowRobot{"view/followRobot", false};
inline const Preference<bool> kShowFrameTimes{"view/showFrameTimes", false};
/// Seconds of history in the plots; 0: the whole run.
inline const Preference<double> kPlotWindow{"view/plotWindow", 60.0};
/// The plots' tab chosen last (PlotsPanel::wantedTab()).
inline const Preference<int> kPlotTab{"view/plotTab", 0};
/// 0: embedded, 1: external, 2: NXT (LinkKind).
inline const Preference<int> kLinkKind{"link/kind", 0};
inline const Preference<QString> kLinkAddress{"link/address",
                                              QStringLiteral("udp://127.0.0.1:5600")};
inline const Preference<double> kSimulatorSpeed{"link/speed", 1.0};
/// The NXT's address as typed ("bt:00:16:53:…", "serial:/dev/rfcomm0", "tcp:HOST:PORT").
inline const Preference<QString> kNxtAddress{"nxt/address", {}};
inline const Preference<bool> kNxtRelay{"nxt/relay", false};
/// A robot profile (TOML) applied to NXT runs; empty: none.
inline const Preference<QString> kNxtProfile{"nxt/profile", {}};
inline const Preference<bool> kNxtEmulated{"nxt/emulated", false};
/// The bricks connected to, most recent first (remember_robot() keeps the list).
inline const Preference<QStringList> kRecentRobots{"nxt/recent", {}};
/// The lesson step shown last ("a" … "f" in the built-in lesson).
inline const Preference<QString> kExperiment{"lesson/experiment", QStringLiteral("f")};
/// The teacher's lesson file in use; empty: the built-in LegoFeup lesson.
inline const Preference<QString> kLessonFile{"lesson/file", {}};
/// The folder the lesson's files (answers, reports, run logs) were last saved in or read from.
inline const Preference<QString> kLessonFolder{"lesson/folder", {}};

}  // namespace preferences

/// Where the configuration in use is kept between sessions (the CLI's TOML format).
QString last_config_path();

/// The link chosen last time (the robot, the simulator's address and speed, the NXT's).
LinkChoice saved_link_choice();
void save_link_choice(const LinkChoice& choice);

/// How many recent robots are kept.
inline constexpr int kMaxRecentRobots = 8;
/// `recent` with `address` moved (or added) to the front, without duplicates, at most
/// kMaxRecentRobots long.
QStringList with_recent_robot(QStringList recent, const QString& address);
/// Puts `address` first in the persisted recent robots.
void remember_robot(const QString& address);

}  // namespace legofeup::ui
