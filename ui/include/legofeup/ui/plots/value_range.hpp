#pragma once
// The extent of a series' values, kept up to date as points arrive, so the y axes of the
// whole-run view rescale without scanning the run again every frame.

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace legofeup::ui {

struct ValueRange {
    double min = std::numeric_limits<double>::infinity();
    double max = -std::numeric_limits<double>::infinity();
    /// The smallest value > 0: the lower end of a logarithmic axis.
    double min_positive = std::numeric_limits<double>::infinity();

    /// Takes one value in; NaN and ±∞ (gaps) are skipped.
    void include(double value) {
        if (!std::isfinite(value)) {
            return;
        }
        min = std::min(min, value);
        max = std::max(max, value);
        if (value > 0.0) {
            min_positive = std::min(min_positive, value);
        }
    }
    void include(const ValueRange& other) {
        min = std::min(min, other.min);
        max = std::max(max, other.max);
        min_positive = std::min(min_positive, other.min_positive);
    }
    bool empty() const { return min > max; }
    bool has_positive() const { return std::isfinite(min_positive); }
};

struct AxisSpan {
    double lower = 0.0;
    double upper = 1.0;
};

/// The axis range that shows `values` with a margin: 5 % of the span on a linear axis, 5 %
/// of the decades on a logarithmic one (values ≤ 0 ignored there). A single value gets a
/// small span around it. Nothing to show: nullopt.
inline std::optional<AxisSpan> padded_span(const ValueRange& values, bool logarithmic) {
    if (logarithmic) {
        if (!values.has_positive()) {
            return std::nullopt;
        }
        const double lo = std::log10(values.min_positive);
        const double hi = std::log10(std::max(values.max, values.min_positive));
        const double margin = std::max(0.05 * (hi - lo), 0.1);
        return AxisSpan{std::pow(10.0, lo - margin), std::pow(10.0, hi + margin)};
    }
    if (values.empty()) {
        return std::nullopt;
    }
    const double extent = values.max - values.min;
    const double margin = extent > 0.0 ? 0.05 * extent : std::max(0.1 * std::abs(values.max), 1e-3);
    return AxisSpan{values.min - margin, values.max + margin};
}

}  // namespace legofeup::ui
