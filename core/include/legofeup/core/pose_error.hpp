#pragma once
// The error of a pose estimate against the truth: the one definition every metric, plot,
// export and NEES uses, so a sign read in one place means the same in every other.
//
//   x̃ = x̂ − x = (x̂ − x,  ŷ − y,  wrap(θ̂ − θ)),   wrap to (−π, π] (angles.hpp)
//
// Estimate minus truth: x̃ is positive when the estimate lies too far along +x (+y, turned
// too far counter-clockwise), as in metrology's "error = measured − reference" (VIM 2.16).
// Bar-Shalom, Li & Kirubarajan write the estimation error the other way round, x − x̂; the
// NEES x̃ᵀP⁻¹x̃ is a quadratic form and the same for either sign, so the choice shows only in
// signed plots and exports — and there it is this one everywhere.

#include <cmath>

#include "legofeup/core/angles.hpp"
#include "legofeup/core/state.hpp"

namespace legofeup {

/// wrap(θ̂ − θ): how far the heading `estimate` is turned counter-clockwise from the true
/// heading `truth`, rad, in (−π, π]. For any heading judged against the truth (estimate,
/// integrated gyro, compass).
inline double heading_error(double estimate, double truth) {
    return wrap_angle(estimate - truth);
}

struct PoseError {
    double x = 0.0;      ///< x̂ − x, m
    double y = 0.0;      ///< ŷ − y, m
    double theta = 0.0;  ///< wrap(θ̂ − θ), rad, in (−π, π]

    /// ‖(x̂, ŷ) − (x, y)‖, m.
    double position() const { return std::hypot(x, y); }
    /// |θ̃|, rad, in [0, π].
    double heading() const { return std::abs(theta); }
    /// x̃ as a state vector, indexed by kX, kY, kTheta.
    StateVector vector() const { return {x, y, theta}; }
};

/// x̃ = x̂ − x of `estimate` against `truth` (the estimate first, as in x̂ − x).
inline PoseError pose_error(const Pose2& estimate, const Pose2& truth) {
    return {estimate.x - truth.x, estimate.y - truth.y, heading_error(estimate.theta, truth.theta)};
}
inline PoseError pose_error(const StateVector& estimate, const Pose2& truth) {
    return pose_error(to_pose(estimate), truth);
}

}  // namespace legofeup
