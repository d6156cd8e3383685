#include "legofeup/ui/window/at_run_time.hpp"

#include <QObject>
#include <memory>
#include <utility>

#include "legofeup/ui/session/session.hpp"

namespace legofeup::ui {

void at_run_time(Session& session, double seconds, std::function<void()> then) {
    auto* watch = new QObject(&session);  // the connections' context: deleted once fired
    auto pending = std::make_shared<std::function<void()>>(std::move(then));
    const auto fire = [watch, pending] {
        if (!*pending) {
            return;  // already called (both signals in one event-loop turn)
        }
        const std::function<void()> now = std::exchange(*pending, nullptr);
        watch->deleteLater();
        now();
    };
    QObject::connect(&session, &Session::samplesAppended, watch, [&session, seconds, fire] {
        const RunHistory& history = session.history();
        if (!history.empty() && history.latest().snapshot.time >= seconds) {
            fire();
        }
    });
    QObject::connect(&session, &Session::phaseChanged, watch, [fire](RunPhase phase) {
        if (phase == RunPhase::Finished || phase == RunPhase::Stopped
            || phase == RunPhase::Failed) {
            fire();
        }
    });
}

}  // namespace legofeup::ui
