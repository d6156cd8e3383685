#pragma once
// Linear models for the filters of LegoFeup Lab: with them the ExtendedKalmanFilter is the
// plain Kalman filter (its Jacobians are the model's matrices), so the linear KFs of the
// lessons (paper 003) share its numerics: LDLT, Joseph form, the base's guards.
//
//   process      x ← Φ·x + u + w,   w ~ N(0, Q)      (u: the known input term, e.g. B·u)
//   measurement  z = H·x + v,       v ~ N(0, R)

#include <Eigen/Core>

namespace legofeup {

/// The state space of a linear filter: plain vectors, no angles to wrap.
template <int N>
struct EuclideanStateSpace {
    static constexpr int kSize = N;
    using Vector = Eigen::Matrix<double, N, 1>;

    static void normalize(Vector& /*x*/) {}
    static Vector difference(const Vector& a, const Vector& b) { return a - b; }
};

template <int N>
class LinearProcessModel {
  public:
    static constexpr int kNoiseSize = N;
    using Vector = Eigen::Matrix<double, N, 1>;
    using Matrix = Eigen::Matrix<double, N, N>;

    LinearProcessModel(const Matrix& transition, const Vector& input, const Matrix& noise)
        : phi_(transition), u_(input), q_(noise) {}

    Vector propagate(const Vector& x, const Vector& noise) const { return phi_ * x + u_ + noise; }
    Vector predict_state(const Vector& x) const { return phi_ * x + u_; }
    const Matrix& state_jacobian(const Vector& /*x*/) const { return phi_; }
    Matrix noise_jacobian(const Vector& /*x*/) const { return Matrix::Identity(); }
    const Matrix& noise_covariance() const { return q_; }

  private:
    Matrix phi_;  // Φ
    Vector u_;
    Matrix q_;  // Q
};

template <int M, int N>
class LinearMeasurement {
  public:
    static constexpr int kSize = M;
    using Vector = Eigen::Matrix<double, M, 1>;
    using Matrix = Eigen::Matrix<double, M, M>;
    using Jacobian = Eigen::Matrix<double, M, N>;
    using StateVector = Eigen::Matrix<double, N, 1>;

    LinearMeasurement(const Vector& z, const Jacobian& h, const Matrix& r) : z_(z), h_(h), r_(r) {}

    const Vector& measurement() const { return z_; }
    Vector predict_measurement(const StateVector& x) const { return h_ * x; }
    const Jacobian& jacobian(const StateVector& /*x*/) const { return h_; }
    const Matrix& noise_covariance() const { return r_; }
    Vector residual(const Vector& a, const Vector& b) const { return a - b; }

  private:
    Vector z_;
    Jacobian h_;  // H
    Matrix r_;    // R
};

}  // namespace legofeup
