#pragma once
// Feature association (paper Fig. 4): which wall does an IR observation belong to?
//
// The paper decides from the estimated pose which wall the robot is next to. We do the same
// geometrically, for any wall map: cast both sensor beams from the estimated pose, take the
// nearest wall that both beams hit, and accept it only if the measured geometry (ObsAng and
// the centre's distance D_c) fits what the estimate predicts for that wall. Every rejection
// says why, so students can see when and why updates are skipped.
//
// Two gates decide whether the measurement fits (AssociationParams::gate):
//
// - Fixed (the paper's, the default): |ObsAng error| ≤ 20° and |D_c error| ≤ 10 cm. They
//   ignore P, so once the estimate is more than 10 cm across a wall no wall is ever taken
//   again, however much P grows.
// - Mahalanobis: with the wall's measurement z = [n·p, θ] (wall_measurement.hpp), the
//   innovation ν = z − h(X̂) and its predicted covariance S = ∇h_X P ∇h_Xᵀ + ∇h_r R ∇h_rᵀ,
//   accept when d² = νᵀ S⁻¹ ν ≤ χ²₂(p), the χ²(2) quantile at the gate probability p. For a
//   consistent filter d² is χ²(2), so a right wall is refused with probability 1 − p; as P
//   grows the gate widens, and a lost filter takes the walls again.
//
// d² (and the χ² threshold) are computed whenever a candidate wall is found, under either gate,
// so a run with the fixed gates shows what the Mahalanobis gate would have decided.

#include <cstdint>
#include <optional>
#include <string_view>

#include <Eigen/Core>

#include "legofeup/core/angles.hpp"
#include "legofeup/core/ir_geometry.hpp"
#include "legofeup/core/walls.hpp"

namespace legofeup {

/// Which test decides whether a measured wall fits the predicted one.
enum class AssociationGate : std::uint8_t {
    Fixed,        ///< |ObsAng error| and |D_c error| under fixed limits (the paper's)
    Mahalanobis,  ///< νᵀS⁻¹ν under the χ²(2) quantile at gate_probability
};

const char* to_string(AssociationGate gate);  ///< "fixed", "mahalanobis"
std::optional<AssociationGate> association_gate_from_string(std::string_view text);

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
    AssociationGate gate = AssociationGate::Fixed;
    /// p of the Mahalanobis gate: a consistent filter's right wall passes with probability p.
    double gate_probability = 0.99;
};

enum class AssociationOutcome : std::uint8_t {
    Associated,        ///< the observation belongs to `wall`
    NoObservation,     ///< not both IR readings in range: nothing to associate
    NoWallInView,      ///< from the estimate, no wall is in front of both sensors
    ObliqueIncidence,  ///< the predicted wall is seen too obliquely to trust
    AngleMismatch,     ///< measured ObsAng too far from the prediction
    DistanceMismatch,  ///< measured distance too far from the prediction
    /// νᵀS⁻¹ν above the χ²(2) gate (AssociationGate::Mahalanobis)
    MahalanobisMismatch,
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
    /// The gate the outcome was decided by.
    AssociationGate gate = AssociationGate::Fixed;
    /// d² = νᵀS⁻¹ν of the candidate wall, whichever gate decided (infinite if S is singular),
    /// and the χ²(2) quantile the Mahalanobis gate compares it with; 0 without a candidate.
    double mahalanobis_d2 = 0.0;
    double mahalanobis_threshold = 0.0;

    bool associated() const { return outcome == AssociationOutcome::Associated; }
};

/// The filter's belief the association is judged from: the (predicted) pose and its P.
struct PoseBelief {
    Pose2 pose;
    StateCovariance covariance = StateCovariance::Zero();
};

/// Associates an observation, made with both IR readings in range, with a wall of the map.
/// `ir_max_range` is the sensors' trusted maximum range (metres); `ir_covariance` is R, the
/// covariance of [ε_ds1, ε_ds2] in m² (for d²).
AssociationResult associate_wall(const PoseBelief& belief, const WallObservation& observation,
                                 const WallMap& walls, const IrMount& mount, double ir_max_range,
                                 const Eigen::Matrix2d& ir_covariance,
                                 const AssociationParams& params);

/// The same with the Mahalanobis gate's threshold given, as association_gate_threshold(
/// params.gate_probability) returns it: the loop computes it once per configuration, since
/// the quantile's Newton iterations cost several times a whole loop step.
AssociationResult associate_wall(const PoseBelief& belief, const WallObservation& observation,
                                 const WallMap& walls, const IrMount& mount, double ir_max_range,
                                 const Eigen::Matrix2d& ir_covariance,
                                 const AssociationParams& params, double gate_threshold);

/// The Mahalanobis gate's threshold: the χ²(2) quantile at `probability`.
double association_gate_threshold(double probability);

}  // namespace legofeup
