#pragma once
// LDLᵀ of a small fixed-size symmetric matrix, without pivoting, written out.
//
// A = L·D·Lᵀ with L unit lower triangular and D = diag(d): for j = 0 … N−1
//   d_j  = A_jj − Σ_{k<j} L_jk²·d_k
//   L_ij = (A_ij − Σ_{k<j} L_ik·L_jk·d_k) / d_j                    (i > j)
// Only the lower triangle of A is read. A symmetric A is positive definite if and only if
// every pivot d_j > 0, and a positive definite A needs no pivoting for a stable
// factorisation. Solving A·x = b: L·y = b forward, then Lᵀ·x = D⁻¹·y backward.
//
// Who uses it: the covariance guard (is P, 1×1 … 3×3, positive definite?), the filters'
// gain and NIS (S⁻¹·ν, S of a 1-, 2- or 3-dimensional measurement, solved, never inverted),
// the wall association's Mahalanobis distance and the NEES. Why not Eigen::LDLT: its
// general, pivoted, run-time sized path cost more than the rest of a filter step for these
// sizes (benchmarks in bench/core_bench.cpp); these loops over compile-time bounds unroll to
// a few dozen flops and touch no memory but their own.

#include <Eigen/Core>

namespace legofeup {

template <int N>
class SmallLdlt {
  public:
    using Matrix = Eigen::Matrix<double, N, N>;
    using Vector = Eigen::Matrix<double, N, 1>;

    /// Factorises A (its lower triangle). Returns whether every pivot is > 0, i.e. whether A
    /// is positive definite; a NaN anywhere fails. After a failure solve() must not be used.
    bool factorise(const Matrix& A) {
        for (int j = 0; j < N; ++j) {
            double pivot = A(j, j);
            for (int k = 0; k < j; ++k) {
                pivot -= lower_(j, k) * lower_(j, k) * pivots_(k);
            }
            if (!(pivot > 0.0)) {
                return false;  // also catches NaN
            }
            pivots_(j) = pivot;
            for (int i = j + 1; i < N; ++i) {
                double value = A(i, j);
                for (int k = 0; k < j; ++k) {
                    value -= lower_(i, k) * lower_(j, k) * pivots_(k);
                }
                lower_(i, j) = value / pivot;
            }
        }
        return true;
    }

    /// x with A·x = b, for the A last factorised successfully.
    Vector solve(const Vector& b) const {
        Vector y;
        for (int i = 0; i < N; ++i) {  // L·y = b
            double value = b(i);
            for (int k = 0; k < i; ++k) {
                value -= lower_(i, k) * y(k);
            }
            y(i) = value;
        }
        Vector x;
        for (int i = N - 1; i >= 0; --i) {  // Lᵀ·x = D⁻¹·y
            double value = y(i) / pivots_(i);
            for (int k = i + 1; k < N; ++k) {
                value -= lower_(k, i) * x(k);
            }
            x(i) = value;
        }
        return x;
    }

    /// d_j: the pivots of the last factorisation (valid up to the one that failed).
    double pivot(int j) const { return pivots_(j); }
    /// L_ij (i > j) of the last factorisation.
    double lower(int i, int j) const { return lower_(i, j); }

  private:
    Matrix lower_ = Matrix::Zero();  ///< L below the diagonal (its unit diagonal is not stored)
    Vector pivots_ = Vector::Zero();
};

}  // namespace legofeup
