#pragma once
// Every sample of a session's run, whole, copied as the session announces them: the
// session's history keeps only the recent ones whole (run_history.hpp), and a test that
// looks back over a whole run needs all of them.

#include <QObject>
#include <cstddef>
#include <vector>

#include "legofeup/ui/session/session.hpp"

namespace legofeup::ui::testing {

class SampleRecorder {
  public:
    explicit SampleRecorder(const Session& session) : session_(session) {
        QObject::connect(&session, &Session::historyRestarted, &context_,
                         [this] { samples_.clear(); });
        QObject::connect(&session, &Session::samplesAppended, &context_,
                         [this](int first, int count) { take(first, count); });
    }

    /// The run's samples so far (since the session's history last restarted).
    const std::vector<RunSample>& samples() const { return samples_; }

  private:
    void take(int first, int count) {
        const RunHistory& history = session_.history();
        if (first == 0) {
            samples_.clear();
        }
        for (int i = first; i < first + count; ++i) {
            samples_.push_back(*history.sample(static_cast<std::size_t>(i)));  // the latest batch
        }
    }

    const Session& session_;
    QObject context_;  ///< the connections end with the recorder
    std::vector<RunSample> samples_;
};

}  // namespace legofeup::ui::testing
