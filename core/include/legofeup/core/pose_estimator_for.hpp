#pragma once
// A filter class as a PoseEstimator: every overload of the interface forwards to the
// filter's own template predict(model) / update(model, gate), so each model's hooks are
// compiled into the filter's step (no call per hook); the one virtual call per step is the
// choice of filter.
//
// Filter needs (FilterBase provides the first four):
//   state(), covariance(), last_repairs(), reset(x, P), set_limits(limits)
//   template predict(const Model&) -> StepStatus
//   template update(const Model&, const MahalanobisGate&) -> UpdateReport<Model::kSize, 3>
//   optionally set_params(const UkfParams&) (the UKF's spread)
//   optionally configure(const PoseEstimatorSettings&), reset_uniform(), summary() and
//   xs(), ys(), thetas(), weights() (the particle filter: its own tuning, a cloud over the
//   free space, the cloud's summary and its particles)

#include "legofeup/core/pose_estimator.hpp"

namespace legofeup {

template <class Filter>
class PoseEstimatorFor final : public PoseEstimator {
  public:
    explicit PoseEstimatorFor(FilterKind kind) : kind_(kind) {}

    using PoseEstimator::update;

    FilterKind kind() const override { return kind_; }
    void configure(const PoseEstimatorSettings& settings) override {
        free_space_ = settings.free_space;
        if constexpr (requires { filter_.configure(settings); }) {
            filter_.configure(settings);
        } else {
            filter_.set_limits(settings.limits);
            if constexpr (requires { filter_.set_params(settings.ukf); }) {
                filter_.set_params(settings.ukf);
            }
        }
    }

    bool reset(const StateVector& x, const StateCovariance& P) override {
        return filter_.reset(x, P);
    }
    bool reset_uniform() override {
        if constexpr (requires { filter_.reset_uniform(); }) {
            return filter_.reset_uniform();
        } else {
            // A Gaussian with the uniform's first two moments.
            return free_space_ && !free_space_->empty()
                   && filter_.reset(free_space_->mean(), free_space_->covariance());
        }
    }
    ParticleSummary particles() const override {
        if constexpr (requires { filter_.summary(); }) {
            return filter_.summary();
        } else {
            return {};
        }
    }
    void sample_cloud(std::size_t max_points, std::vector<ParticlePoint>& out) const override {
        if constexpr (requires { filter_.weights(); }) {
            thin_particles(filter_.xs(), filter_.ys(), filter_.thetas(), filter_.weights(),
                           max_points, out);
        } else {
            out.clear();
        }
    }
    bool weighs_scans() const override {
        return requires(Filter & f, const ScanLikelihood& scan) {
            f.update(scan);
        };
    }
    StepStatus update(const ScanLikelihood& scan) override {
        if constexpr (requires { filter_.update(scan); }) {
            return filter_.update(scan);
        } else {
            return StepStatus::NotAttempted;
        }
    }
    /// The filter itself (for tests of one filter through the interface).
    const Filter& filter() const { return filter_; }
    const StateVector& state() const override { return filter_.state(); }
    const StateCovariance& covariance() const override { return filter_.covariance(); }
    std::uint8_t last_repairs() const override { return filter_.last_repairs(); }

    StepStatus predict(const OdometryProcessModel& model) override {
        return filter_.predict(model);
    }
    StepStatus predict(const CompassOdometryProcessModel& model) override {
        return filter_.predict(model);
    }
    StepStatus predict(const LaserProcessModel& model) override { return filter_.predict(model); }

    PoseUpdateReport<WallMeasurement::kSize> update(const WallMeasurement& model,
                                                    const MahalanobisGate& gate) override {
        return filter_.update(model, gate);
    }
    PoseUpdateReport<BeaconBearingMeasurement::kSize> update(const BeaconBearingMeasurement& model,
                                                             const MahalanobisGate& gate) override {
        return filter_.update(model, gate);
    }
    PoseUpdateReport<CompassMeasurement::kSize> update(const CompassMeasurement& model,
                                                       const MahalanobisGate& gate) override {
        return filter_.update(model, gate);
    }
    PoseUpdateReport<LaserPoseMeasurement::kSize> update(const LaserPoseMeasurement& model,
                                                         const MahalanobisGate& gate) override {
        return filter_.update(model, gate);
    }

  private:
    FilterKind kind_;
    Filter filter_;
    std::shared_ptr<const FreeSpace> free_space_;
};

}  // namespace legofeup
