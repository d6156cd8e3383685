#pragma once
// The thin base every Gaussian filter of LegoFeup Lab shares (the EKF and the UKF of the pose,
// the 5-state fusion EKF, the speed KFs): it owns the state x and covariance P and guards what
// goes into them. The estimation steps live in the derived filters; the problem lives in model
// hooks. The loop holds the pose filters through PoseEstimator (pose_estimator.hpp).
//
// A state space supplies
//   static constexpr int kSize;                 dimension of x
//   static void normalize(Vector& x);           e.g. wrap headings to (−π, π]
//   static Vector difference(a, b);             a − b, with headings wrapped
// Process and measurement models are described next to the filters that use them.

#include <Eigen/Core>
#include <cstdint>

#include "legofeup/core/covariance_guard.hpp"

namespace legofeup {

enum class StepStatus : std::uint8_t {
    Applied,            ///< the step changed x and P
    NotAttempted,       ///< nothing to do (no measurement)
    RejectedNonFinite,  ///< an input or the result was NaN/Inf: x and P unchanged
    RejectedSingular,   ///< the innovation covariance S was not positive definite
    RejectedByGate,     ///< the NIS exceeded the Mahalanobis gate
    AppliedLinearised,  ///< a UKF prediction done as the EKF's: the sigma points could not be
                        ///< drawn (n + κ ≤ 0, P or Q not factorisable); x and P did move
};

const char* to_string(StepStatus status);

template <class StateSpace>
class FilterBase {
  public:
    static constexpr int kSize = StateSpace::kSize;
    using Vector = Eigen::Matrix<double, kSize, 1>;
    using Covariance = Eigen::Matrix<double, kSize, kSize>;

    const Vector& state() const { return x_; }
    const Covariance& covariance() const { return P_; }
    const CovarianceLimits& limits() const { return limits_; }
    void set_limits(const CovarianceLimits& limits) { limits_ = limits; }

    /// Sets x and P (conditioned). Returns false, changing nothing, if they are not finite.
    bool reset(const Vector& x, const Covariance& P) { return commit(x, P) == StepStatus::Applied; }

    /// The repairs condition_covariance made at the last committed step (0: none).
    std::uint8_t last_repairs() const { return last_repairs_; }

  protected:
    /// Accepts a candidate posterior: rejects it if anything is NaN/Inf, otherwise
    /// normalises the state and conditions the covariance.
    StepStatus commit(Vector x, Covariance P) {
        if (!x.allFinite() || !P.allFinite()) {
            return StepStatus::RejectedNonFinite;
        }
        StateSpace::normalize(x);
        last_repairs_ = condition_covariance<kSize>(P, limits_);
        x_ = x;
        P_ = P;
        return StepStatus::Applied;
    }

  private:
    Vector x_ = Vector::Zero();
    Covariance P_ = Covariance::Identity();
    CovarianceLimits limits_;
    std::uint8_t last_repairs_ = kRepairNone;
};

}  // namespace legofeup
