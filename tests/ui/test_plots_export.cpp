// Exporting the plots: PNG, PDF and SVG files that open, atomically written; an unusable
// directory reported by name with nothing written.
#include <unistd.h>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QTest>

#include "legofeup/ui/plots/plots_panel.hpp"
#include "support/lockstep_history.hpp"

using legofeup::ui::ExportFormat;
using legofeup::ui::ExportResult;
using legofeup::ui::PlotsPanel;
using legofeup::ui::RunHistory;

namespace {

using legofeup::ui::testing::one_lap;

/// The plots a wall-lesson run shows (the further lessons' plots have no data in it, so
/// they are neither shown nor exported).
constexpr int kWallLessonPlots = 7;

QByteArray contents(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

QStringList entries(const QString& directory) {
    return QDir(directory).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot);
}

}  // namespace

class PlotsExportTest : public QObject {
    Q_OBJECT

  private slots:
    void every_plot_in_every_format() {
        PlotsPanel panel(one_lap());
        QTemporaryDir directory;
        QVERIFY(directory.isValid());
        const ExportResult result =
            panel.exportPlots(directory.path(), legofeup::ui::kAllExportFormats, QSize(900, 600));
        QVERIFY2(result.ok(), qPrintable(result.error));
        QCOMPARE(result.files.size(), 3 * kWallLessonPlots);
        // Nothing else: no temporary file left behind.
        QCOMPARE(entries(directory.path()).size(), result.files.size());
        for (const char* stem : {"covariance", "position_error", "heading_error", "wheel_speeds",
                                 "ir_distances", "nis", "nees"}) {
            const QString base = directory.filePath(QLatin1String(stem));
            QVERIFY(result.files.contains(base + QStringLiteral(".png")));

            const QByteArray png = contents(base + QStringLiteral(".png"));
            QVERIFY2(png.startsWith(QByteArray("\x89PNG\r\n\x1a\n", 8)), stem);
            const QImage image = QImage::fromData(png, "PNG");
            QCOMPARE(image.size(), QSize(900, 600));

            const QByteArray pdf = contents(base + QStringLiteral(".pdf"));
            QVERIFY2(pdf.startsWith("%PDF"), stem);
            QVERIFY(pdf.trimmed().endsWith("%%EOF"));

            const QByteArray svg = contents(base + QStringLiteral(".svg"));
            QVERIFY2(svg.contains("<svg"), stem);
            QSvgRenderer renderer(svg);
            QVERIFY2(renderer.isValid(), stem);
        }
    }

    void only_the_chosen_formats() {
        PlotsPanel panel(one_lap());
        QTemporaryDir directory;
        const ExportResult result =
            panel.exportPlots(directory.path(), ExportFormat::Svg, QSize(400, 300));
        QVERIFY(result.ok());
        QCOMPARE(result.files.size(), kWallLessonPlots);
        for (const QString& file : result.files) {
            QVERIFY(file.endsWith(QStringLiteral(".svg")));
        }
        QVERIFY(!panel.exportPlots(directory.path(), {}, QSize(400, 300)).ok());
        QVERIFY(!panel.exportPlots(directory.path(), ExportFormat::Png, QSize(0, 300)).ok());
    }

    void a_missing_directory_is_named_and_nothing_written() {
        PlotsPanel panel(one_lap());
        QTemporaryDir parent;
        const QString missing = parent.filePath(QStringLiteral("no/such/dir"));
        const ExportResult result = panel.exportPlots(missing);
        QVERIFY(!result.ok());
        QVERIFY2(result.error.contains(missing), qPrintable(result.error));
        QVERIFY(result.files.isEmpty());
        QVERIFY(entries(parent.path()).isEmpty());
    }

    void a_file_in_place_of_the_directory_is_named_and_nothing_written() {
        PlotsPanel panel(one_lap());
        QTemporaryDir parent;
        const QString file_path = parent.filePath(QStringLiteral("plots"));
        QFile file(file_path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.close();
        const ExportResult result = panel.exportPlots(file_path);
        QVERIFY(!result.ok());
        QVERIFY2(result.error.contains(file_path), qPrintable(result.error));
        QCOMPARE(entries(parent.path()), QStringList{QStringLiteral("plots")});
    }

    void a_read_only_directory_is_named_and_nothing_written() {
        PlotsPanel panel(one_lap());
        QTemporaryDir directory;
        QVERIFY(QFile::setPermissions(directory.path(), QFile::ReadOwner | QFile::ExeOwner
                                                            | QFile::ReadUser | QFile::ExeUser));
        if (::geteuid() == 0) {
            QFile::setPermissions(directory.path(), QFile::ReadOwner | QFile::WriteOwner
                                                        | QFile::ExeOwner | QFile::ReadUser
                                                        | QFile::WriteUser | QFile::ExeUser);
            QSKIP("root writes into read-only directories");
        }
        const ExportResult result = panel.exportPlots(directory.path());
        QFile::setPermissions(directory.path(), QFile::ReadOwner | QFile::WriteOwner
                                                    | QFile::ExeOwner | QFile::ReadUser
                                                    | QFile::WriteUser | QFile::ExeUser);
        QVERIFY(!result.ok());
        QVERIFY2(result.error.contains(directory.path()), qPrintable(result.error));
        QVERIFY(entries(directory.path()).isEmpty());
    }
};

QTEST_MAIN(PlotsExportTest)
#include "test_plots_export.moc"
