#include "legofeup/lessons/grading.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <vector>

#include "legofeup/core/chi_square.hpp"
#include "legofeup/core/effective_samples.hpp"
#include "legofeup/core/state.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/run_summary.hpp"

namespace legofeup::lessons {
namespace {

/// Mean, sample standard deviation and range of one metric over the seeds.
struct Spread {
    double sum = 0.0;
    double sum_squares = 0.0;
    double min = 0.0;
    double max = 0.0;
    std::size_t count = 0;

    void add(double value) {
        min = count == 0 ? value : std::min(min, value);
        max = count == 0 ? value : std::max(max, value);
        sum += value;
        sum_squares += value * value;
        ++count;
    }
    double mean() const { return sum / static_cast<double>(count); }
    // s² = (Σx² − n·x̄²)/(n − 1); clamped at 0 against rounding when all values are equal.
    double standard_deviation() const {
        if (count < 2) {
            return 0.0;
        }
        const double n = static_cast<double>(count);
        return std::sqrt(std::max(0.0, (sum_squares - n * mean() * mean()) / (n - 1.0)));
    }
};

/// A run's metrics without the machine-dependent ones (wall time, real-time factor).
nlohmann::json deterministic_metrics(const RunResult& result) {
    nlohmann::json metrics = result_metrics_to_json(result);
    for (auto it = metrics.begin(); it != metrics.end();) {
        it = is_machine_dependent_metric(it.key()) ? metrics.erase(it) : std::next(it);
    }
    return metrics;
}

std::optional<double> as_number(const nlohmann::json& value) {
    if (value.is_boolean()) {
        return value.get<bool>() ? 1.0 : 0.0;
    }
    if (value.is_number()) {
        return value.get<double>();
    }
    return std::nullopt;
}

/// The bounds metrics of a time average, pooled over the seeds (below), and their confidence.
struct TimeAverageBounds {
    const char* name;
    double confidence;
};
constexpr TimeAverageBounds kTimeAverageNeesBounds[] = {
    {"time_average_nees_95_bounds", 0.95},
    {"time_average_nees_99_9_bounds", 0.999},
};
constexpr const char* kNeesEffectiveSamples = "nees_effective_samples";
constexpr const char* kMeanNees = "mean_nees";
constexpr const char* kNeesDispersion = "nees_dispersion";
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

/// Each seed's mean NEES and the effective samples it is worth; nullopt when a seed has
/// either missing (no truth).
struct SeedAverages {
    std::vector<double> averages;
    std::vector<double> effective;
};

std::optional<SeedAverages> seed_averages(const nlohmann::json& per_seed) {
    SeedAverages seeds;
    for (const nlohmann::json& seed : per_seed) {
        const nlohmann::json& metrics = seed["metrics"];
        for (const char* name : {kNeesEffectiveSamples, kMeanNees}) {
            if (!metrics.contains(name) || !metrics[name].is_number()) {
                return std::nullopt;
            }
        }
        seeds.effective.push_back(metrics[kNeesEffectiveSamples].get<double>());
        seeds.averages.push_back(metrics[kMeanNees].get<double>());
    }
    return seeds;
}

/// The interval, at `confidence`, of the mean over the seeds of the per-seed mean NEES, for a
/// consistent filter. Seed i's time average is worth N_i independent χ²(3) values (its
/// nees_effective_samples); the seeds are independent, and the mean weighs them equally, so
/// it is worth N = S² / Σ 1/N_i (pooled_effective_samples) and its interval is
/// χ²(3N)/N — far narrower than one seed's. Seeds differ more than their N_i say (each
/// robot's own systematic errors repeat lap after lap): N is divided by the averages'
/// dispersion φ when φ > 1 (nees_dispersion), which widens the interval by about √φ without
/// excusing a filter whose NEES is off by a factor. Null without truth.
nlohmann::json pooled_time_average_bounds(const SeedAverages& seeds, double dispersion,
                                          double confidence) {
    const std::vector<double> equal_weights(seeds.effective.size(), 1.0);
    const double pooled = dispersion_corrected_samples(
        pooled_effective_samples(equal_weights, seeds.effective), dispersion);
    if (!(pooled > 0.0)) {
        return nullptr;
    }
    const ChiSquareInterval bounds =
        time_average_chi_square_interval(kStateSize, pooled, confidence);
    return {bounds.lower, bounds.upper};
}

}  // namespace

std::vector<std::uint64_t> grading_seeds(const GradingSpec& spec, const GradingRequest& request) {
    const int count = request.seeds > 0 ? request.seeds : spec.seeds;
    const std::uint64_t first = request.first_seed.value_or(spec.first_seed);
    std::vector<std::uint64_t> seeds;
    for (int i = 0; i < count; ++i) {
        seeds.push_back(first + static_cast<std::uint64_t>(i));
    }
    return seeds;
}

nlohmann::json grade_submission(const Lesson& lesson, const Submission& submission,
                                const GradingRequest& request,
                                const analysis::BatchProgress& progress) {
    if (!lesson.grading) {
        throw InputError({{lesson.source, 0, "grading", "",
                           "the lesson has no [grading] section, so it cannot grade"}});
    }
    const GradingSpec& spec = *lesson.grading;
    const std::vector<std::uint64_t> seeds = grading_seeds(spec, request);

    std::vector<ResolvedRun> runs;
    runs.reserve(seeds.size());
    for (const std::uint64_t seed : seeds) {
        RunConfig config = submission.tuned;
        config.seed = seed;
        if (request.laps) {
            config.laps = *request.laps;
        }
        runs.push_back(resolve(config));
    }
    const std::vector<RunResult> results = analysis::run_batch(runs, request.jobs, progress);

    nlohmann::json per_seed = nlohmann::json::array();
    std::map<std::string, Spread> spreads;  // ordered by name: the JSON is reproducible
    std::set<std::string> absent;           // null on some seed (no truth): no mean either
    for (std::size_t i = 0; i < runs.size(); ++i) {
        nlohmann::json metrics = deterministic_metrics(results[i]);
        for (const auto& [name, value] : metrics.items()) {
            if (const auto number = as_number(value)) {
                spreads[name].add(*number);
            } else if (value.is_null()) {
                absent.insert(name);
            }
        }
        per_seed.push_back({{"seed", seeds[i]}, {"metrics", std::move(metrics)}});
    }

    // The checks see the mean of every metric. A bounds metric (an array) of one step is the
    // same for every seed — it depends on the configuration only — so the first seed's
    // stands; the bounds of a time average are pooled over the seeds, as the mean is.
    nlohmann::json means = nlohmann::json::object();
    nlohmann::json aggregate = nlohmann::json::object();
    for (const auto& [name, spread] : spreads) {
        if (absent.contains(name)) {
            continue;  // a mean over the seeds that had it would pass for all seeds'
        }
        means[name] = spread.mean();
        aggregate[name] = {{"mean", spread.mean()},
                           {"std", spread.standard_deviation()},
                           {"min", spread.min},
                           {"max", spread.max}};
    }
    for (const std::string& name : absent) {
        means[name] = nullptr;  // its checks fail, saying why (evaluate_checks)
        aggregate[name] = nullptr;
    }
    if (!per_seed.empty()) {
        for (const auto& [name, value] : per_seed.front()["metrics"].items()) {
            if (value.is_array()) {
                means[name] = value;
            }
        }
        const std::optional<SeedAverages> averages = seed_averages(per_seed);
        const double dispersion =
            averages ? nees_dispersion(averages->averages, averages->effective, kStateSize) : kNan;
        for (const TimeAverageBounds& bounds : kTimeAverageNeesBounds) {
            means[bounds.name] =
                averages ? pooled_time_average_bounds(*averages, dispersion, bounds.confidence)
                         : nullptr;
            aggregate[bounds.name] = means[bounds.name];
        }
        // φ, reported beside the bounds it widened (null without truth or with one seed).
        aggregate[kNeesDispersion] =
            std::isfinite(dispersion) ? nlohmann::json(dispersion) : nlohmann::json(nullptr);
    }
    nlohmann::json checks = nlohmann::json::array();
    bool passed = true;
    int checks_passed = 0;
    for (const CheckResult& result : evaluate_checks(spec.checks, means)) {
        checks.push_back({{"expression", result.check.expression},
                          {"description", result.check.description},
                          {"value", result.actual},
                          {"passed", result.passed},
                          {"message", result.message}});
        passed = passed && result.passed;
        checks_passed += result.passed ? 1 : 0;
    }

    nlohmann::json grade = {
        {"lesson", lesson.id},
        {"step", spec.step},
        {"submission", submission.source},
        {"students", submission.students},
        {"tuning", submission.tuning_toml},
        {"seeds", seeds},
        {"per_seed", std::move(per_seed)},
        {"aggregate", std::move(aggregate)},
        {"checks", std::move(checks)},
        {"checks_passed", checks_passed},
        {"checks_total", spec.checks.size()},
        {"passed", passed},
    };
    grade["summary"] = grading_summary(grade);
    return grade;
}

std::string grading_summary(const nlohmann::json& grade) {
    std::string text = grade.value("passed", false) ? "PASS" : "FAIL";
    char counts[96];
    std::snprintf(counts, sizeof counts, " — %d/%d checks on the mean over %zu seeds",
                  grade.value("checks_passed", 0), grade.value("checks_total", 0),
                  grade.contains("seeds") ? grade["seeds"].size() : std::size_t{0});
    text += counts;
    if (grade.contains("checks")) {
        const char* separator = ": ";
        for (const nlohmann::json& check : grade["checks"]) {
            text += separator;
            text += check.value("passed", false) ? "✓ " : "✗ ";
            text += check.value("message", std::string{});
            separator = "; ";
        }
    }
    return text;
}

}  // namespace legofeup::lessons
