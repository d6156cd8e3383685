// The calibration dialogs (QtTest, offscreen), filled in as a student would: the IR fit and
// UMBmark give exactly what the library functions give for the same measurements, bad
// entries are refused with their row, column and text, and "Save to profile" writes a
// profile the library reads back, keeping what the calibration did not touch.

#include <qcustomplot.h>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

#include "legofeup/lessons/calibration/ir_calibration.hpp"
#include "legofeup/lessons/calibration/umbmark.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/robot_profile.hpp"
#include "legofeup/ui/calibration/ir_calibration_dialog.hpp"
#include "legofeup/ui/calibration/number_table.hpp"
#include "legofeup/ui/calibration/umbmark_dialog.hpp"
#include "legofeup/ui/session/session.hpp"
#include "support/screenshot.hpp"

using namespace legofeup;
using namespace legofeup::ui;

namespace {

/// A sensor whose curve differs from the configuration's: C_M = 3200, C_R = 12, b = 1.5,
/// read at 4 … 30 cm, the A/D rounded to whole counts as the brick reports it.
struct IrMeasurements {
    QStringList adc;
    QStringList distance;
    std::vector<lessons::IrCalibrationPoint> points;

    IrMeasurements() {
        const double distances[] = {0.04, 0.05, 0.06, 0.08, 0.10, 0.12,
                                    0.15, 0.18, 0.21, 0.24, 0.27, 0.30};
        for (const double d : distances) {
            const double a = std::round(3200.0 / (d / 0.01 + 1.5) - 12.0);
            adc << QString::number(a);
            distance << QString::number(d);
            points.push_back({a, d});
        }
    }
};

void fill(NumberTable& table, const QStringList& first, const QStringList& second) {
    table.setRowCount(0);
    for (qsizetype i = 0; i < first.size(); ++i) {
        const int row = table.addRow();
        table.item(row, 0)->setText(first[i]);
        table.item(row, 1)->setText(second[i]);
    }
}

std::string what_of(const std::function<void()>& call) {
    try {
        call();
    } catch (const std::exception& error) {
        return error.what();
    }
    return {};
}

}  // namespace

class CalibrationDialogsTest : public QObject {
    Q_OBJECT

  private:
    QTemporaryDir dir_;
    std::unique_ptr<Session> session_;

    QString path(const char* name) const { return dir_.filePath(QLatin1String(name)); }

    /// A profile with values no calibration here changes: they must survive a save.
    QString existingProfile(const char* name) const {
        lessons::RobotProfile profile;
        profile.name = "classroom robot 3";
        profile.wheel_base = 0.125;
        profile.front_ir_port = 2;
        profile.power_per_meter_per_second = 250.0;
        lessons::save_robot_profile(path(name).toStdString(), profile);
        return path(name);
    }

