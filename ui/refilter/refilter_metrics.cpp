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

const std::array<Row, 8>& rows() {
    static const std::array<Row, 8> kRows = {{
        {QT_TRANSLATE_NOOP("RefilterMetrics", "RMS position error"),
         [](const RunMetrics& m) { return metres(m.rms_position_error); }},
        {QT_TRANSLATE_NOOP("RefilterMetrics", "Final position error"),
         [](const RunMetrics& m) { return metres(m.final_position_error); }},
        {QT_TRANSLATE_NOOP("RefilterMetrics", "Largest position error"),
         [](const RunMetrics& m) { return metres(m.max_position_error); }},
        {QT_TRANSLATE_NOOP("RefilterMetrics", "RMS heading error"),
         [](const RunMetrics& m) { return degrees(m.rms_heading_error); }},
        {QT_TRANSLATE_NOOP("RefilterMetrics", "Mean NEES (χ²(3) 95 %)"),
         [](const RunMetrics& m) {
             return QStringLiteral("%1  [%2, %3]")
                 .arg(m.mean_nees, 0, 'f', 2)
                 .arg(m.nees_bounds.lower, 0, 'f', 2)
                 .arg(m.nees_bounds.upper, 0, 'f', 2);
         }},
        {QT_TRANSLATE_NOOP("RefilterMetrics", "Steps with NEES inside"),
         [](const RunMetrics& m) {
             return QStringLiteral("%1 %").arg(m.nees_inside_fraction * 100.0, 0, 'f', 1);
         }},
        {QT_TRANSLATE_NOOP("RefilterMetrics", "Mean NIS"),
         [](const RunMetrics& m) { return QString::number(m.mean_nis, 'f', 2); }},
        {QT_TRANSLATE_NOOP("RefilterMetrics", "Wall updates applied / rejected"),
         [](const RunMetrics& m) {
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
            auto* item = new QTableWidgetItem(metrics ? definition.value(*metrics)
                                                      : QObject::tr("no truth"));
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
