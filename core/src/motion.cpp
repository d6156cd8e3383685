#include "legofeup/core/motion.hpp"

#include <algorithm>
#include <cmath>

namespace legofeup {

WheelSpeeds limit_wheel_speeds(const WheelSpeeds& wheels, double max_speed) {
    const double largest = std::max(std::abs(wheels.right), std::abs(wheels.left));
    if (largest <= max_speed || !(largest > 0.0)) {
        return wheels;
    }
    const double scale = max_speed / largest;
    return {wheels.right * scale, wheels.left * scale};
}

}  // namespace legofeup
