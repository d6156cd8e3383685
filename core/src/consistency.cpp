#include "legofeup/core/consistency.hpp"

#include <limits>

#include "legofeup/core/small_ldlt.hpp"

namespace legofeup {

double normalized_estimation_error(const PoseError& error, const StateCovariance& covariance) {
    const StateVector x_tilde = error.vector();  // x̃ = x̂ − x
    SmallLdlt<kStateSize> ldlt;
    if (!x_tilde.allFinite() || !covariance.allFinite() || !ldlt.factorise(covariance)) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    return x_tilde.dot(ldlt.solve(x_tilde));  // x̃ᵀ P⁻¹ x̃, solved, never inverted
}

double normalized_estimation_error(const StateVector& truth, const StateVector& estimate,
                                   const StateCovariance& covariance) {
    return normalized_estimation_error(pose_error(estimate, to_pose(truth)), covariance);
}

}  // namespace legofeup
