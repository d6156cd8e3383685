#pragma once
// The Unscented Kalman Filter (paper 002 §II.C, eq. 11–15), with the same model objects as
// the EKF so the loop can swap one for the other.
//
// Unscented transform of a Gaussian (mean m, covariance P) of dimension n through g:
//   sigma points   X₀ = m,  Xᵢ = m + (√((n+κ)·P))ᵢ,  Xₙ₊ᵢ = m − (√((n+κ)·P))ᵢ     (eq. 11)
//                  (√ is the lower Cholesky factor; (·)ᵢ its i-th column)
//   weights        W₀ = κ/(n+κ),  Wᵢ = 1/(2(n+κ)),  i = 1…2n                       (eq. 13)
//   transformed    Yᵢ = g(Xᵢ)                                                        (eq. 12)
//   mean           Ȳ = Σ Wᵢ·Yᵢ         (angles: see angle_mean.hpp)                  (eq. 14)
//   covariance     P_y = Σ Wᵢ·(Yᵢ − Ȳ)(Yᵢ − Ȳ)ᵀ   (differences wrapped)              (eq. 15)
//
// Prediction: the noise q enters f non-additively (the odometry noise acts on d and Δθ),
// so we transform the augmented state [X; q] ~ N([X̂; 0], blkdiag(P, Q)) of dimension
// n = N + N_q. Its Cholesky factor is blkdiag(√P, √Q), so each sigma point perturbs either
// X or q. (With additive noise this equals the paper's "P_y + V".)
// Update: sigma points of N(X̂, P), n = N; Z̄ = Σ Wᵢ·h(Xᵢ); S = Σ Wᵢ·ΔZᵢΔZᵢᵀ + R;
//   P_xz = Σ Wᵢ·ΔXᵢΔZᵢᵀ;  W = P_xz·S⁻¹ (LDLT solves);  X̂ ← X̂ + W·(z − Z̄);  P ← P − W·S·Wᵀ.
//
// Process model hooks:   kNoiseSize, propagate(x, q) = f(X, U, q), noise_covariance() = Q.
// Measurement hooks:     kSize, measurement(), predict_measurement(x), noise_covariance(),
//                        residual(a, b); optionally weighted_mean(points, weights) for a
//                        measurement with angles (otherwise Z̄ = Z₀ + Σ Wᵢ·residual(Zᵢ, Z₀)).
// State space hooks:     kSize, normalize, difference; optionally weighted_mean.
//
// Prediction without sigma points: when n + κ ≤ 0, Cholesky refuses P, or Q is not positive
// semi-definite, the transform cannot be taken; the prediction is then the EKF's (linearised,
// linearised_prediction.hpp) and reported as AppliedLinearised, so the motion is never lost.
// Q may be only semi-definite (a zero noise component is legal); a non-finite Q is rejected
// (RejectedNonFinite) as the EKF rejects it. An update that cannot draw sigma points is
// rejected (RejectedSingular) leaving x and P unchanged: a skipped correction loses nothing. A W₀ <
// 0 (κ < 0) can make the transformed covariance indefinite; the base's conditioning repairs P and
// an indefinite S is rejected like the EKF's.

#include <Eigen/Cholesky>
#include <array>
#include <concepts>
#include <cstddef>

#include "legofeup/core/extended_kalman_filter.hpp"  // StepStatus, MahalanobisGate, UpdateReport
#include "legofeup/core/filter_base.hpp"
#include "legofeup/core/lesson_filters_config.hpp"
#include "legofeup/core/linearised_prediction.hpp"
#include "legofeup/core/matrix_square_root.hpp"

