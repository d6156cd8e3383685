#include "legofeup/ui/arena/covariance_ellipse.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "legofeup/core/angles.hpp"

namespace legofeup::ui {

double confidence_probability(EllipseConfidence level) {
    switch (level) {
        case EllipseConfidence::OneSigma:
            return 1.0 - std::exp(-0.5);  // P(χ²₂ ≤ 1) = 0.3935
        case EllipseConfidence::Percent95:
            return 0.95;
        case EllipseConfidence::Percent99:
            return 0.99;
    }
    return 0.0;
}

double confidence_scale(EllipseConfidence level) {
    if (level == EllipseConfidence::OneSigma) {
        return 1.0;
    }
    // χ²₂ is the exponential distribution with mean 2: its p-quantile is −2·ln(1 − p).
    return std::sqrt(-2.0 * std::log(1.0 - confidence_probability(level)));
}

const char* confidence_label(EllipseConfidence level) {
    switch (level) {
        case EllipseConfidence::OneSigma:
            return "1σ ellipse";
        case EllipseConfidence::Percent95:
            return "95 % ellipse";
        case EllipseConfidence::Percent99:
            return "99 % ellipse";
    }
    return "";
}

const char* confidence_note(EllipseConfidence level) {
    switch (level) {
        case EllipseConfidence::OneSigma:
            return "1σ ellipse: holds 39.3 % of the probability in 2-D\n"
                   "(68.3 % is the 1-D figure)";
        case EllipseConfidence::Percent95:
            return "95 % ellipse: holds 95 % of the probability\n"
                   "(k = √χ²₂(0.95) = 2.45 standard deviations)";
        case EllipseConfidence::Percent99:
            return "99 % ellipse: holds 99 % of the probability\n"
                   "(k = √χ²₂(0.99) = 3.03 standard deviations)";
    }
    return "";
}

bool CovarianceEllipse::contains(const Vector2& point) const {
    if (!valid) {
        return false;
    }
    // Rotate into the ellipse's axes: u along the major axis, v along the minor one.
    const Vector2 d = point - centre;
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    const double u = c * d.x() + s * d.y();
    const double v = -s * d.x() + c * d.y();
    if (semi_minor <= 0.0) {  // degenerate: a segment (or a point)
        return v == 0.0 && std::abs(u) <= semi_major;
    }
    const double uu = u / semi_major;
    const double vv = v / semi_minor;
    return uu * uu + vv * vv <= 1.0;
}

CovarianceEllipse covariance_ellipse(const Vector2& centre, const Eigen::Matrix2d& covariance,
                                     double scale) {
    CovarianceEllipse ellipse;
    ellipse.centre = centre;
    if (!centre.allFinite() || !covariance.allFinite() || !std::isfinite(scale) || scale <= 0.0) {
        return ellipse;
    }
    // 1. Symmetrise (P is symmetric up to rounding) and decompose: P = V·diag(λ)·Vᵀ, λ ascending.
    const Eigen::Matrix2d symmetric = 0.5 * (covariance + covariance.transpose());
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(symmetric);
    if (solver.info() != Eigen::Success) {
        return ellipse;
    }
    const double lambda_minor = solver.eigenvalues()(0);
    const double lambda_major = solver.eigenvalues()(1);
    // 2. Positive semi-definite up to rounding: a tiny negative eigenvalue is zero, anything
    //    clearly negative means P is not a covariance.
    const double tolerance = 1e-12 * std::max(std::abs(lambda_major), 1e-300);
    if (lambda_major < 0.0 || lambda_minor < -tolerance) {
        return ellipse;
    }
    // 3. Semi-axes k·√λ and the major axis' direction, folded into (−π/2, π/2].
    const Vector2 major = solver.eigenvectors().col(1);
    double angle = std::atan2(major.y(), major.x());
    if (angle > kPi / 2.0) {
        angle -= kPi;
    } else if (angle <= -kPi / 2.0) {
        angle += kPi;
    }
    ellipse.semi_major = scale * std::sqrt(lambda_major);
    ellipse.semi_minor = scale * std::sqrt(std::max(lambda_minor, 0.0));
    ellipse.angle = angle;
    ellipse.valid = true;
    return ellipse;
}

CovarianceEllipse covariance_ellipse(const Vector2& centre, const Eigen::Matrix2d& covariance,
                                     EllipseConfidence level) {
    return covariance_ellipse(centre, covariance, confidence_scale(level));
}

std::vector<Vector2> ellipse_polygon(const CovarianceEllipse& ellipse, int count) {
    std::vector<Vector2> points;
    if (!ellipse.valid) {
        return points;
    }
    count = std::max(count, 3);
    points.reserve(static_cast<std::size_t>(count));
    const double c = std::cos(ellipse.angle);
    const double s = std::sin(ellipse.angle);
    for (int i = 0; i < count; ++i) {
        const double t = 2.0 * kPi * i / count;
        const double u = ellipse.semi_major * std::cos(t);
        const double v = ellipse.semi_minor * std::sin(t);
        points.emplace_back(ellipse.centre.x() + c * u - s * v, ellipse.centre.y() + s * u + c * v);
    }
    return points;
}

}  // namespace legofeup::ui
