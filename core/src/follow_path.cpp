#include "legofeup/core/follow_path.hpp"

#include <stdexcept>
#include <utility>

namespace legofeup {

std::vector<PathSegment> square_path(const ArenaSpec& arena) {
    const double h = 0.5 * arena.path_side;
    const Vector2 corners[] = {{-h, -h}, {h, -h}, {h, h}, {-h, h}};
    std::vector<PathSegment> segments;
    for (int i = 0; i < 4; ++i) {
        segments.emplace_back(LineSegment{corners[i], corners[(i + 1) % 4]});
    }
    return segments;
}

FollowPath::FollowPath(std::vector<PathSegment> segments, int laps)
    : segments_(std::move(segments)),
      laps_(laps),
      active_(segments_.empty() ? throw std::invalid_argument("FollowPath: empty path")
                                : start_segment(segments_.front())) {}

FollowPath::Active FollowPath::start_segment(const PathSegment& segment) {
    if (const auto* line = std::get_if<LineSegment>(&segment)) {
        return FollowLine(line->from, line->to);
    }
    const auto& arc = std::get<ArcSegment>(segment);
    return FollowCircle(arc.centre, arc.radius, arc.counter_clockwise, arc.sweep);
}

ControlOutput FollowPath::step(const Pose2& estimate, const MotionLimits& limits,
                               const ControllerGains& gains) {
    const auto follow_active_segment = [&] {
        return std::visit([&](auto& routine) { return routine.step(estimate, limits, gains); },
                          active_);
    };
    if (!finished()) {
        ControlOutput out = follow_active_segment();
        if (out.finished) {
            // The segment is done: move on (and count the lap when the path wraps around).
            index_ = (index_ + 1) % static_cast<int>(segments_.size());
            if (index_ == 0) {
                ++completed_laps_;
            }
            active_ = start_segment(segments_[static_cast<std::size_t>(index_)]);
            if (!finished()) {
                out = follow_active_segment();
            }
        }
        if (!finished()) {
            out.finished = false;  // a segment ended, not the path
            return out;
        }
    }
    ControlOutput stopped;  // all laps driven: stand still
    stopped.finished = true;
    return stopped;
}

}  // namespace legofeup
