/// @file
/// FunctionRef: a reference to a callable, for the World's callback queries. Two pointers, copied by
/// value, never allocating (as C++26's std::function_ref); it does not own the callable, so the
/// callable must outlive the call it is passed to, as a lambda written in the call does.
#pragma once

#include <functional>
#include <memory>
#include <type_traits>
#include <utility>

namespace collide2d {

/// A reference to a callable of the signature, as FunctionRef<bool(const BodyShape&)>.
template <class Signature>
class FunctionRef;

/// A reference to a callable invocable as R(Args...).
template <class R, class... Args>
class FunctionRef<R(Args...)> {
 public:
  /// Any callable object invocable as R(Args...): a lambda, a function object, a function pointer.
  template <class F>
  requires(!std::is_same_v<std::remove_cvref_t<F>, FunctionRef> && std::is_object_v<std::remove_reference_t<F>> &&
           std::is_invocable_r_v<R, F&, Args...>) FunctionRef(F&& f)
  noexcept  // NOLINT(google-explicit-constructor): a lambda converts where a callback is taken
      : object_(const_cast<void*>(static_cast<const void*>(std::addressof(f)))),
        call_([](void* object, Args... args) -> R {
          return std::invoke(*static_cast<std::add_pointer_t<std::remove_reference_t<F>>>(object),
                             std::forward<Args>(args)...);
        }) {}

  /// Calls the callable referred to.
  R operator()(Args... args) const { return call_(object_, std::forward<Args>(args)...); }

 private:
  void* object_;
  R (*call_)(void*, Args...);
};

}  // namespace collide2d
