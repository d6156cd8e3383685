#pragma once
// How the simulated Sharp GP2D120 sensors turn a true distance into an A/D value
// (docs/simulator.md, "IR sensors").
//
// Ideal (the paper's simulation): the filter's own curve, Gaussian noise of constant σ in
// metres added to the distance. Realistic: each sensor is a unit of its own, whose output is
// the nominal one scaled and shifted, A_true(D) = g·A(D) + o, with g and o drawn once per run
// from the seed; the noise is on the output (A/D counts), so mapped back through the
// flattening curve the distance noise grows roughly as (D/a + b)².
//
// g·A + o is again eq. 2: g·(C_M/(D/a + b) − C_R) + o = g·C_M/(D/a + b) − (g·C_R − o), so a
// unit's true curve is (g·C_M, g·C_R − o, b), which a calibration can recover.

#include <cstdint>
#include <optional>
#include <string_view>

#include "legofeup/core/sharp_ir.hpp"

namespace legofeup::sim {

enum class IrSensorModel : std::uint8_t {
    Ideal,      ///< the filter's curve, constant noise in metres (paper 000)
    Realistic,  ///< each sensor its own curve, noise on the voltage
};

const char* to_string(IrSensorModel model);
/// "ideal" or "realistic"; nullopt for anything else.
std::optional<IrSensorModel> ir_sensor_model_from_string(std::string_view text);

/// One sensor unit's deviation from the nominal output: A_true = gain·A_nominal + offset.
struct IrUnit {
    double gain = 1.0;    ///< g, relative output swing
    double offset = 0.0;  ///< o, output shift, A/D counts
};

/// The unit's true curve in the form of eq. 2: C_M' = g·C_M, C_R' = g·C_R − o, and the
/// fold-back's contact value g·contact_adc + o (the rest of `nominal` is kept).
SharpIrCurve unit_curve(const SharpIrCurve& nominal, const IrUnit& unit);

/// σ of the realistic model's output noise, A/D counts: the noise that makes the distance
/// noise σ_D at `reference_distance` on the nominal curve. |dD/dA| = a·(D/a + b)²/C_M, so
/// σ_A = σ_D·C_M / (a·(D_ref/a + b)²).
double ir_output_noise_counts(const SharpIrCurve& nominal, double distance_noise,
                              double reference_distance);

/// The realistic reading: quantize(g·A(distance) + o + noise_counts), A the nominal curve with
/// its fold-back (adc_from_distance).
std::uint16_t realistic_ir_adc(const SharpIrCurve& nominal, const IrUnit& unit, double distance,
                               double noise_counts);

}  // namespace legofeup::sim
