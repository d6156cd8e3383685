// The plots panel's data: one point per sample (or per reading, per update), the values read
// from the right fields, batches adding up to one, the χ² bounds, the time window.
#include <qcustomplot.h>
#include <QSet>
#include <QSignalSpy>
#include <QTest>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "legofeup/core/chi_square.hpp"
#include "legofeup/ui/plots/plots_panel.hpp"
#include "support/lockstep_history.hpp"

using legofeup::GroundTruth;
using legofeup::kTheta;
using legofeup::kX;
using legofeup::kY;
using legofeup::StepStatus;
using legofeup::ui::BoundSide;
using legofeup::ui::PlotKind;
using legofeup::ui::PlotsPanel;
using legofeup::ui::RunHistory;
using legofeup::ui::RunSample;
using legofeup::ui::Series;

namespace {

using legofeup::ui::testing::one_lap;
using legofeup::ui::testing::one_lap_run;
using legofeup::ui::testing::one_lap_samples;

int size_of(const PlotsPanel& panel, Series series) {
    return panel.graph(series)->dataCount();
}

double last_value(const PlotsPanel& panel, Series series) {
    const auto data = panel.graph(series)->data();
    return (data->constEnd() - 1)->value;
}

/// A number as the history's record keeps it (a float) and the plots draw it.
double as_recorded(double value) {
    return static_cast<double>(static_cast<float>(value));
}

/// Both NaN, or equal.
bool same(double a, double b) {
    return (std::isnan(a) && std::isnan(b)) || a == b;
}

/// A sample at `time` with heading estimate `estimate` and true heading `truth`.
RunSample heading_sample(double time, double estimate, double truth) {
    RunSample sample;
    sample.snapshot.time = time;
    sample.snapshot.estimate << 0.5, 0.5, estimate;
    sample.snapshot.covariance.setIdentity();
    sample.snapshot.covariance *= 1e-2;
    GroundTruth true_state;
    true_state.time = time;
    true_state.pose = {0.5, 0.5, truth};
    sample.truth = true_state;
    return sample;
}

}  // namespace

