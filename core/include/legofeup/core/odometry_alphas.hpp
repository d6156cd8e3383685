#pragma once
// Probabilistic Robotics' odometry motion noise α₁…α₄ (Thrun, Burgard & Fox, Table 5.6,
// sample_motion_model_odometry), as extra noise the particle filter can add on top of the
// lesson's Q. Q is the lessons' own noise, stated per control period (the same for all
// three filters); the α's make the noise grow with the motion itself, as the book teaches,
// so that a turn on the spot spreads the headings and a long straight the positions.
//
// A particle's motion over one step, f(X, U, 0) − X, is split as the book splits
// odometry, in the particle's own frame: a rotation δ_rot1 towards the direction of travel,
// a translation δ_trans, a rotation δ_rot2 to the final heading. Each part gets a zero-mean
// Gaussian error of variance
//
//   σ²_rot1  = α₁ δ_rot1² + α₂ δ_trans²
//   σ²_trans = α₃ δ_trans² + α₄ (δ_rot1² + δ_rot2²)
//   σ²_rot2  = α₁ δ_rot2² + α₂ δ_trans²
//
// (α₁: rotation from rotation, α₂: rotation from translation, α₃: translation from
// translation, α₄: translation from rotation; the book's units: α₁ and α₃ unitless, α₂
// rad²/m², α₄ m²/rad²). The pose the process model gave (with Q's noise) moves by the
// difference between the book's noisy motion and the noise-free one. Driving backwards,
// δ_rot1 would be ≈ ±π; as in ROS AMCL, the rotations' noise uses the smaller of |δ| and
// π − |δ| so that reversing is not mistaken for a half turn. All α's zero: no change, and
// no random draw (the stream, and so the run, is the one without α's).

#include "legofeup/core/random_stream.hpp"
#include "legofeup/core/state.hpp"

namespace legofeup {

struct OdometryAlphas {
    double rotation_from_rotation = 0.0;        ///< α₁
    double rotation_from_translation = 0.0;     ///< α₂, rad²/m²
    double translation_from_translation = 0.0;  ///< α₃
    double translation_from_rotation = 0.0;     ///< α₄, m²/rad²

    bool any() const {
        return rotation_from_rotation > 0.0 || rotation_from_translation > 0.0
               || translation_from_translation > 0.0 || translation_from_rotation > 0.0;
    }
    friend bool operator==(const OdometryAlphas&, const OdometryAlphas&) = default;
};

/// The pose `moved` (where the process model took the particle from `from`, with Q's noise)
/// with the α's error added; `noiseless` is f(from, U, 0). Draws three normals from `random`.
StateVector add_odometry_alpha_noise(const StateVector& from, const StateVector& noiseless,
                                     const StateVector& moved, const OdometryAlphas& alphas,
                                     RandomStream& random);

}  // namespace legofeup
