#pragma once
// Closest-hit ray casting in the Box2D world (IR sensors, beacon line of sight, laser
// scanner), skipping the robot's own fixtures. Private.

#include <box2d/box2d.h>

#include <optional>

namespace legofeup::sim {

/// Distance from `origin` along the unit `direction` to the nearest fixture not belonging to
/// `ignored`, or nullopt when nothing is hit within `length`.
std::optional<double> closest_hit(const b2World& world, const b2Body* ignored, const b2Vec2& origin,
                                  const b2Vec2& direction, double length);

/// closest_hit(), or `length` when nothing is hit within it (how the IR sensors see nothing).
double cast_ir_ray(const b2World& world, const b2Body* ignored, const b2Vec2& origin,
                   const b2Vec2& direction, double length);

}  // namespace legofeup::sim
