#pragma once
// A slider over decades for variances (Q, R, P0): students sweep 1e-12 … 1e3 in one drag and
// see the filter respond. The slider only proposes values; the exact one is typed next to it.

#include <QSlider>

namespace legofeup::ui {

class LogSlider : public QSlider {
    Q_OBJECT

  public:
    /// Spans 10^min_decade … 10^max_decade in steps of a twentieth of a decade.
    LogSlider(int min_decade, int max_decade, QWidget* parent = nullptr);

    /// Shows `value` (out-of-span values sit at the end; ≤ 0 at the start) without emitting.
    void showValue(double value);
    /// The value at a slider position, rounded to two significant digits (1.1e-05, not
    /// 1.12201845e-05), so what the slider proposes is what a student would type.
    double valueAt(int position) const;

  signals:
    void valueProposed(double value);

  private:
    static constexpr int kStepsPerDecade = 20;
};

}  // namespace legofeup::ui