  private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        qputenv("XDG_CONFIG_HOME", dir_.path().toUtf8());
        QCoreApplication::setOrganizationName(QStringLiteral("LegoFeupTest"));
        QCoreApplication::setApplicationName(QStringLiteral("LegoFeup Lab Calibration Test"));
    }

    void init() { session_ = std::make_unique<Session>(lessons::find_experiment("f")->config); }
    void cleanup() { session_.reset(); }

    void theIrFitIsTheLibrarysFitAndIsShown() {
        IrCalibrationDialog dialog(*session_);
        dialog.show();
        const IrMeasurements measured;
        fill(*dialog.table(), measured.adc, measured.distance);
        QVERIFY(!dialog.saveButton()->isEnabled());
        QTest::mouseClick(dialog.fitButton(), Qt::LeftButton);
        QVERIFY2(dialog.fit().has_value(), qPrintable(dialog.messageLabel()->text()));

        const lessons::IrFit expected =
            lessons::fit_ir_curve(measured.points, session_->resolved().loop.ir_curve);
        const lessons::IrFit fit = *dialog.fit();
        QCOMPARE(fit.curve.c_m, expected.curve.c_m);
        QCOMPARE(fit.curve.c_r, expected.curve.c_r);
        QCOMPARE(fit.curve.b, expected.curve.b);
        QCOMPARE(fit.rms_residual, expected.rms_residual);
        QVERIFY(std::abs(fit.curve.c_m - 3200.0) < 100.0);  // near the sensor's own curve
        const QString shown = dialog.resultLabel()->text();
        QVERIFY2(shown.contains(QString::number(expected.curve.c_m, 'g', 6)), qPrintable(shown));
        QVERIFY(shown.contains(QString::number(expected.curve.c_r, 'g', 5)));
        QVERIFY(shown.contains(QString::number(expected.rms_residual * 1000.0, 'f', 2)));
        QVERIFY(dialog.saveButton()->isEnabled());

        // The plots: every point, the fitted curve through them, every residual in mm.
        QCOMPARE(dialog.curvePlot()->graph(0)->data()->size(), int(measured.points.size()));
        QVERIFY(dialog.curvePlot()->graph(1)->data()->size() > 100);
        QCOMPARE(dialog.residualPlot()->graph(0)->data()->size(), int(measured.points.size()));
        for (std::size_t i = 0; i < measured.points.size(); ++i) {  // kept sorted by A/D
            const auto point =
                dialog.residualPlot()->graph(0)->data()->findBegin(measured.points[i].adc, false);
            QCOMPARE(point->key, measured.points[i].adc);
            QCOMPARE(point->value, expected.residuals[i] * 1000.0);
        }

        // Editing a point invalidates the fit: nothing stale can be saved.
        dialog.table()->item(0, 1)->setText(QStringLiteral("0.041"));
        QVERIFY(!dialog.fit().has_value());
        QVERIFY(!dialog.saveButton()->isEnabled());
    }

    void badIrEntriesAreRefusedPrecisely() {
        IrCalibrationDialog dialog(*session_);
        const IrMeasurements measured;
        QStringList distances = measured.distance;
        distances[1] = QStringLiteral("0,05");
        fill(*dialog.table(), measured.adc, distances);
        QVERIFY(!dialog.runFit());
        QCOMPARE(dialog.messageLabel()->text(),
                 QStringLiteral("Row 2, distance (m): '0,05' is not a number (use a point for "
                                "decimals)"));
        QVERIFY(!dialog.fit().has_value());

        QStringList adc = measured.adc;
        adc[3] = QString();
        fill(*dialog.table(), adc, measured.distance);
        QVERIFY(!dialog.runFit());
        QCOMPARE(dialog.messageLabel()->text(), QStringLiteral("Row 4, A/D: empty"));

        // What only the library can judge is refused in its words: too few points.
        fill(*dialog.table(), measured.adc.mid(0, 3), measured.distance.mid(0, 3));
        QVERIFY(!dialog.runFit());
        const std::vector<lessons::IrCalibrationPoint> three(measured.points.begin(),
                                                             measured.points.begin() + 3);
        const std::string expected =
            what_of([&] { lessons::fit_ir_curve(three, session_->resolved().loop.ir_curve); });
        QVERIFY(!expected.empty());
        QCOMPARE(dialog.messageLabel()->text(), QString::fromStdString(expected));
    }

    void irPointsImportFromCsvWithTheLibrarysReader() {
        IrCalibrationDialog dialog(*session_);
        const IrMeasurements measured;
        QFile csv(path("ir.csv"));
        QVERIFY(csv.open(QIODevice::WriteOnly));
        csv.write("adc,distance_m\n# at the lab bench\n");
        for (qsizetype i = 0; i < measured.adc.size(); ++i) {
            csv.write(
                QStringLiteral("%1,%2\n").arg(measured.adc[i], measured.distance[i]).toUtf8());
        }
        csv.close();
        QVERIFY2(dialog.importCsv(csv.fileName()), qPrintable(dialog.messageLabel()->text()));
        QCOMPARE(dialog.table()->rowCount(), int(measured.points.size()));
        const auto points = dialog.points();
        QVERIFY(points.has_value());
        for (std::size_t i = 0; i < points->size(); ++i) {
            QCOMPARE((*points)[i].adc, measured.points[i].adc);
            QCOMPARE((*points)[i].distance, measured.points[i].distance);
        }
        QFile bad(path("bad.csv"));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write("adc,distance_m\n500,x\n");
        bad.close();
        QVERIFY(!dialog.importCsv(bad.fileName()));
        QVERIFY2(dialog.messageLabel()->text().contains(QStringLiteral("bad.csv:2")),
                 qPrintable(dialog.messageLabel()->text()));
        QCOMPARE(dialog.table()->rowCount(), int(measured.points.size()));  // kept
    }

    void theIrFitIsSavedIntoTheProfileKeepingTheRest() {
        IrCalibrationDialog dialog(*session_);
        const IrMeasurements measured;
        fill(*dialog.table(), measured.adc, measured.distance);
        QVERIFY(!dialog.saveToProfile(path("early.toml")));  // nothing fitted yet
        QVERIFY(!QFile::exists(path("early.toml")));
        QVERIFY(dialog.runFit());
        const QString file = existingProfile("ir-robot.toml");
        QVERIFY2(dialog.saveToProfile(file), qPrintable(dialog.messageLabel()->text()));
        const lessons::RobotProfile read = lessons::load_robot_profile(file.toStdString());
        QCOMPARE(read.ir_curve.c_m, dialog.fit()->curve.c_m);
        QCOMPARE(read.ir_curve.c_r, dialog.fit()->curve.c_r);
        QCOMPARE(read.ir_curve.b, dialog.fit()->curve.b);
        QCOMPARE(read.name, std::string("classroom robot 3"));
        QCOMPARE(read.wheel_base, 0.125);
        QCOMPARE(read.front_ir_port, 2);
        QCOMPARE(read.power_per_meter_per_second, 250.0);
        // A new file is a new profile with the defaults and the fit.
        QVERIFY(dialog.saveToProfile(path("new-robot.toml")));
        QCOMPARE(lessons::load_robot_profile(path("new-robot.toml").toStdString()).ir_curve.c_m,
                 dialog.fit()->curve.c_m);
    }

    // Rows that say their sensor give it its own curve, as `calibrate ir` does with a sensor
    // column: the library's calibration, shown, drawn and saved; rows that say nothing give
    // the one curve only, and saving it removes the sensors' own curves from the profile.
    void rowsThatSayTheirSensorGiveItsOwnCurve() {
        IrCalibrationDialog dialog(*session_);
        dialog.show();
        const IrMeasurements measured;  // the front unit
        QStringList adc = measured.adc;
        QStringList distance = measured.distance;
        std::vector<lessons::IrCalibrationPoint> points;
        for (lessons::IrCalibrationPoint point : measured.points) {
            point.sensor = kFrontSensor;
            points.push_back(point);
        }
        for (const lessons::IrCalibrationPoint& point : measured.points) {  // a rear unit 8 % off
            const double a = std::round(3450.0 / (point.distance / 0.01 + 1.5) - 12.0);
            adc << QString::number(a);
            distance << QString::number(point.distance);
            points.push_back({a, point.distance, kRearSensor});
        }
        fill(*dialog.table(), adc, distance);
        for (int row = 0; row < dialog.table()->rowCount(); ++row) {
            dialog.table()->setChoice(row, row < measured.adc.size() ? 1 : 2);
        }
        QVERIFY2(dialog.runFit(), qPrintable(dialog.messageLabel()->text()));
        const lessons::IrCalibration expected =
            lessons::fit_ir_calibration(points, session_->resolved().loop.ir_curve, {});
        const auto& shown = dialog.calibration();
        QVERIFY(shown.has_value());
        QVERIFY(shown->own[0].has_value() && shown->own[1].has_value());
        QCOMPARE(shown->own[0]->curve.c_m, expected.own[0]->curve.c_m);
        QCOMPARE(shown->own[1]->curve.c_m, expected.own[1]->curve.c_m);
        QCOMPARE(shown->both.curve.c_m, expected.both.curve.c_m);
        QVERIFY(std::abs(shown->own[1]->curve.c_m - 3450.0) < 100.0);
        const QString text = dialog.resultLabel()->text();
        QVERIFY2(text.contains(QStringLiteral("Front sensor's own curve: C_M = %1")
                                   .arg(expected.own[0]->curve.c_m, 0, 'g', 6)),
                 qPrintable(text));
        QVERIFY(text.contains(QStringLiteral("Rear sensor's own curve")));
        QVERIFY(dialog.curvePlot()->graph(3)->data()->size() > 100);
        QVERIFY(dialog.curvePlot()->graph(4)->data()->size() > 100);
        testing::save_screenshot(dialog, "ir-calibration");

        const QString file = existingProfile("two-sensors.toml");
        QVERIFY2(dialog.saveToProfile(file), qPrintable(dialog.messageLabel()->text()));
        lessons::RobotProfile read = lessons::load_robot_profile(file.toStdString());
        QVERIFY(read.ir_sensor_parameters[1].has_value());
        QCOMPARE(read.ir_sensor_parameters[1]->c_m, expected.own[1]->curve.c_m);
        QCOMPARE(read.ir_sensor_parameters[0]->b, expected.own[0]->curve.b);
        QCOMPARE(read.ir_curve.c_m, expected.both.curve.c_m);

        // Changing a row's sensor is a change of the points: the fit is gone.
        dialog.table()->setChoice(0, 0);
        QVERIFY(!dialog.calibration().has_value());
        for (int row = 0; row < dialog.table()->rowCount(); ++row) {
            dialog.table()->setChoice(row, 0);
        }
        QVERIFY(dialog.runFit());
        QVERIFY(!dialog.calibration()->own[0] && !dialog.calibration()->own[1]);
        QVERIFY(!dialog.resultLabel()->text().contains(QStringLiteral("own curve")));
        QVERIFY(dialog.saveToProfile(file));
        read = lessons::load_robot_profile(file.toStdString());
        QVERIFY(!read.ir_sensor_parameters[0] && !read.ir_sensor_parameters[1]);
    }

    void aCsvFilesSensorColumnFillsTheTablesSensors() {
        IrCalibrationDialog dialog(*session_);
        QFile csv(path("sensors.csv"));
        QVERIFY(csv.open(QIODevice::WriteOnly));
        csv.write("adc,distance_m,sensor\n580,0.04,front\n300,0.09,rear\n");
        csv.close();
        QVERIFY2(dialog.importCsv(csv.fileName()), qPrintable(dialog.messageLabel()->text()));
        QCOMPARE(dialog.table()->choice(0), 1);
        QCOMPARE(dialog.table()->choice(1), 2);
        const auto read = dialog.points();
        QVERIFY(read.has_value());
        QCOMPARE((*read)[0].sensor, std::optional<IrSensor>(kFrontSensor));
        QCOMPARE((*read)[1].sensor, std::optional<IrSensor>(kRearSensor));
    }

    void takeCurrentAdcAveragesTheLiveRobotsLatestFrames() {
        IrCalibrationDialog dialog(*session_);
        QVERIFY(!dialog.takeFrontButton()->isEnabled());  // no run yet
        QVERIFY(!dialog.takeCurrentAdc(0));
        QVERIFY(dialog.messageLabel()->text().contains(QStringLiteral("No run is live")));
        LinkChoice fast;
        fast.speed = 5.0;
        session_->setLinkChoice(fast);
        session_->start();
        QTRY_VERIFY_WITH_TIMEOUT(session_->history().size() >= 30, 20000);
        QTRY_VERIFY(dialog.takeRearButton()->isEnabled());
        dialog.table()->setCurrentCell(2, 0);
        QTest::mouseClick(dialog.takeRearButton(), Qt::LeftButton);
        // The history only changes on this thread: it is what the click saw.
        const RunHistory& history = session_->history();
        double sum = 0.0;
        int count = 0;
        for (std::size_t i = history.size(); i > 0 && count < kAdcAverageFrames; --i) {
            const LoopSnapshot& snapshot = history.sample(i - 1)->snapshot;  // recent: whole
            if (!snapshot.frame_missing) {
                sum += snapshot.ir[1].adc;
                ++count;
            }
        }
        QCOMPARE(count, kAdcAverageFrames);
        const double expected = std::round(sum / count * 10.0) / 10.0;
        QCOMPARE(dialog.table()->item(2, 0)->text().toDouble(), expected);
        QCOMPARE(dialog.table()->choice(2), 2);  // the row now says the rear sensor took it
        session_->stop();
    }

    void umbmarkIsTheLibrarysAndIsSavedIntoTheProfile() {
        UmbmarkDialog dialog(*session_);
        dialog.show();
        dialog.sideField()->setText(QStringLiteral("2"));
        dialog.wheelBaseField()->setText(QStringLiteral("0.12"));
        dialog.rightDiameterField()->setText(QStringLiteral("0.0432"));
        dialog.leftDiameterField()->setText(QStringLiteral("0.0432"));
        dialog.countsField()->setText(QStringLiteral("360"));
        const QStringList cw_x{"-0.061", "-0.055", "-0.07", "-0.058", "-0.066"};
        const QStringList cw_y{"-0.048", "-0.052", "-0.06", "-0.047", "-0.05"};
        const QStringList ccw_x{"0.021", "0.018", "0.025", "0.02", "0.016"};
        const QStringList ccw_y{"-0.031", "-0.027", "-0.035", "-0.03", "-0.026"};
        fill(*dialog.clockwiseTable(), cw_x, cw_y);
        fill(*dialog.counterClockwiseTable(), ccw_x, ccw_y);
        QTest::mouseClick(dialog.computeButton(), Qt::LeftButton);
        QVERIFY2(dialog.result().has_value(), qPrintable(dialog.messageLabel()->text()));

        lessons::UmbmarkInput input;
        input.side = 2.0;
        input.wheel_base = 0.12;
        input.right_wheel_diameter = 0.0432;
        input.left_wheel_diameter = 0.0432;
        input.counts_per_turn = 360.0;
        for (qsizetype i = 0; i < cw_x.size(); ++i) {
            input.clockwise.emplace_back(cw_x[i].toDouble(), cw_y[i].toDouble());
            input.counter_clockwise.emplace_back(ccw_x[i].toDouble(), ccw_y[i].toDouble());
        }
        const lessons::UmbmarkResult expected = lessons::umbmark(input);
        const lessons::UmbmarkResult& result = *dialog.result();
        QCOMPARE(result.e_d, expected.e_d);
        QCOMPARE(result.e_b, expected.e_b);
        QCOMPARE(result.wheel_base, expected.wheel_base);
        QCOMPARE(result.right_wheel_diameter, expected.right_wheel_diameter);
        QCOMPARE(result.left_wheel_diameter, expected.left_wheel_diameter);
        QCOMPARE(result.codo_right, expected.codo_right);
        const QString shown = dialog.resultLabel()->text();
        QVERIFY2(shown.contains(QString::number(expected.e_d, 'f', 5)), qPrintable(shown));
        QVERIFY(shown.contains(QString::number(expected.e_b, 'f', 5)));
        QVERIFY(shown.contains(QString::number(expected.codo_left, 'f', 2)));
        QCOMPARE(dialog.errorPlot()->graph(0)->data()->size(), 5);
        QCOMPARE(dialog.errorPlot()->graph(2)->data()->size(), 2);  // the two centres
        testing::save_screenshot(dialog, "umbmark");

        const QString file = existingProfile("umb-robot.toml");
        QVERIFY2(dialog.saveToProfile(file), qPrintable(dialog.messageLabel()->text()));
        const lessons::RobotProfile read = lessons::load_robot_profile(file.toStdString());
        QCOMPARE(read.wheel_base, expected.wheel_base);
        QCOMPARE(read.right_wheel_diameter, expected.right_wheel_diameter);
        QCOMPARE(read.left_wheel_diameter, expected.left_wheel_diameter);
        QVERIFY(std::abs(read.codo_right - expected.codo_right) < 1e-9 * expected.codo_right);
        QCOMPARE(read.name, std::string("classroom robot 3"));
        QCOMPARE(read.front_ir_port, 2);
    }

    void badUmbmarkEntriesAreRefusedPrecisely() {
        UmbmarkDialog dialog(*session_);
        dialog.sideField()->setText(QStringLiteral("2m"));
        fill(*dialog.clockwiseTable(), {"-0.06"}, {"-0.05"});
        fill(*dialog.counterClockwiseTable(), {"0.02"}, {"-0.03"});
        QVERIFY(!dialog.compute());
        QCOMPARE(dialog.messageLabel()->text(), QStringLiteral("Side L (m): '2m' is not a number"));

        dialog.sideField()->setText(QStringLiteral("2"));
        fill(*dialog.counterClockwiseTable(), {"0.02"}, {"-0,03"});
        QVERIFY(!dialog.compute());
        QCOMPARE(dialog.messageLabel()->text(),
                 QStringLiteral("Counter-clockwise: Row 1, y (m): '-0,03' is not a number (use "
                                "a point for decimals)"));

        // Centimetres typed as metres: the library's check, in its words.
        fill(*dialog.counterClockwiseTable(), {"20"}, {"-30"});
        QVERIFY(!dialog.compute());
        const std::optional<lessons::UmbmarkInput> input = dialog.input();
        QVERIFY(input.has_value());
        const std::string expected = what_of([&] { lessons::umbmark(*input); });
        QVERIFY(!expected.empty());
        QCOMPARE(dialog.messageLabel()->text(), QString::fromStdString(expected));
        QVERIFY(!dialog.result().has_value());
        QVERIFY(!dialog.saveButton()->isEnabled());
    }
};

QTEST_MAIN(CalibrationDialogsTest)
#include "test_calibration_dialogs.moc"