class PlotsPanelTest : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() {
        QVERIFY2(one_lap_samples().size() > 1000,
                 qPrintable(QString::number(one_lap_samples().size())));
    }

    void every_graph_has_a_point_per_sample() {
        const RunHistory& history = one_lap();
        PlotsPanel panel(history);
        panel.historyRestarted();
        const int n = static_cast<int>(history.size());
        panel.samplesAppended(0, n);

        for (Series series :
             {Series::Px, Series::Py, Series::Ptheta, Series::SigmaXUpper, Series::SigmaXLower,
              Series::SigmaYUpper, Series::SigmaYLower, Series::ErrorX, Series::ErrorY,
              Series::SigmaThetaUpper, Series::SigmaThetaLower, Series::ErrorTheta,
              Series::V1Command, Series::V2Command, Series::V1True, Series::V2True, Series::Ds1,
              Series::Ds2, Series::Nees}) {
            QCOMPARE(size_of(panel, series), n);
        }
        const RunSample& last = history.latest();
        QCOMPARE(last_value(panel, Series::Px), as_recorded(last.snapshot.covariance(kX, kX)));
        QCOMPARE(last_value(panel, Series::Py), as_recorded(last.snapshot.covariance(kY, kY)));
        QCOMPARE(last_value(panel, Series::Ptheta),
                 as_recorded(last.snapshot.covariance(kTheta, kTheta)));
        QCOMPARE(last_value(panel, Series::V1Command), as_recorded(last.snapshot.wheels.right));
        QCOMPARE(last_value(panel, Series::V2Command), as_recorded(last.snapshot.wheels.left));
        QCOMPARE(last_value(panel, Series::SigmaXLower),
                 -std::sqrt(as_recorded(last.snapshot.covariance(kX, kX))));
        QCOMPARE(last_value(panel, Series::SigmaThetaUpper),
                 std::sqrt(as_recorded(last.snapshot.covariance(kTheta, kTheta))) * 180.0
                     / std::numbers::pi);
        QCOMPARE(last_value(panel, Series::ErrorY),
                 last.snapshot.estimate(kY) - last.truth->pose.y);
        QCOMPARE(last_value(panel, Series::Nees), last.nees);
        QCOMPARE((panel.graph(Series::Px)->data()->constEnd() - 1)->key, last.snapshot.time);
        // A step whose whole sample the history no longer keeps is drawn from its record.
        constexpr int kDropped = 107;
        QVERIFY(history.sample(kDropped) == nullptr);
        const RunSample& old = one_lap_samples()[kDropped];
        const auto at = [&](Series series) { return panel.graph(series)->data()->at(kDropped); };
        QCOMPARE(at(Series::Px)->key, old.snapshot.time);
        QCOMPARE(at(Series::Px)->value, as_recorded(old.snapshot.covariance(kX, kX)));
        QCOMPARE(at(Series::ErrorY)->value, old.snapshot.estimate(kY) - old.truth->pose.y);
        QCOMPARE(at(Series::V2Command)->value, as_recorded(old.snapshot.wheels.left));
        QCOMPARE(at(Series::Nees)->value, old.nees);
    }

    void ir_distances_have_gaps_out_of_range() {
        const RunHistory& history = one_lap();
        PlotsPanel panel(history);
        const auto& samples = one_lap_samples();
        for (int sensor = 0; sensor < 2; ++sensor) {
            const Series series = sensor == 0 ? Series::Ds1 : Series::Ds2;
            int in_range = 0;
            int drawn = 0;
            auto point = panel.graph(series)->data()->constBegin();
            for (const RunSample& sample : samples) {
                const auto& reading = sample.snapshot.ir[static_cast<std::size_t>(sensor)].reading;
                if (reading.in_range()) {
                    ++in_range;
                    QCOMPARE(point->value, as_recorded(reading.distance));
                } else {
                    QVERIFY(std::isnan(point->value));
                }
                drawn += std::isnan(point->value) ? 0 : 1;
                ++point;
            }
            QVERIFY(in_range > 100);
            QVERIFY(in_range < static_cast<int>(samples.size()));
            QCOMPARE(drawn, in_range);
        }
    }

    void nis_has_a_point_per_update() {
        const RunHistory& history = one_lap();
        PlotsPanel panel(history);
        int updates = 0;
        double last_nis = 0.0;
        for (const RunSample& sample : one_lap_samples()) {
            const auto& update = sample.snapshot.update;
            if (update.status != StepStatus::NotAttempted && std::isfinite(update.nis)) {
                ++updates;
                last_nis = update.nis;
            }
        }
        QVERIFY(updates > 100);
        QCOMPARE(size_of(panel, Series::Nis), updates);
        QCOMPARE(last_value(panel, Series::Nis), as_recorded(last_nis));
    }

    void heading_error_is_wrapped() {
        RunHistory history;
        history.restart({});
        history.append({heading_sample(0.0, std::numbers::pi - 0.01, -std::numbers::pi + 0.01),
                        heading_sample(0.05, -std::numbers::pi + 0.01, std::numbers::pi - 0.01)});
        PlotsPanel panel(history);
        const auto data = panel.graph(Series::ErrorTheta)->data();
        QCOMPARE(data->size(), 2);
        // θ̂ − θ = 2π − 0.02 wraps to −0.02 rad = −1.146°, not ~360°.
        QVERIFY(std::abs(data->at(0)->value - -1.1459156) < 1e-6);
        QVERIFY(std::abs(data->at(1)->value - 1.1459156) < 1e-6);
        // The band is ±σθ in degrees: σθ = 0.1 rad.
        QVERIFY(std::abs(panel.graph(Series::SigmaThetaUpper)->data()->at(0)->value - 5.7295780)
                < 1e-6);
    }

    void two_batches_give_the_same_data_as_one() {
        const RunHistory& history = one_lap();
        const std::vector<RunSample>& samples = one_lap_samples();
        const int n = static_cast<int>(samples.size());
        PlotsPanel whole(history);
        RunHistory growing;
        growing.restart(history.scene());
        PlotsPanel grown(growing);
        const int split = 1234;
        growing.append({samples.begin(), samples.begin() + split});
        grown.samplesAppended(0, split);
        growing.append({samples.begin() + split, samples.end()});
        grown.samplesAppended(split, n - split);

        for (int s = 0; s < legofeup::ui::kSeriesCount; ++s) {
            const auto series = static_cast<Series>(s);
            const auto a = whole.graph(series)->data();
            const auto b = grown.graph(series)->data();
            QCOMPARE(b->size(), a->size());
            for (int i = 0; i < a->size(); ++i) {
                QCOMPARE(b->at(i)->key, a->at(i)->key);
                QVERIFY2(same(b->at(i)->value, a->at(i)->value), qPrintable(QString::number(i)));
            }
        }
        for (int k = 0; k < legofeup::ui::kPlotKindCount; ++k) {
            const auto kind = static_cast<PlotKind>(k);
            QCOMPARE(grown.plot(kind)->yAxis->range().lower,
                     whole.plot(kind)->yAxis->range().lower);
            QCOMPARE(grown.plot(kind)->yAxis->range().upper,
                     whole.plot(kind)->yAxis->range().upper);
        }
    }

    void repeated_or_skipped_announcements_keep_every_sample_once() {
        const RunHistory& history = one_lap();
        RunHistory growing;
        growing.restart(history.scene());
        PlotsPanel panel(growing);
        growing.append({one_lap_samples().begin(), one_lap_samples().begin() + 100});
        panel.samplesAppended(0, 50);
        panel.samplesAppended(0, 50);   // repeated: nothing new
        panel.samplesAppended(60, 40);  // 50…59 were never announced: taken too
        QCOMPARE(panel.graph(Series::Px)->dataCount(), 100);
        QCOMPARE(panel.graph(Series::Px)->data()->at(99)->key, one_lap_samples()[99].snapshot.time);
    }

    void consistency_bounds_are_the_chi_square_quantiles() {
        PlotsPanel panel(one_lap());
        const auto bound = [&](PlotKind kind, BoundSide side) {
            const QCPItemStraightLine* line = panel.boundLine(kind, side);
            // Horizontal: both points at the bound.
            return line->point1->coords().y() == line->point2->coords().y()
                       ? line->point1->coords().y()
                       : std::numeric_limits<double>::quiet_NaN();
        };
        // Against the library …
        QCOMPARE(bound(PlotKind::Nis, BoundSide::Lower), legofeup::chi_square_quantile(0.025, 2));
        QCOMPARE(bound(PlotKind::Nis, BoundSide::Upper), legofeup::chi_square_quantile(0.975, 2));
        QCOMPARE(bound(PlotKind::Nees, BoundSide::Lower), legofeup::chi_square_quantile(0.025, 3));
        QCOMPARE(bound(PlotKind::Nees, BoundSide::Upper), legofeup::chi_square_quantile(0.975, 3));
        // … and against tabulated values (χ²(2): −2 ln(1 − p)).
        QVERIFY(std::abs(bound(PlotKind::Nis, BoundSide::Lower) - 0.0506356) < 1e-6);
        QVERIFY(std::abs(bound(PlotKind::Nis, BoundSide::Upper) - 7.377759) < 1e-5);
        QVERIFY(std::abs(bound(PlotKind::Nees, BoundSide::Lower) - 0.2157953) < 1e-6);
        QVERIFY(std::abs(bound(PlotKind::Nees, BoundSide::Upper) - 9.348404) < 1e-5);
        QVERIFY(panel.boundLine(PlotKind::Covariance, BoundSide::Upper) == nullptr);
        // The bounds are on screen.
        for (PlotKind kind : {PlotKind::Nis, PlotKind::Nees}) {
            const QCPRange y = panel.plot(kind)->yAxis->range();
            QVERIFY(y.contains(bound(kind, BoundSide::Lower)));
            QVERIFY(y.contains(bound(kind, BoundSide::Upper)));
            QVERIFY(panel.plot(kind)->yAxis->scaleType() == QCPAxis::stLogarithmic);
        }
    }

    void the_time_window_follows_the_latest_sample() {
        const RunHistory& history = one_lap();
        PlotsPanel panel(history);
        const double first = history.record(0).time;
        const double last = history.latest().snapshot.time;
        panel.setTimeWindow(30.0);
        QCOMPARE(panel.timeWindow(), 30.0);
        for (int k = 0; k < legofeup::ui::kPlotKindCount; ++k) {
            const QCPRange x = panel.plot(static_cast<PlotKind>(k))->xAxis->range();
            QCOMPARE(x.lower, last - 30.0);
            QCOMPARE(x.upper, last);
        }
        // The y axes show what is in the window, and only that.
        for (int k = 0; k < legofeup::ui::kPlotKindCount; ++k) {
            QCustomPlot* plot = panel.plot(static_cast<PlotKind>(k));
            const QCPRange y = plot->yAxis->range();
            const bool log = plot->yAxis->scaleType() == QCPAxis::stLogarithmic;
            for (int g = 0; g < plot->graphCount(); ++g) {
                const auto data = plot->graph(g)->data();
                for (auto it = data->findBegin(last - 30.0, false); it != data->constEnd(); ++it) {
                    if (std::isfinite(it->value) && (!log || it->value > 1e-3)) {
                        QVERIFY2(y.contains(it->value), qPrintable(plot->objectName()));
                    }
                }
            }
        }
        const QCPRange window_px = panel.plot(PlotKind::Covariance)->yAxis->range();

        panel.setTimeWindow(0.0);
        for (int k = 0; k < legofeup::ui::kPlotKindCount; ++k) {
            const QCPRange x = panel.plot(static_cast<PlotKind>(k))->xAxis->range();
            QCOMPARE(x.lower, first);
            QCOMPARE(x.upper, last);
        }
        // The whole run's y axis spans more than the last 30 s's exactly when its values do
        // (P grows and shrinks along the lap; whether its extremes fall in the last 30 s
        // depends on the tuning), and it shows every value of the run.
        QCustomPlot* covariance = panel.plot(PlotKind::Covariance);
        const QCPRange whole_px = covariance->yAxis->range();
        constexpr double kNone = std::numeric_limits<double>::infinity();
        double run_low = kNone, run_high = 0.0, window_low = kNone, window_high = 0.0;
        for (int g = 0; g < covariance->graphCount(); ++g) {
            const auto data = covariance->graph(g)->data();
            for (auto it = data->constBegin(); it != data->constEnd(); ++it) {
                if (!(std::isfinite(it->value) && it->value > 0.0)) {
                    continue;
                }
                QVERIFY2(whole_px.contains(it->value), qPrintable(QString::number(it->value)));
                run_low = std::min(run_low, it->value);
                run_high = std::max(run_high, it->value);
                if (it->key >= last - 30.0) {
                    window_low = std::min(window_low, it->value);
                    window_high = std::max(window_high, it->value);
                }
            }
        }
        QVERIFY(run_high > run_low && window_high > window_low);
        if (run_high / run_low > window_high / window_low) {
            QVERIFY(whole_px.upper / whole_px.lower > window_px.upper / window_px.lower);
        } else {
            QCOMPARE(whole_px.upper / whole_px.lower, window_px.upper / window_px.lower);
        }
    }

    void dense_views_are_drawn_light() {
        // Four laps end to end: more samples than the fill limit.
        const RunHistory& lap = one_lap();
        RunHistory history;
        history.restart(lap.scene());
        const double duration = lap.latest().snapshot.time + 0.05;
        for (int copy = 0; copy < 4; ++copy) {
            std::vector<RunSample> shifted = one_lap_samples();
            for (RunSample& sample : shifted) {
                sample.snapshot.time += copy * duration;
            }
            history.append(std::move(shifted));
        }
        QVERIFY(history.size() > PlotsPanel::kDenseView);
        PlotsPanel panel(history);
        const auto filled = [&](Series band) {
            return panel.graph(band)->brush().style() != Qt::NoBrush
                   && panel.graph(band)->channelFillGraph() != nullptr;
        };
        for (Series band : {Series::SigmaXLower, Series::SigmaYLower, Series::SigmaThetaLower}) {
            QVERIFY(!filled(band));
        }
        const double thin = panel.graph(Series::Px)->pen().widthF();
        panel.setTimeWindow(30.0);
        for (Series band : {Series::SigmaXLower, Series::SigmaYLower, Series::SigmaThetaLower}) {
            QVERIFY(filled(band));
        }
        QVERIFY(panel.graph(Series::Px)->pen().widthF() > thin);
        panel.setTextScale(1.3);  // a new look keeps the fills of the current view
        QVERIFY(filled(Series::SigmaXLower));
        panel.setTimeWindow(0.0);
        QVERIFY(!filled(Series::SigmaXLower));
    }

    void restart_clears_every_graph() {
        RunHistory history = legofeup::ui::testing::history_of(one_lap_run());
        PlotsPanel panel(history);
        QVERIFY(panel.graph(Series::Px)->dataCount() > 0);
        history.restart(history.scene());
        panel.historyRestarted();
        for (int s = 0; s < legofeup::ui::kSeriesCount; ++s) {
            QCOMPARE(panel.graph(static_cast<Series>(s))->dataCount(), 0);
        }
    }

    void replots_are_timed_and_coalesced() {
        RunHistory history;
        history.restart(one_lap().scene());
        PlotsPanel panel(history);
        panel.resize(900, 700);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QCoreApplication::processEvents();
        QSignalSpy replots(panel.plot(PlotKind::Covariance), &QCustomPlot::afterReplot);
        QSignalSpy hidden_replots(panel.plot(PlotKind::Nis), &QCustomPlot::afterReplot);
        const std::size_t frames = panel.frameStats().summary().total;
        const auto& samples = one_lap_samples();
        for (int i = 0; i < 5; ++i) {
            history.append({samples[static_cast<std::size_t>(i)]});
            panel.samplesAppended(i, 1);
        }
        QTRY_COMPARE(replots.count(), 1);  // five batches, one replot
        QCOMPARE(panel.frameStats().summary().total, frames + 1);
        QCOMPARE(hidden_replots.count(), 0);  // on a hidden tab: not drawn …
        auto* tabs = panel.findChild<QTabWidget*>();
        tabs->setCurrentIndex(2);  // … until shown
        QTRY_COMPARE(hidden_replots.count(), 1);
        // A hidden plot keeps no picture (one paint buffer per shown plot): shown again, it is
        // replotted at once, so its first paint is the plot and not a blank.
        tabs->setCurrentIndex(0);
        QTRY_COMPARE(replots.count(), 2);
        const QImage image = panel.plot(PlotKind::Covariance)->grab().toImage();
        QSet<QRgb> colours;
        for (int y = 0; y < image.height(); y += 3) {
            for (int x = 0; x < image.width(); x += 3) {
                colours.insert(image.pixel(x, y));
            }
        }
        QVERIFY2(colours.size() > 3, qPrintable(QString::number(colours.size())));
    }

    void text_scale_and_palette_reach_the_plots() {
        PlotsPanel panel(one_lap());
        QCustomPlot* plot = panel.plot(PlotKind::WheelSpeeds);
        const double normal = plot->xAxis->tickLabelFont().pointSizeF();
        panel.setTextScale(1.6);
        QVERIFY(std::abs(plot->xAxis->tickLabelFont().pointSizeF() - 1.6 * normal) < 1e-6);
        QVERIFY(plot->legend->font().pointSizeF() > normal);

        QPalette dark;
        dark.setColor(QPalette::Base, QColor(30, 30, 30));
        dark.setColor(QPalette::WindowText, QColor(230, 230, 230));
        panel.setPalette(dark);
        QCOMPARE(plot->toPixmap(200, 150).toImage().pixelColor(1, 1), QColor(30, 30, 30));
        QCOMPARE(plot->xAxis->tickLabelColor(), QColor(230, 230, 230));
        // Series colours stay readable on the dark background.
        QVERIFY(panel.graph(Series::V1Command)->pen().color().lightnessF() > 0.5F);
    }
};

QTEST_MAIN(PlotsPanelTest)
#include "test_plots_panel.moc"
