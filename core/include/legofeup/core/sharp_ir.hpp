#pragma once
// The Sharp GP2D120 infrared range sensor read through the NXT's 10-bit A/D (paper eq. 2).
//
// The paper fits the characteristic curve with D = a·(C_M / (A + C_R) − b), A the A/D value.
// The defaults below are the published GP2D120 linearisation R[cm] = 2914 / (A + 5) − 1 for a
// 10-bit reading over 0–5 V, i.e. a = 0.01 m, C_M = 2914, C_R = 5, b = 1. It puts 4 cm at
// A ≈ 578 (2.8 V) and 30 cm at A ≈ 89 (0.43 V), as in the data sheet.
//
// Below about 3 cm the real output falls again (the reflected spot leaves the detector), so a
// robot touching a wall reads like a wall 10–15 cm away. adc_from_distance models that
// fold-back for simulation; the loop cannot tell, which is why readings are range-checked.

#include <cstdint>

namespace legofeup {

struct SharpIrCurve {
    double a = 0.01;              ///< scale of the fit, metres per fit unit (the fit is in cm)
    double c_m = 2914.0;          ///< C_M, constant of multiplication
    double c_r = 5.0;             ///< C_R, constant of linearisation (A/D counts)
    double b = 1.0;               ///< offset of the fit, fit units
    double min_range = 0.04;      ///< readings closer than this are not trusted, metres
    double max_range = 0.30;      ///< readings farther than this are not trusted, metres
    double peak_distance = 0.03;  ///< the output peaks here and folds back below it, metres
    double contact_adc = 205.0;   ///< output with the target touching the sensor (≈1.0 V)
    int adc_max = 1023;           ///< full scale of the A/D converter
};

/// Eq. 2's four parameters: what differs between two units of the sensor and what a
/// calibration fits. The trusted range, the fold-back and the A/D scale stay the curve's.
struct IrCurveParameters {
    double a = 0.01;
    double c_m = 2914.0;
    double c_r = 5.0;
    double b = 1.0;

    bool operator==(const IrCurveParameters&) const = default;
};

/// The eq. 2 parameters of `curve`.
IrCurveParameters curve_parameters(const SharpIrCurve& curve);
/// `curve` with its eq. 2 parameters replaced by `parameters`.
SharpIrCurve with_curve_parameters(SharpIrCurve curve, const IrCurveParameters& parameters);

enum class IrStatus : std::uint8_t {
    InRange,      ///< min_range ≤ D ≤ max_range: usable for an observation
    TooFar,       ///< D > max_range, or no finite distance (A + C_R ≤ 0)
    TooClose,     ///< D < min_range: closer than the trusted range (or folded back)
    Unavailable,  ///< the link delivered no valid reading (e.g. the NXT's "valid" flag)
};

const char* to_string(IrStatus status);

struct IrDistance {
    double distance = 0.0;  ///< eq. 2 evaluated at A, metres (infinity when A + C_R ≤ 0)
    IrStatus status = IrStatus::TooFar;

    bool in_range() const { return status == IrStatus::InRange; }
};

/// Eq. 2: A/D value → distance, with the validity range applied.
IrDistance distance_from_adc(double adc, const SharpIrCurve& curve);

/// The inverse of eq. 2 (distance → A/D value, before quantisation) for d ≥ peak_distance,
/// and the fold-back towards contact_adc below it. Infinite distance gives the curve's
/// asymptote. Used by simulators and tests; clamp and round with quantize_adc.
double adc_from_distance(double distance, const SharpIrCurve& curve);

/// Rounds a voltage-proportional value to the converter's integer codes [0, adc_max].
std::uint16_t quantize_adc(double value, int adc_max);

}  // namespace legofeup
