#include "legofeup/ui/plots/plots_panel.hpp"

#include <qcustomplot.h>
#include <QComboBox>
#include <QEvent>
#include <QHideEvent>
#include <QResizeEvent>
#include <QSplitter>
#include <QTabWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "legofeup/ui/plots/plot_style.hpp"

namespace legofeup::ui {

namespace {

struct Tab {
    const char* title;
    std::vector<PlotKind> plots;
};

/// The tabs: what a student compares side by side.
std::vector<Tab> tabs() {
    return {
        {"Estimate", {PlotKind::Covariance, PlotKind::PositionError, PlotKind::HeadingError}},
        {"Commands && sensors", {PlotKind::WheelSpeeds, PlotKind::IrDistances}},
        {"Consistency", {PlotKind::Nis, PlotKind::Nees}},
        // The further lessons': each tab and plot appears once the run has its data.
        {"Beacons && filters", {PlotKind::Bearings, PlotKind::ShadowError, PlotKind::FilterCost}},
        {"Heading && speed sensors",
         {PlotKind::HeadingSensors, PlotKind::TurnRate, PlotKind::WheelSpeedEstimates}},
        {"Laser scan matching",
         {PlotKind::LaserMatches, PlotKind::LaserMismatches, PlotKind::LaserInnovation}},
        {"Particle filter", {PlotKind::Particles}},
    };
}

struct WindowChoice {
    const char* label;
    double seconds;
};
constexpr WindowChoice kWindowChoices[] = {
    {"Last 30 s", 30.0}, {"Last 60 s", 60.0}, {"Last 2 min", 120.0}, {"Whole run", 0.0}};

std::size_t index_of(PlotKind kind) {
    return static_cast<std::size_t>(kind);
}
std::size_t index_of(Series series) {
    return static_cast<std::size_t>(series);
}

QString bound_label(int dof, const char* percent, double value) {
    return QStringLiteral("χ²(%1) %2 %: %3")
        .arg(dof)
        .arg(QLatin1String(percent))
        .arg(value, 0, 'g', 3);
}

QString ir_range_label(double range) {
    return QStringLiteral("trusted range %1 m").arg(range, 0, 'f', 2);
}

QString min_matched_label(int points) {
    return QStringLiteral("min matched points %1: fewer is a mismatch").arg(points);
}

QString recovery_label(const LaserScene& laser) {
    return laser.kidnap_recovery
               ? QStringLiteral("recovery after %1").arg(laser.recovery_after_mismatches)
               : QStringLiteral("recovery off (would be after %1)")
                     .arg(laser.recovery_after_mismatches);
}

/// A plot of the panel, which keeps its picture only while it is shown: one paint buffer of
/// its size (the overlay layer, which nothing here draws on, shares the plot's buffer instead
/// of one of its own), and none while hidden. A buffer is 1.2 MB at 1200 × 260; of the 16
/// plots only a tab's two or three are ever shown at once, and QCustomPlot would otherwise
/// keep two buffers for each plot it ever replotted, hidden tabs' included.
class PanelPlot final : public QCustomPlot {
  public:
    PanelPlot() {
        if (QCPLayer* overlay = layer(QStringLiteral("overlay"))) {
            overlay->setMode(QCPLayer::lmLogical);
        }
        // A replot while hidden (QCustomPlot queues one of its own when it is made) leaves no
        // buffer behind; the next one, once shown, makes it again.
        connect(this, &QCustomPlot::afterReplot, this, [this] {
            if (!isVisible()) {
                dropBuffers();
            }
        });
    }

  protected:
    void showEvent(QShowEvent* event) override {
        QCustomPlot::showEvent(event);
        if (mPaintBuffers.isEmpty()) {
            replot(rpQueuedRefresh);  // now, before the first paint: no blank frame
        }
    }
    void hideEvent(QHideEvent* event) override {
        QCustomPlot::hideEvent(event);
        dropBuffers();
    }
    void resizeEvent(QResizeEvent* event) override {
        if (isVisible()) {
            QCustomPlot::resizeEvent(event);  // replots into buffers of the new size
        } else {
            setViewport(rect());  // replotted when shown
        }
    }

