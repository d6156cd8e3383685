#include "legofeup/ui/refilter/refilter_metrics.hpp"

#include <QCoreApplication>
#include <QHeaderView>
#include <QTableWidget>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>

namespace legofeup::ui {
namespace {

struct Row {
    const char* label;
    std::function<QString(const RunMetrics&)> value;
};

QString metres(double value) {
    return QStringLiteral("%1 m").arg(value, 0, 'f', 4);
}

QString degrees(double radians) {
    return QStringLiteral("%1°").arg(radians * 180.0 / std::numbers::pi, 0, 'f', 2);
}

/// A row that needs the truth: `value` of the run's TruthMetrics, or a dash that says why
/// there is none (a log of a real robot).
template <typename Value>
std::function<QString(const RunMetrics&)> with_truth(Value value) {
    return [value](const RunMetrics& m) {
        return m.truth ? value(*m.truth, m)
                       : QCoreApplication::translate("RefilterMetrics", "— (no ground truth)");
    };
}

const std::array<Row, 8>& rows() {
    using Truth = const TruthMetrics&;
    using Run = const RunMetrics&;
    static const std::array<Row, 8> kRows = {{
        {QT_TRANSLATE_NOOP("RefilterMetrics", "RMS position error"),
         with_truth([](Truth t, Run) { return metres(t.rms_position_error); })},
        {QT_TRANSLATE_NOOP("RefilterMetrics", "Final position error"),
         with_truth([](Truth t, Run) { return metres(t.final_position_error); })},
        {QT_TRANSLATE_NOOP("RefilterMetrics", "Largest position error"),
         with_truth([](Truth t, Run) { return metres(t.max_position_error); })},
        {QT_TRANSLATE_NOOP("RefilterMetrics", "RMS heading error"),
         with_truth([](Truth t, Run) { return degrees(t.rms_heading_error); })},
        {QT_TRANSLATE_NOOP("RefilterMetrics", "Mean NEES (95 % bounds of a time average)"),
         with_truth([](Truth t, Run) {
             return QStringLiteral("%1  [%2, %3]")
                 .arg(t.mean_nees, 0, 'f', 2)
                 .arg(t.time_average_nees_bounds.lower, 0, 'f', 2)
                 .arg(t.time_average_nees_bounds.upper, 0, 'f', 2);
         })},
        {QT_TRANSLATE_NOOP("RefilterMetrics", "Steps with NEES inside"),
         with_truth([](Truth t, Run) {
             return QStringLiteral("%1 %").arg(t.nees_inside_fraction * 100.0, 0, 'f', 1);
         })},
        {QT_TRANSLATE_NOOP("RefilterMetrics", "Mean NIS"),
         [](Run m) { return QString::number(m.mean_nis, 'f', 2); }},
        {QT_TRANSLATE_NOOP("RefilterMetrics", "Wall updates applied / rejected"),
         [](Run m) {
             return QStringLiteral("%1 / %2").arg(m.updates_applied).arg(m.updates_rejected);
         }},
    }};
    return kRows;
}

}  // namespace

void show_refilter_metrics(QTableWidget& table, const std::optional<RunMetrics>& old_metrics,
                           const std::optional<RunMetrics>& new_metrics) {
    table.clear();
    table.setColumnCount(2);
    table.setRowCount(static_cast<int>(rows().size()));
    table.setHorizontalHeaderLabels(
        {QObject::tr("Recorded settings"), QObject::tr("New settings")});
    int row = 0;
    for (const Row& definition : rows()) {
        table.setVerticalHeaderItem(row, new QTableWidgetItem(QCoreApplication::translate(
                                             "RefilterMetrics", definition.label)));
        const auto cell = [&](int column, const std::optional<RunMetrics>& metrics) {
            auto* item = new QTableWidgetItem(metrics ? definition.value(*metrics) : QString());
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            table.setItem(row, column, item);
        };
        cell(0, old_metrics);
        cell(1, new_metrics);
        ++row;
    }
    table.horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table.verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
}

}  // namespace legofeup::ui
