#pragma once
// Tools ▸ IR sensor calibration: (A/D, distance) pairs measured with a target at known
// distances, typed, imported from CSV or taken from the running robot, each saying which
// sensor took it (or not); the paper's curve (eq. 2) D = a·(C_M/(A + C_R) − b) fitted to all
// of them by nonlinear least squares, and each sensor's own curve to its points
// (lessons::fit_ir_calibration, as `legofeup-cli calibrate ir` does); the fits and the
// residuals plotted; C_M, C_R and b saved to the robot profile (docs/calibration.md).

#include <QDialog>
#include <optional>
#include <vector>

#include "legofeup/lessons/calibration/ir_calibration.hpp"

class QCustomPlot;
class QLabel;
class QPushButton;

namespace legofeup::ui {

class NumberTable;
class Session;

class IrCalibrationDialog : public QDialog {
    Q_OBJECT

  public:
    /// Starts the fit from the session's IR curve; takes A/D values from its history.
    explicit IrCalibrationDialog(const Session& session, QWidget* parent = nullptr);
    ~IrCalibrationDialog() override;

    NumberTable* table() const { return table_; }
    QPushButton* fitButton() const { return fit_button_; }
    QPushButton* takeFrontButton() const { return take_front_; }
    QPushButton* takeRearButton() const { return take_rear_; }
    QPushButton* saveButton() const { return save_; }
    QLabel* resultLabel() const { return result_; }
    /// Where problems are shown (a bad cell, too few points, a failed save).
    QLabel* messageLabel() const { return message_; }
    QCustomPlot* curvePlot() const { return curve_plot_; }
    QCustomPlot* residualPlot() const { return residual_plot_; }
    /// The last successful fit of the one curve to every point (nullopt before one, or after
    /// the table changed).
    std::optional<lessons::IrFit> fit() const;
    /// The last successful calibration: that fit and each sensor's own, where it has points.
    const std::optional<lessons::IrCalibration>& calibration() const { return calibration_; }

    /// The table's points, with the sensor each row says took it; nullopt (with the message
    /// shown) if a cell is bad.
    std::optional<std::vector<lessons::IrCalibrationPoint>> points();

  public slots:
    /// Fits eq. 2 to the table's points and shows the result, or says why not.
    bool runFit();
    /// Replaces the table with the points of a CSV file (`adc,distance_m`, optionally
    /// `,sensor`). Returns success.
    bool importCsv(const QString& path);
    /// Writes C_M, C_R and b into the robot profile at `path` (read first if it exists, so
    /// its other values stay): the one curve, and each sensor's own where it was fitted (a
    /// sensor without its own points loses any own curve). Returns success.
    bool saveToProfile(const QString& path);
    /// The A/D of sensor `sensor` (0: front, 1: rear) averaged over the latest frames, into
    /// the selected row (or a new one), which then says that sensor took it. Returns false
    /// when no run is live.
    bool takeCurrentAdc(int sensor);

  private:
    void showProblem(const QString& text);
    void showFit();
    void clearFit();
    void refreshTakeButtons();
    void askImport();
    void askSave();

    const Session& session_;
    SharpIrCurve start_;
    NumberTable* table_ = nullptr;
    QPushButton* fit_button_ = nullptr;
    QPushButton* take_front_ = nullptr;
    QPushButton* take_rear_ = nullptr;
    QPushButton* save_ = nullptr;
    QLabel* result_ = nullptr;
    QLabel* message_ = nullptr;
    QCustomPlot* curve_plot_ = nullptr;
    QCustomPlot* residual_plot_ = nullptr;
    std::optional<lessons::IrCalibration> calibration_;
    std::vector<lessons::IrCalibrationPoint> fitted_points_;
};

/// How many of the latest frames "Take current A/D" averages (a second at 20 Hz).
inline constexpr int kAdcAverageFrames = 20;

}  // namespace legofeup::ui
