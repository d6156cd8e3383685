#pragma once
// The particle filter over the pose X = [x, y, θ] (Monte Carlo localisation; Thrun, Burgard
// & Fox, Probabilistic Robotics, ch. 4 and 8). It runs on the same model hooks as the UKF
// (unscented_kalman_filter.hpp's concepts), so every lesson's models serve all three filters:
//
//   predict(process model)   1. every particle moves by f(Xᵢ, U, qᵢ) with its own noise draw
//                               qᵢ ~ N(0, Q), Q the model's — the EKF's Q (Table 4.3 line 4,
//                               sample_motion_model with the odometry model of eq. 10);
//                               plus, when set, the book's α₁…α₄ noise on its motion
//                               (odometry_alphas.hpp, Table 5.6)
//   update(measurement, gate) 2. weights wᵢ ← wᵢ·p(z | Xᵢ), p the Gaussian of the model's R
//                               around h(Xᵢ) (Table 4.3 line 5)
//                             3. the likelihood's long- and short-term averages w_slow,
//                               w_fast (augmented MCL, Table 8.3 lines 8–10)
//                             4. low-variance resampling (Table 4.4) when N_eff < threshold·N
//                             0. (at the start of the next update) recovery: each particle is
//                               replaced by a free-space draw with probability
//                               max(0, 1 − w_fast/w_slow) (Table 8.3 lines 12–19), before the
//                               update weighs it
//   state(), covariance()     5. the weighted mean (θ on the circle: atan2 of the weighted
//                               sines and cosines) and covariance of the cloud, conditioned
//                               by the covariance guard like every filter's P, so that the
//                               ellipse, NEES and the plots read it as they read the EKF's
//
// The update's report is the Gaussian summary of the same step: ẑ the weighted mean of
// h(Xᵢ), S their weighted covariance plus R, ν = z − ẑ, NIS = νᵀS⁻¹ν, and W the gain a
// Kalman filter with this cloud's cross-covariance would apply (for display only: the cloud
// moves by its weights, not by W). The gate rejects on that NIS, as the EKF's does.
//
// All particles impossible (every likelihood NaN, or an underflow to 0 even in the log
// domain) is refused: the update reports RejectedNonFinite and the weights stay as they
// were. The random stream is the filter's own (random_stream.hpp), restarted from the
// configured seed at every reset.

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "legofeup/core/angles.hpp"
#include "legofeup/core/extended_kalman_filter.hpp"  // StepStatus, MahalanobisGate, UpdateReport
#include "legofeup/core/filter_base.hpp"
#include "legofeup/core/likelihood_field.hpp"
#include "legofeup/core/matrix_square_root.hpp"
#include "legofeup/core/odometry_alphas.hpp"
#include "legofeup/core/particle_summary.hpp"
#include "legofeup/core/pose_estimator_settings.hpp"
#include "legofeup/core/pose_state_space.hpp"
#include "legofeup/core/random_stream.hpp"
#include "legofeup/core/small_ldlt.hpp"
#include "legofeup/core/unscented_kalman_filter.hpp"  // the hook concepts

namespace legofeup {

class ParticleFilter : public FilterBase<PoseStateSpace> {
    using Base = FilterBase<PoseStateSpace>;

  public:
    ParticleFilter();

    /// Takes the tuning, seed and free space. A new particle count resamples the cloud to
    /// that many (low-variance, so the distribution is kept); the rest applies from the next
    /// step.
    void configure(const PoseEstimatorSettings& settings);

    /// N particles drawn from N(x, P) with equal weights (P not factorisable: its diagonal;
    /// P = 0: every particle at x). Returns false, changing nothing, if x or P is not finite.
    bool reset(const StateVector& x, const StateCovariance& P);
    /// N particles uniform over the configured free space (global localisation). Returns
    /// false, changing nothing, when there is none.
    bool reset_uniform();

    // 1. Prediction.
    template <UkfProcessModel<kStateSize> Model>
    StepStatus predict(const Model& model);

    // 2–5. Update.
    template <UkfMeasurementModel<kStateSize> Model>
    UpdateReport<Model::kSize, kStateSize> update(const Model& model,
                                                  const MahalanobisGate& gate = {});

