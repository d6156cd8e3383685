#pragma once
// Closest-hit ray casting for the IR sensors, skipping the robot's own fixtures. Private.

#include <box2d/box2d.h>

namespace legofeup::sim {

/// Distance from `origin` along the unit `direction` to the nearest fixture not belonging to
/// `ignored`, or `length` when nothing is hit within it.
double cast_ir_ray(const b2World& world, const b2Body* ignored, const b2Vec2& origin,
                   const b2Vec2& direction, double length);

}  // namespace legofeup::sim
