#pragma once
// The Extended Kalman Filter (paper Algorithm 1, eq. 11–21).
//
// Process model hooks (one object per step, carrying its input U and noise Q):
//   static constexpr int kNoiseSize;
//   Vector predict_state(const Vector& x)            f(X, U, 0)          (eq. 11)
//   Matrix<N,N> state_jacobian(const Vector& x)      ∇f_X = ∂f/∂X        (eq. 13)
//   Matrix<N,Nq> noise_jacobian(const Vector& x)     ∇f_q = ∂f/∂q        (eq. 13)
//   Matrix<Nq,Nq> noise_covariance()                 Q
//   optionally linearise(const Vector& x)           {state, state_jacobian, noise_jacobian}
//                                                    the three above at once, for a model
//                                                    whose three share work (the odometry's
//                                                    cos φ and sin φ); the same bits as the
//                                                    three separate hooks (a test checks it)
// Measurement model hooks (one object per measurement):
//   static constexpr int kSize;
//   Vector measurement()                             z
//   Vector predict_measurement(const Vector& x)      h(X)
//   Matrix<M,N> jacobian(const Vector& x)            ∇h_X                (eq. 17)
//   Matrix<M,M> noise_covariance()                   ∇h_r·R·∇h_rᵀ        (eq. 16)
//   Vector residual(z, ẑ)                            z − ẑ, angles wrapped
//
// Numerics: S is factorised with LDLT (never inverted); the covariance update is the Joseph
// form P⁺ = (I − W∇h_X)·P·(I − W∇h_X)ᵀ + W·R_z·Wᵀ, which equals eq. 21 (corrected) for the
// optimal gain and stays positive semi-definite for any gain; the base then symmetrises
// and floors P. Non-finite inputs or results leave x and P unchanged.

#include <concepts>
#include <limits>

#include "legofeup/core/filter_base.hpp"
#include "legofeup/core/small_ldlt.hpp"

namespace legofeup {

template <class M, int N>
concept EkfProcessModel = requires(const M& model, const Eigen::Matrix<double, N, 1>& x) {
    { M::kNoiseSize } -> std::convertible_to<int>;
    { model.predict_state(x) } -> std::convertible_to<Eigen::Matrix<double, N, 1>>;
    { model.state_jacobian(x) } -> std::convertible_to<Eigen::Matrix<double, N, N>>;
    { model.noise_jacobian(x) } -> std::convertible_to<Eigen::Matrix<double, N, M::kNoiseSize>>;
    {
        model.noise_covariance()
        } -> std::convertible_to<Eigen::Matrix<double, M::kNoiseSize, M::kNoiseSize>>;
};

template <class M, int N>
concept EkfMeasurementModel = requires(const M& model, const Eigen::Matrix<double, N, 1>& x,
                                       const Eigen::Matrix<double, M::kSize, 1>& z) {
    { model.measurement() } -> std::convertible_to<Eigen::Matrix<double, M::kSize, 1>>;
    { model.predict_measurement(x) } -> std::convertible_to<Eigen::Matrix<double, M::kSize, 1>>;
    { model.jacobian(x) } -> std::convertible_to<Eigen::Matrix<double, M::kSize, N>>;
    { model.noise_covariance() } -> std::convertible_to<Eigen::Matrix<double, M::kSize, M::kSize>>;
    { model.residual(z, z) } -> std::convertible_to<Eigen::Matrix<double, M::kSize, 1>>;
};

/// Optional Mahalanobis gate: reject a measurement whose NIS exceeds `threshold`
/// (use chi_square_quantile(p, kSize) for a gate at probability p).
struct MahalanobisGate {
    bool enabled = false;
    double threshold = std::numeric_limits<double>::infinity();
};

/// Everything one update computed, for the snapshot and the plots.
template <int M, int N>
struct UpdateReport {
    StepStatus status = StepStatus::NotAttempted;
    Eigen::Matrix<double, M, 1> measurement = Eigen::Matrix<double, M, 1>::Zero();  ///< z
    Eigen::Matrix<double, M, 1> predicted = Eigen::Matrix<double, M, 1>::Zero();    ///< h(X̂)
    Eigen::Matrix<double, M, 1> innovation = Eigen::Matrix<double, M, 1>::Zero();   ///< ν
    Eigen::Matrix<double, M, M> innovation_covariance = Eigen::Matrix<double, M, M>::Zero();  ///< S
    Eigen::Matrix<double, N, M> gain = Eigen::Matrix<double, N, M>::Zero();  ///< W (eq. 16)
    double nis = std::numeric_limits<double>::quiet_NaN();                   ///< νᵀS⁻¹ν
};

/// The part of an update the EKF and the UKF share once they have ν and S (in `report`) and
/// the cross-covariance C between state and measurement (P·∇h_Xᵀ for the EKF, P_xz for the
/// UKF): factorise S with LDLᵀ (small_ldlt.hpp), compute the NIS, apply the gate and the gain W =
/// C·S⁻¹. Returns false, with report.status saying why, when the update must not go on.
template <int M, int N>
bool solve_gain(UpdateReport<M, N>& report, const Eigen::Matrix<double, N, M>& cross,
                const MahalanobisGate& gate) {
    SmallLdlt<M> ldlt;
    if (!ldlt.factorise(report.innovation_covariance)) {
        report.status = StepStatus::RejectedSingular;
        return false;
    }
    report.nis = report.innovation.dot(ldlt.solve(report.innovation));
    if (gate.enabled && !(report.nis <= gate.threshold)) {
        report.status = StepStatus::RejectedByGate;
        return false;
    }
    // W = C·S⁻¹: each row of W is (S⁻¹·row of C)ᵀ since S is symmetric.
    for (int row = 0; row < N; ++row) {
        report.gain.row(row) = ldlt.solve(cross.row(row).transpose()).transpose();
    }
    return true;
}

template <class StateSpace>
class ExtendedKalmanFilter : public FilterBase<StateSpace> {
    using Base = FilterBase<StateSpace>;