    /// Weights the cloud by per-particle log-likelihoods computed by the caller (the laser's
    /// likelihood field, whose measurement is a whole scan): steps 2–5 with
    /// log p(z | Xᵢ) = log_likelihood(Xᵢ), and `dimension` scalar readings in z (the
    /// likelihood per reading, exp(log p / dimension), is what w_slow and w_fast average, so
    /// that a scan of 80 beams and a pair of IR readings give averages of like size).
    template <class LogLikelihood>
    StepStatus weigh(LogLikelihood&& log_likelihood, int dimension);

    /// A laser scan against the map's likelihood field: weigh() with scan_log_likelihood,
    /// one reading per end point. NotAttempted for a scan without end points.
    StepStatus update(const ScanLikelihood& scan);

    const ParticleSummary& summary() const { return summary_; }
    std::span<const double> xs() const { return x_; }
    std::span<const double> ys() const { return y_; }
    std::span<const double> thetas() const { return theta_; }
    std::span<const double> weights() const { return weight_; }
    const ParticleFilterTuning& tuning() const { return tuning_; }

  private:
    StateVector particle(std::size_t i) const { return {x_[i], y_[i], theta_[i]}; }
    void set_particle(std::size_t i, const StateVector& p) {
        x_[i] = p(kX);
        y_[i] = p(kY);
        theta_[i] = wrap_angle(p(kTheta));
    }
    void resize(std::size_t count);
    template <class Draw>
    bool start_cloud(Draw&& draw);
    /// Steps 2–4 once logl_ holds log p(z | Xᵢ).
    StepStatus apply_likelihoods(int dimension);
    /// Step 4: low-variance resampling to `count` particles.
    void resample(std::size_t count);
    /// Step 0: the injection the last update decided (augmented MCL).
    void inject_pending();
    /// N_eff = 1 / Σ wᵢ² of the weights now (steps 4 and 5).
    double effective_count() const;
    /// Step 5: publishes the cloud's moments and summary.
    StepStatus publish();
    /// One pose from the free space (requires one).
    StateVector random_pose();

