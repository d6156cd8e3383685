#pragma once
// Central-difference Jacobians, the independent check of every analytic Jacobian.

#include <Eigen/Core>
#include <random>

#include "legofeup/core/angles.hpp"

namespace legofeup::testing {

/// J(i, j) ≈ (f(x + h·e_j) − f(x − h·e_j))_i / 2h. Output components listed in
/// `angle_outputs` (a bit mask) are differenced with wrapping, so a heading near ±π works.
template <int M, int N, class Function>
Eigen::Matrix<double, M, N> central_difference(const Function& f,
                                               const Eigen::Matrix<double, N, 1>& x,
                                               double h = 1e-6, unsigned angle_outputs = 0) {
    Eigen::Matrix<double, M, N> jacobian;
    for (int j = 0; j < N; ++j) {
        Eigen::Matrix<double, N, 1> plus = x;
        Eigen::Matrix<double, N, 1> minus = x;
        plus(j) += h;
        minus(j) -= h;
        const Eigen::Matrix<double, M, 1> difference = f(plus) - f(minus);
        for (int i = 0; i < M; ++i) {
            const bool angle = (angle_outputs >> i) & 1U;
            jacobian(i, j) = (angle ? wrap_angle(difference(i)) : difference(i)) / (2.0 * h);
        }
    }
    return jacobian;
}

/// Uniform doubles for random test states.
class Uniform {
  public:
    explicit Uniform(unsigned seed) : rng_(seed) {}
    double operator()(double low, double high) {
        return std::uniform_real_distribution<double>(low, high)(rng_);
    }
    std::mt19937_64& engine() { return rng_; }

  private:
    std::mt19937_64 rng_;
};

}  // namespace legofeup::testing
