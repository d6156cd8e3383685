#pragma once
// What the arena's legend holds for a run: the rows every run has (truth, estimate, the
// other filter, odometry, ellipse, trail, maps, path) and, at their sections, the rows of
// the layers drawn for it (arena_layer.hpp).

#include <span>
#include <vector>

#include "legofeup/ui/arena/arena_colors.hpp"
#include "legofeup/ui/arena/arena_layer.hpp"
#include "legofeup/ui/arena/arena_legend.hpp"
#include "legofeup/ui/arena/covariance_ellipse.hpp"
#include "legofeup/ui/run_history.hpp"

namespace legofeup::ui {

/// The view's settings the legend follows.
struct LegendOptions {
    bool show_truth = true;
    bool show_odometry = true;
    bool show_trail = true;
    EllipseConfidence confidence = EllipseConfidence::OneSigma;
};

std::vector<LegendRow> arena_legend_rows(const RunHistory& history, const ArenaColors& colors,
                                         const LegendOptions& options,
                                         std::span<const ArenaLayer* const> layers);

}  // namespace legofeup::ui
