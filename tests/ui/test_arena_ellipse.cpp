// The covariance ellipse: semi-axes and orientation from P's position block, the confidence
// scales, and (Monte Carlo) the probability the drawn ellipse really holds.

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <cmath>
#include <limits>
#include <random>

#include "legofeup/core/angles.hpp"
#include "legofeup/core/chi_square.hpp"
#include "legofeup/ui/arena/covariance_ellipse.hpp"

namespace legofeup::ui {
namespace {

Eigen::Matrix2d rotation(double angle) {
    Eigen::Matrix2d r;
    r << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
    return r;
}

/// Difference of two axis angles modulo π (an ellipse's axis has no direction).
double axis_angle_error(double a, double b) {
    return std::abs(std::remainder(a - b, kPi));
}

TEST(ArenaEllipse, DiagonalCovarianceGivesAxisAlignedSemiAxes) {
    const Eigen::Matrix2d p = Eigen::Vector2d(4.0, 1.0).asDiagonal();
    const CovarianceEllipse e = covariance_ellipse(Vector2(1.0, -2.0), p, 1.0);
    ASSERT_TRUE(e.valid);
    EXPECT_NEAR(e.semi_major, 2.0, 1e-12);
    EXPECT_NEAR(e.semi_minor, 1.0, 1e-12);
    EXPECT_NEAR(axis_angle_error(e.angle, 0.0), 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(e.centre.x(), 1.0);
    EXPECT_DOUBLE_EQ(e.centre.y(), -2.0);
}

TEST(ArenaEllipse, MajorAxisAlongYWhenYVarianceIsLarger) {
    const Eigen::Matrix2d p = Eigen::Vector2d(0.25, 9.0).asDiagonal();
    const CovarianceEllipse e = covariance_ellipse(Vector2::Zero(), p, 1.0);
    ASSERT_TRUE(e.valid);
    EXPECT_NEAR(e.semi_major, 3.0, 1e-12);
    EXPECT_NEAR(e.semi_minor, 0.5, 1e-12);
    EXPECT_NEAR(axis_angle_error(e.angle, kPi / 2.0), 0.0, 1e-12);
}

TEST(ArenaEllipse, RotatedCovarianceGivesBackTheRotation) {
    for (const double angle : {0.3, 1.2, -0.7, 2.5, -2.9, kPi / 2.0}) {
        const Eigen::Matrix2d r = rotation(angle);
        const Eigen::Matrix2d p = r * Eigen::Vector2d(0.09, 0.01).asDiagonal() * r.transpose();
        const CovarianceEllipse e = covariance_ellipse(Vector2::Zero(), p, 2.0);
        ASSERT_TRUE(e.valid) << angle;
        EXPECT_NEAR(e.semi_major, 2.0 * 0.3, 1e-12) << angle;
        EXPECT_NEAR(e.semi_minor, 2.0 * 0.1, 1e-12) << angle;
        EXPECT_NEAR(axis_angle_error(e.angle, angle), 0.0, 1e-9) << angle;
        EXPECT_GT(e.angle, -kPi / 2.0);
        EXPECT_LE(e.angle, kPi / 2.0);
    }
}

TEST(ArenaEllipse, ConfidenceScalesMatchTheChiSquareQuantile) {
    EXPECT_DOUBLE_EQ(confidence_scale(EllipseConfidence::OneSigma), 1.0);
    for (const auto& [level, p] : {std::pair{EllipseConfidence::Percent95, 0.95},
                                   std::pair{EllipseConfidence::Percent99, 0.99}}) {
        EXPECT_NEAR(confidence_scale(level), std::sqrt(chi_square_quantile(p, 2.0)), 1e-9);
        EXPECT_NEAR(confidence_scale(level), std::sqrt(-2.0 * std::log(1.0 - p)), 1e-12);
        EXPECT_DOUBLE_EQ(confidence_probability(level), p);
    }
    EXPECT_NEAR(confidence_scale(EllipseConfidence::Percent95), 2.4477, 1e-4);
    EXPECT_NEAR(confidence_scale(EllipseConfidence::Percent99), 3.0349, 1e-4);
    // In 2-D the 1σ ellipse holds P(χ²₂ ≤ 1), not the 1-D 68.3 %.
    EXPECT_NEAR(confidence_probability(EllipseConfidence::OneSigma), chi_square_cdf(1.0, 2.0),
                1e-12);
    EXPECT_NEAR(confidence_probability(EllipseConfidence::OneSigma), 0.3935, 1e-4);
}

TEST(ArenaEllipse, LevelOverloadScalesTheSemiAxes) {
    const Eigen::Matrix2d p = Eigen::Vector2d(4.0, 1.0).asDiagonal();
    const CovarianceEllipse e =
        covariance_ellipse(Vector2::Zero(), p, EllipseConfidence::Percent99);
    ASSERT_TRUE(e.valid);
    EXPECT_NEAR(e.semi_major, 2.0 * std::sqrt(-2.0 * std::log(0.01)), 1e-12);
    EXPECT_NEAR(e.semi_minor, std::sqrt(-2.0 * std::log(0.01)), 1e-12);
}

TEST(ArenaEllipse, LabelsAreHonestAboutTwoDimensions) {
    EXPECT_STREQ(confidence_label(EllipseConfidence::OneSigma), "1σ ellipse");
    EXPECT_STREQ(confidence_label(EllipseConfidence::Percent95), "95 % ellipse");
    EXPECT_STREQ(confidence_label(EllipseConfidence::Percent99), "99 % ellipse");
    const std::string note = confidence_note(EllipseConfidence::OneSigma);
    EXPECT_NE(note.find("39.3 %"), std::string::npos) << note;
    EXPECT_NE(note.find("1-D"), std::string::npos) << note;
}

/// The fraction of draws from N(0, P) inside the ellipse is the level's probability.
TEST(ArenaEllipse, MonteCarloCoverageMatchesTheConfidence) {
    const Eigen::Matrix2d r = rotation(0.6);
    const Eigen::Matrix2d p = r * Eigen::Vector2d(0.04, 0.0025).asDiagonal() * r.transpose();
    const Eigen::Matrix2d l = p.llt().matrixL();
    const Vector2 centre(0.4, -1.1);
    for (const auto& [level, expected] : {std::pair{EllipseConfidence::OneSigma, 0.3935},
                                          std::pair{EllipseConfidence::Percent95, 0.95},
                                          std::pair{EllipseConfidence::Percent99, 0.99}}) {
        const CovarianceEllipse e = covariance_ellipse(centre, p, level);
        ASSERT_TRUE(e.valid);
        std::mt19937_64 rng(20240601);
        std::normal_distribution<double> normal(0.0, 1.0);
        constexpr int kDraws = 20000;
        int inside = 0;
        for (int i = 0; i < kDraws; ++i) {
            const Vector2 draw = centre + l * Vector2(normal(rng), normal(rng));
            inside += e.contains(draw) ? 1 : 0;
        }
        EXPECT_NEAR(static_cast<double>(inside) / kDraws, expected, 0.01)
            << confidence_label(level);
    }
}

TEST(ArenaEllipse, PolygonPointsLieOnTheEllipse) {
    const Eigen::Matrix2d r = rotation(-0.4);
    const Eigen::Matrix2d p = r * Eigen::Vector2d(0.16, 0.04).asDiagonal() * r.transpose();
    const Vector2 centre(-1.0, 0.5);
    const CovarianceEllipse e = covariance_ellipse(centre, p, 1.0);
    const std::vector<Vector2> points = ellipse_polygon(e, 36);
    ASSERT_EQ(points.size(), 36u);
    const Eigen::LLT<Eigen::Matrix2d> p_factor(p);
    for (const Vector2& point : points) {
        const Vector2 d = point - centre;
        EXPECT_NEAR(d.dot(p_factor.solve(d)), 1.0, 1e-9);  // Mahalanobis distance k = 1
    }
}

TEST(ArenaEllipse, BadCovarianceIsInvalidNeverACrash) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    Eigen::Matrix2d with_nan = Eigen::Matrix2d::Identity();
    with_nan(0, 1) = nan;
    Eigen::Matrix2d with_inf = Eigen::Matrix2d::Identity();
    with_inf(1, 1) = inf;
    const Eigen::Matrix2d negative_definite = -Eigen::Matrix2d::Identity();
    Eigen::Matrix2d indefinite;
    indefinite << 1.0, 2.0, 2.0, 1.0;  // eigenvalues 3 and −1
    for (const Eigen::Matrix2d& p : {with_nan, with_inf, negative_definite, indefinite}) {
        const CovarianceEllipse e = covariance_ellipse(Vector2::Zero(), p, 1.0);
        EXPECT_FALSE(e.valid) << p;
        EXPECT_TRUE(ellipse_polygon(e, 16).empty());
        EXPECT_FALSE(e.contains(Vector2::Zero()));
    }
    EXPECT_FALSE(covariance_ellipse(Vector2(nan, 0.0), Eigen::Matrix2d::Identity(), 1.0).valid);
}

TEST(ArenaEllipse, SingularCovarianceIsAValidSegment) {
    const Eigen::Matrix2d p = Eigen::Vector2d(1.0, 0.0).asDiagonal();
    const CovarianceEllipse e = covariance_ellipse(Vector2::Zero(), p, 1.0);
    ASSERT_TRUE(e.valid);
    EXPECT_NEAR(e.semi_major, 1.0, 1e-12);
    EXPECT_EQ(e.semi_minor, 0.0);
    EXPECT_TRUE(e.contains(Vector2(0.5, 0.0)));
    EXPECT_FALSE(e.contains(Vector2(0.5, 0.1)));
    const CovarianceEllipse zero =
        covariance_ellipse(Vector2::Zero(), Eigen::Matrix2d::Zero(), 1.0);
    EXPECT_TRUE(zero.valid);
    EXPECT_EQ(zero.semi_major, 0.0);
}

}  // namespace
}  // namespace legofeup::ui
