// Ellipse–ellipse contact: the global maximum of the separation over every direction, by a climb
// that a bound over every direction certifies, else by branch and bound over arcs of directions
// (deepest_direction.h says why no local maximum can pass for it). With a limit, the search ends at
// the first direction whose s passes it; with a tolerance, at the first that within_tolerance
// certifies.
#include <collide2d/kernels.h>

#include "narrowphase/contact/contact_limit.h"
#include "narrowphase/shared/curved/curved_contact.h"

#include <algorithm>

namespace collide2d {

Contact contact_ellipse_ellipse(const Ellipse& a, const Ellipse& b, const ContactOptions& options) {
  return contact_ellipse_ellipse(a, Orientation::of(a.angle), b, Orientation::of(b.angle), options);
}

Contact contact_ellipse_ellipse(const Ellipse& a, const Orientation& a_orientation, const Ellipse& b,
                                const Orientation& b_orientation, const ContactOptions& options) {
  using Pair = detail::SupportPair<double, detail::EllipseSupport<double>, detail::EllipseSupport<double>>;
  const Pair p =
      Pair::of(a, detail::Rotation<double>::of(a_orientation), b, detail::Rotation<double>::of(b_orientation));
  const double stop = detail::separation_limit(p.scale, options);
  const double size = std::max(detail::longest(a), detail::longest(b));
  const detail::Deepest<double> d =
      detail::deepest_direction(p, p.from_world(options.guess), stop, detail::tolerance_of(p, size, options));
  if (detail::beyond_limit(d.at.s, p.scale, options)) return Contact::beyond(d.at.s);
  return detail::curved_contact(p, a.center, b.center, d);
}

}  // namespace collide2d
