#pragma once
// The plots panel: one QCustomPlot per PlotKind (plot_series.hpp), time in seconds on x,
// grouped in tabs of two or three plots stacked in a splitter.
//
// It follows the RunHistory incrementally: samplesAppended adds only the new samples' points
// and queues one replot per visible plot (repaints coalesce into one per event-loop turn);
// hidden plots are replotted when they are shown, and keep no picture while hidden (one
// paint buffer per shown plot, none per hidden one: plots_panel.cpp's PanelPlot). The y
// axes rescale to the visible data without scanning the whole run: running extents for the
// whole-run view, a scan of the window's points (found by binary search) for the scrolling view. A
// view of more than kDenseView samples (the whole of a long run) is drawn lighter: the ±σ bands as
// outlines and the lines 1 px thinner, since filling a band through 36,000 samples costs the
// rasteriser ~30 ms a frame and wide antialiased lines half as much again.

#include <QBrush>
#include <QPen>
#include <QWidget>
#include <array>
#include <chrono>
#include <cstdint>
#include <optional>

#include "legofeup/ui/frame_stats.hpp"
#include "legofeup/ui/plots/plot_export.hpp"
#include "legofeup/ui/plots/plot_series.hpp"
#include "legofeup/ui/plots/value_range.hpp"
#include "legofeup/ui/run_history.hpp"

class QComboBox;
class QCustomPlot;
class QCPGraph;
class QCPItemStraightLine;
class QCPItemText;
class QTabWidget;

namespace legofeup::ui {

enum class BoundSide : int { Lower = 0, Upper = 1 };

class PlotsPanel : public QWidget {
    Q_OBJECT

  public:
    /// Samples in view above which a graph is drawn the light way (5 minutes at 20 Hz).
    static constexpr int kDenseView = 6000;

    explicit PlotsPanel(const RunHistory& history, QWidget* parent = nullptr);
    ~PlotsPanel() override;
    PlotsPanel(const PlotsPanel&) = delete;
    PlotsPanel& operator=(const PlotsPanel&) = delete;

    /// The plot of `kind` (owned by the panel; to show it alone, reparent it).
    QCustomPlot* plot(PlotKind kind) const;
    /// The graph drawing `series`.
    QCPGraph* graph(Series series) const;
    /// Whether the plot of `kind` is shown: always for the wall lesson's plots, once one of
    /// its series has a point for the further lessons' (PlotDefinition::optional).
    bool plotShown(PlotKind kind) const;
    /// The χ² 95 % bound lines of the Nis and Nees plots (nullptr for the other plots).
    QCPItemStraightLine* boundLine(PlotKind kind, BoundSide side) const;
    /// The height of reference line `index` (0 or 1) of the plot of `kind`: the χ² bounds,
    /// the IR's trusted range, the laser's min matched points and recovery threshold;
    /// nullopt when the plot has no such line.
    std::optional<double> referenceValue(PlotKind kind, int index) const;
    /// Whether the plots that need the truth (errors, NEES) say the run has none (a real
    /// robot): its latest sample came without truth.
    bool showsNoTruth() const { return no_truth_shown_; }

    /// The tab chosen last (by a click or setWantedTab()): shown whenever it has a plot.
    int wantedTab() const { return wanted_tab_; }
    /// Shows tab `index` now, or once it has data (a lesson's tab before its run starts).
    void setWantedTab(int index);

    /// Seconds of history shown; 0 = the whole run.
    double timeWindow() const { return time_window_; }
    double textScale() const { return text_scale_; }
    /// The duration of each frame: all plots replotted for one batch of samples.
    const FrameStats& frameStats() const { return frame_stats_; }

    /// Writes every plot into `directory` as <file stem>.png/.pdf/.svg (covariance.png,
    /// wheel_speeds.svg …) at `size` pixels, in the current colours. Never throws; the
    /// result lists the files written or says what failed.
    ExportResult exportPlots(const QString& directory, ExportFormats formats = kAllExportFormats,
                             QSize size = QSize(1200, 800));

  public slots:
    /// The history started over: clears every graph.
    void historyRestarted();
    /// Samples [first, first + count) were appended to the history: adds their points only.
    void samplesAppended(int first, int count);
    /// Shows the last `seconds` of the run, scrolling with the latest sample; 0 = all of it.
    void setTimeWindow(double seconds);
    /// Scales every plot text (ticks, labels, legends, titles): ~1.6 for a projector.
    void setTextScale(double scale);
    /// Takes the colours and font of the widget's palette (also done on a palette change).
    void applyPalette();

  protected:
    void changeEvent(QEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    QCustomPlot* buildPlot(PlotKind kind);
    void addReferenceLine(PlotKind kind, int index, double value, const QString& label);
    void moveReferenceLine(PlotKind kind, int index, double value, const QString& label);
    /// The laser plots' min_matched_points and recovery lines, from the history's scene.
    void moveLaserThresholds();
    void clearGraphs();
    void updateAxes();
    void updateAxes(PlotKind kind, double lower, double upper);
    ValueRange visibleValues(Series series, double lower, double upper) const;
    void lightenDenseGraphs(PlotKind kind, double lower, double upper);
    void requestReplots();
    void onBeforeReplot(PlotKind kind);
    void onAfterReplot();
    void showNoTruth(bool shown);
    /// Shows the optional plots that have data, and the tabs with a plot shown.
    void showPresentPlots();

    const RunHistory& history_;
    std::uint64_t epoch_ = 0;
    std::size_t taken_ = 0;  ///< samples of the history already in the graphs
    double first_time_ = 0.0;
    double last_time_ = 0.0;
    double time_window_ = 0.0;
    double text_scale_ = 1.0;

    QTabWidget* tabs_ = nullptr;
    QComboBox* window_choice_ = nullptr;
    std::array<QCustomPlot*, kPlotKindCount> plots_{};
    std::array<QCPGraph*, kSeriesCount> graphs_{};
    std::array<ValueRange, kSeriesCount> extents_{};  ///< every value since the restart
    std::array<double, kSeriesCount> smoothed_{};     ///< SeriesDefinition::smoothing's state
    std::array<bool, kSeriesCount> has_points_{};     ///< a point since the restart
    /// Each graph's pen and fill from the look, used while few enough points are in view.
    std::array<QPen, kSeriesCount> pens_{};
    std::array<QBrush, kSeriesCount> brushes_{};
    /// Horizontal reference lines with their labels: the χ² bounds, the IR trusted range,
    /// the laser's min_matched_points and recovery threshold.
    struct ReferenceLine {
        QCPItemStraightLine* line = nullptr;
        QCPItemText* label = nullptr;
        double value = 0.0;
    };
    std::array<std::array<ReferenceLine, 2>, kPlotKindCount> references_{};
    /// "No ground truth" on the plots that need it; nullptr on the others.
    std::array<QCPItemText*, kPlotKindCount> no_truth_{};
    bool no_truth_shown_ = false;
    int wanted_tab_ = 0;

    std::array<bool, kPlotKindCount> replot_pending_{};  ///< queued, not yet run
    std::chrono::steady_clock::time_point replot_started_;
    std::chrono::nanoseconds frame_time_{0};
    FrameStats frame_stats_;
};

}  // namespace legofeup::ui
