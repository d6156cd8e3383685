#pragma once
// Filter consistency (Bar-Shalom et al.): the normalised estimation error squared.

#include "legofeup/core/pose_error.hpp"
#include "legofeup/core/state.hpp"

namespace legofeup {

/// NEES ε = x̃ᵀ P⁻¹ x̃ of the pose error x̃ = x̂ − x (pose_error.hpp: heading wrapped). For a
/// consistent filter ε ~ χ²(3). Returns NaN if P is not positive definite or anything is not
/// finite.
double normalized_estimation_error(const PoseError& error, const StateCovariance& covariance);

/// The same, forming x̃ = pose_error(estimate, truth) first.
double normalized_estimation_error(const StateVector& truth, const StateVector& estimate,
                                   const StateCovariance& covariance);

}  // namespace legofeup
