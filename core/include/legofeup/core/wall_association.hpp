#pragma once
// Feature association (paper Fig. 4): which wall does an IR observation belong to?
//
// The paper decides from the estimated pose which wall the robot is next to. We do the same
// geometrically, for any wall map: cast both sensor beams from the estimated pose, take the
// nearest wall that both beams hit, and accept it only if the measured geometry (ObsAng and
// the centre's distance D_c) fits what the estimate predicts for that wall. Every rejection
// says why, so students can see when and why updates are skipped.

#include <cstdint>

#include "legofeup/core/angles.hpp"
#include "legofeup/core/ir_geometry.hpp"
#include "legofeup/core/walls.hpp"

namespace legofeup {

struct AssociationParams {
    /// Predicted beam hits may fall this far beyond either end of a wall, metres.
    double segment_margin = 0.10;
    /// Predicted beam lengths may exceed the IR maximum range by this much, metres.
    double range_margin = 0.10;
    /// A wall seen at a predicted |ObsAng| above this is rejected (e.g. turning at a corner).
    double max_incidence = degrees_to_radians(40.0);
    /// Largest accepted |measured − predicted| ObsAng, radians.
    double max_angle_error = degrees_to_radians(20.0);
    /// Largest accepted |measured − predicted| distance from the centre to the wall, metres.
    double max_distance_error = 0.10;
};

enum class AssociationOutcome : std::uint8_t {
    Associated,        ///< the observation belongs to `wall`
    NoObservation,     ///< not both IR readings in range: nothing to associate
    NoWallInView,      ///< from the estimate, no wall is in front of both sensors
    ObliqueIncidence,  ///< the predicted wall is seen too obliquely to trust
    AngleMismatch,     ///< measured ObsAng too far from the prediction
    DistanceMismatch,  ///< measured distance too far from the prediction
};

const char* to_string(AssociationOutcome outcome);

struct AssociationResult {
    AssociationOutcome outcome = AssociationOutcome::NoObservation;
    int wall = -1;  ///< index into the wall map of the wall the beams hit (when one did)
    int side = 0;   ///< σ = ±1: the side of that wall's normal the robot is on
    double predicted_ds_front = 0.0;  ///< beam lengths predicted from the estimate, metres
    double predicted_ds_rear = 0.0;
    double predicted_angle = 0.0;     ///< ObsAng predicted from the estimate, radians
    double predicted_distance = 0.0;  ///< D_c predicted from the estimate, metres
    double angle_error = 0.0;         ///< measured − predicted ObsAng, radians
    double distance_error = 0.0;      ///< measured − predicted D_c, metres

    bool associated() const { return outcome == AssociationOutcome::Associated; }
};

/// Associates an observation, made with both IR readings in range, with a wall of the map.
/// `ir_max_range` is the sensors' trusted maximum range (metres).
AssociationResult associate_wall(const Pose2& estimate, const WallObservation& observation,
                                 const WallMap& walls, const IrMount& mount, double ir_max_range,
                                 const AssociationParams& params);

}  // namespace legofeup
