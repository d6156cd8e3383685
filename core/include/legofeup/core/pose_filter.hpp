#pragma once
// The pose filter of the loop: an EKF or a UKF over X = [x, y, θ], chosen by a setting that
// may change while the robot runs. Both filters take the same process and measurement
// models; switching hands the current x and P over, so the estimate continues unbroken.

#include "legofeup/core/extended_kalman_filter.hpp"
#include "legofeup/core/lesson_filters_config.hpp"
#include "legofeup/core/pose_state_space.hpp"
#include "legofeup/core/unscented_kalman_filter.hpp"

namespace legofeup {

class PoseFilter {
  public:
    explicit PoseFilter(FilterKind kind = FilterKind::Ekf) : kind_(kind) {}

    FilterKind kind() const { return kind_; }

    /// Switches the algorithm; the new one starts from the current x and P.
    void set_kind(FilterKind kind) {
        if (kind == kind_) {
            return;
        }
        const StateVector x = state();
        const StateCovariance P = covariance();
        kind_ = kind;
        active().reset(x, P);
    }

    void set_ukf_params(const UkfParams& params) { ukf_.set_params(params); }
    void set_limits(const CovarianceLimits& limits) {
        ekf_.set_limits(limits);
        ukf_.set_limits(limits);
    }

    bool reset(const StateVector& x, const StateCovariance& P) { return active().reset(x, P); }

    const StateVector& state() const { return active().state(); }
    const StateCovariance& covariance() const { return active().covariance(); }
    std::uint8_t last_repairs() const { return active().last_repairs(); }

    template <class Model>
    StepStatus predict(const Model& model) {
        return kind_ == FilterKind::Ekf ? ekf_.predict(model) : ukf_.predict(model);
    }

    template <class Model>
    UpdateReport<Model::kSize, kStateSize> update(const Model& model,
                                                  const MahalanobisGate& gate = {}) {
        return kind_ == FilterKind::Ekf ? ekf_.update(model, gate) : ukf_.update(model, gate);
    }

  private:
    FilterBase<PoseStateSpace>& active() {
        return kind_ == FilterKind::Ekf ? static_cast<FilterBase<PoseStateSpace>&>(ekf_)
                                        : static_cast<FilterBase<PoseStateSpace>&>(ukf_);
    }
    const FilterBase<PoseStateSpace>& active() const {
        return kind_ == FilterKind::Ekf ? static_cast<const FilterBase<PoseStateSpace>&>(ekf_)
                                        : static_cast<const FilterBase<PoseStateSpace>&>(ukf_);
    }

    FilterKind kind_;
    ExtendedKalmanFilter<PoseStateSpace> ekf_;
    UnscentedKalmanFilter<PoseStateSpace> ukf_;
};

}  // namespace legofeup
