#pragma once
// Keeping a covariance matrix a covariance matrix.
//
// Students type absurd Q and R on purpose (1e-12 … 1e6); the filter must stay finite,
// symmetric and positive semi-definite whatever they type. After every predict and update
// the filter base passes P through condition_covariance:
//   1. symmetrise, P ← (P + Pᵀ)/2 (rounding makes the two triangles drift apart);
//   2. ceiling: rows/columns with P_ii > max are scaled by √(max/P_ii) (a congruence, so
//      correlations and definiteness are kept);
//   3. floor: P_ii < min gets (min − P_ii) added on the diagonal (adding a PSD matrix);
//   4. if P is not robustly positive definite (an eigenvalue ≤ 1e-13·trace P, from
//      cancellation; an LDLᵀ of P − 1e-13·trace(P)·I fails), P is
//      projected onto the PD cone by clamping its eigenvalues to ≥ min (and to ≥ 1e-12 of
//      the largest, the most a double can resolve); if rounding in rebuilding P from its
//      eigenvectors still leaves it indefinite, a growing multiple of the identity is added.

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "legofeup/core/small_ldlt.hpp"

namespace legofeup {

struct CovarianceLimits {
    double min_variance = 1e-12;  ///< floor on every variance (state units squared)
    double max_variance = 1e12;   ///< ceiling on every variance
};

/// Smallest eigenvalue kept by the projection, relative to the largest.
inline constexpr double kRelativeEigenvalueFloor = 1e-12;

/// What condition_covariance had to do, as bit flags (0: nothing).
enum CovarianceRepair : std::uint8_t {
    kRepairNone = 0,
    kRepairCeiling = 1,
    kRepairFloor = 2,
    kRepairProjection = 4,
};

/// True if the symmetric matrix P is positive definite: every pivot of its LDLᵀ
/// factorisation (Cholesky without square roots, small_ldlt.hpp) is positive.
template <int N>
bool is_positive_definite(const Eigen::Matrix<double, N, N>& P) {
    return SmallLdlt<N>().factorise(P);
}

/// Smallest eigenvalue, relative to trace(P), that the guard accepts without projecting.
/// A pivot of a few ε·‖P‖ passes an exact LDLᵀ test but is rounding noise: another order
/// of the same arithmetic (Eigen's LLT, another compiler) finds the matrix indefinite.
inline constexpr double kPositiveDefiniteMargin = 1e-13;

/// True if every eigenvalue of the symmetric P exceeds kPositiveDefiniteMargin·trace(P):
/// P − margin·I is positive definite. The margin is far above rounding (ε·‖P‖ ≈ 2e-16·‖P‖),
/// so any Cholesky of P succeeds, and below the projection's floor (1e-12·λ_max ≥
/// 1e-12·trace/N), so a projected P passes.
template <int N>
bool is_robustly_positive_definite(const Eigen::Matrix<double, N, N>& P) {
    Eigen::Matrix<double, N, N> shifted = P;
    shifted.diagonal().array() -= kPositiveDefiniteMargin * P.trace();
    return is_positive_definite<N>(shifted);
}

/// Conditions P in place (see the file comment). P must be finite. Returns the repairs made.
template <int N>
std::uint8_t condition_covariance(Eigen::Matrix<double, N, N>& P, const CovarianceLimits& limits) {
    std::uint8_t repairs = kRepairNone;
    P = (0.5 * (P + P.transpose())).eval();

    Eigen::Matrix<double, N, 1> scale = Eigen::Matrix<double, N, 1>::Ones();
    for (int i = 0; i < N; ++i) {
        if (P(i, i) > limits.max_variance) {
            scale(i) = std::sqrt(limits.max_variance / P(i, i));
            repairs |= kRepairCeiling;
        }
    }
    if (repairs & kRepairCeiling) {
        // P ← S·P·S elementwise; s_i·s_j == s_j·s_i exactly, so P stays exactly symmetric.
        for (int i = 0; i < N; ++i) {
            for (int j = 0; j < N; ++j) {
                P(i, j) *= scale(i) * scale(j);
            }
        }
    }

    for (int i = 0; i < N; ++i) {
        if (P(i, i) < limits.min_variance) {
            P(i, i) = limits.min_variance;  // == P_ii + (min − P_ii)
            repairs |= kRepairFloor;
        }
    }

    if (!is_robustly_positive_definite<N>(P)) {
        // Clamp to the floor, and to 1e-12 of the largest eigenvalue: a condition number
        // beyond ~1e12 cannot be represented in doubles and would fail Cholesky again.
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> eigen(P);
        const double floor = std::max(limits.min_variance,
                                      kRelativeEigenvalueFloor * eigen.eigenvalues().maxCoeff());
        const auto clamped = eigen.eigenvalues().cwiseMax(floor);
        P = eigen.eigenvectors() * clamped.asDiagonal() * eigen.eigenvectors().transpose();
        P = (0.5 * (P + P.transpose())).eval();
        // Rebuilding P from its eigenvectors rounds each entry by ~ε·λ_max, far below the
        // floor, so P passes the test above. Should it not (a floor at the ceiling), δ·I,
        // which lifts every eigenvalue by exactly δ, is added with δ doubling until it does.
        for (double lift = floor;
             !is_robustly_positive_definite<N>(P) && lift < limits.max_variance; lift *= 2.0) {
            P.diagonal().array() += lift;
        }
        repairs |= kRepairProjection;
    }
    return repairs;
}

}  // namespace legofeup
