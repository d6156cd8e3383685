#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "legofeup/core/sharp_ir.hpp"

namespace legofeup {
namespace {

// The published GP2D120 linearisation, written out independently: R[cm] = 2914/(A + 5) − 1.
double published_distance_cm(double adc) {
    return 2914.0 / (adc + 5.0) - 1.0;
}

TEST(SharpIr, DefaultCurveIsThePublishedGp2d120Fit) {
    const SharpIrCurve curve;
    for (double adc : {90.0, 150.0, 300.0, 500.0, 570.0}) {
        EXPECT_NEAR(distance_from_adc(adc, curve).distance, published_distance_cm(adc) / 100.0,
                    1e-12)
            << "A = " << adc;
    }
}

TEST(SharpIr, ValidityRangeIsFourToThirtyCentimetres) {
    const SharpIrCurve curve;
    // 4 cm ⇔ A = 2914/5 − 5 = 577.8 and 30 cm ⇔ A = 2914/31 − 5 = 89.0 (hand-worked).
    EXPECT_NEAR(adc_from_distance(0.04, curve), 577.8, 1e-9);
    EXPECT_NEAR(adc_from_distance(0.30, curve), 2914.0 / 31.0 - 5.0, 1e-9);
    EXPECT_EQ(distance_from_adc(577.0, curve).status, IrStatus::InRange);
    EXPECT_EQ(distance_from_adc(579.0, curve).status, IrStatus::TooClose);
    EXPECT_EQ(distance_from_adc(90.0, curve).status, IrStatus::InRange);
    EXPECT_EQ(distance_from_adc(88.0, curve).status, IrStatus::TooFar);
    EXPECT_EQ(distance_from_adc(0.0, curve).status, IrStatus::TooFar);
}

TEST(SharpIr, NonPositiveDenominatorIsInfinitelyFar) {
    const SharpIrCurve curve;
    const IrDistance reading = distance_from_adc(-5.0, curve);  // A + C_R = 0
    EXPECT_EQ(reading.status, IrStatus::TooFar);
    EXPECT_TRUE(std::isinf(reading.distance));
}

TEST(SharpIr, InverseRoundTripsOverTheFittedRange) {
    const SharpIrCurve curve;
    for (double d = 0.03; d <= 0.8; d += 0.001) {
        EXPECT_NEAR(distance_from_adc(adc_from_distance(d, curve), curve).distance, d, 1e-12);
    }
}

TEST(SharpIr, OutputFallsMonotonicallyWithDistanceAboveThePeak) {
    const SharpIrCurve curve;
    double previous = adc_from_distance(curve.peak_distance, curve);
    for (double d = curve.peak_distance + 0.001; d < 1.0; d += 0.001) {
        const double adc = adc_from_distance(d, curve);
        EXPECT_LT(adc, previous);
        previous = adc;
    }
}

TEST(SharpIr, FoldsBackBelowThePeakSoContactLooksFar) {
    const SharpIrCurve curve;
    const double peak = adc_from_distance(curve.peak_distance, curve);
    EXPECT_DOUBLE_EQ(adc_from_distance(0.0, curve), curve.contact_adc);
    EXPECT_LT(adc_from_distance(0.01, curve), peak);
    EXPECT_LT(adc_from_distance(0.0, curve), adc_from_distance(0.02, curve));
    // Touching the wall reads like a wall ~13 cm away: inside the trusted range, ambiguous.
    const IrDistance at_contact = distance_from_adc(adc_from_distance(0.0, curve), curve);
    EXPECT_EQ(at_contact.status, IrStatus::InRange);
    EXPECT_NEAR(at_contact.distance, published_distance_cm(205.0) / 100.0, 1e-12);
    // Negative distances (numerical slop in a simulator) clamp to contact.
    EXPECT_DOUBLE_EQ(adc_from_distance(-0.01, curve), curve.contact_adc);
}

TEST(SharpIr, InfiniteDistanceGivesTheAsymptote) {
    const SharpIrCurve curve;
    EXPECT_DOUBLE_EQ(adc_from_distance(std::numeric_limits<double>::infinity(), curve), -5.0);
    EXPECT_EQ(quantize_adc(adc_from_distance(std::numeric_limits<double>::infinity(), curve),
                           curve.adc_max),
              0);
}

TEST(SharpIr, QuantisationRoundsAndClampsToTenBits) {
    EXPECT_EQ(quantize_adc(177.4, 1023), 177);
    EXPECT_EQ(quantize_adc(177.6, 1023), 178);
    EXPECT_EQ(quantize_adc(-3.0, 1023), 0);
    EXPECT_EQ(quantize_adc(5000.0, 1023), 1023);
    EXPECT_EQ(quantize_adc(std::numeric_limits<double>::quiet_NaN(), 1023), 0);
}

TEST(SharpIr, QuantisationErrorAtTheWallDistanceIsBelowAMillimetre) {
    // At the arena's ≈15 cm one A/D count is ≈0.9 mm: the 10-bit reading resolves walls well.
    const SharpIrCurve curve;
    const double adc = adc_from_distance(0.15, curve);
    const double step = distance_from_adc(std::floor(adc), curve).distance
                        - distance_from_adc(std::floor(adc) + 1.0, curve).distance;
    EXPECT_GT(step, 0.0005);
    EXPECT_LT(step, 0.001);
}

}  // namespace
}  // namespace legofeup
