#pragma once
// The covariance matrix P of the latest step, shown numerically (paper Fig. 9 a), with the
// standard deviations and the step's wall update: what a student reads off while the ellipse
// grows and collapses. A wall the association refused is named with the test that refused it
// (the fixed angle or distance gate with its error and limit, or the Mahalanobis gate with
// d² and its χ² threshold).

#include <QWidget>
#include <array>

class QLabel;

namespace legofeup {
struct LoopSnapshot;
}

namespace legofeup::ui {

class RunHistory;
struct ArenaScene;

class CovarianceView : public QWidget {
    Q_OBJECT

  public:
    explicit CovarianceView(const RunHistory& history, QWidget* parent = nullptr);

    /// The text shown in cell (row, column) of P.
    QString cellText(int row, int column) const;
    /// The line under the σs: the step's wall update, or why there was none.
    QString updateText() const;

    /// What the association and the update of a wall-lesson step did, as that line says it.
    static QString wallUpdateText(const LoopSnapshot& snapshot, const ArenaScene& scene);

  public slots:
    void historyRestarted();
    void samplesAppended(int first, int count);

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void showLatest();
    /// The laser lesson's line: the latest scan's match and its innovation, or why not.
    void showLaserUpdate();
    void useMonospaceFont();

    const RunHistory& history_;
    std::array<QLabel*, 9> cells_{};
    QLabel* sigmas_ = nullptr;
    QLabel* update_ = nullptr;
};

}  // namespace legofeup::ui