  private:
    void dropBuffers() { mPaintBuffers.clear(); }
};

}  // namespace

PlotsPanel::PlotsPanel(const RunHistory& history, QWidget* parent)
    : QWidget(parent), history_(history), epoch_(history.epoch()) {
    tabs_ = new QTabWidget(this);
    tabs_->setDocumentMode(true);
    for (const Tab& tab : tabs()) {
        auto* splitter = new QSplitter(Qt::Vertical);
        splitter->setChildrenCollapsible(false);
        for (PlotKind kind : tab.plots) {
            splitter->addWidget(buildPlot(kind));
        }
        tabs_->addTab(splitter, QString::fromUtf8(tab.title));  // "&&" shows one '&'
    }

    window_choice_ = new QComboBox(tabs_);
    window_choice_->setToolTip(tr("Time shown on the plots"));
    for (const WindowChoice& choice : kWindowChoices) {
        window_choice_->addItem(tr(choice.label), choice.seconds);
    }
    window_choice_->setCurrentIndex(window_choice_->findData(time_window_));
    connect(window_choice_, &QComboBox::currentIndexChanged, this,
            [this](int index) { setTimeWindow(window_choice_->itemData(index).toDouble()); });
    tabs_->setCornerWidget(window_choice_, Qt::TopRightCorner);
    connect(tabs_, &QTabWidget::tabBarClicked, this, [this](int index) {
        if (index >= 0) {
            wanted_tab_ = index;
        }
    });

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(tabs_);
    showPresentPlots();

    applyPalette();
    historyRestarted();
    if (!history_.empty()) {
        samplesAppended(0, static_cast<int>(history_.size()));
    }
}

PlotsPanel::~PlotsPanel() = default;

QCustomPlot* PlotsPanel::buildPlot(PlotKind kind) {
    const PlotDefinition& definition = plot_definition(kind);
    auto* plot = new PanelPlot;
    plots_[index_of(kind)] = plot;
    plot->setObjectName(QString::fromUtf8(definition.file_stem));
    plot->setMinimumSize(240, 150);
    plot->setPlottingHint(QCP::phFastPolylines, true);
    plot->installEventFilter(this);

    add_header(*plot, QString::fromUtf8(definition.title));

    plot->xAxis->setLabel(tr("t (s)"));
    plot->yAxis->setLabel(QString::fromUtf8(definition.y_label));
    plot->xAxis2->setVisible(true);
    plot->yAxis2->setVisible(true);
    plot->xAxis2->setTicks(false);
    plot->yAxis2->setTicks(false);
    plot->xAxis2->setTickLabels(false);
    plot->yAxis2->setTickLabels(false);
    if (definition.log_y) {
        plot->yAxis->setScaleType(QCPAxis::stLogarithmic);
        plot->yAxis2->setScaleType(QCPAxis::stLogarithmic);
        plot->yAxis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
        plot->yAxis->setNumberFormat(QStringLiteral("eb"));
        plot->yAxis->setNumberPrecision(0);
        plot->yAxis->grid()->setSubGridVisible(true);
        plot->yAxis->setRange(1e-3, 1e1);
    }

    for (const SeriesDefinition& series : series_definitions()) {
        if (series.plot != kind) {
            continue;
        }
        QCPGraph* graph = plot->addGraph();
        graph->setName(QString::fromUtf8(series.name));
        graphs_[index_of(series.series)] = graph;
        if (series.look == SeriesLook::BandEdge) {
            graph->removeFromLegend();
        }
    }
    for (const SeriesDefinition& series : series_definitions()) {
        if (series.plot == kind && series.look == SeriesLook::Band) {
            graphs_[index_of(series.series)]->setChannelFillGraph(
                graphs_[index_of(series.fill_to)]);
        }
    }

    if (definition.chi_square_dof > 0) {
        const ChiSquareInterval bounds = consistency_bounds(definition.chi_square_dof);
        addReferenceLine(kind, static_cast<int>(BoundSide::Lower), bounds.lower,
                         bound_label(definition.chi_square_dof, "2.5", bounds.lower));
        addReferenceLine(kind, static_cast<int>(BoundSide::Upper), bounds.upper,
                         bound_label(definition.chi_square_dof, "97.5", bounds.upper));
    }
    if (kind == PlotKind::IrDistances) {
        const double range = history_.scene().ir_max_range;
        addReferenceLine(kind, 0, range, ir_range_label(range));
    }
    const LaserScene& laser = history_.scene().laser;
    if (kind == PlotKind::LaserMatches) {
        addReferenceLine(kind, 0, laser.min_matched_points,
                         min_matched_label(laser.min_matched_points));
    }
    if (kind == PlotKind::LaserMismatches) {
        addReferenceLine(kind, 0, laser.recovery_after_mismatches, recovery_label(laser));
    }

    if (kind == PlotKind::PositionError || kind == PlotKind::HeadingError
        || kind == PlotKind::Nees) {
        auto* note = new QCPItemText(plot);
        note->position->setType(QCPItemPosition::ptAxisRectRatio);
        note->position->setCoords(0.5, 0.5);
        note->setText(
            tr("No ground truth on this link: a real robot's pose is unknown, "
               "so there is no error to show"));
        note->setVisible(false);
        no_truth_[index_of(kind)] = note;
    }

    connect(plot, &QCustomPlot::beforeReplot, this, [this, kind] { onBeforeReplot(kind); });
    connect(plot, &QCustomPlot::afterReplot, this, [this] { onAfterReplot(); });
    return plot;
}

void PlotsPanel::addReferenceLine(PlotKind kind, int index, double value, const QString& label) {
    QCustomPlot* plot = plots_[index_of(kind)];
    ReferenceLine& reference = references_[index_of(kind)][static_cast<std::size_t>(index)];
    reference.line = new QCPItemStraightLine(plot);
    reference.label = new QCPItemText(plot);
    reference.label->position->setAxisRect(plot->axisRect());
    reference.label->position->setTypeX(QCPItemPosition::ptAxisRectRatio);
    reference.label->position->setTypeY(QCPItemPosition::ptPlotCoords);
    // Lower bounds labelled above their line, the others below: inside the range shown. The
    // laser's min matched points is a lower bound too (the matches lie above it).
    const bool lower_bound =
        (plot_definition(kind).chi_square_dof > 0 && index == static_cast<int>(BoundSide::Lower))
        || kind == PlotKind::LaserMatches;
    reference.label->setPositionAlignment(Qt::AlignRight
                                          | (lower_bound ? Qt::AlignBottom : Qt::AlignTop));
    reference.label->setPadding(QMargins(3, 1, 3, 1));
    moveReferenceLine(kind, index, value, label);
}

void PlotsPanel::moveReferenceLine(PlotKind kind, int index, double value, const QString& label) {
    ReferenceLine& reference = references_[index_of(kind)][static_cast<std::size_t>(index)];
    reference.value = value;
    // Any two points at the same height: the line is infinite.
    reference.line->point1->setCoords(0.0, value);
    reference.line->point2->setCoords(1.0, value);
    reference.label->position->setCoords(0.995, value);
    reference.label->setText(label);
}

QCustomPlot* PlotsPanel::plot(PlotKind kind) const {
    return plots_[index_of(kind)];
}

QCPGraph* PlotsPanel::graph(Series series) const {
    return graphs_[index_of(series)];
}

QCPItemStraightLine* PlotsPanel::boundLine(PlotKind kind, BoundSide side) const {
    if (plot_definition(kind).chi_square_dof <= 0) {
        return nullptr;
    }
    return references_[index_of(kind)][static_cast<std::size_t>(side)].line;
}

std::optional<double> PlotsPanel::referenceValue(PlotKind kind, int index) const {
    if (index < 0 || index > 1) {
        return std::nullopt;
    }
    const ReferenceLine& reference = references_[index_of(kind)][static_cast<std::size_t>(index)];
    return reference.line != nullptr ? std::optional<double>(reference.value) : std::nullopt;
}

void PlotsPanel::historyRestarted() {
    epoch_ = history_.epoch();
    taken_ = 0;
    first_time_ = 0.0;
    last_time_ = 0.0;
    clearGraphs();
    showPresentPlots();
    showNoTruth(false);
    const double range = history_.scene().ir_max_range;
    moveReferenceLine(PlotKind::IrDistances, 0, range, ir_range_label(range));
    moveLaserThresholds();
    updateAxes();
    requestReplots();
}

void PlotsPanel::moveLaserThresholds() {
    // From the scene, which follows the thresholds a run is retuned with while it goes.
    const LaserScene& laser = history_.scene().laser;
    moveReferenceLine(PlotKind::LaserMatches, 0, laser.min_matched_points,
                      min_matched_label(laser.min_matched_points));
    moveReferenceLine(PlotKind::LaserMismatches, 0, laser.recovery_after_mismatches,
                      recovery_label(laser));
}

void PlotsPanel::clearGraphs() {
    for (QCPGraph* graph : graphs_) {
        graph->data()->clear();
    }
    extents_.fill(ValueRange{});
    smoothed_.fill(std::numeric_limits<double>::quiet_NaN());
    has_points_.fill(false);
}

void PlotsPanel::samplesAppended(int first, int count) {
    if (history_.epoch() != epoch_) {
        // The restart was missed: start over from the new history.
        historyRestarted();
        first = 0;
        count = static_cast<int>(history_.size());
    }
    // The records, not the samples: a panel built on a long run (or one that missed a
    // restart) takes every step in, and only the records are all still there.
    const std::vector<StepRecord>& records = history_.records();
    // Everything not yet taken up to the announced end: a skipped announcement leaves no
    // hole, a repeated one adds nothing.
    const auto announced_end = static_cast<std::size_t>(std::max(0, first) + std::max(0, count));
    const std::size_t end = std::min(announced_end, records.size());
    if (end <= taken_) {
        return;
    }
    const std::size_t begin = taken_;
    const auto n = static_cast<qsizetype>(end - begin);
    QVector<double> keys;
    QVector<double> values;
    keys.reserve(n);
    values.reserve(n);
    std::array<double, kMaxPointsPerSample> several{};
    for (const SeriesDefinition& series : series_definitions()) {
        keys.clear();
        values.clear();
        const std::size_t s = index_of(series.series);
        ValueRange& extent = extents_[s];
        const auto add = [&](double time, double value) {
            if (series.smoothing > 0.0 && std::isfinite(value)) {
                // s ← s + a·(v − s), starting from the first value.
                double& smoothed = smoothed_[s];
                smoothed = std::isfinite(smoothed)
                               ? smoothed + series.smoothing * (value - smoothed)
                               : value;
                value = smoothed;
            }
            keys.append(time);
            values.append(value);
            extent.include(value);
        };
        for (std::size_t i = begin; i < end; ++i) {
            const StepRecord& step = records[i];
            if (series.values != nullptr) {
                const int points = series.values(step, several);
                for (int p = 0; p < points; ++p) {
                    add(step.time, several[static_cast<std::size_t>(p)]);
                }
            } else if (const std::optional<double> value = series.value(step)) {
                add(step.time, *value);
            }
        }
        if (!keys.isEmpty()) {
            graphs_[s]->addData(keys, values, true);
            has_points_[s] = true;
        }
    }
    showPresentPlots();
    if (begin == 0) {
        first_time_ = records.front().time;
    }
    last_time_ = records[end - 1].time;
    taken_ = end;
    showNoTruth(!records[end - 1].has_truth);
    moveLaserThresholds();
    updateAxes();
    requestReplots();
}

void PlotsPanel::showNoTruth(bool shown) {
    no_truth_shown_ = shown;
    for (QCPItemText* note : no_truth_) {
        if (note != nullptr) {
            note->setVisible(shown);
        }
    }
}

void PlotsPanel::setTimeWindow(double seconds) {
    time_window_ = std::isfinite(seconds) ? std::max(0.0, seconds) : 0.0;
    int index = window_choice_->findData(time_window_);
    if (index < 0) {
        window_choice_->addItem(tr("Last %1 s").arg(time_window_), time_window_);
        index = window_choice_->count() - 1;
    }
    {
        const QSignalBlocker blocker(window_choice_);
        window_choice_->setCurrentIndex(index);
    }
    updateAxes();
    requestReplots();
}

void PlotsPanel::setTextScale(double scale) {
    text_scale_ = std::isfinite(scale) ? std::clamp(scale, 0.5, 4.0) : 1.0;
    applyPalette();
}

void PlotsPanel::applyPalette() {
    const PlotLook look = plot_look(palette(), font(), text_scale_);
    for (QCustomPlot* plot : plots_) {
        apply_look(*plot, look);
        fit_legend(*plot, plot->width());
    }
    for (const SeriesDefinition& series : series_definitions()) {
        QCPGraph* graph = graphs_[index_of(series.series)];
        apply_look(*graph, series, look);
        pens_[index_of(series.series)] = graph->pen();
        brushes_[index_of(series.series)] = graph->brush();
    }
    updateAxes();  // and the light drawing of dense views
    requestReplots();
}

void PlotsPanel::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    if (event->type() == QEvent::PaletteChange || event->type() == QEvent::FontChange) {
        applyPalette();
    }
}

