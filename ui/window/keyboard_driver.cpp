#include "legofeup/ui/window/keyboard_driver.hpp"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTextEdit>
#include <algorithm>

#include "legofeup/ui/session/session.hpp"

namespace legofeup::ui {
namespace {

enum class Drive { None, Forward, Back, Left, Right, Stop };

Drive drive_of(int key) {
    switch (key) {
        case Qt::Key_Up:
        case Qt::Key_W:
            return Drive::Forward;
        case Qt::Key_Down:
        case Qt::Key_S:
            return Drive::Back;
        case Qt::Key_Left:
        case Qt::Key_A:
            return Drive::Left;
        case Qt::Key_Right:
        case Qt::Key_D:
            return Drive::Right;
        case Qt::Key_Space:
            return Drive::Stop;
        default:
            return Drive::None;
    }
}

bool typing_into_text() {
    const QWidget* focus = QApplication::focusWidget();
    return qobject_cast<const QLineEdit*>(focus) != nullptr
           || qobject_cast<const QAbstractSpinBox*>(focus) != nullptr
           || qobject_cast<const QTextEdit*>(focus) != nullptr
           || qobject_cast<const QPlainTextEdit*>(focus) != nullptr;
}

}  // namespace

KeyboardDriver::KeyboardDriver(Session& session, QObject* parent)
    : QObject(parent), session_(session) {
    connect(&session_, &Session::manualDrivingChanged, this, [this](bool manual) {
        if (!manual) {
            held_.clear();
            speed_ = turn_rate_ = 0.0;
        }
    });
}

bool KeyboardDriver::eventFilter(QObject* watched, QEvent* event) {
    const bool press = event->type() == QEvent::KeyPress;
    if ((!press && event->type() != QEvent::KeyRelease) || !session_.manualDriving()
        || typing_into_text()) {
        return QObject::eventFilter(watched, event);
    }
    const auto* key = static_cast<QKeyEvent*>(event);
    const Drive drive = drive_of(key->key());
    if (drive == Drive::None || key->modifiers() & (Qt::ControlModifier | Qt::AltModifier)) {
        return QObject::eventFilter(watched, event);
    }
    // A key event reaches the window's QWindow first, which hands it to the focus widget:
    // act there, and consume it so no other widget also acts on it.
    if (!watched->isWidgetType()) {
        return QObject::eventFilter(watched, event);
    }
    if (drive == Drive::Stop) {
        held_.clear();
    } else if (press && !key->isAutoRepeat()) {
        held_.insert(key->key());
    } else if (!press && !key->isAutoRepeat()) {
        held_.remove(key->key());
    }
    send();
    return true;
}

void KeyboardDriver::send() {
    const MotionLimits& limits = session_.resolved().loop.motion;
    int forward = 0;
    int left = 0;
    for (const int key : held_) {
        switch (drive_of(key)) {
            case Drive::Forward:
                ++forward;
                break;
            case Drive::Back:
                --forward;
                break;
            case Drive::Left:
                ++left;
                break;
            case Drive::Right:
                --left;
                break;
            default:
                break;
        }
    }
    speed_ = limits.v_ref * std::clamp(forward, -1, 1);
    turn_rate_ = limits.w_ref * std::clamp(left, -1, 1);
    session_.setManualCommand(speed_, turn_rate_);
}

}  // namespace legofeup::ui
