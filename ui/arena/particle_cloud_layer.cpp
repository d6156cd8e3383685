// The particle filter's layer (filter.kind = "pf"): the cloud of the latest step as dots under
// the robots, a particle's weight as its dot's opacity. The cloud comes thinned
// (RunSample::particles: at most kParticlesShown points, particle_cloud.hpp), and the dots go
// out in four drawPoints calls, one per opacity band, so 10,000 particles cost what 1,000
// dots cost (ui_arena_bench measures it).
#include <array>

#include "arena_drawing.hpp"
#include "arena_text.hpp"
#include "legofeup/ui/arena/arena_layer.hpp"
#include "legofeup/ui/arena/arena_sizes.hpp"

namespace legofeup::ui {

namespace {

/// The opacity bands: a point of relative weight w (1 for the heaviest) falls in the first
/// band whose lower edge it reaches; its dots are drawn at the band's alpha. The faintest
/// band stays visible, as a particle the filter keeps is a place it still considers.
struct OpacityBand {
    float lowest_weight;
    int alpha;
};
constexpr std::array<OpacityBand, 4> kOpacityBands{{
    {0.75F, 255},
    {0.5F, 190},
    {0.25F, 130},
    {0.0F, 70},
}};

class ParticleCloudLayer final : public ArenaLayer {
  public:
    const char* name() const override { return "particle cloud"; }

    void draw(ArenaStage stage, ArenaPainter& painter, const ArenaFrame& frame) const override {
        if (stage != ArenaStage::Marks || frame.latest == nullptr || !frame.latest->particles) {
            return;
        }
        std::array<QPolygonF, kOpacityBands.size()> bands;
        for (QPolygonF& band : bands) {
            band.reserve(static_cast<qsizetype>(frame.latest->particles->size()));
        }
        for (const ParticlePoint& point : *frame.latest->particles) {
            std::size_t band = 0;
            while (band + 1 < kOpacityBands.size()
                   && point.weight < kOpacityBands[band].lowest_weight) {
                ++band;
            }
            bands[band].append(QPointF(widen(point.x), widen(point.y)));
        }
        // Faintest first, so the heavy particles sit on top.
        for (std::size_t band = bands.size(); band-- > 0;) {
            painter.scan_points(
                bands[band],
                arena_drawing::with_alpha(frame.style.colors.particles, kOpacityBands[band].alpha),
                kArenaSizes.particle_dot);
        }
    }

    void add_legend_rows(LegendSection section, const LegendContext& context,
                         std::vector<LegendRow>& rows) const override {
        if (section != LegendSection::Sensors || context.latest == nullptr
            || context.latest->particles.count == 0) {
            return;
        }
        rows.push_back({{LegendEntry::Swatch::Dots, context.colors.particles,
                         arena_text::tr("particles: the fainter, the less weight")}});
    }
};

}  // namespace

const ArenaLayer& particle_cloud_layer() {
    static const ParticleCloudLayer layer;
    return layer;
}

}  // namespace legofeup::ui
