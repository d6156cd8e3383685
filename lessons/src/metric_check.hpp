#pragma once
// Reading a lesson's check expressions ("final_position_error_m > 0.2", "mean_nees within
// nees_95_bounds", "routine_finished") and the kinds of metric they may name. Private to
// lessons/.

#include <cstdint>
#include <string>
#include <string_view>

#include "legofeup/lessons/lesson.hpp"

namespace legofeup::lessons {

/// What a key of summary.json's "metrics" holds, as far as a check is concerned.
enum class MetricKind : std::uint8_t {
    Unknown,  ///< no such metric, or one a check cannot use (the association counts)
    Number,
    Boolean,  ///< true/false; counts as 1/0
    Bounds,   ///< [lower, upper], the right-hand side of "within"
};

MetricKind metric_kind(std::string_view name);

/// An expression parsed into `check` (its metric, operator, threshold or bounds metric and
/// the expression itself), or the reason it does not parse or names no usable metric.
struct ParsedCheck {
    MetricCheck check;
    std::string problem;  ///< empty when the expression is good
};

ParsedCheck parse_check_expression(std::string_view expression);

}  // namespace legofeup::lessons
