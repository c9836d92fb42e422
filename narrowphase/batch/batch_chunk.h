// Private: what the batched kernels (overlap_batch.cpp, contact_batch.cpp) share. Work goes in
// chunks of up to 256 pairs: scalar code writes each pair's kernel inputs (its lanes, lanes.h, with the
// one-off kernel's rounding) into one array per field, the vector kernel runs on the chunk, and the
// results are read back pair by pair.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>

namespace collide2d::detail {

// At least the doubles in the widest vector of any Highway target (256 bytes for SVE and RVV):
// a kernel of any target that reads a chunk's first n pairs in whole vectors reads no further than
// n rounded up to a multiple of this.
inline constexpr std::size_t kMaxLanes = 256 / sizeof(double);

// A chunk of pairs, one array per field, and a byte per pair for a kernel's verdict. 256 pairs, or
// fewer where the fields are many: the arrays are written pair by pair and then read by the kernel,
// and stay within 24 KiB so that the reads find them in a 32 KiB L1 data cache. Each array is a
// little longer than the chunk: arrays a multiple of 4 KiB apart would alias at the same cache
// set, and the pair-by-pair writes that fill a chunk would stall on it.
template <std::size_t kFields>
struct Chunk {
  static constexpr std::size_t pairs_within(std::size_t bytes) {
    std::size_t n = 256;
    while (n > kMaxLanes && kFields * (n + 8) * sizeof(double) > bytes) n /= 2;
    return n;
  }
  static constexpr std::size_t kPairs = pairs_within(24 * 1024);
  static constexpr std::size_t kStride = kPairs + 8;
  static_assert(kPairs % kMaxLanes == 0);

  double field[kFields][kStride];
  std::uint8_t verdict[kPairs];
};

// Fills the chunk with pairs start ... start + count - 1 (lanes_of(k): pair k's lanes), and the
// lanes after them up to a multiple of kMaxLanes with copies of the last, so that every lane a
// kernel reads holds a valid pair.
template <std::size_t kFields, class LanesOf>
void fill_chunk(Chunk<kFields>& chunk, std::size_t start, std::size_t count, LanesOf lanes_of) {
  for (std::size_t i = 0; i < count; ++i) {
    const auto fields = lanes_of(start + i).fields();
    for (std::size_t f = 0; f < kFields; ++f) chunk.field[f][i] = fields[f];
  }
  const std::size_t padded = (count + kMaxLanes - 1) / kMaxLanes * kMaxLanes;
  for (std::size_t f = 0; f < kFields; ++f)
    std::fill(chunk.field[f] + count, chunk.field[f] + padded, chunk.field[f][count - 1]);
}

// Throws std::invalid_argument naming `what` and the lengths unless every input list has `out`
// entries, the length of the output list of `results`.
void check_lengths(const char* what, std::span<const std::size_t> in, std::size_t out,
                   const char* results = "verdicts");

}  // namespace collide2d::detail
