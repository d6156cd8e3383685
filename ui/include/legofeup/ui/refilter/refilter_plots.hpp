#pragma once
// The re-filter overlay: the arena seen from above with the true path, the recorded run's
// estimate (the old settings) and the re-filtered one (the new settings), and the position
// error of both over time — the same raw readings, two tunings side by side.

#include <QWidget>
#include <vector>

#include "legofeup/core/walls.hpp"
#include "legofeup/lessons/recording/refilter.hpp"

class QCustomPlot;
class QCPCurve;
class QCPGraph;

namespace legofeup::ui {

class RefilterPlots : public QWidget {
    Q_OBJECT

  public:
    explicit RefilterPlots(QWidget* parent = nullptr);

    /// Draws `result` over the arena's `walls` (may be empty).
    void showResult(const lessons::RefilterResult& result, const std::vector<Wall>& walls);
    void clear();

    QCustomPlot& trajectory() const { return *trajectory_; }
    QCustomPlot& error() const { return *error_; }
    QCPCurve& truthPath() const { return *truth_; }
    QCPCurve& oldPath() const { return *old_path_; }
    QCPCurve& newPath() const { return *new_path_; }
    QCPGraph& oldError() const { return *old_error_; }
    QCPGraph& newError() const { return *new_error_; }

  protected:
    void changeEvent(QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

  private:
    void applyLook();
    void fitTrajectory();

    QCustomPlot* trajectory_ = nullptr;
    QCustomPlot* error_ = nullptr;
    std::vector<QCPCurve*> walls_;
    QCPCurve* truth_ = nullptr;
    QCPCurve* old_path_ = nullptr;
    QCPCurve* new_path_ = nullptr;
    QCPGraph* old_error_ = nullptr;
    QCPGraph* new_error_ = nullptr;
};

}  // namespace legofeup::ui