bool PlotsPanel::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Resize) {
        if (auto* resized = qobject_cast<QCustomPlot*>(watched)) {
            fit_legend(*resized, resized->width());
        }
    }
    return QWidget::eventFilter(watched, event);
}

void PlotsPanel::updateAxes() {
    double lower = first_time_;
    double upper = last_time_;
    if (time_window_ > 0.0) {
        // Scroll once the run is longer than the window; until then fill it from the left.
        lower = std::max(first_time_, last_time_ - time_window_);
        upper = lower + time_window_;
        if (last_time_ - time_window_ >= first_time_) {
            lower = last_time_ - time_window_;
            upper = last_time_;
        }
    } else if (upper <= lower) {
        upper = lower + 1.0;
    }
    for (int k = 0; k < kPlotKindCount; ++k) {
        updateAxes(static_cast<PlotKind>(k), lower, upper);
    }
}

void PlotsPanel::updateAxes(PlotKind kind, double lower, double upper) {
    QCustomPlot* plot = plots_[index_of(kind)];
    plot->xAxis->setRange(lower, upper);
    plot->xAxis2->setRange(lower, upper);
    lightenDenseGraphs(kind, lower, upper);

    ValueRange values;
    for (const SeriesDefinition& series : series_definitions()) {
        if (series.plot != kind) {
            continue;
        }
        values.include(time_window_ > 0.0 ? visibleValues(series.series, lower, upper)
                                          : extents_[index_of(series.series)]);
    }
    if (values.empty()) {
        return;  // nothing to show yet: keep the axis as it is
    }
    for (const ReferenceLine& reference : references_[index_of(kind)]) {
        if (reference.line != nullptr) {
            values.include(reference.value);
        }
    }
    const PlotDefinition& definition = plot_definition(kind);
    if (definition.chi_square_dof > 0) {
        // NIS and NEES can be tiny; a few decades below the lower bound is enough.
        const double floor = consistency_bounds(definition.chi_square_dof).lower * 1e-2;
        values.min_positive = std::max(values.min_positive, floor);
    }
    if (const std::optional<AxisSpan> span = padded_span(values, definition.log_y)) {
        plot->yAxis->setRange(span->lower, span->upper);
        plot->yAxis2->setRange(span->lower, span->upper);
    }
}

