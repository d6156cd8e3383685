// The beacon lesson's layer (paper 002): each beacon as a diamond with its id, and this
// step's bearings from the estimate, measured (applied or not) and expected.
#include "arena_text.hpp"
#include "legofeup/ui/arena/arena_layer.hpp"

namespace legofeup::ui {

namespace {

class BeaconsLayer final : public ArenaLayer {
  public:
    const char* name() const override { return "beacons"; }

    void draw(ArenaStage stage, ArenaPainter& painter, const ArenaFrame& frame) const override {
        const BeaconMap& beacons = frame.history.scene().beacons;
        if (beacons.empty()) {
            return;
        }
        if (stage == ArenaStage::Marks) {
            painter.beacons(beacons);
        } else if (stage == ArenaStage::Measurements && frame.latest != nullptr) {
            painter.beacon_rays(frame.latest->snapshot, beacons);
        }
    }

    void add_legend_rows(LegendSection section, const LegendContext& context,
                         std::vector<LegendRow>& rows) const override {
        if (section != LegendSection::Sensors || context.scene.beacons.empty()) {
            return;
        }
        using Swatch = LegendEntry::Swatch;
        const ArenaColors& colors = context.colors;
        rows.push_back({{Swatch::Diamond, colors.beacon, arena_text::tr("beacons")}});
        rows.push_back(
            {{Swatch::Line, colors.associated, arena_text::tr("bearings measured, applied")},
             {Swatch::Line, colors.rejected, arena_text::tr("not applied")}});
        rows.push_back(
            {{Swatch::Dashed, colors.foreground, arena_text::tr("bearings the filter expected")}});
    }
};

}  // namespace

const ArenaLayer& beacons_layer() {
    static const BeaconsLayer layer;
    return layer;
}

}  // namespace legofeup::ui
