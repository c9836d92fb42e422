// Private: the World's slots by index (its bodies, its shapes), grown a page at a time once they
// fill one, so that the room held past the last slot stays under a page where a std::vector's
// doubling holds up to as much again, and growing never copies the slots already there. The first
// page grows as a vector does, so that a small World takes little room.
#pragma once

#include <cstddef>
#include <vector>

namespace collide2d::detail {

template <class T>
class Pages {
 public:
  static constexpr std::size_t kBits = 10;
  static constexpr std::size_t kPage = std::size_t{1} << kBits;

  T& operator[](std::size_t i) { return pages_[i >> kBits][i & (kPage - 1)]; }
  const T& operator[](std::size_t i) const { return pages_[i >> kBits][i & (kPage - 1)]; }
  std::size_t size() const { return size_; }

  T& emplace_back() {
    if (pages_.empty() || pages_.back().size() == kPage) {
      pages_.emplace_back();
      if (pages_.size() > 1) pages_.back().reserve(kPage);
    }
    ++size_;
    return pages_.back().emplace_back();
  }

 private:
  std::vector<std::vector<T>> pages_;
  std::size_t size_ = 0;
};

}  // namespace collide2d::detail