ValueRange PlotsPanel::visibleValues(Series series, double lower, double upper) const {
    ValueRange values;
    const QSharedPointer<QCPGraphDataContainer> points = graphs_[index_of(series)]->data();
    // Binary search for the window; one point beyond each end, where the line leaves it.
    const auto end = points->findEnd(upper, true);
    for (auto it = points->findBegin(lower, true); it != end; ++it) {
        values.include(it->value);
    }
    return values;
}

void PlotsPanel::lightenDenseGraphs(PlotKind kind, double lower, double upper) {
    for (const SeriesDefinition& series : series_definitions()) {
        if (series.plot != kind) {
            continue;
        }
        const std::size_t s = index_of(series.series);
        QCPGraph* graph = graphs_[s];
        const QSharedPointer<QCPGraphDataContainer> points = graph->data();
        const bool dense =
            points->findEnd(upper, false) - points->findBegin(lower, false) > kDenseView;
        if (series.look == SeriesLook::Band) {
            graph->setBrush(dense ? QBrush(Qt::NoBrush) : brushes_[s]);
        } else if (series.look == SeriesLook::Line) {
            QPen pen = pens_[s];
            if (dense) {
                pen.setWidthF(std::max(1.0, pen.widthF() - 1.0));
            }
            graph->setPen(pen);
        }
    }
}

