#include "legofeup/core/sharp_ir.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace legofeup {

const char* to_string(IrStatus status) {
    switch (status) {
        case IrStatus::InRange:
            return "in range";
        case IrStatus::TooFar:
            return "too far";
        case IrStatus::TooClose:
            return "too close";
        case IrStatus::Unavailable:
            return "unavailable";
    }
    return "unknown";
}

IrCurveParameters curve_parameters(const SharpIrCurve& curve) {
    return {curve.a, curve.c_m, curve.c_r, curve.b};
}

SharpIrCurve with_curve_parameters(SharpIrCurve curve, const IrCurveParameters& parameters) {
    curve.a = parameters.a;
    curve.c_m = parameters.c_m;
    curve.c_r = parameters.c_r;
    curve.b = parameters.b;
    return curve;
}

IrDistance distance_from_adc(double adc, const SharpIrCurve& curve) {
    const double denominator = adc + curve.c_r;  // A + C_R
    if (!(denominator > 0.0)) {
        return {std::numeric_limits<double>::infinity(), IrStatus::TooFar};
    }
    const double distance = curve.a * (curve.c_m / denominator - curve.b);  // eq. 2
    if (distance > curve.max_range) {
        return {distance, IrStatus::TooFar};
    }
    if (distance < curve.min_range) {
        return {distance, IrStatus::TooClose};
    }
    return {distance, IrStatus::InRange};
}

namespace {

// Eq. 2 solved for A: D/a + b = C_M/(A + C_R)  ⇒  A = C_M / (D/a + b) − C_R.
double fitted_adc(double distance, const SharpIrCurve& curve) {
    return curve.c_m / (distance / curve.a + curve.b) - curve.c_r;
}

}  // namespace

double adc_from_distance(double distance, const SharpIrCurve& curve) {
    if (std::isinf(distance)) {
        return -curve.c_r;  // lim D→∞ of the fit
    }
    if (distance >= curve.peak_distance) {
        return fitted_adc(distance, curve);
    }
    // Fold-back: linear from the contact value at 0 m up to the fit's value at the peak.
    const double peak_adc = fitted_adc(curve.peak_distance, curve);
    const double fraction = std::max(distance, 0.0) / curve.peak_distance;
    return curve.contact_adc + (peak_adc - curve.contact_adc) * fraction;
}

std::uint16_t quantize_adc(double value, int adc_max) {
    if (std::isnan(value)) {
        return 0;
    }
    const double clamped = std::clamp(std::round(value), 0.0, static_cast<double>(adc_max));
    return static_cast<std::uint16_t>(clamped);
}

}  // namespace legofeup
