#pragma once
// FollowPath (paper §IV.A): a path made of lines and arcs, each followed with the basic
// routines, switching to the next one when the current one is finished. The LegoFeup square
// is four FollowLine segments.

#include <variant>
#include <vector>

#include "legofeup/core/path_controllers.hpp"
#include "legofeup/core/walls.hpp"

namespace legofeup {

struct LineSegment {
    Vector2 from = Vector2::Zero();
    Vector2 to = Vector2::Zero();
};

struct ArcSegment {
    Vector2 centre = Vector2::Zero();
    double radius = 0.0;
    bool counter_clockwise = true;
    double sweep = 0.0;  ///< angle to travel around the centre, radians (> 0)
};

using PathSegment = std::variant<LineSegment, ArcSegment>;

/// The square path of the standard arena: side L_p centred on the origin, counter-clockwise
/// from (−L_p/2, −L_p/2) heading +x.
std::vector<PathSegment> square_path(const ArenaSpec& arena);

class FollowPath {
  public:
    /// `laps` ≤ 0 repeats the path for ever. The path must have at least one segment.
    FollowPath(std::vector<PathSegment> segments, int laps);

    ControlOutput step(const Pose2& estimate, const MotionLimits& limits,
                       const ControllerGains& gains);

    const std::vector<PathSegment>& segments() const { return segments_; }
    int laps() const { return laps_; }
    int segment_index() const { return index_; }
    int completed_laps() const { return completed_laps_; }
    bool finished() const { return laps_ > 0 && completed_laps_ >= laps_; }

  private:
    using Active = std::variant<FollowLine, FollowCircle>;
    static Active start_segment(const PathSegment& segment);

    std::vector<PathSegment> segments_;
    int laps_;
    int index_ = 0;
    int completed_laps_ = 0;
    Active active_;
};

}  // namespace legofeup
