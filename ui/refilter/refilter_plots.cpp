#include "legofeup/ui/refilter/refilter_plots.hpp"

#include <qcustomplot.h>
#include <QEvent>
#include <QHBoxLayout>
#include <QTimer>
#include <algorithm>
#include <cmath>

#include "legofeup/core/pose_error.hpp"
#include "legofeup/ui/plots/plot_style.hpp"

namespace legofeup::ui {
namespace {

QCPCurve* path_curve(QCustomPlot& plot, const QString& name) {
    auto* curve = new QCPCurve(plot.xAxis, plot.yAxis);
    curve->setName(name);
    curve->setLineStyle(QCPCurve::lsLine);
    return curve;
}

/// ‖(x̂, ŷ) − (x, y)‖ of pose_error, m.
double distance(const Pose2& truth, const StateVector& estimate) {
    return pose_error(estimate, truth).position();
}

}  // namespace

RefilterPlots::RefilterPlots(QWidget* parent) : QWidget(parent) {
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    trajectory_ = new QCustomPlot(this);
    trajectory_->setObjectName(QStringLiteral("refilterTrajectory"));
    error_ = new QCustomPlot(this);
    error_->setObjectName(QStringLiteral("refilterError"));
    layout->addWidget(trajectory_, 1);
    layout->addWidget(error_, 1);

    trajectory_->xAxis->setLabel(tr("x (m)"));
    trajectory_->yAxis->setLabel(tr("y (m)"));
    truth_ = path_curve(*trajectory_, tr("truth"));
    old_path_ = path_curve(*trajectory_, tr("estimate, recorded settings"));
    new_path_ = path_curve(*trajectory_, tr("estimate, new settings"));
    add_header(*trajectory_, tr("Paths: truth and both estimates"));

    error_->xAxis->setLabel(tr("time (s)"));
    error_->yAxis->setLabel(tr("position error (m)"));
    old_error_ = error_->addGraph();
    old_error_->setName(tr("recorded settings"));
    new_error_ = error_->addGraph();
    new_error_->setName(tr("new settings"));
    add_header(*error_, tr("Position error: estimate − truth"));
    applyLook();
}

void RefilterPlots::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    if (event->type() == QEvent::PaletteChange || event->type() == QEvent::FontChange) {
        applyLook();
        trajectory_->replot();
        error_->replot();
    }
}

void RefilterPlots::applyLook() {
    const PlotLook look = plot_look(palette(), font(), 1.0);
    for (QCustomPlot* plot : {trajectory_, error_}) {
        apply_look(*plot, look);
    }
    // The truth in the text colour, thin; the old estimate dashed, the new one bold.
    truth_->setPen(QPen(look.text, look.line_width));
    old_path_->setPen(QPen(look.series[1], look.line_width * 1.5, Qt::DashLine));
    new_path_->setPen(QPen(look.series[0], look.line_width * 1.5));
    old_error_->setPen(old_path_->pen());
    new_error_->setPen(new_path_->pen());
    for (QCPCurve* wall : walls_) {
        wall->setPen(QPen(look.grid, look.line_width * 2));
    }
}

void RefilterPlots::clear() {
    for (QCPCurve* wall : walls_) {
        trajectory_->removePlottable(wall);
    }
    walls_.clear();
    for (QCPCurve* curve : {truth_, old_path_, new_path_}) {
        curve->data()->clear();
    }
    old_error_->data()->clear();
    new_error_->data()->clear();
    trajectory_->replot();
    error_->replot();
}

void RefilterPlots::showResult(const lessons::RefilterResult& result,
                               const std::vector<Wall>& walls) {
    clear();
    for (const Wall& wall : walls) {
        auto* curve = new QCPCurve(trajectory_->xAxis, trajectory_->yAxis);
        curve->addData({0.0, 1.0}, {wall.start.x(), wall.end.x()}, {wall.start.y(), wall.end.y()});
        curve->removeFromLegend();
        walls_.push_back(curve);
    }
    const auto count = static_cast<int>(result.steps.size());
    QVector<double> index(count);
    QVector<double> time(count);
    QVector<double> old_x(count);
    QVector<double> old_y(count);
    QVector<double> new_x(count);
    QVector<double> new_y(count);
    QVector<double> truth_index;
    QVector<double> truth_x;
    QVector<double> truth_y;
    QVector<double> error_time;
    QVector<double> old_error;
    QVector<double> new_error;
    for (int i = 0; i < count; ++i) {
        const lessons::RefilterStep& step = result.steps[static_cast<std::size_t>(i)];
        index[i] = i;
        time[i] = step.time;
        old_x[i] = step.old_estimate(0);
        old_y[i] = step.old_estimate(1);
        new_x[i] = step.new_estimate(0);
        new_y[i] = step.new_estimate(1);
        if (step.truth) {
            truth_index << i;
            truth_x << step.truth->x;
            truth_y << step.truth->y;
            error_time << step.time;
            old_error << distance(*step.truth, step.old_estimate);
            new_error << distance(*step.truth, step.new_estimate);
        }
    }
    truth_->setData(truth_index, truth_x, truth_y, true);
    old_path_->setData(index, old_x, old_y, true);
    new_path_->setData(index, new_x, new_y, true);
    old_error_->setData(error_time, old_error, true);
    new_error_->setData(error_time, new_error, true);
    applyLook();
    fitTrajectory();
    error_->rescaleAxes();
    error_->yAxis->setRangeLower(0.0);
    trajectory_->replot();
    error_->replot();
}

void RefilterPlots::fitTrajectory() {
    trajectory_->replot(QCustomPlot::rpImmediateRefresh);  // lays the axis rect out
    trajectory_->rescaleAxes();
    // Equal scales on both axes, so the arena is not distorted: widen the shorter range.
    QCPRange x = trajectory_->xAxis->range();
    QCPRange y = trajectory_->yAxis->range();
    const double width = std::max(1, trajectory_->axisRect()->width());
    const double height = std::max(1, trajectory_->axisRect()->height());
    const double metres_per_pixel = std::max(x.size() / width, y.size() / height) * 1.05;
    trajectory_->xAxis->setRange(x.center(), metres_per_pixel * width, Qt::AlignCenter);
    trajectory_->yAxis->setRange(y.center(), metres_per_pixel * height, Qt::AlignCenter);
}

void RefilterPlots::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    // Once the plots have their new size: legends wrapped to fit, the arena's metres square.
    QTimer::singleShot(0, this, [this] {
        fit_legend(*trajectory_, trajectory_->width());
        fit_legend(*error_, error_->width());
        if (!old_path_->data()->isEmpty()) {
            fitTrajectory();
        }
        trajectory_->replot();
        error_->replot();
    });
}

}  // namespace legofeup::ui
