#include "legofeup/core/odometry_alphas.hpp"

#include <algorithm>
#include <cmath>

#include "legofeup/core/angles.hpp"

namespace legofeup {
namespace {

/// A rotation's size for its noise: |δ|, or π − |δ| when that is smaller (driving backwards
/// turns by ≈ ±π towards the direction of travel without turning the robot).
double rotation_size(double rotation) {
    const double size = std::abs(rotation);
    return std::min(size, kPi - size);
}

/// Below this translation (m) the direction of travel is undefined: δ_rot1 = 0 and the
/// whole turn is δ_rot2, as for a turn on the spot.
constexpr double kNoTranslation = 1e-9;

}  // namespace

StateVector add_odometry_alpha_noise(const StateVector& from, const StateVector& noiseless,
                                     const StateVector& moved, const OdometryAlphas& alphas,
                                     RandomStream& random) {
    // The noise-free motion in the book's three parts (Table 5.6 lines 2–4).
    const double dx = noiseless(kX) - from(kX);
    const double dy = noiseless(kY) - from(kY);
    const double translation = std::hypot(dx, dy);
    const double rot1 =
        translation < kNoTranslation ? 0.0 : wrap_angle(std::atan2(dy, dx) - from(kTheta));
    const double rot2 = wrap_angle(noiseless(kTheta) - from(kTheta) - rot1);
    const double r1 = rotation_size(rot1);
    const double r2 = rotation_size(rot2);
    const double t2 = translation * translation;
    // Their errors (lines 5–7).
    const double e_rot1 =
        std::sqrt(alphas.rotation_from_rotation * r1 * r1 + alphas.rotation_from_translation * t2)
        * random.normal();
    const double e_trans = std::sqrt(alphas.translation_from_translation * t2
                                     + alphas.translation_from_rotation * (r1 * r1 + r2 * r2))
                           * random.normal();
    const double e_rot2 =
        std::sqrt(alphas.rotation_from_rotation * r2 * r2 + alphas.rotation_from_translation * t2)
        * random.normal();
    // The noisy motion (lines 8–10) less the noise-free one, added to the pose Q moved.
    const double direction = from(kTheta) + rot1;
    const double noisy_direction = direction + e_rot1;
    const double noisy_translation = translation + e_trans;
    return {moved(kX) + noisy_translation * std::cos(noisy_direction) - dx,
            moved(kY) + noisy_translation * std::sin(noisy_direction) - dy,
            wrap_angle(moved(kTheta) + e_rot1 + e_rot2)};
}

}  // namespace legofeup
