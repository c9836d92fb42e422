// Private: the table of pairs. One row per pair of kinds, A before B in rank order (shapes/kinds.h),
// holding the pair's kernel for each query:
//   overlap(a, b), posed_overlap(a, oa, b, ob)   overlap/overlap_<a>_<b>.cpp
//   distance(a, b)                               distance/distance_<a>_<b>.cpp
//   contact(a, oa, b, ob, options, swapped)      contact/contact_<a>_<b>.cpp (swapped: the caller
//                                                gave B first)
//   in_callers_order                             whether contact() then writes the caller's order
//                                                itself, else the dispatch turns it
//   boundary(a, b)                               the gap between boundary curves, where it applies
//   batched                                      whether batch.h tests the pair in SIMD lanes
// A row that takes the convex cores' methods (OnCores: overlap/overlap_cores.cpp and
// overlap_core_ellipse.cpp, and their distance and contact twins) names the kernels it has of its
// own. The queries (query.cpp), the World's batches and the batched kernels are derived from the
// table; every pair of kinds must have a row (the check at the end names a pair without one).
// docs/algorithms/README.md shows the table, each query's kernel file for each pair; the pair_table
// test holds it to this one.
#pragma once

#include <collide2d/kernels.h>
#include <collide2d/query.h>

#include "narrowphase/contact/capsule_segment.h"
#include "narrowphase/contact/circle_circle.h"
#include "narrowphase/contact/contact_rect_rect.h"
#include "narrowphase/dispatch.h"
#include "narrowphase/shared/cores/convex_core.h"

#include <optional>
#include <type_traits>

namespace collide2d::detail {

// The orientation a kernel takes for a shape: a kind with no angle (a circle) has none.
template <class T>
Orientation orientation_of(const T& x) {
  if constexpr (requires { x.angle; }) {
    return Orientation::of(x.angle);
  } else {
    return {};
  }
}

// The queries a row does not support: the boundary distance of every pair with a core shape.
struct NoBoundary {
  template <class X, class Y>
  [[noreturn]] static DistanceResult boundary(const X&, const Y&) {
    throw UnsupportedPair(
        "the boundary distance covers circles and ellipses, not rectangles, polygons, capsules or segments");
  }
};

// A row for a pair of kinds the queries do not take: each throws UnsupportedPair.
struct Unsupported {
  static constexpr bool batched = false;
  [[noreturn]] static void refuse() { throw UnsupportedPair("the queries do not take this pair of kinds"); }
  template <class X, class Y>
  static bool overlap(const X&, const Y&) {
    refuse();
  }
  template <class X, class Y>
  static bool posed_overlap(const X&, const Orientation&, const Y&, const Orientation&) {
    refuse();
  }
  template <class X, class Y>
  static DistanceResult distance(const X&, const Y&) {
    refuse();
  }
  template <class X, class Y>
  static Contact contact(const X&, const Orientation&, const Y&, const Orientation&, const ContactOptions&, bool) {
    refuse();
  }
  template <class X, class Y>
  static DistanceResult boundary(const X&, const Y&) {
    refuse();
  }
};

// The methods on convex cores (narrowphase/shared/cores/convex_core.h): two cores, or a core and an
// ellipse, the pair's cores placed in A's frame (in the ellipse's, against one).
struct OnCores : NoBoundary {
  static constexpr bool batched = false;
  // The cores write a contact the caller's way round themselves (`swapped`: the caller gave B
  // first), which costs them nothing, rather than have the dispatch turn it (Contact::swapped()).
  // A row whose kernel does not says so.
  static constexpr bool in_callers_order = true;

