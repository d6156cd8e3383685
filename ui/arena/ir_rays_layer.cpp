// The LegoFeup lesson's layer (paper 000): the two IR rays from the estimate, coloured by
// whether this step's update used them, dashed to the trusted range when out of range.
#include "arena_text.hpp"
#include "legofeup/ui/arena/arena_layer.hpp"

namespace legofeup::ui {

namespace {

class IrRaysLayer final : public ArenaLayer {
  public:
    const char* name() const override { return "IR rays"; }

    void draw(ArenaStage stage, ArenaPainter& painter, const ArenaFrame& frame) const override {
        if (stage != ArenaStage::Measurements || frame.latest == nullptr) {
            return;
        }
        const ArenaScene& scene = frame.history.scene();
        painter.ir_rays(frame.latest->snapshot, scene.ir_mount, scene.ir_max_range);
    }

    void add_legend_rows(LegendSection section, const LegendContext& context,
                         std::vector<LegendRow>& rows) const override {
        if (section != LegendSection::Sensors) {
            return;
        }
        using Swatch = LegendEntry::Swatch;
        const ArenaColors& colors = context.colors;
        rows.push_back(
            {{Swatch::Band, colors.associated, arena_text::tr("IR rays used; the wall matched")}});
        rows.push_back({{Swatch::Line, colors.rejected, arena_text::tr("IR rays not used")},
                        {Swatch::Dashed, colors.out_of_range, arena_text::tr("out of range")}});
    }
};

}  // namespace

const ArenaLayer& ir_rays_layer() {
    static const IrRaysLayer layer;
    return layer;
}

}  // namespace legofeup::ui