    ParticleFilterTuning tuning_;
    std::uint64_t seed_ = 1;
    std::shared_ptr<const FreeSpace> free_space_;
    RandomStream random_;
    std::vector<double> x_, y_, theta_, weight_;
    std::vector<double> logl_;                          // this update's log-likelihoods
    std::vector<double> next_x_, next_y_, next_theta_;  // resampling's scratch
    double w_slow_ = 0.0;
    double w_fast_ = 0.0;
    double pending_inject_ = 0.0;
    /// N_eff of the last update's weights, before the resampling they may have triggered;
    /// 0 until the cloud's first update (ParticleSummary::effective).
    double weighed_effective_ = 0.0;
    ParticleSummary summary_;
};

// ---------------------------------------------------------------------------------------------

template <UkfProcessModel<kStateSize> Model>
StepStatus ParticleFilter::predict(const Model& model) {
    constexpr int Nq = Model::kNoiseSize;
    using NoiseVector = Eigen::Matrix<double, Nq, 1>;
    using NoiseMatrix = Eigen::Matrix<double, Nq, Nq>;
    const NoiseMatrix Q = model.noise_covariance();
    NoiseMatrix root;  // L with L·Lᵀ = Q: q = L·n, n ~ N(0, I), has covariance Q
    if (!Q.allFinite() || !psd_square_root<Nq>(Q, root)) {
        return StepStatus::RejectedNonFinite;
    }
    // 1. Xᵢ ← f(Xᵢ, U, qᵢ), qᵢ = L·nᵢ; then the α's error on the motion f(Xᵢ, U, 0) − Xᵢ.
    const OdometryAlphas& alphas = tuning_.motion_alphas;
    const bool with_alphas = alphas.any();
    for (std::size_t i = 0; i < x_.size(); ++i) {
        NoiseVector n;
        for (int k = 0; k < Nq; ++k) {
            n(k) = random_.normal();
        }
        const StateVector from = particle(i);
        StateVector moved = model.propagate(from, NoiseVector(root * n));
        if (with_alphas) {
            moved = add_odometry_alpha_noise(from, model.propagate(from, NoiseVector::Zero()),
                                             moved, alphas, random_);
        }
        if (!moved.allFinite()) {
            return StepStatus::RejectedNonFinite;  // a model that cannot move a particle
        }
        set_particle(i, moved);
    }
    return publish();
}

template <UkfMeasurementModel<kStateSize> Model>
UpdateReport<Model::kSize, kStateSize> ParticleFilter::update(const Model& model,
                                                              const MahalanobisGate& gate) {
    constexpr int M = Model::kSize;
    using MeasurementVector = Eigen::Matrix<double, M, 1>;
    using MeasurementMatrix = Eigen::Matrix<double, M, M>;
    UpdateReport<M, kStateSize> report;
    inject_pending();  // 0.
    report.measurement = model.measurement();
    const MeasurementMatrix R = model.noise_covariance();
    SmallLdlt<M> r_ldlt;
    if (!report.measurement.allFinite() || !R.allFinite()) {
        report.status = StepStatus::RejectedNonFinite;
        return report;
    }
    if (!r_ldlt.factorise(R)) {
        report.status = StepStatus::RejectedSingular;
        return report;
    }
    // The Gaussian summary: deviations dᵢ = h(Xᵢ) − h(X̂) (wrapped by the model's residual)
    // and their weighted moments; with them ν, S, the cross-covariance C and the NIS.
    const StateVector mean = state();
    const MeasurementVector reference = model.predict_measurement(mean);
    MeasurementVector d_mean = MeasurementVector::Zero();
    MeasurementMatrix d_outer = MeasurementMatrix::Zero();
    Eigen::Matrix<double, kStateSize, M> cross = Eigen::Matrix<double, kStateSize, M>::Zero();
    StateVector dx_mean = StateVector::Zero();
    for (std::size_t i = 0; i < x_.size(); ++i) {
        const StateVector p = particle(i);
        const MeasurementVector predicted = model.predict_measurement(p);
        const MeasurementVector nu = model.residual(report.measurement, predicted);
        logl_[i] = -0.5 * nu.dot(r_ldlt.solve(nu));  // 2. log p(z | Xᵢ) up to a constant
        const MeasurementVector d = model.residual(predicted, reference);
        const double w = weight_[i];
        d_mean += w * d;
        d_outer += w * d * d.transpose();
        const StateVector dx = PoseStateSpace::difference(p, mean);
        dx_mean += w * dx;
        cross += w * dx * d.transpose();
    }
    report.predicted = reference + d_mean;
    report.innovation = model.residual(report.measurement, reference) - d_mean;
    const MeasurementMatrix spread = d_outer - d_mean * d_mean.transpose();
    report.innovation_covariance = spread + R;
    report.innovation_covariance =
        (0.5 * (report.innovation_covariance + report.innovation_covariance.transpose())).eval();
    cross -= dx_mean * d_mean.transpose();  // C = Σ wᵢ (Xᵢ − X̄)(dᵢ − d̄)ᵀ
    if (!report.innovation.allFinite() || !report.innovation_covariance.allFinite()) {
        report.status = StepStatus::RejectedNonFinite;
        return report;
    }
    if (!solve_gain<M, kStateSize>(report, cross, gate)) {
        return report;
    }
    // The likelihood's constant: p = exp(log) / √((2π)^M |R|), for w_slow and w_fast.
    double log_det = 0.0;
    for (int k = 0; k < M; ++k) {
        log_det += std::log(r_ldlt.pivot(k));
    }
    const double log_normaliser = -0.5 * (M * std::log(2.0 * kPi) + log_det);
    for (double& value : logl_) {
        value += log_normaliser;
    }
    report.status = apply_likelihoods(M);
    return report;
}

template <class LogLikelihood>
StepStatus ParticleFilter::weigh(LogLikelihood&& log_likelihood, int dimension) {
    inject_pending();  // 0.
    for (std::size_t i = 0; i < x_.size(); ++i) {
        logl_[i] = log_likelihood(x_[i], y_[i], theta_[i]);
    }
    return apply_likelihoods(dimension);
}

}  // namespace legofeup
