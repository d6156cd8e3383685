// small_angle_sincos (small_angle_sincos.hpp) against libm's std::sin and std::cos: on a
// million angles over (−2π, 2π), the range the particle filter's circular mean feeds it,
// at every quadrant boundary, and at 0, where it must be exact (a one-particle cloud then
// publishes its heading to the bit).

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "legofeup/core/angles.hpp"
#include "legofeup/core/small_angle_sincos.hpp"

namespace legofeup {
namespace {

TEST(SmallAngleSincos, AgreesWithLibmWithinTwoUnitsOfTheLastPlace) {
    std::mt19937_64 engine(3);
    std::uniform_real_distribution<double> angle(-2.0 * kPi, 2.0 * kPi);
    double worst = 0.0;
    for (int i = 0; i < 1'000'000; ++i) {
        const double a = angle(engine);
        const SinCos value = small_angle_sincos(a);
        worst =
            std::max({worst, std::abs(value.sin - std::sin(a)), std::abs(value.cos - std::cos(a))});
    }
    EXPECT_LE(worst, 2.3e-16);
}

TEST(SmallAngleSincos, IsRightOnEitherSideOfEveryQuadrantBoundary) {
    for (int k = -4; k <= 4; ++k) {
        const double boundary = (k + 0.5) * kPi / 2.0;  // where the rounding of a·2/π flips
        for (const double a : {std::nextafter(boundary, -10.0), boundary,
                               std::nextafter(boundary, 10.0), k * kPi / 2.0}) {
            const SinCos value = small_angle_sincos(a);
            EXPECT_NEAR(value.sin, std::sin(a), 2.3e-16) << a;
            EXPECT_NEAR(value.cos, std::cos(a), 2.3e-16) << a;
        }
    }
}

TEST(SmallAngleSincos, ZeroGivesExactlyZeroAndOne) {
    const SinCos zero = small_angle_sincos(0.0);
    EXPECT_EQ(zero.sin, 0.0);
    EXPECT_EQ(zero.cos, 1.0);
}

}  // namespace
}  // namespace legofeup
