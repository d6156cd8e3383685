#include "legofeup/ui/calibration/umbmark_dialog.hpp"

#include <qcustomplot.h>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>
#include <cmath>
#include <numbers>

#include "legofeup/core/angles.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/ui/calibration/number_table.hpp"
#include "legofeup/ui/calibration/profile_file.hpp"
#include "legofeup/ui/panels/number_text.hpp"
#include "legofeup/ui/plots/plot_style.hpp"
#include "legofeup/ui/session/session.hpp"

namespace legofeup::ui {
namespace {

/// The odometry in use: the run's robot profile if it has one that loads, else the
/// configuration's robot (Codo given as counts per metre turned back into diameters).
lessons::UmbmarkInput odometry_in_use(const Session& session) {
    lessons::UmbmarkInput input;
    input.side = 2.0;
    const QString profile_path = session.linkChoice().robot_profile;
    if (!profile_path.isEmpty() && QFileInfo::exists(profile_path)) {
        try {
            const lessons::RobotProfile profile =
                lessons::load_robot_profile(profile_path.toStdString());
            input.wheel_base = profile.wheel_base;
            input.right_wheel_diameter = profile.right_wheel_diameter;
            input.left_wheel_diameter = profile.left_wheel_diameter;
            input.counts_per_turn = lessons::kNxtCountsPerTurn;
            return input;
        } catch (const lessons::InputError&) {
            // Fall back to the configuration: the dialog's fields can be corrected by hand.
        }
    }
    const lessons::RobotGeometry& robot = session.config().robot;
    const auto diameter = [&](double codo) {
        return codo > 0.0 ? robot.counts_per_turn / (std::numbers::pi * codo)
                          : robot.wheel_diameter;
    };
    input.wheel_base = robot.wheel_base;
    input.right_wheel_diameter = diameter(robot.codo_right);
    input.left_wheel_diameter = diameter(robot.codo_left);
    input.counts_per_turn = robot.counts_per_turn;
    return input;
}

QLineEdit* number_field(double value, const char* name, QWidget* parent) {
    auto* field = new QLineEdit(number_text(value), parent);
    field->setObjectName(QLatin1String(name));
    return field;
}

QString metres(double value) {
    return QStringLiteral("%1 mm").arg(value * 1000.0, 0, 'f', 2);
}

}  // namespace

UmbmarkDialog::UmbmarkDialog(const Session& session, QWidget* parent)
    : QDialog(parent), session_(session) {
    setObjectName(QStringLiteral("umbmarkDialog"));
    setWindowTitle(tr("Odometry calibration (UMBmark)"));
    const lessons::UmbmarkInput start = odometry_in_use(session);

    auto* intro = new QLabel(
        tr("Drive the square of side L with odometry only (experiment a's path, no wall "
           "updates), clockwise and counter-clockwise, at least 5 times each. After each run "
           "measure where the robot stopped relative to where it started: x along the first "
           "side, y to the robot's left at the start, in metres. Borenstein & Feng (1996)."),
        this);
    intro->setWordWrap(true);

    auto* square = new QGroupBox(tr("The square and the odometry in use"), this);
    auto* form = new QFormLayout(square);
    side_ = number_field(start.side, "umbSide", square);
    wheel_base_ = number_field(start.wheel_base, "umbWheelBase", square);
    right_diameter_ = number_field(start.right_wheel_diameter, "umbRightDiameter", square);
    left_diameter_ = number_field(start.left_wheel_diameter, "umbLeftDiameter", square);
    counts_ = number_field(start.counts_per_turn, "umbCounts", square);
    form->addRow(tr("Side L (m):"), side_);
    form->addRow(tr("Wheel base b (m):"), wheel_base_);
    form->addRow(tr("Right wheel D_R (m):"), right_diameter_);
    form->addRow(tr("Left wheel D_L (m):"), left_diameter_);
    form->addRow(tr("Counts per turn:"), counts_);

    const QStringList columns{tr("x (m)"), tr("y (m)")};
    const auto runs = [&](const QString& title, NumberTable*& table, const char* name) {
        auto* box = new QGroupBox(title, this);
        table = new NumberTable(columns, box);
        table->setObjectName(QLatin1String(name));
        auto* add = new QPushButton(tr("Add row"), box);
        auto* remove = new QPushButton(tr("Remove rows"), box);
        connect(add, &QPushButton::clicked, table, [table] {
            table->setCurrentCell(table->addRow(), 0);
            table->editItem(table->currentItem());
        });
        connect(remove, &QPushButton::clicked, table, &NumberTable::removeSelectedRows);
        connect(table, &QTableWidget::itemChanged, this, &UmbmarkDialog::clearResult);
        connect(table->model(), &QAbstractItemModel::rowsRemoved, this,
                &UmbmarkDialog::clearResult);
        auto* buttons = new QHBoxLayout;
        buttons->addWidget(add);
        buttons->addWidget(remove);
        buttons->addStretch(1);
        auto* layout = new QVBoxLayout(box);
        layout->addWidget(table, 1);
        layout->addLayout(buttons);
        for (int i = 0; i < 5; ++i) {
            table->addRow();
        }
        return box;
    };
    QGroupBox* cw_box = runs(tr("Clockwise runs: return errors"), clockwise_, "umbClockwise");
    QGroupBox* ccw_box = runs(tr("Counter-clockwise runs: return errors"), counter_clockwise_,
                              "umbCounterClockwise");

    compute_ = new QPushButton(tr("&Compute"), this);
    compute_->setObjectName(QStringLiteral("umbCompute"));
    compute_->setDefault(true);
    save_ = new QPushButton(tr("&Save to profile…"), this);
    save_->setObjectName(QStringLiteral("umbSave"));
    save_->setEnabled(false);
    result_ = result_label(tr("Enter the return errors, then Compute."), "umbResult", 6,
                           this);  // five lines and "saved"
    message_ = message_label("umbMessage", this);

    plot_ = new QCustomPlot(this);
    plot_->setObjectName(QStringLiteral("umbPlot"));
    plot_->setMinimumSize(320, 280);
    plot_->plotLayout()->insertRow(0);
    plot_->plotLayout()->addElement(0, 0, new QCPTextElement(plot_, tr("Return errors")));
    plot_->xAxis->setLabel(tr("x (m)"));
    plot_->yAxis->setLabel(tr("y (m)"));
    const PlotLook look = plot_look(palette(), font(), 1.0);
    apply_look(*plot_, look);
    const auto scatter = [&](const QString& name, const QColor& colour,
                             QCPScatterStyle::ScatterShape shape, double size) {
        QCPGraph* graph = plot_->addGraph();
        graph->setName(name);
        graph->setLineStyle(QCPGraph::lsNone);
        graph->setScatterStyle(QCPScatterStyle(shape, colour, colour, size));
    };
    scatter(tr("clockwise"), look.series[0], QCPScatterStyle::ssCircle, 7);
    scatter(tr("counter-clockwise"), look.series[1], QCPScatterStyle::ssSquare, 7);
    scatter(tr("centres of gravity"), look.text, QCPScatterStyle::ssCrossCircle, 13);
    plot_->legend->setVisible(true);

    auto* left = new QVBoxLayout;
    left->addWidget(square);
    left->addWidget(cw_box, 1);
    left->addWidget(ccw_box, 1);
    auto* right = new QVBoxLayout;
    right->addWidget(plot_, 1);
    right->addWidget(result_);
    right->addWidget(message_);
    auto* columns_layout = new QHBoxLayout;
    columns_layout->addLayout(left, 2);
    columns_layout->addLayout(right, 3);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(compute_, QDialogButtonBox::ActionRole);
    buttons->addButton(save_, QDialogButtonBox::ActionRole);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(columns_layout, 1);
    layout->addWidget(buttons);

    connect(compute_, &QPushButton::clicked, this, &UmbmarkDialog::compute);
    connect(save_, &QPushButton::clicked, this, [this] {
        const QString path = ask_profile_path(this, session_.linkChoice().robot_profile);
        if (!path.isEmpty()) {
            saveToProfile(path);
        }
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    for (QLineEdit* field : {side_, wheel_base_, right_diameter_, left_diameter_, counts_}) {
        connect(field, &QLineEdit::textEdited, this, &UmbmarkDialog::clearResult);
    }
    showResult();
    resize(1100, 720);
}

UmbmarkDialog::~UmbmarkDialog() = default;

void UmbmarkDialog::showProblem(const QString& text) {
    message_->setText(text);
}

std::optional<lessons::UmbmarkInput> UmbmarkDialog::input() {
    lessons::UmbmarkInput input;
    const std::array<std::pair<QLineEdit*, double*>, 5> fields = {{
        {side_, &input.side},
        {wheel_base_, &input.wheel_base},
        {right_diameter_, &input.right_wheel_diameter},
        {left_diameter_, &input.left_wheel_diameter},
        {counts_, &input.counts_per_turn},
    }};
    const QFormLayout* form = qobject_cast<QFormLayout*>(side_->parentWidget()->layout());
    for (const auto& [field, value] : fields) {
        const std::optional<double> number = parse_number(field->text());
        if (!number) {
            QString name = field->objectName();
            if (form != nullptr) {
                if (auto* label = qobject_cast<QLabel*>(form->labelForField(field))) {
                    name = label->text().remove(QLatin1Char(':'));
                }
            }
            showProblem(tr("%1: '%2' is not a number").arg(name, field->text().trimmed()));
            field->setFocus();
            return std::nullopt;
        }
        *value = *number;
    }
    const auto read_runs = [this](NumberTable* table, const QString& which,
                                  std::vector<Vector2>& errors) {
        QString problem;
        const auto rows = table->numbers(&problem);
        if (!rows) {
            showProblem(QStringLiteral("%1: %2").arg(which, problem));
            return false;
        }
        for (const std::vector<double>& row : *rows) {
            errors.emplace_back(row[0], row[1]);
        }
        return true;
    };
    if (!read_runs(clockwise_, tr("Clockwise"), input.clockwise)
        || !read_runs(counter_clockwise_, tr("Counter-clockwise"), input.counter_clockwise)) {
        return std::nullopt;
    }
    return input;
}

bool UmbmarkDialog::compute() {
    showProblem({});
    std::optional<lessons::UmbmarkInput> measured = input();
    if (!measured) {
        clearResult();
        return false;
    }
    try {
        computed_ = lessons::umbmark(*measured);
    } catch (const lessons::InputError& error) {
        clearResult();
        showProblem(QString::fromUtf8(error.what()));
        return false;
    }
    used_ = std::move(measured);
    showResult();
    save_->setEnabled(true);
    return true;
}

void UmbmarkDialog::clearResult() {
    if (!computed_) {
        return;
    }
    computed_.reset();
    used_.reset();
    save_->setEnabled(false);
    result_->setText(tr("The entries changed: compute again."));
    showResult();
}

void UmbmarkDialog::showResult() {
    for (int i = 0; i < plot_->graphCount(); ++i) {
        plot_->graph(i)->data()->clear();
    }
    double extent = 0.05;
    if (computed_ && used_) {
        const lessons::UmbmarkResult& r = *computed_;
        for (const Vector2& error : used_->clockwise) {
            plot_->graph(0)->addData(error.x(), error.y());
            extent = std::max({extent, std::abs(error.x()), std::abs(error.y())});
        }
        for (const Vector2& error : used_->counter_clockwise) {
            plot_->graph(1)->addData(error.x(), error.y());
            extent = std::max({extent, std::abs(error.x()), std::abs(error.y())});
        }
        plot_->graph(2)->addData(r.centre_cw.x(), r.centre_cw.y());
        plot_->graph(2)->addData(r.centre_ccw.x(), r.centre_ccw.y());
        result_->setText(tr("Centres of gravity: cw (%1, %2), ccw (%3, %4); E_max,syst = %5\n"
                            "α = %6°, β = %7° (from x: %8°, %9°; from y: %10°, %11°)\n"
                            "E_d = D_R/D_L = %12     E_b = b_actual/b = %13\n"
                            "Corrected: D_R = %14 m, D_L = %15 m, b = %16 m\n"
                            "Codo_R = %17, Codo_L = %18 counts/m")
                             .arg(metres(r.centre_cw.x()), metres(r.centre_cw.y()),
                                  metres(r.centre_ccw.x()), metres(r.centre_ccw.y()),
                                  metres(r.e_max_syst))
                             .arg(radians_to_degrees(r.alpha), 0, 'f', 3)
                             .arg(radians_to_degrees(r.beta), 0, 'f', 3)
                             .arg(radians_to_degrees(r.alpha_from_x), 0, 'f', 3)
                             .arg(radians_to_degrees(r.beta_from_x), 0, 'f', 3)
                             .arg(radians_to_degrees(r.alpha_from_y), 0, 'f', 3)
                             .arg(radians_to_degrees(r.beta_from_y), 0, 'f', 3)
                             .arg(r.e_d, 0, 'f', 5)
                             .arg(r.e_b, 0, 'f', 5)
                             .arg(r.right_wheel_diameter, 0, 'f', 6)
                             .arg(r.left_wheel_diameter, 0, 'f', 6)
                             .arg(r.wheel_base, 0, 'f', 5)
                             .arg(r.codo_right, 0, 'f', 2)
                             .arg(r.codo_left, 0, 'f', 2));
    }
    plot_->xAxis->setRange(-1.2 * extent, 1.2 * extent);
    plot_->yAxis->setRange(-1.2 * extent, 1.2 * extent);
    plot_->replot();
}

bool UmbmarkDialog::saveToProfile(const QString& path) {
    if (!computed_) {
        showProblem(tr("Compute first: there is nothing to save."));
        return false;
    }
    return save_and_report(
        path, [this](lessons::RobotProfile& profile) { apply_umbmark(profile, *computed_); },
        *result_, *message_);
}

}  // namespace legofeup::ui
