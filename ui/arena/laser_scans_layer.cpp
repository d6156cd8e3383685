// The laser lesson's layer (paper 001): the latest scan at the estimated scanner pose, the
// scan the filter expected and the scan at the true pose as dots, and the scan matching's
// status in the top-left corner. (The map is the world's, drawn for every run.)
#include <QFontMetricsF>

#include "arena_text.hpp"
#include "legofeup/ui/arena/arena_layer.hpp"
#include "legofeup/ui/arena/arena_sizes.hpp"
#include "legofeup/ui/arena/laser_layer.hpp"

namespace legofeup::ui {

namespace {

class LaserScansLayer final : public ArenaLayer {
  public:
    const char* name() const override { return "laser scans"; }

    void draw(ArenaStage stage, ArenaPainter& painter, const ArenaFrame& frame) const override {
        if (stage == ArenaStage::Marks) {
            draw_scans(painter, frame);
        } else if (stage == ArenaStage::Labels) {
            draw_status(painter, frame);
        }
    }

    void add_legend_rows(LegendSection section, const LegendContext& context,
                         std::vector<LegendRow>& rows) const override {
        if (section != LegendSection::Scans || !context.scene.laser.active) {
            return;
        }
        using Swatch = LegendEntry::Swatch;
        const ArenaColors& colors = context.colors;
        rows.push_back(
            {{Swatch::Dots, colors.associated, arena_text::tr("scan at the estimate: matched")},
             {Swatch::Dots, colors.rejected, arena_text::tr("mismatch")}});
        LegendRow expected{
            {Swatch::Dots, colors.expected_scan, arena_text::tr("expected (ray-cast)")}};
        if (context.truth_shown) {
            expected.push_back(
                {Swatch::Dots, colors.truth_scan, arena_text::tr("scan at the true pose")});
        }
        rows.push_back(expected);
    }

  private:
    static void draw_scans(ArenaPainter& painter, const ArenaFrame& frame) {
        const ArenaColors& colors = frame.style.colors;
        const LaserScanPoints scan = latest_laser_scan_points(frame.history);
        painter.scan_points(scan.expected, colors.expected_scan, kArenaSizes.scan_dot);
        if (frame.show_truth) {
            painter.scan_points(scan.measured_at_truth, colors.truth_scan,
                                kArenaSizes.truth_scan_dot);
        }
        painter.scan_points(scan.measured, scan.matched ? colors.associated : colors.rejected,
                            kArenaSizes.scan_dot);
    }

    /// Top left, clear of the scale bar (bottom left); below the legend when the legend is a
    /// strip across the top.
    static void draw_status(ArenaPainter& painter, const ArenaFrame& frame) {
        const QString status = latest_laser_status_text(frame.history);
        if (status.isEmpty()) {
            return;
        }
        const LaserUpdate& laser = latest_scan_sample(frame.history)->snapshot.laser;
        const QColor color =
            laser.matched ? frame.style.colors.associated : frame.style.colors.rejected;
        const QFontMetricsF metrics(frame.style.font);
        const QSizeF size(metrics.horizontalAdvance(status) + kArenaSizes.status_padding.width(),
                          metrics.height() + kArenaSizes.status_padding.height());
        const double left = kArenaSizes.corner_inset;
        double top = kArenaSizes.corner_inset;
        if (const QRectF& legend = frame.legend_box;
            !legend.isEmpty() && legend.intersects(QRectF(QPointF(left, top), size))) {
            top = legend.bottom() + kArenaSizes.status_below_legend;
        }
        painter.label(QPointF(left, top + size.height()), status, color);
    }
};

}  // namespace

const ArenaLayer& laser_scans_layer() {
    static const LaserScansLayer layer;
    return layer;
}

}  // namespace legofeup::ui
