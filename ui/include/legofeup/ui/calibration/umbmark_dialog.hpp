#pragma once
// Tools ▸ Odometry calibration (UMBmark): the robot drives a square clockwise and
// counter-clockwise on odometry alone; the student measures where it stopped each time and
// enters the return errors; lessons::umbmark gives the wheel-diameter ratio E_d, the wheel
// base factor E_b and the corrected diameters, wheel base and Codo, saved to the robot
// profile (docs/calibration.md).

#include <QDialog>
#include <optional>

#include "legofeup/lessons/calibration/umbmark.hpp"

class QCustomPlot;
class QLabel;
class QLineEdit;
class QPushButton;

namespace legofeup::ui {

class NumberTable;
class Session;

class UmbmarkDialog : public QDialog {
    Q_OBJECT

  public:
    /// The odometry being corrected starts as the run's profile's (if it loads) or the
    /// configuration's robot.
    explicit UmbmarkDialog(const Session& session, QWidget* parent = nullptr);
    ~UmbmarkDialog() override;

    QLineEdit* sideField() const { return side_; }
    QLineEdit* wheelBaseField() const { return wheel_base_; }
    QLineEdit* rightDiameterField() const { return right_diameter_; }
    QLineEdit* leftDiameterField() const { return left_diameter_; }
    QLineEdit* countsField() const { return counts_; }
    NumberTable* clockwiseTable() const { return clockwise_; }
    NumberTable* counterClockwiseTable() const { return counter_clockwise_; }
    QPushButton* computeButton() const { return compute_; }
    QPushButton* saveButton() const { return save_; }
    QLabel* resultLabel() const { return result_; }
    QLabel* messageLabel() const { return message_; }
    QCustomPlot* errorPlot() const { return plot_; }
    const std::optional<lessons::UmbmarkResult>& result() const { return computed_; }

    /// What the fields and tables say; nullopt (with the message shown) if one is bad.
    std::optional<lessons::UmbmarkInput> input();

  public slots:
    /// Computes UMBmark's corrections and shows them, or says why not.
    bool compute();
    /// Writes the corrected diameters and wheel base into the profile at `path` (read
    /// first if it exists). Returns success.
    bool saveToProfile(const QString& path);

  private:
    void showProblem(const QString& text);
    void showResult();
    void clearResult();

    const Session& session_;
    QLineEdit* side_ = nullptr;
    QLineEdit* wheel_base_ = nullptr;
    QLineEdit* right_diameter_ = nullptr;
    QLineEdit* left_diameter_ = nullptr;
    QLineEdit* counts_ = nullptr;
    NumberTable* clockwise_ = nullptr;
    NumberTable* counter_clockwise_ = nullptr;
    QPushButton* compute_ = nullptr;
    QPushButton* save_ = nullptr;
    QLabel* result_ = nullptr;
    QLabel* message_ = nullptr;
    QCustomPlot* plot_ = nullptr;
    std::optional<lessons::UmbmarkInput> used_;
    std::optional<lessons::UmbmarkResult> computed_;
};

}  // namespace legofeup::ui
