// Check expressions: parsing them (with the reason when they do not parse) and evaluating
// them against a run's metrics.
#include "metric_check.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <vector>

#include "legofeup/lessons/run_summary.hpp"
#include "toml_values.hpp"

namespace legofeup::lessons {
namespace {

constexpr const char* kForms =
    "write `METRIC < NUMBER` (or <=, >, >=), `METRIC within BOUNDS_METRIC`, or the name of a "
    "true/false METRIC";

std::string trim(std::string_view text) {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string_view::npos) {
        return {};
    }
    const auto last = text.find_last_not_of(" \t");
    return std::string(text.substr(first, last - first + 1));
}

std::optional<double> number_in(const std::string& text) {
    if (text.empty()) {
        return std::nullopt;
    }
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || !std::isfinite(value)) {
        return std::nullopt;
    }
    return value;
}

bool is_word(const std::string& text) {
    if (text.empty()) {
        return false;
    }
    for (const char c : text) {
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) {
            return false;
        }
    }
    return true;
}

std::string unknown_metric(const std::string& name) {
    const std::string match = closest_match(name, known_metrics());
    return "no metric '" + name + "'" + (match.empty() ? "" : " (did you mean '" + match + "'?)")
           + "; the metrics are the keys of summary.json's \"metrics\" (docs/lessons.md)";
}

std::string bounds_metrics() {
    std::string list;
    for (const std::string& name : known_metrics()) {
        if (metric_kind(name) == MetricKind::Bounds) {
            list += (list.empty() ? "" : ", ") + name;
        }
    }
    return list;
}

// The left-hand metric of a comparison: a number or a true/false value.
std::string comparable_problem(const std::string& metric) {
    if (!is_word(metric)) {
        return std::string("expected a metric name before the operator; ") + kForms;
    }
    switch (metric_kind(metric)) {
        case MetricKind::Unknown:
            return unknown_metric(metric);
        case MetricKind::Bounds:
            return "'" + metric + "' is a pair of bounds: use it on the right of `within`";
        case MetricKind::Number:
        case MetricKind::Boolean:
            break;
    }
    return {};
}

// The right-hand side of `within`: a metric holding [lower, upper].
std::string bounds_problem(const std::string& name) {
    switch (metric_kind(name)) {
        case MetricKind::Bounds:
            return {};
        case MetricKind::Unknown:
            return is_word(name) ? unknown_metric(name)
                                 : "expected a bounds metric after `within`, e.g. "
                                   "time_average_nees_95_bounds";
        case MetricKind::Number:
        case MetricKind::Boolean:
            break;
    }
    return "'" + name + "' is not a pair of bounds (those are: " + bounds_metrics() + ")";
}

/// A bounds metric made for another statistic than the one it would judge.
struct WrongPairing {
    const char* metric;
    const char* bounds;
    const char* why;
};

// The bounds of one step's NEES are far wider than those of the NEES averaged over a run's
// steps (or over seeds): a pessimistic (mean NEES 0.3) or an overconfident filter passes them.
constexpr WrongPairing kWrongPairings[] = {
    {"mean_nees", "nees_95_bounds",
     "nees_95_bounds are the bounds of one step's NEES, far wider than those of mean_nees, a "
     "time average: write `mean_nees within time_average_nees_95_bounds` (docs/lessons.md)"},
};

std::string pairing_problem(const std::string& metric, const std::string& bounds) {
    for (const WrongPairing& pairing : kWrongPairings) {
        if (metric == pairing.metric && bounds == pairing.bounds) {
            return pairing.why;
        }
    }
    return {};
}

struct Operator {
    const char* symbol;
    MetricCheck::Op op;
};

// Longest symbols first, so "<=" is not read as "<".
constexpr Operator kOperators[] = {{"<=", MetricCheck::Op::LessOrEqual},
                                   {">=", MetricCheck::Op::GreaterOrEqual},
                                   {"<", MetricCheck::Op::Less},
                                   {">", MetricCheck::Op::Greater}};

const char* symbol_of(MetricCheck::Op op) {
    for (const Operator& candidate : kOperators) {
        if (candidate.op == op) {
            return candidate.symbol;
        }
    }
    return "within";
}

ParsedCheck parse_comparison(const std::string& text, std::size_t at, const Operator& op) {
    ParsedCheck parsed;
    parsed.check.expression = text;
    parsed.check.op = op.op;
    parsed.check.metric = trim(std::string_view(text).substr(0, at));
    const std::string right = trim(std::string_view(text).substr(at + std::strlen(op.symbol)));
    parsed.problem = comparable_problem(parsed.check.metric);
    if (!parsed.problem.empty()) {
        return parsed;
    }
    if (const auto threshold = number_in(right)) {
        parsed.check.threshold = *threshold;
    } else {
        parsed.problem = "'" + right + "' after " + op.symbol + " is not a number";
    }
    return parsed;
}

