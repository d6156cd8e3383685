#pragma once
// Filter consistency (Bar-Shalom et al.): the normalised estimation error squared.

#include "legofeup/core/state.hpp"

namespace legofeup {

/// NEES ε = x̃ᵀ P⁻¹ x̃ with x̃ = truth − estimate (heading wrapped). For a consistent filter
/// ε ~ χ²(3). Returns NaN if P is not positive definite or anything is not finite.
double normalized_estimation_error(const StateVector& truth, const StateVector& estimate,
                                   const StateCovariance& covariance);

}  // namespace legofeup
