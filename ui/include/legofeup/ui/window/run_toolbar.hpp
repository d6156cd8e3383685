#pragma once
// The run's controls: start, pause, stop, reset; where the robot is (embedded simulator,
// an external legofeup-sim, an NXT — chosen in the connect dialog); the simulator's speed;
// and the path controller switch (off: drive with the keyboard).

#include <QToolBar>

class QAction;
class QCheckBox;
class QComboBox;
class QLineEdit;
class QToolButton;

namespace legofeup::ui {

class ConnectDialog;
class Session;
enum class RunPhase : std::uint8_t;

class RunToolBar : public QToolBar {
    Q_OBJECT

  public:
    explicit RunToolBar(Session& session, QWidget* parent = nullptr);

    QAction* startAction() const { return start_; }
    QAction* pauseAction() const { return pause_; }
    QAction* stopAction() const { return stop_; }
    QAction* resetAction() const { return reset_; }
    QComboBox* linkChoice() const { return link_; }
    QLineEdit* addressField() const { return address_; }
    QComboBox* speedChoice() const { return speed_; }
    QCheckBox* pathControllerSwitch() const { return path_controller_; }
    /// Shows the NXT chosen (its address, or "emulated brick"); opens the connect dialog.
    QToolButton* nxtButton() const { return nxt_; }
    /// "Connect to an NXT…": opens the connect dialog (hidden in a build without the NXT).
    QAction* connectAction() const { return connect_; }
    /// Puts `action` with the run's controls, after Reset (Kidnap robot…).
    void addRunAction(QAction* action);

  public slots:
    /// Opens the connect dialog (window-modal, not blocking); accepting it makes the NXT the
    /// robot of the next start, cancelling keeps the robot chosen before. Returns it; null in
    /// a build without the NXT (nxt_supported()), which has no dialog and offers no NXT.
    ConnectDialog* openConnectDialog();

  private:
    void phaseChanged(RunPhase phase);
    void linkEdited();
    void showLinkFields();
    /// Selects `speed` in the speed box, adding it in order when the box lacks it.
    void selectSpeed(double speed);

    Session& session_;
    QAction* start_ = nullptr;
    QAction* pause_ = nullptr;
    QAction* stop_ = nullptr;
    QAction* reset_ = nullptr;
    QComboBox* link_ = nullptr;
    QLineEdit* address_ = nullptr;
    QAction* address_action_ = nullptr;
    QComboBox* speed_ = nullptr;
    QAction* speed_action_ = nullptr;
    QToolButton* nxt_ = nullptr;
    QAction* nxt_action_ = nullptr;
    QAction* connect_ = nullptr;
    QCheckBox* path_controller_ = nullptr;
};

}  // namespace legofeup::ui
