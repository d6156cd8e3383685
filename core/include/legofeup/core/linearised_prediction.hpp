#pragma once
// The EKF's prediction (paper 000 eq. 11–13) for any process model, as a fallback for the UKF
// when it cannot draw sigma points (n + κ ≤ 0, a P Cholesky refuses, a Q that is not
// positive semi-definite). Dropping the step instead would leave the estimate where it was
// while the robot drove on: the motion lost, and P too small for the error that follows.
//
//   X̂⁻ = f(X̂, U, 0),   P⁻ = F·P·Fᵀ + G·Q·Gᵀ,   F = ∂f/∂X,  G = ∂f/∂q  at (X̂, 0)
//
// F and G are the model's own Jacobians when it has the EKF's hooks (EkfProcessModel);
// otherwise they are central differences of propagate(x, q),
//   column j of F ≈ (f(X̂ + h·e_j, 0) − f(X̂ − h·e_j, 0)) / 2h,  h = 1e-6·max(1, |X̂_j|),
// (differences taken with the state space's wrap for angles), whose error is O(h²) ≈ 1e-12
// relative: far below anything the filter resolves.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "legofeup/core/extended_kalman_filter.hpp"

namespace legofeup {

template <class StateSpace>
struct LinearisedPrediction {
    Eigen::Matrix<double, StateSpace::kSize, 1> state;
    Eigen::Matrix<double, StateSpace::kSize, StateSpace::kSize> covariance;
};

template <class StateSpace, class Model>
LinearisedPrediction<StateSpace> linearised_prediction(
    const Model& model, const Eigen::Matrix<double, StateSpace::kSize, 1>& x,
    const Eigen::Matrix<double, StateSpace::kSize, StateSpace::kSize>& P) {
    constexpr int N = StateSpace::kSize;
    constexpr int Nq = Model::kNoiseSize;
    using Vector = Eigen::Matrix<double, N, 1>;
    using NoiseVector = Eigen::Matrix<double, Nq, 1>;
    const Eigen::Matrix<double, Nq, Nq> Q = model.noise_covariance();
    if constexpr (EkfProcessModel<Model, N>) {
        const auto F = model.state_jacobian(x);
        const auto G = model.noise_jacobian(x);
        return {model.predict_state(x), F * P * F.transpose() + G * Q * G.transpose()};
    } else {
        const NoiseVector no_noise = NoiseVector::Zero();
        Eigen::Matrix<double, N, N> F;
        for (int j = 0; j < N; ++j) {
            const double h = 1e-6 * std::max(1.0, std::abs(x(j)));
            Vector ahead = x;
            Vector behind = x;
            ahead(j) += h;
            behind(j) -= h;
            F.col(j) = StateSpace::difference(model.propagate(ahead, no_noise),
                                              model.propagate(behind, no_noise))
                       / (2.0 * h);
        }
        Eigen::Matrix<double, N, Nq> G;
        for (int j = 0; j < Nq; ++j) {
            constexpr double h = 1e-6;  // noise components are small: an absolute step
            NoiseVector ahead = no_noise;
            NoiseVector behind = no_noise;
            ahead(j) = h;
            behind(j) = -h;
            G.col(j) = StateSpace::difference(model.propagate(x, ahead), model.propagate(x, behind))
                       / (2.0 * h);
        }
        return {model.propagate(x, no_noise), F * P * F.transpose() + G * Q * G.transpose()};
    }
}

}  // namespace legofeup
