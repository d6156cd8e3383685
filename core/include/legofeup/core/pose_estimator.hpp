#pragma once
// The pose estimator of the loop: one interface over every filter of X = [x, y, θ] (the EKF,
// the UKF, and whatever comes next), so the loop asks "predict with this model", "update
// with this measurement", "what is x̂ and P" without knowing which algorithm answers.
//
//   predict(process model)            → StepStatus            (X̂, P move by the model)
//   update(measurement model, gate)   → UpdateReport<M, 3>     (z, h(X̂), ν, S, W, NIS)
//   state(), covariance()             → X̂, P after the last step
//   last_repairs()                    → what the covariance guard had to do
//   reset(x, P), configure(settings)  → a new belief, new limits and parameters
//   reset_uniform()                   → "the pose is unknown": the particle filter spreads
//                                       its cloud over the free space, a Gaussian filter
//                                       takes the free space's mean and covariance
//   particles()                       → the particle filter's cloud summary (count 0 for
//                                       the Gaussian filters)
//   sample_cloud(max, out)            → a thinned copy of the cloud to draw (empty for the
//                                       Gaussian filters; particle_cloud.hpp)
//   weighs_scans(), update(scan)      → the particle filter's laser model: a whole scan
//                                       against the map's likelihood field
//
// The models are the concrete hook objects of the lessons (odometry_process_model.hpp,
// wall_measurement.hpp, …): the interface lists each one, so a filter sees the model's own
// type and inlines its hooks; only the choice of filter is virtual, one call per step.
// A filter class with template predict/update (extended_kalman_filter.hpp's hook table)
// becomes an estimator through PoseEstimatorFor<Filter> (pose_estimator_for.hpp) and one
// entry in the registry (pose_estimator_registry.hpp). A new model is one overload here and
// one in PoseEstimatorFor.

#include <cstdint>

#include "legofeup/core/beacon_bearing.hpp"
#include "legofeup/core/compass_model.hpp"
#include "legofeup/core/covariance_guard.hpp"
#include "legofeup/core/extended_kalman_filter.hpp"  // StepStatus, MahalanobisGate, UpdateReport
#include "legofeup/core/laser_pose_measurement.hpp"
#include "legofeup/core/laser_process_model.hpp"
#include "legofeup/core/lesson_filters_config.hpp"
#include "legofeup/core/likelihood_field.hpp"
#include "legofeup/core/odometry_process_model.hpp"
#include "legofeup/core/particle_cloud.hpp"
#include "legofeup/core/particle_summary.hpp"
#include "legofeup/core/pose_estimator_settings.hpp"
#include "legofeup/core/state.hpp"
#include "legofeup/core/wall_measurement.hpp"

namespace legofeup {

template <int M>
using PoseUpdateReport = UpdateReport<M, kStateSize>;

class PoseEstimator {
  public:
    virtual ~PoseEstimator() = default;

    virtual FilterKind kind() const = 0;
    virtual void configure(const PoseEstimatorSettings& settings) = 0;

    /// Sets x and P (conditioned). Returns false, changing nothing, if they are not finite.
    virtual bool reset(const StateVector& x, const StateCovariance& P) = 0;
    /// The pose is unknown: a belief over the whole of the configured free space. Returns
    /// false, changing nothing, when none was configured (or it is empty).
    virtual bool reset_uniform() = 0;

    virtual const StateVector& state() const = 0;
    virtual const StateCovariance& covariance() const = 0;
    /// The repairs condition_covariance made at the last committed step (0: none).
    virtual std::uint8_t last_repairs() const = 0;
    /// The particle cloud's summary after the last step (count 0: not a particle filter).
    virtual ParticleSummary particles() const = 0;
    /// At most `max_points` particles of the cloud after the last step, for drawing
    /// (thin_particles); `out` is cleared first and stays empty for a Gaussian filter.
    virtual void sample_cloud(std::size_t max_points, std::vector<ParticlePoint>& out) const = 0;

    // Prediction, one overload per process model.
    virtual StepStatus predict(const OdometryProcessModel& model) = 0;
    virtual StepStatus predict(const CompassOdometryProcessModel& model) = 0;
    virtual StepStatus predict(const LaserProcessModel& model) = 0;

    // Update, one overload per measurement model; the gate is off unless given.
    virtual PoseUpdateReport<WallMeasurement::kSize> update(const WallMeasurement& model,
                                                            const MahalanobisGate& gate) = 0;
    virtual PoseUpdateReport<BeaconBearingMeasurement::kSize> update(
        const BeaconBearingMeasurement& model, const MahalanobisGate& gate) = 0;
    virtual PoseUpdateReport<CompassMeasurement::kSize> update(const CompassMeasurement& model,
                                                               const MahalanobisGate& gate) = 0;
    virtual PoseUpdateReport<LaserPoseMeasurement::kSize> update(const LaserPoseMeasurement& model,
                                                                 const MahalanobisGate& gate) = 0;

    /// Whether the filter weighs whole laser scans against the map's likelihood field (the
    /// particle filter) rather than taking the ICP match as a pose observation.
    virtual bool weighs_scans() const = 0;
    /// A scan weighed against the likelihood field; NotAttempted unless weighs_scans().
    virtual StepStatus update(const ScanLikelihood& scan) = 0;

    /// An update without a gate.
    template <class Model>
    PoseUpdateReport<Model::kSize> update(const Model& model) {
        return update(model, MahalanobisGate{});
    }

  protected:
    PoseEstimator() = default;
    PoseEstimator(const PoseEstimator&) = default;
    PoseEstimator& operator=(const PoseEstimator&) = default;
};

}  // namespace legofeup
