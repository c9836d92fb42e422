// Private: dispatch over pairs of kinds, derived from a list of kinds (shapes/kinds.h) and the pair
// table (pairs.h), whose row Pair<A, B> holds the kernels of the pair A, B in rank order. Generic over
// the list, so that a list with a kind of its own (a test's) dispatches alike.
#pragma once

#include "shapes/kinds.h"

#include <collide2d/query.h>

#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>

namespace collide2d::detail {

// The kernels of two kinds, A before B in rank order (pairs.h): a pair with no row has no
// definition, and the check below names it.
template <class A, class B>
struct Pair;

template <class A, class B>
struct KindPair {
  using First = A;
  using Second = B;
};

// Every pair of the kinds, A's rank at most B's, as a tuple of KindPair, in rank order.
template <class... Ts>
struct PairsOf {
  using type = std::tuple<>;
};
template <class T, class... Ts>
struct PairsOf<T, Ts...> {
  using type = decltype(std::tuple_cat(std::declval<std::tuple<KindPair<T, T>, KindPair<T, Ts>...>>(),
                                       std::declval<typename PairsOf<Ts...>::type>()));
};
template <class List>
struct AllPairs;
template <class... Ts>
struct AllPairs<KindList<Ts...>> {
  using type = typename PairsOf<Ts...>::type;
};

// Fails for a pair with no row in the table; the compiler's message names the pair
// ("required from RowCheck<Rect, HalfPlane>").
template <class A, class B>
struct RowCheck {
  static_assert(
      requires { sizeof(Pair<A, B>); },
      "the pair table has no row for this pair of kinds: give it its kernels, or Unsupported "
      "(narrowphase/pairs.h)");
};
// Each pair's check is a base of its own, so that the compiler instantiates (and names) every one
// that fails rather than stopping at the first.
template <class Tuple>
struct RowChecks;
template <class... P>
struct RowChecks<std::tuple<P...>> : RowCheck<typename P::First, typename P::Second>... {};
template <class List>
constexpr bool every_pair_has_a_row() {
  return sizeof(RowChecks<typename AllPairs<List>::type>) > 0;
}

// The pairs of the list whose row has a batch (batch.h), as a tuple of KindPair.
template <class Tuple>
struct BatchedOf;
template <class... P>
struct BatchedOf<std::tuple<P...>> {
  using type = decltype(std::tuple_cat(
      std::declval<
          std::conditional_t<Pair<typename P::First, typename P::Second>::batched, std::tuple<P>, std::tuple<>>>()...));
};
template <class List>
using BatchedPairs = typename BatchedOf<typename AllPairs<List>::type>::type;

// The row of two kinds in either order.
template <class List, class X, class Y>
using RowOf = std::conditional_t<(List::template rank<X>() <= List::template rank<Y>()), Pair<X, Y>, Pair<Y, X>>;

// Whether the pair of kinds, either way round, has a batch.
template <class X, class Y>
constexpr bool batched = RowOf<Kinds, X, Y>::batched;

// kernel(x, y, swapped) with the pair in the list's rank order, two shapes of one kind by key
// (shapes/kinds.h), so that swapping A and B swaps the result bit for bit.
template <class List, class X, class Y, class Kernel>
auto kinds_in_rank_order(const X& x, const Y& y, Kernel& kernel) {
  if constexpr (List::template rank<X>() < List::template rank<Y>()) {
    return kernel(x, y, false);
  } else if constexpr (List::template rank<X>() > List::template rank<Y>()) {
    return kernel(y, x, true);
  } else {
    return precedes(y, x) ? kernel(y, x, true) : kernel(x, y, false);
  }
}
template <class List, class Variant, class Kernel>
auto in_rank_order(const Variant& a, const Variant& b, Kernel kernel) {
  return std::visit([&kernel](const auto& x, const auto& y) { return kinds_in_rank_order<List>(x, y, kernel); }, a, b);
}

// The queries on two shapes of a list's kinds, from their row: in rank order, the result turned
// back to the caller's order. The callers validate the shapes.
template <class List, class Variant>
bool overlap_of(const Variant& a, const Variant& b) {
  return in_rank_order<List>(a, b, [](const auto& x, const auto& y, bool) {
    return Pair<std::decay_t<decltype(x)>, std::decay_t<decltype(y)>>::overlap(x, y);
  });
}
template <class List, class Variant>
bool posed_overlap_of(const Variant& a, const Orientation& oa, const Variant& b, const Orientation& ob) {
  return in_rank_order<List>(a, b, [&](const auto& x, const auto& y, bool swapped) {
    using Row = Pair<std::decay_t<decltype(x)>, std::decay_t<decltype(y)>>;
    return swapped ? Row::posed_overlap(x, ob, y, oa) : Row::posed_overlap(x, oa, y, ob);
  });
}
template <class List, class Variant>
DistanceResult distance_of(const Variant& a, const Variant& b) {
  return in_rank_order<List>(a, b, [](const auto& x, const auto& y, bool swapped) {
    const DistanceResult r = Pair<std::decay_t<decltype(x)>, std::decay_t<decltype(y)>>::distance(x, y);
    return swapped ? r.swapped() : r;
  });
}
template <class List, class Variant>
DistanceResult boundary_of(const Variant& a, const Variant& b) {
  return in_rank_order<List>(a, b, [](const auto& x, const auto& y, bool swapped) {
    const DistanceResult r = Pair<std::decay_t<decltype(x)>, std::decay_t<decltype(y)>>::boundary(x, y);
    return swapped ? r.swapped() : r;
  });
}
// A pair given the other way round has its guess turned round, and its result swapped back (by the
// row itself where it writes the caller's order: in_callers_order).
template <class List, class X, class Y>
Contact contact_of_kinds(const X& a, const Orientation& oa, const Y& b, const Orientation& ob,
                         const ContactOptions& options) {
  auto kernel = [&](const auto& x, const auto& y, bool swapped) {
    using Row = Pair<std::decay_t<decltype(x)>, std::decay_t<decltype(y)>>;
    if (!swapped) return Row::contact(x, oa, y, ob, options, false);
    ContactOptions reversed = options;
    reversed.guess = -options.guess;
    if constexpr (requires { requires Row::in_callers_order; }) {
      return Row::contact(x, ob, y, oa, reversed, true);
    } else {
      return Row::contact(x, ob, y, oa, reversed, true).swapped();
    }
  };
  return kinds_in_rank_order<List>(a, b, kernel);
}
template <class List, class Variant>
Contact contact_of(const Variant& a, const Orientation& oa, const Variant& b, const Orientation& ob,
                   const ContactOptions& options) {
  return std::visit([&](const auto& x, const auto& y) { return contact_of_kinds<List>(x, oa, y, ob, options); }, a, b);
}

}  // namespace collide2d::detail
