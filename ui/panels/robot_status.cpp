#include "legofeup/ui/panels/robot_status.hpp"

#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include "legofeup/ui/session/session.hpp"

namespace legofeup::ui {
namespace {

const QColor kWarning(0xc6, 0x28, 0x28);

QString link_text(const Session& session) {
    const LiveRunStatus& status = session.status();
    const LinkChoice& choice = session.linkChoice();
    if (!status.link.empty()) {
        const QString link = QString::fromStdString(status.link);
        return choice.kind == LinkKind::Nxt && choice.emulated
                   ? QObject::tr("%1, an emulated brick").arg(link)
                   : link;
    }
    switch (choice.kind) {
        case LinkKind::Embedded:
            return QObject::tr("The embedded simulator");
        case LinkKind::External:
            return QObject::tr("legofeup-sim at %1").arg(choice.address);
        case LinkKind::Nxt:
            return choice.emulated
                       ? QObject::tr("An emulated NXT (at the next start)")
                       : QObject::tr("NXT at %1 (at the next start)")
                             .arg(choice.nxt_address.isEmpty() ? QObject::tr("no address yet")
                                                               : choice.nxt_address);
    }
    return {};
}

}  // namespace

QString connection_state_text(RunPhase phase, const LiveRunStatus& status) {
    switch (phase) {
        case RunPhase::Idle:
        case RunPhase::Stopped:
        case RunPhase::Finished:
            return QObject::tr("Disconnected");
        case RunPhase::Connecting:
            return QObject::tr("Connecting…");
        case RunPhase::Failed:
            return QObject::tr("Failed: %1").arg(QString::fromStdString(status.message));
        case RunPhase::Running:
        case RunPhase::Paused:
            break;
    }
    if (status.health) {
        switch (status.health->state) {
            case lessons::LinkState::Connecting:
                return QObject::tr("Connecting…");
            case lessons::LinkState::Failed:
                return QObject::tr("Failed: %1")
                    .arg(QString::fromStdString(status.health->last_error));
            case lessons::LinkState::Disconnected:
                return QObject::tr("Disconnected");
            case lessons::LinkState::Connected:
                break;
        }
    }
    return QObject::tr("Connected");
}

QString battery_text(const lessons::LinkHealth& quality) {
    if (!quality.battery_millivolts) {
        return {};
    }
    return QStringLiteral("%1 V").arg(*quality.battery_millivolts / 1000.0, 0, 'f', 2);
}

bool battery_low(const lessons::LinkHealth& quality) {
    return quality.battery_millivolts && *quality.battery_millivolts / 1000.0 < kLowBatteryVolts;
}

QString cycle_text(const lessons::LinkHealth& quality) {
    if (quality.frames == 0 || quality.mean_cycle_seconds <= 0.0) {
        return {};
    }
    return QStringLiteral("%1 ms (%2 Hz)")
        .arg(quality.mean_cycle_seconds * 1000.0, 0, 'f', 0)
        .arg(quality.rate_hz(), 0, 'f', 1);
}

QString robot_status_line(RunPhase phase, const LiveRunStatus& status) {
    const lessons::LinkHealth* robot = status.robot_health();
    if (robot == nullptr) {
        return {};
    }
    // The state's word only: the reason of a failure is in the Robot dock and the message.
    QString state = connection_state_text(phase, status);
    state = state.left(state.indexOf(QLatin1Char(':')));
    QStringList parts{QObject::tr("NXT: %1").arg(state)};
    if (const QString battery = battery_text(*robot); !battery.isEmpty()) {
        parts << (battery_low(*robot) ? QObject::tr("%1 (low)").arg(battery) : battery);
    }
    if (const QString cycle = cycle_text(*robot); !cycle.isEmpty()) {
        parts << cycle;
    }
    if (robot->timeouts > 0) {
        parts << (robot->timeouts == 1 ? QObject::tr("1 timeout")
                                       : QObject::tr("%1 timeouts").arg(robot->timeouts));
    }
    return parts.join(QStringLiteral(" · "));
}

RobotStatusView::RobotStatusView(Session& session, QWidget* parent)
    : QWidget(parent), session_(session) {
    setObjectName(QStringLiteral("robotStatus"));
    const auto value = [this](const char* name) {
        auto* label = new QLabel(this);
        label->setObjectName(QLatin1String(name));
        label->setWordWrap(true);
        label->setTextInteractionFlags(Qt::TextSelectableByMouse);
        return label;
    };
    link_ = value("robotLink");
    state_ = value("robotState");
    battery_ = value("robotBattery");
    battery_->setToolTip(tr("The brick's battery. Below %1 V the motors lose speed and the "
                            "Bluetooth link gets unreliable: change the batteries.")
                             .arg(kLowBatteryVolts));
    cycle_ = value("robotCycle");
    cycle_->setToolTip(
        tr("The link's mean cycle time (one frame of counts and A/D values in, "
           "one wheel command out) and its rate; last and longest below"));
    timeouts_ = value("robotTimeouts");
    timeouts_->setToolTip(
        tr("Cycles whose replies came too late (the loop predicted without "
           "a frame), replies refused, IR readings the brick flagged"));
    reconnect_ = new QPushButton(tr("&Reconnect"), this);
    reconnect_->setObjectName(QStringLiteral("reconnect"));
    reconnect_->setToolTip(tr("Connect again with the same choice and start a new run"));
    connect(reconnect_, &QPushButton::clicked, &session_, &Session::start);

    auto* form = new QFormLayout;
    form->addRow(tr("Robot:"), link_);
    form->addRow(tr("State:"), state_);
    form->addRow(tr("Battery:"), battery_);
    form->addRow(tr("Cycle:"), cycle_);
    form->addRow(tr("Timeouts:"), timeouts_);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(reconnect_, 0, Qt::AlignLeft);
    layout->addStretch(1);
    refresh();
}

void RobotStatusView::refresh() {
    const LiveRunStatus& status = session_.status();
    const RunPhase phase = session_.phase();
    link_->setText(link_text(session_));
    state_->setText(connection_state_text(phase, status));
    QPalette state_palette = palette();
    if (phase == RunPhase::Failed) {
        state_palette.setColor(QPalette::WindowText, kWarning);
    }
    state_->setPalette(state_palette);

    const lessons::LinkHealth* nxt = status.robot_health();
    const bool on_nxt = nxt || session_.linkChoice().kind == LinkKind::Nxt;
    const QString none = on_nxt ? tr("—") : tr("— (a simulator)");
    const QString battery = nxt ? battery_text(*nxt) : QString();
    battery_->setText(battery.isEmpty()   ? none
                      : battery_low(*nxt) ? tr("%1 — low: change the batteries").arg(battery)
                                          : battery);
    QPalette battery_palette = palette();
    if (nxt && battery_low(*nxt)) {
        battery_palette.setColor(QPalette::WindowText, kWarning);
    }
    battery_->setPalette(battery_palette);
    const QString cycle = nxt ? cycle_text(*nxt) : QString();
    cycle_->setText(cycle.isEmpty() ? none
                                    : tr("%1\nlast %2 ms, longest %3 ms, %4 cycles")
                                          .arg(cycle)
                                          .arg(nxt->last_cycle_seconds * 1000.0, 0, 'f', 0)
                                          .arg(nxt->max_cycle_seconds * 1000.0, 0, 'f', 0)
                                          .arg(nxt->frames));
    timeouts_->setText(nxt ? tr("%1 (replies refused: %2, IR readings invalid: %3)")
                                 .arg(nxt->timeouts)
                                 .arg(nxt->rejected_replies)
                                 .arg(nxt->invalid_readings)
                           : none);
    reconnect_->setVisible(phase == RunPhase::Failed);
}

}  // namespace legofeup::ui
