// Private: a value's bits read as another type of the same size, as std::bit_cast, which the C++
// library of Emscripten 3.1 lacks.
#pragma once

#include <cstring>
#include <type_traits>

namespace collide2d::detail {

template <class To, class From>
To bit_copy(const From& from) {
  static_assert(sizeof(To) == sizeof(From) && std::is_trivially_copyable_v<To> && std::is_trivially_copyable_v<From>);
  To to;
  std::memcpy(&to, &from, sizeof to);
  return to;
}

}  // namespace collide2d::detail
