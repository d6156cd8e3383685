#include "legofeup/ui/panels/log_slider.hpp"

#include <QSignalBlocker>
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

namespace legofeup::ui {

LogSlider::LogSlider(int min_decade, int max_decade, QWidget* parent)
    : QSlider(Qt::Horizontal, parent) {
    setRange(min_decade * kStepsPerDecade, max_decade * kStepsPerDecade);
    setPageStep(kStepsPerDecade);
    setFocusPolicy(Qt::StrongFocus);
    connect(this, &QSlider::valueChanged, this,
            [this](int position) { emit valueProposed(valueAt(position)); });
}

void LogSlider::showValue(double value) {
    const QSignalBlocker blocker(this);
    const double position =
        value > 0.0 ? std::round(std::log10(value) * kStepsPerDecade) : minimum();
    setValue(static_cast<int>(
        std::clamp(position, static_cast<double>(minimum()), static_cast<double>(maximum()))));
}

double LogSlider::valueAt(int position) const {
    const double exact = std::pow(10.0, static_cast<double>(position) / kStepsPerDecade);
    // Through text, so the result is the double "1.1e-05" reads as, not 11 × 1e-06.
    std::array<char, 32> text{};
    const auto written =
        std::to_chars(text.data(), text.data() + text.size(), exact, std::chars_format::general, 2);
    double rounded = exact;
    std::from_chars(text.data(), written.ptr, rounded);
    return rounded;
}

}  // namespace legofeup::ui
