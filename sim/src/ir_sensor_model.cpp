#include "legofeup/sim/ir_sensor_model.hpp"

namespace legofeup::sim {

const char* to_string(IrSensorModel model) {
    return model == IrSensorModel::Realistic ? "realistic" : "ideal";
}

std::optional<IrSensorModel> ir_sensor_model_from_string(std::string_view text) {
    if (text == "ideal") {
        return IrSensorModel::Ideal;
    }
    if (text == "realistic") {
        return IrSensorModel::Realistic;
    }
    return std::nullopt;
}

SharpIrCurve unit_curve(const SharpIrCurve& nominal, const IrUnit& unit) {
    SharpIrCurve curve = nominal;
    curve.c_m = unit.gain * nominal.c_m;
    curve.c_r = unit.gain * nominal.c_r - unit.offset;
    curve.contact_adc = unit.gain * nominal.contact_adc + unit.offset;
    return curve;
}

double ir_output_noise_counts(const SharpIrCurve& nominal, double distance_noise,
                              double reference_distance) {
    const double bracket = reference_distance / nominal.a + nominal.b;  // D_ref/a + b
    return distance_noise * nominal.c_m / (nominal.a * bracket * bracket);
}

std::uint16_t realistic_ir_adc(const SharpIrCurve& nominal, const IrUnit& unit, double distance,
                               double noise_counts) {
    const double output = unit.gain * adc_from_distance(distance, nominal) + unit.offset;
    return quantize_adc(output + noise_counts, nominal.adc_max);
}

}  // namespace legofeup::sim
