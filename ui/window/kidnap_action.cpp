#include "legofeup/ui/window/kidnap_action.hpp"

#include <QAction>

#include "legofeup/core/angles.hpp"
#include "legofeup/ui/arena/arena_view.hpp"
#include "legofeup/ui/session/session.hpp"

namespace legofeup::ui {

namespace {

QString usage_tip() {
    return QObject::tr(
        "Kidnap the simulated robot (F9): click where to put it in the arena and drag from "
        "there to aim it. The filter is not told — watch its scans stop matching, then the "
        "recovery");
}

}  // namespace

KidnapAction::KidnapAction(Session& session, ArenaView& arena, QObject* parent)
    : QObject(parent), session_(session), arena_(arena) {
    action_ = new QAction(tr("&Kidnap robot…"), this);
    action_->setObjectName(QStringLiteral("kidnapAction"));
    action_->setShortcut(Qt::Key_F9);
    action_->setCheckable(true);  // checked while the place is being picked
    connect(action_, &QAction::toggled, this, &KidnapAction::toggled);
    connect(&arena_, &ArenaView::posePicked, this, &KidnapAction::picked);
    connect(&arena_, &ArenaView::posePickCancelled, this, [this] {
        const QSignalBlocker blocker(action_);
        action_->setChecked(false);
    });
    connect(&session_, &Session::phaseChanged, this, &KidnapAction::refresh);
    connect(&session_, &Session::linkChoiceChanged, this, &KidnapAction::refresh);
    refresh();
}

void KidnapAction::refresh() {
    const QString refusal = session_.teleportRefusal();
    action_->setEnabled(refusal.isEmpty());
    action_->setToolTip(refusal.isEmpty() ? usage_tip() : refusal);
    if (!refusal.isEmpty() && arena_.pickingPose()) {
        arena_.cancelPosePick();  // the run ended while a place was being picked
    }
}

void KidnapAction::toggled(bool picking) {
    if (picking) {
        arena_.beginPosePick();
    } else {
        arena_.cancelPosePick();
    }
}

void KidnapAction::picked(const Pose2& pose) {
    {
        const QSignalBlocker blocker(action_);
        action_->setChecked(false);
    }
    const QString refused = session_.teleport(pose);
    if (!refused.isEmpty()) {
        emit done(refused);
        return;
    }
    emit done(tr("Kidnapped the robot to x = %1 m, y = %2 m, heading %3°; the filter was not told")
                  .arg(pose.x, 0, 'f', 2)
                  .arg(pose.y, 0, 'f', 2)
                  .arg(radians_to_degrees(pose.theta), 0, 'f', 0));
}

}  // namespace legofeup::ui
