#pragma once
// A lesson's drawing in the arena: a layer. The arena draws what every run has (grid, map,
// walls, paths, robots, estimate, ellipse, legend) and, at fixed stages between those, the
// layers registered for the run's localisation (arena_layers.hpp). A layer also adds its
// rows to the legend, at fixed places among the common rows.
//
// Layers hold no state: what they draw comes from the frame (the history and the style).

#include <QRectF>
#include <vector>

#include "legofeup/ui/arena/arena_colors.hpp"
#include "legofeup/ui/arena/arena_legend.hpp"
#include "legofeup/ui/arena/arena_painter.hpp"
#include "legofeup/ui/run_history.hpp"

namespace legofeup::ui {

/// When a layer draws, in the order a frame is painted.
enum class ArenaStage {
    /// In the world over the paths, under the robots (scans, beacons); also before the
    /// first sample.
    Marks,
    /// This step's measurements, over the robots and under the estimate (IR or bearing
    /// rays); only once there is a sample.
    Measurements,
    /// Texts in widget pixels after the estimate's labels, before the legend.
    Labels,
};

/// Where a layer's legend rows go among the common ones.
enum class LegendSection {
    Sensors,  ///< after the estimate's rows (the ellipse, the trail), before the maps'
    Scans,    ///< after the maps' rows, before the intended path's
};

/// What a layer draws one frame from.
struct ArenaFrame {
    const RunHistory& history;
    const RunSample* latest;  ///< null before the first sample
    const ArenaStyle& style;
    QRectF widget;      ///< the whole widget, widget pixels
    QRectF legend_box;  ///< the legend (or its tab) as drawn; empty when hidden
    bool show_truth = true;
};

/// What a layer's legend rows depend on.
struct LegendContext {
    const ArenaColors& colors;
    const ArenaScene& scene;
    const LoopSnapshot* latest;  ///< null before the first sample
    bool truth_shown = true;     ///< the truth is drawn (shown, and the run has it)
};

class ArenaLayer {
  public:
    virtual ~ArenaLayer() = default;
    /// A short name for tests and messages ("IR rays").
    virtual const char* name() const = 0;
    virtual void draw(ArenaStage stage, ArenaPainter& painter, const ArenaFrame& frame) const = 0;
    virtual void add_legend_rows(LegendSection section, const LegendContext& context,
                                 std::vector<LegendRow>& rows) const = 0;
};

}  // namespace legofeup::ui
