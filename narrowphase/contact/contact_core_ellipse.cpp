// A convex core and an ellipse, where the pair has no kernel of its own: the global maximum of the
// separation over every direction (core_ellipse.h), at a face normal or at a normal of the ellipse
// through a vertex, less the core's radius. To a tolerance, the vertices' roots stop early
// (vertex_peaks): a peak found so has its ellipse point on the vertex's moved by its separation
// along the normal, and its sign certain, so that the verdict is the exact one.
#include "narrowphase/shared/cores/core_ellipse.h"

#include "narrowphase/contact/contact_limit.h"

#include <algorithm>

namespace collide2d::detail {

Contact core_ellipse_contact(const CoreEllipse& p, const ContactOptions& options) {
  const Vec2& o = p.core.center;
  const Vec2 box(std::clamp(o.x(), -p.a, p.a), std::clamp(o.y(), -p.b, p.b));
  if (has_limit(options) && may_pass_limit(o - box, p.core.discs.reach, options)) {
    // The disc of A's reach apart from the ellipse's bounding box: that gap is at most the solids'
    // distance.
    const double gap = (o - box).norm() - p.core.discs.reach;
    if (beyond_limit(gap, o.norm() + p.core.discs.reach + p.a + p.b, options)) return Contact::beyond(gap);
  }
  const double r = p.core.radius;
  const Faces faces = best_face(p);
  if (beyond_limit(faces.best.s - r, scale(p), options)) return Contact::beyond(faces.best.s - r);
  return limited(options, [&] {
    const double size = std::max({p.a, p.b, p.core.discs.reach});
    const Deepest deep = deepest(p, faces, {options.tolerance, options.tolerance / size});
    const Peak& d = deep.peak;
    const Vec2 u = p.world_direction(d.u);
    Contact c = Contact::of(d.s - r, u, p.world_point(Vec2(d.on_a + r * d.u)), p.world_point(d.on_e));
    c.evaluations = deep.roots;
    return c;
  });
}

}  // namespace collide2d::detail
