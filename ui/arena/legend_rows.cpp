#include "legofeup/ui/arena/legend_rows.hpp"

#include "arena_text.hpp"

namespace legofeup::ui {

namespace {

using Swatch = LegendEntry::Swatch;

void add_layer_rows(std::span<const ArenaLayer* const> layers, LegendSection section,
                    const LegendContext& context, std::vector<LegendRow>& rows) {
    for (const ArenaLayer* layer : layers) {
        layer->add_legend_rows(section, context, rows);
    }
}

}  // namespace

std::vector<LegendRow> arena_legend_rows(const RunHistory& history, const ArenaColors& colors,
                                         const LegendOptions& options,
                                         std::span<const ArenaLayer* const> layers) {
    using arena_text::tr;
    const ArenaScene& scene = history.scene();
    // Before the first sample, assume the run will have truth (so the fit leaves room).
    const bool truth = history.empty() || history.latest().truth.has_value();
    const LoopSnapshot* latest = history.empty() ? nullptr : &history.latest().snapshot;
    const LegendContext context{colors, scene, latest, options.show_truth && truth};
    std::vector<LegendRow> legend;
    if (context.truth_shown) {
        legend.push_back({{Swatch::Line, colors.truth, tr("true robot")}});
    }
    legend.push_back({{Swatch::Line, colors.estimate,
                       tr("estimate (%1)")
                           .arg(latest != nullptr ? arena_text::estimator_text(latest->localisation,
                                                                               latest->filter_kind)
                                                  : arena_text::kind_text(FilterKind::Ekf))}});
    if (latest != nullptr && latest->shadow.active) {
        legend.push_back({{Swatch::DashedEllipse, colors.shadow,
                           tr("%1 on the same frames, its ellipse dashed")
                               .arg(arena_text::kind_text(latest->shadow.kind))}});
    }
    if (options.show_odometry) {
        legend.push_back({{Swatch::Line, colors.odometry, tr("odometry only (ghost dashed)")}});
    }
    legend.push_back({{Swatch::Ellipse, colors.ellipse,
                       QString::fromUtf8(confidence_note(options.confidence))}});
    if (options.show_trail) {
        legend.push_back({{Swatch::Line, colors.trail, tr("past ellipses, one per second")}});
    }
    add_layer_rows(layers, LegendSection::Sensors, context, legend);
    if (scene.map) {
        legend.push_back({{Swatch::Box, colors.map_occupied, tr("map: occupied")},
                          {Swatch::Box, colors.map_unknown, tr("unknown")}});
    }
    if (scene.filter_map) {
        legend.push_back({{Swatch::Box, colors.filter_map, tr("the filter's map (outdated)")}});
    }
    add_layer_rows(layers, LegendSection::Scans, context, legend);
    if (!scene.path.empty()) {
        legend.push_back({{Swatch::Dashed, colors.path, tr("intended path")}});
    }
    return legend;
}

}  // namespace legofeup::ui
