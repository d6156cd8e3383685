#include "legofeup/ui/window/run_toolbar.hpp"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QStyle>
#include <QToolButton>
#include <array>

#include "legofeup/ui/session/nxt_connection.hpp"
#include "legofeup/ui/session/session.hpp"

namespace legofeup::ui {
namespace {

/// The speeds the box always offers; any other the session runs at (--speed 4, a speed
/// saved before) is added in order (selectSpeed()).
constexpr std::array kSpeeds = {0.5, 1.0, 2.0, 5.0, 10.0};

QString speed_label(double speed) {
    return QStringLiteral("%1×").arg(speed);
}

}  // namespace

RunToolBar::RunToolBar(Session& session, QWidget* parent)
    : QToolBar(tr("Run"), parent), session_(session) {
    setObjectName(QStringLiteral("runToolBar"));
    setToolButtonStyle(Qt::ToolButtonTextBesideIcon);

    start_ = addAction(style()->standardIcon(QStyle::SP_MediaPlay), tr("Start"));
    start_->setShortcut(Qt::Key_F5);
    start_->setToolTip(tr("Start a run (F5); resumes a paused one"));
    pause_ = addAction(style()->standardIcon(QStyle::SP_MediaPause), tr("Pause"));
    pause_->setCheckable(true);
    pause_->setShortcut(Qt::Key_F6);
    stop_ = addAction(style()->standardIcon(QStyle::SP_MediaStop), tr("Stop"));
    stop_->setShortcut(Qt::Key_F7);
    stop_->setToolTip(tr("Stop the robot (F7); the run's plots stay"));
    reset_ = addAction(style()->standardIcon(QStyle::SP_BrowserReload), tr("Reset"));
    reset_->setShortcut(Qt::Key_F8);
    reset_->setToolTip(tr("Back to the start: empty plots, initial pose (F8)"));
    connect(start_, &QAction::triggered, &session_, &Session::start);
    connect(pause_, &QAction::toggled, &session_, &Session::setPaused);
    connect(stop_, &QAction::triggered, &session_, &Session::stop);
    connect(reset_, &QAction::triggered, &session_, &Session::reset);
    addSeparator();

    path_controller_ = new QCheckBox(tr("Path controller"), this);
    path_controller_->setObjectName(QStringLiteral("pathController"));
    path_controller_->setChecked(!session_.manualDriving());
    path_controller_->setToolTip(
        tr("Off: drive with the arrow keys or WASD, space to stop (V_ref and W_ref set the "
           "speeds)"));
    addWidget(path_controller_);
    connect(path_controller_, &QCheckBox::toggled, this,
            [this](bool on) { session_.setManualDriving(!on); });
    connect(&session_, &Session::manualDrivingChanged, path_controller_,
            [this](bool manual) { path_controller_->setChecked(!manual); });
    addSeparator();

    addWidget(new QLabel(tr("Robot: "), this));
    link_ = new QComboBox(this);
    link_->setObjectName(QStringLiteral("linkChoice"));
    link_->addItem(tr("Embedded simulator"));
    link_->addItem(tr("External legofeup-sim"));
    if (nxt_supported()) {  // a build without the NXT offers none
        link_->addItem(tr("NXT over Bluetooth"));
        link_->setItemData(static_cast<int>(LinkKind::Nxt),
                           tr("A LEGO NXT over Bluetooth, a serial port or TCP, or an emulated "
                              "brick to rehearse with: opens the connect dialog"),
                           Qt::ToolTipRole);
    }
    link_->setCurrentIndex(static_cast<int>(session_.linkChoice().kind));
    addWidget(link_);
    address_ = new QLineEdit(session_.linkChoice().address, this);
    address_->setObjectName(QStringLiteral("linkAddress"));
    address_->setToolTip(tr("The robot port of a running legofeup-sim, e.g. udp://127.0.0.1:5600"));
    address_->setMinimumWidth(fontMetrics().horizontalAdvance(address_->text()) + 24);
    address_action_ = addWidget(address_);
    speed_ = new QComboBox(this);
    speed_->setObjectName(QStringLiteral("simulatorSpeed"));
    speed_->setToolTip(tr("Simulated seconds per real second (applies at the next start)"));
    for (const double speed : kSpeeds) {
        speed_->addItem(speed_label(speed), speed);
    }
    selectSpeed(session_.linkChoice().speed);
    speed_action_ = addWidget(speed_);
    connect_ = new QAction(tr("&Connect to an NXT…"), this);
    connect_->setObjectName(QStringLiteral("connectNxt"));
    connect_->setToolTip(
        tr("Choose the NXT: its address, the relay program, a robot profile, "
           "or an emulated brick"));
    connect_->setVisible(nxt_supported());  // in the Run and Tools menus
    connect(connect_, &QAction::triggered, this, &RunToolBar::openConnectDialog);
    nxt_ = new QToolButton(this);
    nxt_->setObjectName(QStringLiteral("nxtButton"));
    nxt_->setToolButtonStyle(Qt::ToolButtonTextOnly);
    nxt_->setToolTip(connect_->toolTip());
    connect(nxt_, &QToolButton::clicked, this, &RunToolBar::openConnectDialog);
    nxt_action_ = addWidget(nxt_);
    connect(link_, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (static_cast<LinkKind>(index) == LinkKind::Nxt
            && session_.linkChoice().kind != LinkKind::Nxt) {
            openConnectDialog();  // the NXT becomes the robot once the dialog is accepted
            return;
        }
        linkEdited();
    });
    connect(address_, &QLineEdit::editingFinished, this, &RunToolBar::linkEdited);
    connect(speed_, &QComboBox::currentIndexChanged, this, &RunToolBar::linkEdited);

