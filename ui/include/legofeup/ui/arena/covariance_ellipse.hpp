#pragma once
// The covariance ellipse of the position estimate (the original tool's "FEllipses"): the
// region {p : (p − x̂)ᵀ P_xy⁻¹ (p − x̂) ≤ k²} drawn around the estimate. Qt-free.
//
// With P_xy = V·diag(λ₁, λ₂)·Vᵀ (λ₁ ≥ λ₂ ≥ 0) the ellipse has semi-axes k·√λ₁ along the
// first eigenvector and k·√λ₂ along the second. For a 2-D Gaussian the squared Mahalanobis
// distance is χ²(2), so the ellipse holds probability p when k² = χ²₂(p) = −2·ln(1 − p).
// In 2-D the 1σ ellipse (k = 1) holds 1 − e^(−1/2) = 39.3 % of the probability; the
// paper's "68.2 %" is the 1-D figure.

#include <Eigen/Core>
#include <vector>

#include "legofeup/core/state.hpp"

namespace legofeup::ui {

enum class EllipseConfidence { OneSigma, Percent95, Percent99 };

/// Probability inside the ellipse of a 2-D Gaussian: 1 − e^(−1/2), 0.95, 0.99.
double confidence_probability(EllipseConfidence level);
/// k: the scale of the semi-axes, √χ²₂(p) = √(−2·ln(1 − p)); 1 for the 1σ ellipse.
double confidence_scale(EllipseConfidence level);
/// The short label drawn next to the ellipse: "1σ ellipse", "95 % ellipse", "99 % ellipse".
const char* confidence_label(EllipseConfidence level);
/// The longer, honest explanation for the legend and tool tips (UTF-8, two lines).
const char* confidence_note(EllipseConfidence level);

struct CovarianceEllipse {
    bool valid = false;  ///< false for NaN/Inf or a covariance that is not positive semi-definite
    Vector2 centre = Vector2::Zero();
    double semi_major = 0.0;  ///< metres (k·√λ₁)
    double semi_minor = 0.0;  ///< metres (k·√λ₂)
    double angle = 0.0;       ///< of the major axis from +x, radians in (−π/2, π/2]

    /// Whether a world point lies inside (or on) the ellipse; false when invalid.
    bool contains(const Vector2& point) const;
};

/// The ellipse of the 2×2 position covariance `covariance` around `centre`, semi-axes
/// scaled by `scale` (k > 0). Never throws: bad input gives an invalid ellipse.
CovarianceEllipse covariance_ellipse(const Vector2& centre, const Eigen::Matrix2d& covariance,
                                     double scale);
CovarianceEllipse covariance_ellipse(const Vector2& centre, const Eigen::Matrix2d& covariance,
                                     EllipseConfidence level);

/// `count` points (≥ 3) evenly spaced in the ellipse's parameter, in world coordinates,
/// counter-clockwise; empty when the ellipse is invalid.
std::vector<Vector2> ellipse_polygon(const CovarianceEllipse& ellipse, int count);

}  // namespace legofeup::ui
