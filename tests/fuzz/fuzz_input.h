// Fuzz-input helpers: reads numbers and choices from the fuzzer's bytes, and builds shapes from them
// with magnitudes anywhere in double range (extremes and denormals included), so that validation
// and the kernels both get exercised.
#pragma once

#include "shapes/shapes.h"

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace collide2d::fuzz {

class Input {
 public:
  Input(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  bool empty() const { return pos_ >= size_; }
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }

  // Raw 8 bytes as a double half of the time (any bit pattern: NaN, infinity, denormals), otherwise
  // a tame value from one byte (-8 ... 8 in steps) so that shapes often meet.
  double number() {
    if (byte() & 1) {
      double x = 0;
      std::uint8_t raw[8] = {};
      for (std::uint8_t& b : raw) b = byte();
      std::memcpy(&x, raw, sizeof x);
      return x;
    }
    return (static_cast<int>(byte()) - 128) / 16.0;
  }
  double size() {
    const double x = number();
    return x < 0 ? -x : x;
  }

  Shape shape() {
    const Vec2 c(number(), number());
    switch (byte() % 3) {
      case 0: return Circle{c, size()};
      case 1: return Ellipse{c, size(), size(), number()};
      default: return Rect{c, Vec2(size(), size()), number()};
    }
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

// Whether the shape passes validation (the fuzzers check the properties on valid shapes only).
inline bool valid(const Shape& s) {
  try {
    validate(s);
    return true;
  } catch (const InvalidShape&) {
    return false;
  }
}

}  // namespace collide2d::fuzz