namespace legofeup {

template <class M, int N>
concept UkfProcessModel = requires(const M& model, const Eigen::Matrix<double, N, 1>& x,
                                   const Eigen::Matrix<double, M::kNoiseSize, 1>& q) {
    { model.propagate(x, q) } -> std::convertible_to<Eigen::Matrix<double, N, 1>>;
    {
        model.noise_covariance()
        } -> std::convertible_to<Eigen::Matrix<double, M::kNoiseSize, M::kNoiseSize>>;
};

template <class M, int N>
concept UkfMeasurementModel = requires(const M& model, const Eigen::Matrix<double, N, 1>& x,
                                       const Eigen::Matrix<double, M::kSize, 1>& z) {
    { model.measurement() } -> std::convertible_to<Eigen::Matrix<double, M::kSize, 1>>;
    { model.predict_measurement(x) } -> std::convertible_to<Eigen::Matrix<double, M::kSize, 1>>;
    { model.noise_covariance() } -> std::convertible_to<Eigen::Matrix<double, M::kSize, M::kSize>>;
    { model.residual(z, z) } -> std::convertible_to<Eigen::Matrix<double, M::kSize, 1>>;
};

/// The weights of eq. 13 for 2n+1 sigma points (they sum to 1).
template <std::size_t K>
std::array<double, K> unscented_weights(int n, double kappa) {
    std::array<double, K> weights;
    weights.fill(0.5 / (n + kappa));   // Wᵢ = 1/(2(n+κ))
    weights[0] = kappa / (n + kappa);  // W₀ = κ/(n+κ)
    return weights;
}

template <class StateSpace>
class UnscentedKalmanFilter : public FilterBase<StateSpace> {
    using Base = FilterBase<StateSpace>;

  public:
    static constexpr int kSize = Base::kSize;
    using Vector = typename Base::Vector;
    using Covariance = typename Base::Covariance;

    explicit UnscentedKalmanFilter(UkfParams params = {}) : params_(params) {}
    void set_params(const UkfParams& params) { params_ = params; }
    const UkfParams& params() const { return params_; }

    /// Prediction: unscented transform of the augmented [X; q] through f.
    template <UkfProcessModel<kSize> Model>
    StepStatus predict(const Model& model) {
        constexpr int Nq = Model::kNoiseSize;
        constexpr int n = kSize + Nq;  // augmented dimension
        constexpr std::size_t K = 2 * n + 1;
        using NoiseVector = Eigen::Matrix<double, Nq, 1>;
        using NoiseMatrix = Eigen::Matrix<double, Nq, Nq>;

        const NoiseMatrix Q = model.noise_covariance();
        if (!Q.allFinite()) {
            return StepStatus::RejectedNonFinite;
        }
        const double spread = n + params_.kappa;  // n + κ
        Covariance root_p;                        // √((n+κ)·P)
        NoiseMatrix root_q;                       // √((n+κ)·Q)
        if (!(spread > 0.0) || !cholesky_root<kSize>(spread * this->covariance(), root_p)
            || !psd_square_root<Nq>(spread * Q, root_q)) {
            // No sigma points: predict as the EKF does rather than drop the motion.
            const auto linearised =
                linearised_prediction<StateSpace>(model, this->state(), this->covariance());
            const StepStatus status = this->commit(linearised.state, linearised.covariance);
            return status == StepStatus::Applied ? StepStatus::AppliedLinearised : status;
        }

        // Eq. 11–12 on the augmented state: Y₀ = f(X̂, 0); ±columns of √P perturb X,
        // ±columns of √Q perturb q.
        const Vector& x = this->state();
        const NoiseVector no_noise = NoiseVector::Zero();
        constexpr std::size_t kN = kSize;  // index offsets of eq. 11 as array indices
        constexpr std::size_t kAugmented = n;
        std::array<Vector, K> Y;
        Y[0] = model.propagate(x, no_noise);
        for (std::size_t j = 0; j < kN; ++j) {
            const Vector column = root_p.col(static_cast<Eigen::Index>(j));
            Y[1 + j] = model.propagate(normalized(x + column), no_noise);
            Y[1 + kAugmented + j] = model.propagate(normalized(x - column), no_noise);
        }
        for (std::size_t j = 0; j < static_cast<std::size_t>(Nq); ++j) {
            const NoiseVector column = root_q.col(static_cast<Eigen::Index>(j));
            Y[1 + kN + j] = model.propagate(x, column);
            Y[1 + kAugmented + kN + j] = model.propagate(x, NoiseVector(-column));
        }
        const std::array<double, K> w = unscented_weights<K>(n, params_.kappa);

        const Vector mean = state_mean(Y, w);  // eq. 14
        Covariance P = Covariance::Zero();     // eq. 15
        for (std::size_t i = 0; i < K; ++i) {
            const Vector d = StateSpace::difference(Y[i], mean);
            P += w[i] * d * d.transpose();
        }
        return this->commit(mean, P);
    }

