#include "legofeup/ui/plots/plot_export.hpp"

#include "legofeup/ui/write_atomically.hpp"

#include <qcustomplot.h>

#include <QBuffer>
#include <QByteArray>
#include <QDir>
#include <QFileInfo>
#include <QPageSize>
#include <QPdfWriter>
#include <QPixmap>
#include <QSvgGenerator>
#include "legofeup/ui/plots/plot_style.hpp"
#include "legofeup/ui/write_atomically.hpp"

namespace legofeup::ui {

namespace {

struct Format {
    ExportFormat format;
    const char* extension;
};
constexpr Format kFormats[] = {
    {ExportFormat::Png, "png"},
    {ExportFormat::Pdf, "pdf"},
    {ExportFormat::Svg, "svg"},
};

/// Draws `plot` at `size` with a vector-friendly painter on `device` (already set up).
bool paint_vector(QCustomPlot& plot, QPaintDevice& device, QSize size) {
    QCPPainter painter;
    if (!painter.begin(&device)) {
        return false;
    }
    painter.setMode(QCPPainter::pmVectorized);
    painter.setMode(QCPPainter::pmNoCaching);
    plot.toPainter(&painter, size.width(), size.height());
    return painter.end();
}

/// The file's bytes, or an empty array when rendering failed.
QByteArray render(QCustomPlot& plot, ExportFormat format, QSize size, const QString& title) {
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    switch (format) {
        case ExportFormat::Png: {
            const QPixmap pixmap = plot.toPixmap(size.width(), size.height());
            if (pixmap.isNull() || !pixmap.save(&buffer, "PNG")) {
                return {};
            }
            break;
        }
        case ExportFormat::Pdf: {
            // One device pixel per screen pixel, so text and lines keep their proportions;
            // the page is the plot's size in points at that resolution.
            const int dpi = plot.logicalDpiX() > 0 ? plot.logicalDpiX() : 96;
            QPdfWriter writer(&buffer);
            writer.setResolution(dpi);
            writer.setPageSize(
                QPageSize(QSizeF(size.width() * 72.0 / dpi, size.height() * 72.0 / dpi),
                          QPageSize::Point, title, QPageSize::ExactMatch));
            writer.setPageMargins(QMarginsF(0, 0, 0, 0));
            writer.setTitle(title);
            writer.setCreator(QStringLiteral("LegoFeup Lab"));
            if (!paint_vector(plot, writer, size)) {
                return {};
            }
            break;
        }
        case ExportFormat::Svg: {
            QSvgGenerator generator;
            generator.setOutputDevice(&buffer);
            generator.setSize(size);
            generator.setViewBox(QRect(QPoint(0, 0), size));
            generator.setResolution(plot.logicalDpiX() > 0 ? plot.logicalDpiX() : 96);
            generator.setTitle(title);
            if (!paint_vector(plot, generator, size)) {
                return {};
            }
            break;
        }
    }
    return bytes;
}

QString check_directory(const QString& directory) {
    if (directory.isEmpty()) {
        return QStringLiteral("no export directory given");
    }
    const QFileInfo info(directory);
    if (!info.exists()) {
        return QStringLiteral("the export directory %1 does not exist").arg(directory);
    }
    if (!info.isDir()) {
        return QStringLiteral("the export path %1 is not a directory").arg(directory);
    }
    if (!info.isWritable()) {
        return QStringLiteral("the export directory %1 is not writable").arg(directory);
    }
    return {};
}

}  // namespace

ExportResult export_plots(std::span<const NamedPlot> plots, const QString& directory,
                          ExportFormats formats, QSize size) {
    ExportResult result;
    if (formats == ExportFormats()) {
        result.error = QStringLiteral("no export format chosen");
        return result;
    }
    if (size.isEmpty()) {
        result.error =
            QStringLiteral("invalid export size %1×%2 px").arg(size.width()).arg(size.height());
        return result;
    }
    result.error = check_directory(directory);
    if (!result.ok()) {
        return result;
    }
    const QDir dir(directory);
    for (const NamedPlot& named : plots) {
        if (named.plot == nullptr) {
            continue;
        }
        for (const Format& format : kFormats) {
            if (!formats.testFlag(format.format)) {
                continue;
            }
            const QString path =
                dir.filePath(named.file_stem + QLatin1Char('.') + QLatin1String(format.extension));
            fit_legend(*named.plot, size.width());
            const QByteArray bytes = render(*named.plot, format.format, size, named.file_stem);
            fit_legend(*named.plot, named.plot->width());
            if (bytes.isEmpty()) {
                result.error = QStringLiteral("could not render %1").arg(path);
                return result;
            }
            result.error = write_atomically(path, bytes);
            if (!result.ok()) {
                return result;
            }
            result.files.append(path);
        }
    }
    return result;
}

}  // namespace legofeup::ui