  template <class X, class Y, class Run>
  static auto on_core_pair(const X& a, const Orientation& oa, const Y& b, const Orientation& ob, Run run) {
    if constexpr (std::is_same_v<Y, Ellipse>) {
      return run(CoreEllipse::of(a, oa, b, ob));
    } else {
      return run(core_pair(a, oa, b, ob));
    }
  }
  // The discs about the two centres first: they settle most pairs before any core is built.
  template <class X, class Y>
  static bool posed_overlap(const X& a, const Orientation& oa, const Y& b, const Orientation& ob) {
    if (const std::optional<bool> discs = disc_verdict(disc_lanes(a, oa, b, ob))) return *discs;
    return on_core_pair(a, oa, b, ob, [](const auto& p) {
      if constexpr (std::is_same_v<std::decay_t<decltype(p)>, CoreEllipse>) {
        return core_ellipse_overlap(p);
      } else {
        return core_overlap(p);
      }
    });
  }
  template <class X, class Y>
  static bool overlap(const X& a, const Y& b) {
    return posed_overlap(a, orientation_of(a), b, orientation_of(b));
  }
  template <class X, class Y>
  static DistanceResult distance(const X& a, const Y& b) {
    return on_core_pair(a, orientation_of(a), b, orientation_of(b), [](const auto& p) {
      if constexpr (std::is_same_v<std::decay_t<decltype(p)>, CoreEllipse>) {
        return core_ellipse_distance(p);
      } else {
        return core_distance(p);
      }
    });
  }
  // A tie of two polygons' faces keeps the kernel's A's (the pair in rank order), whichever the
  // caller gave first.
  template <class X, class Y>
  static Contact contact(const X& a, const Orientation& oa, const Y& b, const Orientation& ob, const ContactOptions& o,
                         bool swapped) {
    if constexpr (std::is_same_v<Y, Ellipse>) {
      const Contact c = core_ellipse_contact(CoreEllipse::of(a, oa, b, ob), o);
      return swapped ? c.swapped() : c;
    } else {
      return core_contact(a, oa, b, ob, o, swapped);
    }
  }
};

// Whether the row of A and B (in rank order) takes the convex cores' methods.
template <class A, class B>
constexpr bool on_cores = std::is_base_of_v<OnCores, Pair<A, B>>;

// ---- a rectangle first ----

template <>
struct Pair<Rect, Rect> : NoBoundary {
  static constexpr bool batched = true;
  static bool overlap(const Rect& a, const Rect& b) { return overlap_rect_rect(a, b); }
  static bool posed_overlap(const Rect& a, const Orientation& oa, const Rect& b, const Orientation& ob) {
    return overlap_rect_rect(a, oa, b, ob);
  }
  static DistanceResult distance(const Rect& a, const Rect& b) { return distance_rect_rect(a, b); }
  // Where swapped, the kernel's B is the caller's A, whose face the manifold prefers.
  static constexpr bool in_callers_order = true;
  static Contact contact(const Rect& a, const Orientation& oa, const Rect& b, const Orientation& ob,
                         const ContactOptions& o, bool swapped) {
    return contact_rect_rect(a, oa, b, ob, o, swapped);
  }
};
template <>
struct Pair<Rect, ConvexPolygon> : OnCores {};
template <>
struct Pair<Rect, Capsule> : OnCores {};
template <>
struct Pair<Rect, Segment> : OnCores {};
template <>
struct Pair<Rect, Circle> : NoBoundary {
  static constexpr bool batched = true;
  static bool overlap(const Rect& a, const Circle& b) { return overlap_rect_circle(a, b); }
  static bool posed_overlap(const Rect& a, const Orientation& oa, const Circle& b, const Orientation&) {
    return overlap_rect_circle(a, oa, b);
  }
  static DistanceResult distance(const Rect& a, const Circle& b) { return distance_rect_circle(a, b); }
  static Contact contact(const Rect& a, const Orientation& oa, const Circle& b, const Orientation&,
                         const ContactOptions& o, bool) {
    return contact_rect_circle(a, oa, b, o);
  }
};
template <>
struct Pair<Rect, Ellipse> : NoBoundary {
  static constexpr bool batched = true;
  static bool overlap(const Rect& a, const Ellipse& b) { return overlap_rect_ellipse(a, b); }
  static bool posed_overlap(const Rect& a, const Orientation& oa, const Ellipse& b, const Orientation& ob) {
    return overlap_rect_ellipse(a, oa, b, ob);
  }
  static DistanceResult distance(const Rect& a, const Ellipse& b) { return distance_rect_ellipse(a, b); }
  static Contact contact(const Rect& a, const Orientation& oa, const Ellipse& b, const Orientation& ob,
                         const ContactOptions& o, bool) {
    return contact_rect_ellipse(a, oa, b, ob, o);
  }
};

// ---- a polygon first ----

template <>
struct Pair<ConvexPolygon, ConvexPolygon> : OnCores {
  static constexpr bool batched = true;
};
template <>
struct Pair<ConvexPolygon, Capsule> : OnCores {};
template <>
struct Pair<ConvexPolygon, Segment> : OnCores {};
template <>
struct Pair<ConvexPolygon, Circle> : OnCores {
  static constexpr bool in_callers_order = false;
  static constexpr bool batched = true;
  static Contact contact(const ConvexPolygon& a, const Orientation& oa, const Circle& b, const Orientation&,
                         const ContactOptions& o, bool) {
    return contact_polygon_circle(a, oa, b, o);
  }
};
template <>
struct Pair<ConvexPolygon, Ellipse> : OnCores {
  static constexpr bool batched = true;
};

// ---- a capsule first ----

// The capsule's rows write a contact the caller's way round themselves, as the cores do.
template <class B>
struct CapsuleAndSegment : OnCores {
  static Contact contact(const Capsule& a, const Orientation& oa, const B& b, const Orientation& ob,
                         const ContactOptions& o, bool swapped) {
    return capsule_segment_contact(a, oa, b, ob, o, swapped);
  }
};
template <>
struct Pair<Capsule, Capsule> : CapsuleAndSegment<Capsule> {};
template <>
struct Pair<Capsule, Segment> : CapsuleAndSegment<Segment> {};
template <>
struct Pair<Capsule, Circle> : OnCores {
  static constexpr bool in_callers_order = false;
  static constexpr bool batched = true;
  static Contact contact(const Capsule& a, const Orientation& oa, const Circle& b, const Orientation&,
                         const ContactOptions& o, bool) {
    return contact_capsule_circle(a, oa, b, o);
  }
};
template <>
struct Pair<Capsule, Ellipse> : OnCores {
  static constexpr bool batched = true;
};

// ---- a segment first (level geometry: tested one pair at a time) ----

template <>
struct Pair<Segment, Segment> : OnCores {};
template <>
struct Pair<Segment, Circle> : OnCores {
  static constexpr bool in_callers_order = false;
  static Contact contact(const Segment& a, const Orientation& oa, const Circle& b, const Orientation&,
                         const ContactOptions& o, bool) {
    return contact_segment_circle(a, oa, b, o);
  }
};
template <>
struct Pair<Segment, Ellipse> : OnCores {};

// ---- curved pairs ----

template <>
struct Pair<Circle, Circle> {
  static constexpr bool batched = true;
  static bool overlap(const Circle& a, const Circle& b) { return overlap_circle_circle(a, b); }
  static bool posed_overlap(const Circle& a, const Orientation&, const Circle& b, const Orientation&) {
    return overlap_circle_circle(a, b);
  }
  static DistanceResult distance(const Circle& a, const Circle& b) { return distance_circle_circle(a, b); }
  static constexpr bool in_callers_order = true;
  static Contact contact(const Circle& a, const Orientation&, const Circle& b, const Orientation&,
                         const ContactOptions& o, bool swapped) {
    return circle_circle_contact(a, b, o, swapped);
  }
  static DistanceResult boundary(const Circle& a, const Circle& b) { return boundary_distance_circle_circle(a, b); }
};
template <>
struct Pair<Circle, Ellipse> {
  static constexpr bool batched = true;
  static bool overlap(const Circle& a, const Ellipse& b) { return overlap_circle_ellipse(a, b); }
  static bool posed_overlap(const Circle& a, const Orientation&, const Ellipse& b, const Orientation& ob) {
    return overlap_circle_ellipse(a, b, ob);
  }
  static DistanceResult distance(const Circle& a, const Ellipse& b) { return distance_circle_ellipse(a, b); }
  static Contact contact(const Circle& a, const Orientation&, const Ellipse& b, const Orientation& ob,
                         const ContactOptions& o, bool) {
    return contact_circle_ellipse(a, b, ob, o);
  }
  static DistanceResult boundary(const Circle& a, const Ellipse& b) {
    return boundary_distance_ellipse_ellipse({a.center, a.radius, a.radius, 0.0}, b);
  }
};
template <>
struct Pair<Ellipse, Ellipse> {
  static constexpr bool batched = true;
  static bool overlap(const Ellipse& a, const Ellipse& b) { return overlap_ellipse_ellipse(a, b); }
  static bool posed_overlap(const Ellipse& a, const Orientation& oa, const Ellipse& b, const Orientation& ob) {
    return overlap_ellipse_ellipse(a, oa, b, ob);
  }
  static DistanceResult distance(const Ellipse& a, const Ellipse& b) { return distance_ellipse_ellipse(a, b); }
  static Contact contact(const Ellipse& a, const Orientation& oa, const Ellipse& b, const Orientation& ob,
                         const ContactOptions& o, bool) {
    return contact_ellipse_ellipse(a, oa, b, ob, o);
  }
  static DistanceResult boundary(const Ellipse& a, const Ellipse& b) { return boundary_distance_ellipse_ellipse(a, b); }
};

static_assert(every_pair_has_a_row<Kinds>());

}  // namespace collide2d::detail
