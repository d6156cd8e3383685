#pragma once
// Square roots of covariance matrices for the unscented transform: any S with S·Sᵀ = A.

#include <Eigen/Cholesky>
#include <algorithm>

namespace legofeup {

/// The Cholesky factor L (A = L·Lᵀ) of a symmetric positive definite A. Returns false, and
/// leaves `root` unspecified, if A is not positive definite (or not finite).
template <int N>
bool cholesky_root(const Eigen::Matrix<double, N, N>& A, Eigen::Matrix<double, N, N>& root) {
    if (!A.allFinite()) {
        return false;
    }
    const Eigen::LLT<Eigen::Matrix<double, N, N>> llt(A);
    if (llt.info() != Eigen::Success) {
        return false;
    }
    root = llt.matrixL();
    return true;
}

/// A square root of a symmetric positive SEMI-definite A, such as a process noise Q with a
/// component a student set to 0 (a legal covariance that Cholesky refuses). Tries Cholesky
/// first; otherwise uses the pivoted LDLᵀ factorisation A = Pᵀ·L·D·Lᵀ·P and returns
/// Pᵀ·L·√D, with pivots that rounding left a hair below zero (≥ −1e-12·max|D|) read as 0.
/// Returns false if A has a clearly negative pivot (not a covariance) or is not finite.
template <int N>
bool psd_square_root(const Eigen::Matrix<double, N, N>& A, Eigen::Matrix<double, N, N>& root) {
    if (cholesky_root<N>(A, root)) {
        return true;
    }
    if (!A.allFinite()) {
        return false;
    }
    const Eigen::LDLT<Eigen::Matrix<double, N, N>> ldlt(A);
    if (ldlt.info() != Eigen::Success) {
        return false;
    }
    const Eigen::Matrix<double, N, 1> d = ldlt.vectorD();
    const double tolerance = 1e-12 * std::max(d.cwiseAbs().maxCoeff(), 0.0);
    if ((d.array() < -tolerance).any()) {
        return false;
    }
    Eigen::Matrix<double, N, N> L = ldlt.matrixL();
    root = ldlt.transpositionsP().transpose() * L;
    root = (root * d.cwiseMax(0.0).cwiseSqrt().asDiagonal()).eval();
    return true;
}

}  // namespace legofeup
