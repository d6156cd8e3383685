#pragma once
// The "Robot" dock: which robot the run has, the connection's state (Connecting, Connected,
// Failed with the reason, Disconnected) and, for an NXT, its battery, cycle time and rate,
// and timeouts — updated live — with Reconnect after a failure.

#include <QString>
#include <QWidget>

#include "legofeup/ui/session/live_run.hpp"

class QLabel;
class QPushButton;

namespace legofeup::ui {

class Session;

/// Below this the NXT's motors lose speed and its Bluetooth gets unreliable.
inline constexpr double kLowBatteryVolts = 6.5;

/// The connection's state as the dock and the status bar word it: "Connecting…",
/// "Connected", "Failed: <why>", "Disconnected".
QString connection_state_text(RunPhase phase, const LiveRunStatus& status);
/// "7.62 V" (empty before the first reading).
QString battery_text(const lessons::LinkHealth& quality);
bool battery_low(const lessons::LinkHealth& quality);
/// "55 ms (18.2 Hz)": the mean cycle time and rate (empty before the first cycle).
QString cycle_text(const lessons::LinkHealth& quality);
/// The status bar's part for an NXT run: "NXT: Connected · 7.62 V · 55 ms (18.2 Hz) ·
/// 2 timeouts" ("NXT: Failed · …" without the reason, which the dock shows); empty for a
/// simulator.
QString robot_status_line(RunPhase phase, const LiveRunStatus& status);

class RobotStatusView : public QWidget {
    Q_OBJECT

  public:
    explicit RobotStatusView(Session& session, QWidget* parent = nullptr);

    QLabel* stateLabel() const { return state_; }
    QLabel* batteryLabel() const { return battery_; }
    QLabel* cycleLabel() const { return cycle_; }
    QLabel* timeoutsLabel() const { return timeouts_; }
    QPushButton* reconnectButton() const { return reconnect_; }

  public slots:
    /// Shows the session's latest status (called on every batch and phase change).
    void refresh();

  private:
    Session& session_;
    QLabel* link_ = nullptr;
    QLabel* state_ = nullptr;
    QLabel* battery_ = nullptr;
    QLabel* cycle_ = nullptr;
    QLabel* timeouts_ = nullptr;
    QPushButton* reconnect_ = nullptr;
};

}  // namespace legofeup::ui