ParsedCheck parse_words(const std::string& text) {
    ParsedCheck parsed;
    parsed.check.expression = text;
    std::vector<std::string> words;
    for (std::size_t at = 0; at < text.size();) {
        const auto start = text.find_first_not_of(" \t", at);
        if (start == std::string::npos) {
            break;
        }
        const auto end = std::min(text.find_first_of(" \t", start), text.size());
        words.push_back(text.substr(start, end - start));
        at = end;
    }
    if (words.size() == 1) {
        // A bare true/false metric: it must be true (its mean over seeds must be 1).
        parsed.check.metric = words[0];
        parsed.check.op = MetricCheck::Op::GreaterOrEqual;
        parsed.check.threshold = 1.0;
        parsed.problem = comparable_problem(words[0]);
        if (parsed.problem.empty() && metric_kind(words[0]) != MetricKind::Boolean) {
            parsed.problem = "'" + words[0] + "' is a number, not true/false: compare it, e.g. `"
                             + words[0] + " < 0.1`";
        }
        return parsed;
    }
    if (words.size() != 3 || words[1] != "within") {
        parsed.problem = std::string("cannot read this check; ") + kForms;
        return parsed;
    }
    parsed.check.metric = words[0];
    parsed.check.op = MetricCheck::Op::Within;
    parsed.check.bounds_metric = words[2];
    parsed.problem = comparable_problem(words[0]);
    if (parsed.problem.empty()) {
        parsed.problem = bounds_problem(words[2]);
    }
    if (parsed.problem.empty()) {
        parsed.problem = pairing_problem(words[0], words[2]);
    }
    return parsed;
}

std::string format_number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

// The metric as a number (true/false as 1/0), or nothing when absent or not a number.
std::optional<double> value_of(const nlohmann::json& metrics, const std::string& name) {
    if (!metrics.is_object()) {
        return std::nullopt;
    }
    const auto found = metrics.find(name);
    if (found == metrics.end()) {
        return std::nullopt;
    }
    if (found->is_boolean()) {
        return found->get<bool>() ? 1.0 : 0.0;
    }
    if (found->is_number()) {
        return found->get<double>();
    }
    return std::nullopt;
}

std::optional<std::pair<double, double>> bounds_of(const nlohmann::json& metrics,
                                                   const std::string& name) {
    if (!metrics.is_object()) {
        return std::nullopt;
    }
    const auto found = metrics.find(name);
    if (found == metrics.end() || !found->is_array() || found->size() != 2
        || !(*found)[0].is_number() || !(*found)[1].is_number()) {
        return std::nullopt;
    }
    return std::pair((*found)[0].get<double>(), (*found)[1].get<double>());
}

/// Why a metric has no value, after its name: null means the run could not measure it.
std::string absent_because(const nlohmann::json& metrics, const std::string& name) {
    const bool null = metrics.is_object() && metrics.contains(name) && metrics[name].is_null();
    if (null && is_truth_metric(name)) {
        return " needs the ground truth, which this run did not have (a link without truth)";
    }
    return null ? " has no value in this run" : " is not among the run's metrics";
}

CheckResult evaluate(const MetricCheck& check, const nlohmann::json& metrics) {
    CheckResult result{check, false, std::numeric_limits<double>::quiet_NaN(), {}};
    const auto value = value_of(metrics, check.metric);
    if (!value) {
        result.message = check.metric + absent_because(metrics, check.metric) + ": failed";
        return result;
    }
    result.actual = *value;
    const std::string left = check.metric + " = " + format_number(*value);
    if (check.op == MetricCheck::Op::Within) {
        const auto bounds = bounds_of(metrics, check.bounds_metric);
        if (!bounds) {
            result.message = left + ", but " + check.bounds_metric
                             + absent_because(metrics, check.bounds_metric) + ": failed";
            return result;
        }
        result.passed = *value >= bounds->first && *value <= bounds->second;
        result.message = left + " within " + check.bounds_metric + " ["
                         + format_number(bounds->first) + ", " + format_number(bounds->second)
                         + "]";
    } else {
        switch (check.op) {
            case MetricCheck::Op::Less:
                result.passed = *value < check.threshold;
                break;
            case MetricCheck::Op::LessOrEqual:
                result.passed = *value <= check.threshold;
                break;
            case MetricCheck::Op::Greater:
                result.passed = *value > check.threshold;
                break;
            case MetricCheck::Op::GreaterOrEqual:
            case MetricCheck::Op::Within:
                result.passed = *value >= check.threshold;
                break;
        }
        result.message = left + " " + symbol_of(check.op) + " " + format_number(check.threshold);
    }
    result.message += result.passed ? ": passed" : ": failed";
    return result;
}

}  // namespace

ParsedCheck parse_check_expression(std::string_view expression) {
    const std::string text = trim(expression);
    for (const Operator& op : kOperators) {
        if (const auto at = text.find(op.symbol); at != std::string::npos) {
            return parse_comparison(text, at, op);
        }
    }
    return parse_words(text);
}

std::vector<CheckResult> evaluate_checks(const std::vector<MetricCheck>& checks,
                                         const nlohmann::json& metrics) {
    std::vector<CheckResult> results;
    results.reserve(checks.size());
    for (const MetricCheck& check : checks) {
        results.push_back(evaluate(check, metrics));
    }
    return results;
}

}  // namespace legofeup::lessons
