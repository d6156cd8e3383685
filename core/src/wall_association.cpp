#include "legofeup/core/wall_association.hpp"

#include <cmath>
#include <limits>

#include "legofeup/core/chi_square.hpp"
#include "legofeup/core/small_ldlt.hpp"
#include "legofeup/core/wall_measurement.hpp"

namespace legofeup {
namespace {

// d² = νᵀS⁻¹ν of `measurement` against the belief: ν = z − ∇h_X X̂ (θ wrapped),
// S = ∇h_X P ∇h_Xᵀ + ∇h_r R ∇h_rᵀ, solved with LDLᵀ (never an inverse). The model is linear,
// so this is the NIS the EKF's update (and the UKF's, whose sigma points reproduce a linear
// h exactly) computes for the same wall. Infinite when S is not positive definite.
double mahalanobis_distance_squared(const PoseBelief& belief, const WallMeasurement& measurement) {
    const StateVector x = to_state(belief.pose);
    const WallMeasurement::Vector innovation =
        measurement.residual(measurement.measurement(), measurement.predict_measurement(x));
    const WallMeasurement::Jacobian& H = measurement.jacobian(x);
    const Eigen::Matrix2d S =
        H * belief.covariance * H.transpose() + measurement.noise_covariance();
    SmallLdlt<2> ldlt;
    if (!ldlt.factorise(S)) {
        return std::numeric_limits<double>::infinity();
    }
    const double d2 = innovation.dot(ldlt.solve(innovation));
    return std::isfinite(d2) ? d2 : std::numeric_limits<double>::infinity();
}

}  // namespace

const char* to_string(AssociationGate gate) {
    switch (gate) {
        case AssociationGate::Fixed:
            return "fixed";
        case AssociationGate::Mahalanobis:
            return "mahalanobis";
    }
    return "unknown";
}

std::optional<AssociationGate> association_gate_from_string(std::string_view text) {
    for (const AssociationGate gate : {AssociationGate::Fixed, AssociationGate::Mahalanobis}) {
        if (text == to_string(gate)) {
            return gate;
        }
    }
    return std::nullopt;
}

double association_gate_threshold(double probability) {
    return chi_square_quantile(probability, WallMeasurement::kSize);
}

const char* to_string(AssociationOutcome outcome) {
    switch (outcome) {
        case AssociationOutcome::Associated:
            return "associated";
        case AssociationOutcome::NoObservation:
            return "no observation";
        case AssociationOutcome::NoWallInView:
            return "no wall in view of both sensors";
        case AssociationOutcome::ObliqueIncidence:
            return "wall seen too obliquely";
        case AssociationOutcome::AngleMismatch:
            return "angle does not match the predicted wall";
        case AssociationOutcome::DistanceMismatch:
            return "distance does not match the predicted wall";
        case AssociationOutcome::MahalanobisMismatch:
            return "Mahalanobis distance above the gate";
    }
    return "unknown";
}

AssociationResult associate_wall(const PoseBelief& belief, const WallObservation& observation,
                                 const WallMap& walls, const IrMount& mount, double ir_max_range,
                                 const Eigen::Matrix2d& ir_covariance,
                                 const AssociationParams& params) {
    return associate_wall(belief, observation, walls, mount, ir_max_range, ir_covariance, params,
                          association_gate_threshold(params.gate_probability));
}

AssociationResult associate_wall(const PoseBelief& belief, const WallObservation& observation,
                                 const WallMap& walls, const IrMount& mount, double ir_max_range,
                                 const Eigen::Matrix2d& ir_covariance,
                                 const AssociationParams& params, double gate_threshold) {
    const Pose2& estimate = belief.pose;
    AssociationResult result;
    result.outcome = AssociationOutcome::NoWallInView;
    result.gate = params.gate;

    const auto [front, rear] = ir_beams(estimate, mount);
    const double longest = ir_max_range + params.range_margin;

    // 1. The nearest wall that both predicted beams hit, as the real beams would.
    double nearest = std::numeric_limits<double>::infinity();
    for (int index = 0; index < walls.size(); ++index) {
        const WallLine& line = walls.line(index);
        const BeamHit front_hit = cast_beam(front, line, params.segment_margin);
        const BeamHit rear_hit = cast_beam(rear, line, params.segment_margin);
        if (!front_hit.hit || !rear_hit.hit || front_hit.range > longest
            || rear_hit.range > longest) {
            continue;
        }
        const double mean_range = 0.5 * (front_hit.range + rear_hit.range);
        if (mean_range < nearest) {
            nearest = mean_range;
            result.wall = index;
            result.side = line.signed_distance(front.origin) >= 0.0 ? 1 : -1;
            result.predicted_ds_front = front_hit.range;
            result.predicted_ds_rear = rear_hit.range;
        }
    }
    if (result.wall < 0) {
        return result;
    }

    // 2. The geometry the estimate predicts for that wall, against the measured one.
    const WallLine& line = walls.line(result.wall);
    result.predicted_angle = wrap_angle(estimate.theta - facing_heading(line, result.side));
    result.predicted_distance = result.side * line.signed_distance(position_of(estimate));
    result.angle_error = wrap_angle(observation.angle - result.predicted_angle);
    result.distance_error = observation.centre_distance - result.predicted_distance;
    result.mahalanobis_d2 = mahalanobis_distance_squared(
        belief, WallMeasurement(line, result.side, observation, ir_covariance));
    result.mahalanobis_threshold = gate_threshold;

    // 3. The gate. The incidence test is geometry (the two beams must meet one straight
    // wall), not a test of fit, so it comes first under either gate.
    if (std::abs(result.predicted_angle) > params.max_incidence) {
        result.outcome = AssociationOutcome::ObliqueIncidence;
    } else if (params.gate == AssociationGate::Mahalanobis) {
        result.outcome = result.mahalanobis_d2 <= result.mahalanobis_threshold
                             ? AssociationOutcome::Associated
                             : AssociationOutcome::MahalanobisMismatch;
    } else if (std::abs(result.angle_error) > params.max_angle_error) {
        result.outcome = AssociationOutcome::AngleMismatch;
    } else if (std::abs(result.distance_error) > params.max_distance_error) {
        result.outcome = AssociationOutcome::DistanceMismatch;
    } else {
        result.outcome = AssociationOutcome::Associated;
    }
    return result;
}

}  // namespace legofeup
