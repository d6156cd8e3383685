// `legofeup --screenshot-at`'s moment (QtTest, offscreen): at_run_time() calls back once, as
// soon as the run reaches the time asked for — not before it, and not long after — or at the
// run's end when it ends sooner (finished or stopped), and never after the session is gone.

#include <QTest>
#include <memory>

#include "legofeup/lessons/experiments.hpp"
#include "legofeup/ui/session/session.hpp"
#include "legofeup/ui/window/at_run_time.hpp"
#include "support/short_run.hpp"

using namespace legofeup;
using namespace legofeup::ui;

namespace {

constexpr int kPatienceMs = 30000;

/// What the callback saw: how often it ran, and the run's time and phase when it first did.
struct Seen {
    int calls = 0;
    double time = -1.0;
    RunPhase phase = RunPhase::Idle;
};

}  // namespace

class AtRunTimeTest : public QObject {
    Q_OBJECT

  private:
    std::unique_ptr<Session> session_;
    Seen seen_;

    void open(const lessons::RunConfig& config) {
        session_ = std::make_unique<Session>(config);
        LinkChoice fast;
        fast.speed = 10.0;
        session_->setLinkChoice(fast);
    }

    void watch(double seconds) {
        at_run_time(*session_, seconds, [this] {
            if (++seen_.calls == 1) {
                seen_.time =
                    session_->history().empty() ? -1.0 : session_->history().latest().snapshot.time;
                seen_.phase = session_->phase();
            }
        });
    }

  private slots:
    void init() { seen_ = {}; }
    void cleanup() { session_.reset(); }

    void itIsCalledOnceWhenTheRunReachesTheTime() {
        open(lessons::find_experiment("f")->config);
        watch(2.0);
        session_->start();
        QTRY_VERIFY_WITH_TIMEOUT(seen_.calls > 0, kPatienceMs);
        QCOMPARE(seen_.phase, RunPhase::Running);
        QVERIFY2(seen_.time >= 2.0, qPrintable(QString::number(seen_.time)));
        // The first batch past 2 s: at 10× a display frame holds ~0.17 s of the run; a busy
        // machine merges a few.
        QVERIFY2(seen_.time < 3.0, qPrintable(QString::number(seen_.time)));
        QTRY_VERIFY_WITH_TIMEOUT(session_->history().latest().snapshot.time > 4.0, kPatienceMs);
        QCOMPARE(seen_.calls, 1);  // once, though every later batch is past the time too
        session_->stop();
        QTRY_COMPARE_WITH_TIMEOUT(session_->phase(), RunPhase::Stopped, kPatienceMs);
        QCOMPARE(seen_.calls, 1);  // and the run's end does not call it again
    }

    void aRunThatFinishesSoonerCallsItAtItsEnd() {
        open(testing::short_run(lessons::find_experiment("f")->config));  // 3 s
        watch(100.0);
        session_->start();
        QTRY_VERIFY_WITH_TIMEOUT(seen_.calls > 0, kPatienceMs);
        QCOMPARE(seen_.phase, RunPhase::Finished);
        QVERIFY2(seen_.time > 2.5 && seen_.time < 100.0, qPrintable(QString::number(seen_.time)));
        QTest::qWait(200);
        QCOMPARE(seen_.calls, 1);
    }

    void aStoppedRunCallsItAtTheStop() {
        open(lessons::find_experiment("f")->config);
        watch(100.0);
        session_->start();
        QTRY_VERIFY_WITH_TIMEOUT(!session_->history().empty(), kPatienceMs);
        QCOMPARE(seen_.calls, 0);  // running, and not at 100 s yet
        session_->stop();
        QTRY_VERIFY_WITH_TIMEOUT(seen_.calls > 0, kPatienceMs);
        QCOMPARE(seen_.phase, RunPhase::Stopped);
        QVERIFY(seen_.time < 100.0);
    }

    void nothingIsCalledOnceTheSessionIsGone() {
        open(lessons::find_experiment("f")->config);
        watch(0.5);
        session_.reset();
        QTest::qWait(100);
        QCOMPARE(seen_.calls, 0);
    }
};

QTEST_MAIN(AtRunTimeTest)
#include "test_at_run_time.moc"
