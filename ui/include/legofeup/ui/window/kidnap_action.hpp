#pragma once
// Run ▸ Kidnap robot… (F9; also on the toolbar): the kidnapped-robot experiment of paper 001
// §IV-B by hand. The user clicks where the simulated robot goes in the arena and drags from
// there to aim it; the session has the simulator put it there through its control channel.
// The filter is not told: it has to notice from its scans (mismatches, then the recovery).
// Disabled, with the reason as its tooltip, without a run or with an NXT (real or emulated:
// no simulator can lift it).

#include <QObject>
#include <QString>

class QAction;

namespace legofeup {
struct Pose2;
}

namespace legofeup::ui {

class ArenaView;
class Session;

class KidnapAction : public QObject {
    Q_OBJECT

  public:
    KidnapAction(Session& session, ArenaView& arena, QObject* parent = nullptr);

    QAction* action() const { return action_; }

  signals:
    /// What happened, for the status bar ("Kidnapped the robot to …", or why not).
    void done(const QString& message);

  private:
    void refresh();
    void toggled(bool picking);
    void picked(const Pose2& pose);

    Session& session_;
    ArenaView& arena_;
    QAction* action_ = nullptr;
};

}  // namespace legofeup::ui
