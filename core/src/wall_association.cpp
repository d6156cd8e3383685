#include "legofeup/core/wall_association.hpp"

#include <cmath>
#include <limits>

#include "legofeup/core/wall_measurement.hpp"

namespace legofeup {

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
    }
    return "unknown";
}

AssociationResult associate_wall(const Pose2& estimate, const WallObservation& observation,
                                 const WallMap& walls, const IrMount& mount, double ir_max_range,
                                 const AssociationParams& params) {
    AssociationResult result;
    result.outcome = AssociationOutcome::NoWallInView;

    const IrBeam front = ir_beam(estimate, mount, kFrontSensor);
    const IrBeam rear = ir_beam(estimate, mount, kRearSensor);
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

    if (std::abs(result.predicted_angle) > params.max_incidence) {
        result.outcome = AssociationOutcome::ObliqueIncidence;
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
