#pragma once
// The re-filter dialog's table: the metrics of the replay with the recorded settings and with
// the new ones side by side, one row per figure students compare.

#include <optional>

#include "legofeup/core/run_metrics.hpp"

class QTableWidget;

namespace legofeup::ui {

/// Fills `table` (two columns: recorded settings, new settings); empty cells before a
/// re-filter (nullopt). The rows that need the truth say so in a log without one (a real
/// robot); the counts are shown all the same.
void show_refilter_metrics(QTableWidget& table, const std::optional<RunMetrics>& old_metrics,
                           const std::optional<RunMetrics>& new_metrics);

}  // namespace legofeup::ui