  public:
    static constexpr int kSize = Base::kSize;
    using Vector = typename Base::Vector;
    using Covariance = typename Base::Covariance;

    /// Prediction (eq. 11–12): X̂ ← f(X̂, U, 0),  P ← ∇f_X·P·∇f_Xᵀ + ∇f_q·Q·∇f_qᵀ.
    template <EkfProcessModel<kSize> Model>
    StepStatus predict(const Model& model) {
        const Vector& x = this->state();
        if constexpr (requires { model.linearise(x); }) {
            const auto linearised = model.linearise(x);
            return predict_from(linearised.state, linearised.state_jacobian,
                                linearised.noise_jacobian, model.noise_covariance());
        } else {
            // ∇f_X and ∇f_q at the prior estimate.
            return predict_from(model.predict_state(x), model.state_jacobian(x),
                                model.noise_jacobian(x), model.noise_covariance());
        }
    }

    /// Update (eq. 14–21) with one measurement.
    template <EkfMeasurementModel<kSize> Model>
    UpdateReport<Model::kSize, kSize> update(const Model& model, const MahalanobisGate& gate = {}) {
        constexpr int M = Model::kSize;
        using MeasurementMatrix = Eigen::Matrix<double, M, M>;
        UpdateReport<M, kSize> report;
        const Vector& x = this->state();
        const Covariance& P = this->covariance();

        report.measurement = model.measurement();                                  // z
        report.predicted = model.predict_measurement(x);                           // h(X̂)
        report.innovation = model.residual(report.measurement, report.predicted);  // ν = z − h
        const auto H = model.jacobian(x);                                          // ∇h_X
        const MeasurementMatrix R = model.noise_covariance();  // ∇h_r R ∇h_rᵀ
        MeasurementMatrix S = H * P * H.transpose() + R;       // eq. 16
        S = (0.5 * (S + S.transpose())).eval();
        report.innovation_covariance = S;
        if (!report.innovation.allFinite() || !S.allFinite()) {  // S carries any NaN/Inf of R
            report.status = StepStatus::RejectedNonFinite;
            return report;
        }

        // W = P·∇h_Xᵀ·S⁻¹ (eq. 16).
        if (!solve_gain<M, kSize>(report, (H * P).transpose(), gate)) {
            return report;
        }
        const Vector x_new = x + report.gain * report.innovation;  // eq. 14
        const Covariance I_WH = Covariance::Identity() - report.gain * H;
        const Covariance P_new = I_WH * P * I_WH.transpose()  // Joseph form of eq. 21
                                 + report.gain * R * report.gain.transpose();
        report.status = this->commit(x_new, P_new);
        return report;
    }

  private:
    /// Eq. 11–12 once f(X̂), ∇f_X, ∇f_q and Q are known.
    template <class StateJacobian, class NoiseJacobian, class NoiseCovariance>
    StepStatus predict_from(const Vector& predicted, const StateJacobian& F, const NoiseJacobian& G,
                            const NoiseCovariance& Q) {
        const Covariance P = F * this->covariance() * F.transpose() + G * Q * G.transpose();
        return this->commit(predicted, P);
    }
};

}  // namespace legofeup
