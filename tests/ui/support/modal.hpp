#pragma once
// Answering the modal dialogs a menu entry opens (file dialogs, message boxes) from a test:
// every 50 ms the active modal widget, if any, is handed to `answer`, until it returns true
// (or the patience runs out). Polling, since the dialog's exec() blocks the test's own call;
// answering again on the next tick covers a dialog that ignored the first answer (a file
// dialog still loading its folder).

#include <QApplication>
#include <QTimer>
#include <QWidget>
#include <functional>
#include <memory>

namespace legofeup::ui::testing {

inline void answer_modals(std::function<bool(QWidget&)> answer, int patience_ms = 10000) {
    auto* poll = new QTimer;
    auto waited = std::make_shared<int>(0);
    QObject::connect(poll, &QTimer::timeout, [poll, waited, patience_ms, answer] {
        *waited += poll->interval();
        QWidget* modal = QApplication::activeModalWidget();
        if ((modal != nullptr && answer(*modal)) || *waited > patience_ms) {
            poll->stop();
            poll->deleteLater();
        }
    });
    poll->start(50);
}

}  // namespace legofeup::ui::testing
