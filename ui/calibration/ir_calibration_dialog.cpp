#include "legofeup/ui/calibration/ir_calibration_dialog.hpp"

#include <qcustomplot.h>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSplitter>
#include <QVBoxLayout>
#include <algorithm>
#include <array>
#include <cmath>

#include "legofeup/lessons/input_error.hpp"
#include "legofeup/ui/calibration/number_table.hpp"
#include "legofeup/ui/calibration/profile_file.hpp"
#include "legofeup/ui/plots/plot_style.hpp"
#include "legofeup/ui/session/session.hpp"

namespace legofeup::ui {
namespace {

constexpr int kCurvePoints = 200;

QCustomPlot* make_plot(const QString& title, const QString& x_label, const QString& y_label,
                       QWidget* parent) {
    auto* plot = new QCustomPlot(parent);
    plot->setMinimumSize(360, 170);
    plot->plotLayout()->insertRow(0);
    plot->plotLayout()->addElement(0, 0, new QCPTextElement(plot, title));
    plot->xAxis->setLabel(x_label);
    plot->yAxis->setLabel(y_label);
    plot->legend->setVisible(false);
    apply_look(*plot, plot_look(parent->palette(), parent->font(), 1.0));
    return plot;
}

/// The sensor column's choices, in this order: a row that does not say which sensor took it,
/// then front and rear.
constexpr int kNotSaid = 0;
constexpr int kFrontChoice = 1;
constexpr int kRearChoice = 2;

std::optional<IrSensor> sensor_of_choice(int choice) {
    if (choice == kNotSaid) {
        return std::nullopt;
    }
    return choice == kFrontChoice ? kFrontSensor : kRearSensor;
}

int choice_of_sensor(std::optional<IrSensor> sensor) {
    if (!sensor) {
        return kNotSaid;
    }
    return *sensor == kFrontSensor ? kFrontChoice : kRearChoice;
}

/// eq. 2 without the range check: the fitted curve drawn through the points.
double curve_distance(double adc, const SharpIrCurve& curve) {
    return curve.a * (curve.c_m / (adc + curve.c_r) - curve.b);
}

}  // namespace

IrCalibrationDialog::IrCalibrationDialog(const Session& session, QWidget* parent)
    : QDialog(parent), session_(session), start_(session.resolved().loop.ir_curve) {
    setObjectName(QStringLiteral("irCalibrationDialog"));
    setWindowTitle(tr("IR sensor calibration"));

    auto* intro = new QLabel(
        tr("Put a flat target at known distances from the sensor's front face, note the A/D "
           "value at each (or take it from the running robot), then fit the paper's curve "
           "(eq. 2) D = a·(C_M/(A + C_R) − b), a = %1 m. At least 4 points with 3 different "
           "A/D values; 8–12 from 4 cm to 30 cm give a good fit. Points that say which sensor "
           "took them also give that sensor its own curve, as two real sensors differ.")
            .arg(start_.a),
        this);
    intro->setWordWrap(true);

    table_ = new NumberTable({tr("A/D"), tr("distance (m)")}, this,
                             ChoiceColumn{tr("sensor"), {tr("not said"), tr("front"), tr("rear")}});
    table_->setObjectName(QStringLiteral("irPoints"));
    auto* add = new QPushButton(tr("&Add row"), this);
    auto* remove = new QPushButton(tr("Re&move rows"), this);
    auto* import = new QPushButton(tr("&Import CSV…"), this);
    import->setToolTip(
        tr("A CSV file with the header adc,distance_m and one A,D pair a line "
           "(D in metres), or adc,distance_m,sensor and A,D,front or A,D,rear, as "
           "legofeup-cli calibrate ir reads"));
    take_front_ = new QPushButton(tr("Take &front A/D"), this);
    take_rear_ = new QPushButton(tr("Take &rear A/D"), this);
    for (QPushButton* take : {take_front_, take_rear_}) {
        take->setToolTip(tr("The A/D value of the running robot's sensor, averaged over the "
                            "last %1 frames, into the selected row (or a new one), marked "
                            "as that sensor's")
                             .arg(kAdcAverageFrames));
    }
    fit_button_ = new QPushButton(tr("F&it"), this);
    fit_button_->setObjectName(QStringLiteral("irFit"));
    fit_button_->setDefault(true);
    save_ = new QPushButton(tr("&Save to profile…"), this);
    save_->setObjectName(QStringLiteral("irSave"));
    save_->setEnabled(false);

    auto* rows = new QGridLayout;
    rows->addWidget(add, 0, 0);
    rows->addWidget(remove, 0, 1);
    rows->addWidget(import, 0, 2);
    rows->addWidget(take_front_, 1, 0);
    rows->addWidget(take_rear_, 1, 1);
    rows->addWidget(fit_button_, 1, 2);

    // The fit, its quality, each sensor's own curve, saved.
    result_ = result_label(tr("No fit yet."), "irResult", 5, this);
    message_ = message_label("irMessage", this);

    auto* left = new QWidget(this);
    auto* left_layout = new QVBoxLayout(left);
    left_layout->setContentsMargins(0, 0, 0, 0);
    left_layout->addWidget(table_, 1);
    left_layout->addLayout(rows);

    curve_plot_ = make_plot(tr("Distance against A/D: points and the fitted curve"), tr("A/D"),
                            tr("distance (m)"), this);
    curve_plot_->setObjectName(QStringLiteral("irCurvePlot"));
    residual_plot_ =
        make_plot(tr("Residuals: measured − fitted"), tr("A/D"), tr("residual (mm)"), this);
    residual_plot_->setObjectName(QStringLiteral("irResidualPlot"));
    const PlotLook look = plot_look(palette(), font(), 1.0);
    for (QCustomPlot* plot : {curve_plot_, residual_plot_}) {
        QCPGraph* points = plot->addGraph();  // graph 0: the measured points
        points->setLineStyle(QCPGraph::lsNone);
        points->setScatterStyle(
            QCPScatterStyle(QCPScatterStyle::ssCircle, look.series[0], look.series[0], 7));
        points->setName(tr("measured"));
    }
    QCPGraph* fitted = curve_plot_->addGraph();  // graph 1: the fitted curve
    fitted->setPen(QPen(look.series[1], 2.0));
    fitted->setName(tr("fitted eq. 2"));
    QCPGraph* before = curve_plot_->addGraph();  // graph 2: the curve before the fit
    before->setPen(QPen(look.text, 1.0, Qt::DashLine));
    before->setName(tr("before (configuration)"));
    QCPGraph* front_own = curve_plot_->addGraph();  // graph 3: the front sensor's own curve
    front_own->setPen(QPen(look.series[2], 1.5));
    front_own->setName(tr("front sensor's own"));
    QCPGraph* rear_own = curve_plot_->addGraph();  // graph 4: the rear sensor's own curve
    rear_own->setPen(QPen(look.series[3], 1.5));
    rear_own->setName(tr("rear sensor's own"));
    curve_plot_->legend->setVisible(true);
    curve_plot_->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
    auto* zero = new QCPItemStraightLine(residual_plot_);
    zero->point1->setCoords(0.0, 0.0);
    zero->point2->setCoords(1.0, 0.0);
    zero->setPen(QPen(look.text, 1.0, Qt::DotLine));

    auto* plots = new QSplitter(Qt::Vertical, this);
    plots->addWidget(curve_plot_);
    plots->addWidget(residual_plot_);
    plots->setStretchFactor(0, 3);
    plots->setStretchFactor(1, 2);
    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(left);
    split->addWidget(plots);
    split->setStretchFactor(0, 2);
    split->setStretchFactor(1, 3);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(save_, QDialogButtonBox::ActionRole);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addWidget(split, 1);
    layout->addWidget(result_);
    layout->addWidget(message_);
    layout->addWidget(buttons);

    connect(add, &QPushButton::clicked, this, [this] {
        table_->setCurrentCell(table_->addRow(), 0);
        table_->editItem(table_->currentItem());
    });
    connect(remove, &QPushButton::clicked, table_, &NumberTable::removeSelectedRows);
    connect(import, &QPushButton::clicked, this, &IrCalibrationDialog::askImport);
    connect(take_front_, &QPushButton::clicked, this, [this] { takeCurrentAdc(0); });
    connect(take_rear_, &QPushButton::clicked, this, [this] { takeCurrentAdc(1); });
    connect(fit_button_, &QPushButton::clicked, this, &IrCalibrationDialog::runFit);
    connect(save_, &QPushButton::clicked, this, &IrCalibrationDialog::askSave);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(table_, &QTableWidget::itemChanged, this, &IrCalibrationDialog::clearFit);
    connect(table_->model(), &QAbstractItemModel::rowsRemoved, this,
            &IrCalibrationDialog::clearFit);
    connect(&session_, &Session::phaseChanged, this, &IrCalibrationDialog::refreshTakeButtons);
    connect(&session_, &Session::samplesAppended, this, &IrCalibrationDialog::refreshTakeButtons);

    for (int i = 0; i < 4; ++i) {
        table_->addRow();
    }
    refreshTakeButtons();
    showFit();
    resize(1100, 640);
}

IrCalibrationDialog::~IrCalibrationDialog() = default;

void IrCalibrationDialog::showProblem(const QString& text) {
    message_->setText(text);
}

std::optional<std::vector<lessons::IrCalibrationPoint>> IrCalibrationDialog::points() {
    QString problem;
    const auto rows = table_->rows(&problem);
    if (!rows) {
        showProblem(problem);
        return std::nullopt;
    }
    std::vector<lessons::IrCalibrationPoint> points;
    points.reserve(rows->size());
    for (const NumberTable::Row& row : *rows) {
        points.push_back({row.numbers[0], row.numbers[1], sensor_of_choice(row.choice)});
    }
    return points;
}

std::optional<lessons::IrFit> IrCalibrationDialog::fit() const {
    return calibration_ ? std::optional(calibration_->both) : std::nullopt;
}

bool IrCalibrationDialog::runFit() {
    showProblem({});
    const std::optional<std::vector<lessons::IrCalibrationPoint>> measured = points();
    if (!measured) {
        return false;
    }
    try {
        calibration_ = lessons::fit_ir_calibration(*measured, start_, {});
    } catch (const lessons::InputError& error) {
        clearFit();
        showProblem(QString::fromUtf8(error.what()));
        return false;
    }
    fitted_points_ = *measured;
    showFit();
    save_->setEnabled(true);
    return true;
}

void IrCalibrationDialog::clearFit() {
    if (!calibration_) {
        return;
    }
    calibration_.reset();
    save_->setEnabled(false);
    result_->setText(tr("The points changed: fit again."));
}

void IrCalibrationDialog::showFit() {
    QCPGraph* measured = curve_plot_->graph(0);
    QCPGraph* fitted = curve_plot_->graph(1);
    QCPGraph* before = curve_plot_->graph(2);
    QCPGraph* residuals = residual_plot_->graph(0);
    const std::array<QCPGraph*, kIrSensorCount> own_curves{curve_plot_->graph(3),
                                                           curve_plot_->graph(4)};
    for (QCPGraph* graph : {measured, fitted, before, residuals, own_curves[0], own_curves[1]}) {
        graph->data()->clear();
    }
    double lowest = 0.0;
    double highest = start_.adc_max;
    if (calibration_) {
        const lessons::IrFit& both = calibration_->both;
        const SharpIrCurve& curve = both.curve;
        QStringList lines{
            tr("C_M = %1   C_R = %2   b = %3   (a = %4 m)\n"
               "RMS residual %5 mm, largest %6 mm, over %7 points; %8 after %9 iterations.")
                .arg(curve.c_m, 0, 'g', 6)
                .arg(curve.c_r, 0, 'g', 5)
                .arg(curve.b, 0, 'g', 5)
                .arg(curve.a)
                .arg(both.rms_residual * 1000.0, 0, 'f', 2)
                .arg(both.max_abs_residual * 1000.0, 0, 'f', 2)
                .arg(fitted_points_.size())
                .arg(both.converged ? tr("converged") : tr("NOT converged"))
                .arg(both.iterations)};
        for (const IrSensor sensor : {kFrontSensor, kRearSensor}) {
            const auto& own = calibration_->own[static_cast<std::size_t>(sensor)];
            if (!own) {
                continue;
            }
            const QString text =
                sensor == kFrontSensor
                    ? tr(
                        "Front sensor's own curve: C_M = %1   C_R = %2   b = %3; RMS residual "
                        "%4 mm over %5 points.")
                    : tr(
                        "Rear sensor's own curve: C_M = %1   C_R = %2   b = %3; RMS residual "
                        "%4 mm over %5 points.");
            lines << text.arg(own->curve.c_m, 0, 'g', 6)
                         .arg(own->curve.c_r, 0, 'g', 5)
                         .arg(own->curve.b, 0, 'g', 5)
                         .arg(own->rms_residual * 1000.0, 0, 'f', 2)
                         .arg(own->residuals.size());
        }
        result_->setText(lines.join(QLatin1Char('\n')));
        const auto [min_point, max_point] =
            std::minmax_element(fitted_points_.begin(), fitted_points_.end(),
                                [](const auto& p, const auto& q) { return p.adc < q.adc; });
        const double margin = 0.05 * (max_point->adc - min_point->adc);
        lowest = std::max({min_point->adc - margin, 0.0, -curve.c_r + 1.0, -start_.c_r + 1.0});
        highest = std::min(max_point->adc + margin, static_cast<double>(start_.adc_max));
        for (std::size_t i = 0; i < fitted_points_.size(); ++i) {
            measured->addData(fitted_points_[i].adc, fitted_points_[i].distance);
            residuals->addData(fitted_points_[i].adc, both.residuals[i] * 1000.0);
        }
        for (int i = 0; i <= kCurvePoints; ++i) {
            const double adc = lowest + (highest - lowest) * i / kCurvePoints;
            fitted->addData(adc, curve_distance(adc, curve));
            before->addData(adc, curve_distance(adc, start_));
            for (std::size_t sensor = 0; sensor < kIrSensorCount; ++sensor) {
                if (const auto& own = calibration_->own[sensor]) {
                    own_curves[sensor]->addData(adc, curve_distance(adc, own->curve));
                }
            }
        }
    }
    for (QCustomPlot* plot : {curve_plot_, residual_plot_}) {
        plot->xAxis->setRange(lowest, highest);
        bool found = false;
        QCPRange values = plot->graph(0)->getValueRange(found);
        if (plot == curve_plot_ && found) {
            values.expand(QCPRange(0.0, values.upper * 1.1));
        } else if (found) {
            const double span = std::max(std::abs(values.lower), std::abs(values.upper));
            values = QCPRange(-1.2 * span - 0.1, 1.2 * span + 0.1);
        } else {
            values = plot == curve_plot_ ? QCPRange(0.0, 0.35) : QCPRange(-5.0, 5.0);
        }
        plot->yAxis->setRange(values);
        plot->replot();
    }
}

bool IrCalibrationDialog::importCsv(const QString& path) {
    try {
        const std::vector<lessons::IrCalibrationPoint> read =
            lessons::read_ir_points_csv(path.toStdString());
        std::vector<std::vector<double>> rows;
        rows.reserve(read.size());
        for (const lessons::IrCalibrationPoint& point : read) {
            rows.push_back({point.adc, point.distance});
        }
        table_->setRows(rows);
        for (std::size_t row = 0; row < read.size(); ++row) {
            table_->setChoice(static_cast<int>(row), choice_of_sensor(read[row].sensor));
        }
    } catch (const lessons::InputError& error) {
        showProblem(QString::fromUtf8(error.what()));
        return false;
    }
    showProblem({});
    clearFit();
    return true;
}

void IrCalibrationDialog::askImport() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Import IR measurements"), {},
                                                      tr("CSV files (*.csv);;All files (*)"));
    if (!path.isEmpty()) {
        importCsv(path);
    }
}