    connect(&session_, &Session::phaseChanged, this, &RunToolBar::phaseChanged);
    connect(&session_, &Session::linkChoiceChanged, this, &RunToolBar::showLinkFields);
    phaseChanged(session_.phase());
    linkEdited();
}

void RunToolBar::addRunAction(QAction* action) {
    const QList<QAction*> all = actions();
    const qsizetype reset = all.indexOf(reset_);
    insertAction(reset + 1 < all.size() ? all[reset + 1] : nullptr, action);
}

void RunToolBar::linkEdited() {
    LinkChoice choice = session_.linkChoice();  // keeps the NXT's fields
    // No entry is current for an NXT chosen in a build without the NXT: it stays chosen.
    if (link_->currentIndex() >= 0) {
        choice.kind = static_cast<LinkKind>(link_->currentIndex());
    }
    choice.address = address_->text().trimmed();
    choice.speed = speed_->currentData().toDouble();
    session_.setLinkChoice(choice);
    showLinkFields();
}

void RunToolBar::selectSpeed(double speed) {
    int index = speed_->findData(speed);
    if (index < 0) {
        index = 0;
        while (index < speed_->count() && speed_->itemData(index).toDouble() < speed) {
            ++index;
        }
        speed_->insertItem(index, speed_label(speed), speed);
    }
    speed_->setCurrentIndex(index);
}

void RunToolBar::showLinkFields() {
    const LinkChoice& choice = session_.linkChoice();
    {
        const QSignalBlocker block_link(link_);
        const QSignalBlocker block_speed(speed_);
        link_->setCurrentIndex(static_cast<int>(choice.kind));
        selectSpeed(choice.speed);
        if (address_->text().trimmed() != choice.address) {
            address_->setText(choice.address);
        }
    }
    address_action_->setVisible(choice.kind == LinkKind::External);
    speed_action_->setVisible(choice.kind == LinkKind::Embedded);
    nxt_action_->setVisible(choice.kind == LinkKind::Nxt);
    nxt_->setText(choice.emulated                ? tr("Emulated brick…")
                  : choice.nxt_address.isEmpty() ? tr("Choose the NXT…")
                                                 : choice.nxt_address + QStringLiteral(" …"));
}

void RunToolBar::phaseChanged(RunPhase phase) {
    const bool active = session_.running();
    start_->setEnabled(!active || phase == RunPhase::Paused);
    pause_->setEnabled(phase == RunPhase::Running || phase == RunPhase::Paused);
    {
        const QSignalBlocker blocker(pause_);
        pause_->setChecked(phase == RunPhase::Paused);
    }
    stop_->setEnabled(active);
    link_->setEnabled(!active);
    address_->setEnabled(!active);
    speed_->setEnabled(!active);
    nxt_->setEnabled(!active);
    connect_->setEnabled(!active);
}

}  // namespace legofeup::ui
