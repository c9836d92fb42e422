// collide2d's shapes as Box2D v3's bodies of one shape each (bench/box2d_v3/world.cpp,
// bench/box2d_v3/movers.cpp), posed as bench/box2d_v3/shapes.h poses them.
#pragma once

#include <collide2d/world.h>

#include "bench/box2d_v3/shapes.h"

#include <box2d/box2d.h>

#include <type_traits>
#include <variant>

namespace collide2d::box2d_v3 {

inline b2Filter filter_of(const Filter& f) { return {f.category, f.mask, f.group}; }

// A body of one shape, at the shape's pose.
inline b2BodyId add_body(b2WorldId world, const Shape& shape, b2BodyType type = b2_dynamicBody,
                         const Filter& filter = {}, bool sensor = false) {
  return std::visit(
      [&](const auto& s) {
        const auto p = posed(s);
        b2BodyDef body = b2DefaultBodyDef();
        body.type = type;
        body.position = p.transform.p;
        body.rotation = p.transform.q;
        const b2BodyId id = b2CreateBody(world, &body);
        b2ShapeDef def = b2DefaultShapeDef();
        def.filter = filter_of(filter);
        def.isSensor = sensor;
        using S = std::decay_t<decltype(p.shape)>;
        if constexpr (std::is_same_v<S, b2Circle>) {
          b2CreateCircleShape(id, &def, &p.shape);
        } else if constexpr (std::is_same_v<S, b2Capsule>) {
          b2CreateCapsuleShape(id, &def, &p.shape);
        } else if constexpr (std::is_same_v<S, b2Segment>) {
          b2CreateSegmentShape(id, &def, &p.shape);
        } else {
          b2CreatePolygonShape(id, &def, &p.shape);
        }
        return id;
      },
      shape);
}

}  // namespace collide2d::box2d_v3
