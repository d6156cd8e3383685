#include "ir_ray.hpp"

namespace legofeup::sim {
namespace {

class ClosestHitIgnoringBody final : public b2RayCastCallback {
  public:
    explicit ClosestHitIgnoringBody(const b2Body* ignored) : ignored_(ignored) {}

    float ReportFixture(b2Fixture* fixture, const b2Vec2& /*point*/, const b2Vec2& /*normal*/,
                        float fraction) override {
        if (fixture->GetBody() == ignored_) {
            return -1.0f;  // skip this fixture, keep the ray as it is
        }
        closest_ = fraction;
        hit_ = true;
        return fraction;  // clip the ray here: only nearer hits are reported from now on
    }

    bool hit() const { return hit_; }
    float closest() const { return closest_; }

  private:
    const b2Body* ignored_;
    float closest_ = 1.0f;
    bool hit_ = false;
};

}  // namespace

std::optional<double> closest_hit(const b2World& world, const b2Body* ignored, const b2Vec2& origin,
                                  const b2Vec2& direction, double length) {
    ClosestHitIgnoringBody callback(ignored);
    const b2Vec2 end = origin + static_cast<float>(length) * direction;
    world.RayCast(&callback, origin, end);
    if (!callback.hit()) {
        return std::nullopt;
    }
    return static_cast<double>(callback.closest()) * length;
}

double cast_ir_ray(const b2World& world, const b2Body* ignored, const b2Vec2& origin,
                   const b2Vec2& direction, double length) {
    return closest_hit(world, ignored, origin, direction, length).value_or(length);
}

}  // namespace legofeup::sim