bool IrCalibrationDialog::saveToProfile(const QString& path) {
    if (!calibration_) {
        showProblem(tr("Fit first: there is nothing to save."));
        return false;
    }
    return save_and_report(
        path,
        [this](lessons::RobotProfile& profile) {
            lessons::apply_ir_calibration(profile, *calibration_);
        },
        *result_, *message_);
}

void IrCalibrationDialog::askSave() {
    const QString path = ask_profile_path(this, session_.linkChoice().robot_profile);
    if (!path.isEmpty()) {
        saveToProfile(path);
    }
}

bool IrCalibrationDialog::takeCurrentAdc(int sensor) {
    const RunHistory& history = session_.history();
    if (!session_.running() || history.empty()) {
        showProblem(tr("No run is live: start one (with the robot facing the target) first."));
        return false;
    }
    double sum = 0.0;
    int count = 0;
    // The latest steps, which the history keeps whole.
    for (std::size_t i = history.size(); i > history.recent_begin() && count < kAdcAverageFrames;
         --i) {
        const LoopSnapshot& snapshot = history.sample(i - 1)->snapshot;
        if (!snapshot.frame_missing) {
            sum += snapshot.ir[static_cast<std::size_t>(sensor)].adc;
            ++count;
        }
    }
    if (count == 0) {
        showProblem(tr("No frame has come from the robot yet."));
        return false;
    }
    int row = table_->currentRow();
    if (row < 0) {
        row = table_->addRow();
    }
    table_->setNumber(row, 0, std::round(sum / count * 10.0) / 10.0);
    table_->setChoice(row, sensor == 0 ? kFrontChoice : kRearChoice);
    table_->setCurrentCell(row, 1);
    showProblem({});
    return true;
}

void IrCalibrationDialog::refreshTakeButtons() {
    const bool live = session_.running() && !session_.history().empty();
    take_front_->setEnabled(live);
    take_rear_->setEnabled(live);
}

}  // namespace legofeup::ui
