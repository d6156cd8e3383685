#include "legofeup/core/consistency.hpp"

#include <Eigen/Cholesky>
#include <limits>

#include "legofeup/core/pose_state_space.hpp"

namespace legofeup {

double normalized_estimation_error(const StateVector& truth, const StateVector& estimate,
                                   const StateCovariance& covariance) {
    const StateVector error = PoseStateSpace::difference(truth, estimate);
    const Eigen::LDLT<StateCovariance> ldlt(covariance);
    if (!error.allFinite() || !covariance.allFinite() || ldlt.info() != Eigen::Success
        || !(ldlt.vectorD().array() > 0.0).all()) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    return error.dot(ldlt.solve(error));
}

}  // namespace legofeup
