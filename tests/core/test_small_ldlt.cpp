// The written-out LDLᵀ (small_ldlt.hpp) against independent calculations: Eigen's pivoted
// LDLT and its eigenvalues, on random symmetric matrices of each size the filters use.

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <random>

#include "legofeup/core/small_ldlt.hpp"

namespace legofeup {
namespace {

// A random symmetric matrix with eigenvalues spread over `decades` decades (some negative
// when `indefinite`), from a random rotation.
template <int N>
Eigen::Matrix<double, N, N> random_symmetric(std::mt19937_64& random, double decades,
                                             bool indefinite) {
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> exponent(-decades, 0.0);
    Eigen::Matrix<double, N, N> M;
    for (int i = 0; i < N; ++i) {
        for (int j = 0; j < N; ++j) {
            M(i, j) = normal(random);
        }
    }
    const Eigen::HouseholderQR<Eigen::Matrix<double, N, N>> qr(M);
    const Eigen::Matrix<double, N, N> Q = qr.householderQ();
    Eigen::Matrix<double, N, 1> eigenvalues;
    for (int i = 0; i < N; ++i) {
        eigenvalues(i) = std::pow(10.0, exponent(random));
    }
    if (indefinite) {
        eigenvalues(0) = -eigenvalues(0);
    }
    const Eigen::Matrix<double, N, N> A = Q * eigenvalues.asDiagonal() * Q.transpose();
    return 0.5 * (A + A.transpose());
}

template <int N>
void check_against_eigen(std::uint64_t seed) {
    std::mt19937_64 random(seed);
    std::normal_distribution<double> normal;
    for (int trial = 0; trial < 500; ++trial) {
        const bool indefinite = trial % 3 == 0;
        const auto A = random_symmetric<N>(random, 6.0, indefinite);
        SmallLdlt<N> small;
        const bool positive = small.factorise(A);
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> eigen(A);
        EXPECT_EQ(positive, eigen.eigenvalues().minCoeff() > 0.0) << A;
        if (!positive) {
            continue;
        }
        Eigen::Matrix<double, N, 1> b;
        for (int i = 0; i < N; ++i) {
            b(i) = normal(random);
        }
        const Eigen::Matrix<double, N, 1> expected = A.ldlt().solve(b);
        const Eigen::Matrix<double, N, 1> x = small.solve(b);
        // The condition number is at most 1e6: the two solutions agree to ~1e6·ε relative.
        EXPECT_LE((x - expected).norm(), 1e-8 * expected.norm()) << A;
        EXPECT_LE((A * x - b).norm(), 1e-9 * (A.norm() * x.norm() + b.norm())) << A;
        // Backward stable: L·D·Lᵀ reproduces A to a few ε·‖A‖.
        Eigen::Matrix<double, N, N> L = Eigen::Matrix<double, N, N>::Identity();
        Eigen::Matrix<double, N, 1> d;
        for (int j = 0; j < N; ++j) {
            d(j) = small.pivot(j);
            for (int i = j + 1; i < N; ++i) {
                L(i, j) = small.lower(i, j);
            }
        }
        EXPECT_LE((L * d.asDiagonal() * L.transpose() - A).norm(), 1e-14 * A.norm()) << A;
    }
}

TEST(SmallLdlt, OneByOneMatchesEigen) {
    check_against_eigen<1>(11);
}
TEST(SmallLdlt, TwoByTwoMatchesEigen) {
    check_against_eigen<2>(22);
}
TEST(SmallLdlt, ThreeByThreeMatchesEigen) {
    check_against_eigen<3>(33);
}

TEST(SmallLdlt, HandWorkedTwoByTwo) {
    // A = [4 2; 2 3]: d₀ = 4, L₁₀ = 2/4, d₁ = 3 − ½·2 = 2; A·x = (2, 1) gives x = (½, 0).
    Eigen::Matrix2d A;
    A << 4.0, 2.0, 2.0, 3.0;
    SmallLdlt<2> ldlt;
    ASSERT_TRUE(ldlt.factorise(A));
    EXPECT_DOUBLE_EQ(ldlt.pivot(0), 4.0);
    EXPECT_DOUBLE_EQ(ldlt.pivot(1), 2.0);
    const Eigen::Vector2d x = ldlt.solve(Eigen::Vector2d(2.0, 1.0));
    EXPECT_DOUBLE_EQ(x(0), 0.5);
    EXPECT_DOUBLE_EQ(x(1), 0.0);
}

TEST(SmallLdlt, RejectsSingularIndefiniteAndNaN) {
    Eigen::Matrix2d singular;
    singular << 1.0, 1.0, 1.0, 1.0;  // d₁ = 0
    EXPECT_FALSE(SmallLdlt<2>().factorise(singular));
    Eigen::Matrix2d indefinite;
    indefinite << 1.0, 2.0, 2.0, 1.0;  // eigenvalues 3 and −1
    EXPECT_FALSE(SmallLdlt<2>().factorise(indefinite));
    Eigen::Matrix3d with_nan = Eigen::Matrix3d::Identity();
    with_nan(2, 1) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(SmallLdlt<3>().factorise(with_nan));
    EXPECT_FALSE(SmallLdlt<1>().factorise(Eigen::Matrix<double, 1, 1>(0.0)));
}

TEST(SmallLdlt, ReadsOnlyTheLowerTriangle) {
    Eigen::Matrix3d A;
    A << 4.0, 1.0, 0.5,  //
        1.0, 3.0, 0.2,   //
        0.5, 0.2, 2.0;
    Eigen::Matrix3d garbage_above = A;
    garbage_above(0, 1) = 1e9;
    garbage_above(0, 2) = std::numeric_limits<double>::quiet_NaN();
    garbage_above(1, 2) = -7.0;
    SmallLdlt<3> clean;
    SmallLdlt<3> dirty;
    ASSERT_TRUE(clean.factorise(A));
    ASSERT_TRUE(dirty.factorise(garbage_above));
    const Eigen::Vector3d b(1.0, -2.0, 0.5);
    EXPECT_EQ(clean.solve(b), dirty.solve(b));
}

}  // namespace
}  // namespace legofeup
