#pragma once
// Saving plots as files: PNG (raster), PDF and SVG (vector), each written atomically.

#include <QFlags>
#include <QSize>
#include <QString>
#include <QStringList>
#include <span>

class QCustomPlot;

namespace legofeup::ui {

enum class ExportFormat : unsigned {
    Png = 0x1,
    Pdf = 0x2,
    Svg = 0x4,
};
Q_DECLARE_FLAGS(ExportFormats, ExportFormat)
Q_DECLARE_OPERATORS_FOR_FLAGS(ExportFormats)

inline constexpr ExportFormats kAllExportFormats =
    ExportFormats(ExportFormat::Png) | ExportFormat::Pdf | ExportFormat::Svg;

struct ExportResult {
    QStringList files;  ///< every file written (complete), also when a later one failed
    QString error;      ///< empty on success; otherwise says what failed and where

    bool ok() const { return error.isEmpty(); }
};

struct NamedPlot {
    QString file_stem;  ///< e.g. "covariance" → covariance.png, covariance.pdf …
    QCustomPlot* plot = nullptr;
};

/// Writes each plot in each format into `directory` at `size` pixels (the PDF page has the
/// same proportions). Every file is written to a temporary name and renamed when complete,
/// so a failure never leaves a partial file. An unusable directory writes nothing.
ExportResult export_plots(std::span<const NamedPlot> plots, const QString& directory,
                          ExportFormats formats, QSize size);

}  // namespace legofeup::ui