void PlotsPanel::requestReplots() {
    for (std::size_t k = 0; k < plots_.size(); ++k) {
        if (plots_[k]->isVisible()) {
            replot_pending_[k] = true;
            plots_[k]->replot(QCustomPlot::rpQueuedReplot);
        }  // a hidden plot is replotted when it is shown (PanelPlot)
    }
}

void PlotsPanel::onBeforeReplot(PlotKind kind) {
    replot_pending_[index_of(kind)] = false;
    replot_started_ = std::chrono::steady_clock::now();
}

void PlotsPanel::onAfterReplot() {
    frame_time_ += std::chrono::steady_clock::now() - replot_started_;
    // One frame = every plot queued for the same batch; record once the last has run.
    if (std::none_of(replot_pending_.begin(), replot_pending_.end(), [](bool p) { return p; })) {
        frame_stats_.record(frame_time_);
        frame_time_ = std::chrono::nanoseconds{0};
    }
}

bool PlotsPanel::plotShown(PlotKind kind) const {
    if (!plot_definition(kind).optional) {
        return true;
    }
    return std::any_of(series_definitions().begin(), series_definitions().end(),
                       [this, kind](const SeriesDefinition& series) {
                           return series.plot == kind && has_points_[index_of(series.series)];
                       });
}

void PlotsPanel::showPresentPlots() {
    std::vector<Tab> all = tabs();
    for (std::size_t t = 0; t < all.size(); ++t) {
        bool any = false;
        for (PlotKind kind : all[t].plots) {
            const bool shown = plotShown(kind);
            // Hidden, not removed: its graphs keep their data and the splitter its sizes.
            plots_[index_of(kind)]->setVisible(shown);
            any = any || shown;
        }
        tabs_->setTabVisible(static_cast<int>(t), any);
    }
    // The lessons' legends name only the series this run has (no "5-state EKF" in the
    // compass lesson).
    for (const SeriesDefinition& series : series_definitions()) {
        if (!plot_definition(series.plot).optional || series.look == SeriesLook::BandEdge) {
            continue;
        }
        QCPGraph* graph = graphs_[index_of(series.series)];
        const bool listed = has_points_[index_of(series.series)];
        QCustomPlot* plot = plots_[index_of(series.plot)];
        if (listed != plot->legend->hasItemWithPlottable(graph)) {
            if (listed) {
                graph->addToLegend();
            } else {
                graph->removeFromLegend();
            }
            fit_legend(*plot, plot->width());
        }
    }
    // A lesson's tab hidden at a restart comes back as soon as the new run has its data.
    if (tabs_->isTabVisible(wanted_tab_) && tabs_->currentIndex() != wanted_tab_) {
        tabs_->setCurrentIndex(wanted_tab_);
    }
}

void PlotsPanel::setWantedTab(int index) {
    if (index < 0 || index >= tabs_->count()) {
        return;
    }
    wanted_tab_ = index;
    showPresentPlots();
}

ExportResult PlotsPanel::exportPlots(const QString& directory, ExportFormats formats, QSize size) {
    std::vector<NamedPlot> named;
    named.reserve(plots_.size());
    for (int k = 0; k < kPlotKindCount; ++k) {
        const auto kind = static_cast<PlotKind>(k);
        if (!plotShown(kind)) {
            continue;  // a lesson's plot this run has no data for
        }
        named.push_back({QString::fromUtf8(plot_definition(kind).file_stem), plot(kind)});
    }
    return export_plots(named, directory, formats, size);
}

}  // namespace legofeup::ui