    /// Update with one measurement (paper 002 correction step).
    template <UkfMeasurementModel<kSize> Model>
    UpdateReport<Model::kSize, kSize> update(const Model& model, const MahalanobisGate& gate = {}) {
        constexpr int M = Model::kSize;
        constexpr int n = kSize;
        constexpr std::size_t K = 2 * n + 1;
        using MeasurementVector = Eigen::Matrix<double, M, 1>;
        using MeasurementMatrix = Eigen::Matrix<double, M, M>;
        UpdateReport<M, kSize> report;

        const double spread = n + params_.kappa;
        Covariance root_p;
        if (!(spread > 0.0) || !cholesky_root<kSize>(spread * this->covariance(), root_p)) {
            report.status = StepStatus::RejectedSingular;
            return report;
        }
        const Vector& x = this->state();
        const Covariance& P = this->covariance();

        // Sigma points of N(X̂, P) (eq. 11) through h.
        constexpr std::size_t kN = kSize;
        std::array<Vector, K> X;
        X[0] = x;
        for (std::size_t j = 0; j < kN; ++j) {
            const Vector column = root_p.col(static_cast<Eigen::Index>(j));
            X[1 + j] = normalized(x + column);
            X[1 + kN + j] = normalized(x - column);
        }
        std::array<MeasurementVector, K> Z;
        for (std::size_t i = 0; i < K; ++i) {
            Z[i] = model.predict_measurement(X[i]);
        }
        const std::array<double, K> w = unscented_weights<K>(n, params_.kappa);

        report.measurement = model.measurement();                                  // z
        report.predicted = measurement_mean(model, Z, w);                          // Z̄
        report.innovation = model.residual(report.measurement, report.predicted);  // ν = z − Z̄
        const MeasurementMatrix R = model.noise_covariance();
        MeasurementMatrix S = R;
        Eigen::Matrix<double, kSize, M> Pxz = Eigen::Matrix<double, kSize, M>::Zero();
        for (std::size_t i = 0; i < K; ++i) {
            const MeasurementVector dz = model.residual(Z[i], report.predicted);
            S += w[i] * dz * dz.transpose();
            Pxz += w[i] * StateSpace::difference(X[i], x) * dz.transpose();
        }
        S = (0.5 * (S + S.transpose())).eval();
        report.innovation_covariance = S;
        if (!report.innovation.allFinite() || !S.allFinite() || !Pxz.allFinite()) {
            report.status = StepStatus::RejectedNonFinite;
            return report;
        }

        // W = P_xz·S⁻¹.
        if (!solve_gain<M, kSize>(report, Pxz, gate)) {
            return report;
        }
        const Vector x_new = x + report.gain * report.innovation;
        const Covariance P_new = P - report.gain * S * report.gain.transpose();
        report.status = this->commit(x_new, P_new);
        return report;
    }

  private:
    static Vector normalized(Vector x) {
        StateSpace::normalize(x);
        return x;
    }

    /// Eq. 14 for states: the state space's own mean if it has one, otherwise the mean of
    /// the (wrapped) differences from the central point.
    template <std::size_t K>
    static Vector state_mean(const std::array<Vector, K>& points, const std::array<double, K>& w) {
        if constexpr (requires { StateSpace::weighted_mean(points, w); }) {
            return StateSpace::weighted_mean(points, w);
        } else {
            Vector mean = points[0];
            for (std::size_t i = 1; i < K; ++i) {
                mean += w[i] * StateSpace::difference(points[i], points[0]);
            }
            StateSpace::normalize(mean);
            return mean;
        }
    }

    /// Eq. 14 for measurements: the model's weighted_mean if it has one (angles), otherwise
    /// Z₀ + Σ Wᵢ·residual(Zᵢ, Z₀), which is Σ Wᵢ·Zᵢ when residual is a plain subtraction.
    template <class Model, class Point, std::size_t K>
    static Point measurement_mean(const Model& model, const std::array<Point, K>& points,
                                  const std::array<double, K>& w) {
        if constexpr (requires { model.weighted_mean(points, w); }) {
            return model.weighted_mean(points, w);
        } else {
            Point mean = points[0];
            for (std::size_t i = 1; i < K; ++i) {
                mean += w[i] * model.residual(points[i], points[0]);
            }
            return mean;
        }
    }

    UkfParams params_;
};

}  // namespace legofeup
