#include "legofeup/core/angles.hpp"

#include <cmath>

namespace legofeup {

double wrap_angle_slow(double angle) {
    const double wrapped = std::remainder(angle, 2.0 * kPi);  // in [−π, π]
    return wrapped <= -kPi ? wrapped + 2.0 * kPi : wrapped;
}

}  // namespace legofeup
