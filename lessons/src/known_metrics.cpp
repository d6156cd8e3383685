// The metrics a lesson's checks may name: the keys of summary.json's "metrics", read off the
// object run_summary writes, so a metric added there is usable in lessons at once.
#include <algorithm>

#include "legofeup/lessons/run_summary.hpp"
#include "metric_check.hpp"

namespace legofeup::lessons {
namespace {

// A run with a truth, so the metrics that need one hold a value of their kind, not null.
const nlohmann::json& sample_metrics() {
    static const nlohmann::json sample = [] {
        RunResult result;
        result.metrics.truth = TruthMetrics{};
        return result_metrics_to_json(result);
    }();
    return sample;
}

MetricKind kind_of(const nlohmann::json& value) {
    if (value.is_boolean()) {
        return MetricKind::Boolean;
    }
    if (value.is_number()) {
        return MetricKind::Number;
    }
    if (value.is_array() && value.size() == 2 && value[0].is_number() && value[1].is_number()) {
        return MetricKind::Bounds;
    }
    return MetricKind::Unknown;
}

}  // namespace

MetricKind metric_kind(std::string_view name) {
    const auto found = sample_metrics().find(name);
    return found == sample_metrics().end() ? MetricKind::Unknown : kind_of(*found);
}

const std::vector<std::string>& known_metrics() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> usable;
        for (const auto& [name, value] : sample_metrics().items()) {
            if (kind_of(value) != MetricKind::Unknown) {
                usable.push_back(name);
            }
        }
        std::sort(usable.begin(), usable.end());
        return usable;
    }();
    return names;
}

}  // namespace legofeup::lessons
