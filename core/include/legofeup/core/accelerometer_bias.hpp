#pragma once
// The constant bias of the two forward accelerometers over the wheels, estimated while the
// robot runs, so it can be removed before the filters use the accelerations (paper 003
// §3.3–3.4: "the accelerometer data is pre-processed to remove its bias").
//
// Over a wheel the forward specific force is the rate of change of that wheel's surface
// speed u (no slip). So the reading is a_k = u̇ + b + n_k and, summed over the periods T_i
// up to now (t = Σ T_i),
//   Σ a_i·T_i = (u_k − u_0) + b·t + Σ n_i·T_i,
// which gives the bias as the running mean of what the accelerometer says beyond the
// encoders' speed change:
//   b̂ = (Σ a_i·T_i − (u_k − u_0)) / (t + τ₀).
// The encoders' speeds enter only through their end points, so their quantisation error
// (about one count per period) does not accumulate: it shrinks as 1/t, and the white noise
// n (σ_n per reading) as σ_n·√(T/t). At rest u stays 0 and b̂ is the plain mean of the
// readings, the usual calibration at standstill; the estimate keeps improving while the
// robot drives. τ₀ (one second of readings) pulls the first estimates towards 0 (a
// calibrated sensor has little bias) so that the first, noisy readings are not taken for
// it. This needs no truth: a real robot can run it on its own encoders.

#include <array>

namespace legofeup {

class AccelerometerBiasEstimator {
  public:
    /// Seconds of readings the prior b = 0 counts as (τ₀).
    static constexpr double kPriorSeconds = 1.0;

    /// Forgets everything: b̂ = 0, and the next sample only sets the reference speeds.
    void reset();

    /// One period of `period_s` (s): the forward accelerations a (m/s²) and the wheels'
    /// surface speeds u (m/s) from the encoders at its end, [right, left]. Non-finite
    /// values or a non-positive period are ignored.
    void add(const std::array<double, 2>& acceleration, const std::array<double, 2>& wheel_speed,
             double period_s);

    /// b̂ per unit [right, left], m/s².
    std::array<double, 2> bias() const;

  private:
    std::array<double, 2> sum_{};         // Σ a_i·T_i − (u_k − u_0), m/s
    std::array<double, 2> last_speed_{};  // u_k, m/s
    double time_ = 0.0;                   // t, s
    bool have_speed_ = false;
};

}  // namespace legofeup
