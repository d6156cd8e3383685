#include "legofeup/core/accelerometer_bias.hpp"

#include <cmath>

namespace legofeup {

void AccelerometerBiasEstimator::reset() {
    *this = AccelerometerBiasEstimator{};
}

void AccelerometerBiasEstimator::add(const std::array<double, 2>& acceleration,
                                     const std::array<double, 2>& wheel_speed, double period_s) {
    for (std::size_t i = 0; i < 2; ++i) {
        if (!std::isfinite(acceleration[i]) || !std::isfinite(wheel_speed[i])) {
            return;
        }
    }
    if (!std::isfinite(period_s) || !(period_s > 0.0)) {
        return;
    }
    if (!have_speed_) {
        // The first speeds are the reference u_0: nothing to compare the reading with yet.
        last_speed_ = wheel_speed;
        have_speed_ = true;
        return;
    }
    for (std::size_t i = 0; i < 2; ++i) {
        sum_[i] += acceleration[i] * period_s - (wheel_speed[i] - last_speed_[i]);
    }
    last_speed_ = wheel_speed;
    time_ += period_s;
}

std::array<double, 2> AccelerometerBiasEstimator::bias() const {
    const double weight = time_ + kPriorSeconds;  // t + τ₀
    return {sum_[0] / weight, sum_[1] / weight};
}

}  // namespace legofeup
