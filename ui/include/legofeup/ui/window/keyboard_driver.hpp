#pragma once
// Driving the robot with the keyboard while the path controller is off: arrow keys or WASD
// (up/W forward, down/S back, left/A and right/D turn; held keys combine), space stops.
// Installed on the application, it sees keys wherever the focus is, except in text fields,
// where they belong to what is typed.

#include <QObject>
#include <QSet>

namespace legofeup::ui {

class Session;

class KeyboardDriver : public QObject {
    Q_OBJECT

  public:
    explicit KeyboardDriver(Session& session, QObject* parent = nullptr);

    /// The command the held keys give: V (m/s) and W (rad/s), from the run's V_ref and W_ref.
    double speed() const { return speed_; }
    double turnRate() const { return turn_rate_; }

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void send();

    Session& session_;
    QSet<int> held_;
    double speed_ = 0.0;
    double turn_rate_ = 0.0;
};

}  // namespace legofeup::ui
