#pragma once
// The wall observation as the EKF sees it (paper eq. 4–5, 15–20), generalised to any
// straight wall seen from either side.
//
// A wall with canonical normal n and line n·p = c, seen from side σ = ±1 (σ = +1 when the
// robot is on the side n points to), gives
//
//   z = [ n·p , θ ]ᵀ = [ c + σ·D_c ,  ang(σ·n) − π/2 + ObsAng ]ᵀ        (eq. 4–5)
//
// For the paper's walls n is +x or +y, so z₁ is x or y; from inside the square σ = −1 for
// wall_x+ and wall_y+ and σ = +1 for wall_x− and wall_y−, which is the paper's "signal".
// The model is linear in the state, h(X) = ∇h_X·X with ∇h_X = [n_x n_y 0; 0 0 1] (eq. 17,
// C₁ = n_x, C₂ = n_y), and the IR noise r = [ε_ds1, ε_ds2] enters through
// ∇h_r = diag(σ, 1)·∂(D_c, ObsAng)/∂(d_s1, d_s2) (eq. 20).
//
// Two corrections to the printed paper: the innovation is z − h(X̂) (eq. 15 prints
// h(X̂) − z, which with eq. 14 would push the estimate away from the wall), and for wall_x+
// the heading is π/2 + ObsAng (eq. 4 prints π/2 − ObsAng, which contradicts the sensor
// geometry of Fig. 6 and the other three walls).

#include <Eigen/Core>

#include "legofeup/core/ir_geometry.hpp"
#include "legofeup/core/state.hpp"
#include "legofeup/core/walls.hpp"

namespace legofeup {

/// The heading at which the sensors look straight at a wall from side σ (ObsAng = 0).
double facing_heading(const WallLine& wall, int side);

class WallMeasurement {
  public:
    static constexpr int kSize = 2;
    using Vector = Eigen::Vector2d;
    using Jacobian = Eigen::Matrix<double, kSize, kStateSize>;

    /// `ir_covariance` is R, the 2×2 covariance of [ε_ds1, ε_ds2] in m².
    WallMeasurement(const WallLine& wall, int side, const WallObservation& observation,
                    const Eigen::Matrix2d& ir_covariance);

    // Filter hooks (see measurement_model concept in extended_kalman_filter.hpp).
    const Vector& measurement() const { return z_; }
    Vector predict_measurement(const StateVector& x) const { return jacobian_ * x; }
    const Jacobian& jacobian(const StateVector& /*x*/) const { return jacobian_; }
    /// ∇h_r · R · ∇h_rᵀ: the IR noise mapped into the space of z (eq. 16).
    const Eigen::Matrix2d& noise_covariance() const { return noise_covariance_; }
    /// z − ẑ with the heading component wrapped to (−π, π].
    Vector residual(const Vector& z, const Vector& predicted) const;

    /// ∇h_r (eq. 20).
    const Eigen::Matrix2d& noise_jacobian() const { return noise_jacobian_; }

  private:
    Vector z_;
    Jacobian jacobian_;
    Eigen::Matrix2d noise_jacobian_;
    Eigen::Matrix2d noise_covariance_;
};

}  // namespace legofeup
