#pragma once
// Conversions at the Box2D boundary: Box2D stores floats, sim/ computes in doubles.

#include <box2d/box2d.h>

#include "legofeup/core/state.hpp"

namespace legofeup::sim {

inline Vector2 from_b2(const b2Vec2& v) {
    return {static_cast<double>(v.x), static_cast<double>(v.y)};
}

inline b2Vec2 to_b2(const Vector2& v) {
    return {static_cast<float>(v.x()), static_cast<float>(v.y())};
}

inline b2Vec2 to_b2(double x, double y) {
    return {static_cast<float>(x), static_cast<float>(y)};
}

}  // namespace legofeup::sim
