#include "shapes/elementary.h"

#include "shapes/bits.h"
#include "shapes/double_double.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace collide2d::detail {
namespace {

using u64 = std::uint64_t;
__extension__ using u128 = unsigned __int128;  // GCC's and clang's, on every target they build for

// The bits of 2/pi after the binary point, 64 a word, the first bits first; then pi/2 and atan(i/8)
// as double-doubles, beside elementary.h's pi (scripts/elementary_constants.py prints them;
// test_elementary checks the results against 1,300-bit arithmetic).
constexpr std::array<u64, 19> kTwoOverPi{0xa2f9836e4e441529, 0xfc2757d1f534ddc0, 0xdb6295993c439041, 0xfe5163abdebbc561,
                                         0xb7246e3a424dd2e0, 0x06492eea09d1921c, 0xfe1deb1cb129a73e, 0xe88235f52ebb4484,
                                         0xe99c7026b45f7e41, 0x3991d639835339f4, 0x9c845f8bbdf9283b, 0x1ff897ffde05980f,
                                         0xef2f118b5a0a6d1f, 0x6d367ecf27cb09b7, 0x4f463f669e5fea2d, 0x7527bac7ebe5f17b,
                                         0x3d0739f78a5292ea, 0x6bfb5fb11f8d5d08, 0x56033046fc7b6bab};
constexpr DoubleDouble kHalfPi{0x1.921fb54442d18p+0, 0x1.1a62633145c07p-54};
constexpr std::array<DoubleDouble, 9> kAtanEighths{{{0.0, 0.0},
                                                    {0x1.fd5ba9aac2f6ep-4, -0x1.cd37686760c17p-59},
                                                    {0x1.f5b75f92c80ddp-3, 0x1.8ab6e3cf7afbdp-57},
                                                    {0x1.6f61941e4def1p-2, -0x1.c63aae6f6e918p-56},
                                                    {0x1.dac670561bb4fp-2, 0x1.a2b7f222f65e2p-56},
                                                    {0x1.1e00babdefeb4p-1, -0x1.928df287a668fp-58},
                                                    {0x1.4978fa3269ee1p-1, 0x1.2419a87f2a458p-56},
                                                    {0x1.700a7c5784634p-1, -0x1.8c34d25aadef6p-56},
                                                    {0x1.921fb54442d18p-1, 0x1.1a62633145c07p-55}}};
constexpr double kTwoOverPiNearest = 0x1.45f306dc9c883p-1;
// pi/2 as a sum of four doubles, the first three of at most 33 significant bits, so that k times
// each of those is exact for k < 2^20; the four are within 2^-160 of pi/2.
constexpr std::array<double, 4> kHalfPiParts{0x1.921fb544p+0, 0x1.0b4611a6p-34, 0x1.3198a2ep-69,
                                             0x1.b839a252049c1p-104};

// The coefficients of a power series in z = x^2, eight terms from x^first on: the Taylor series of
// sin (first 3) and cos (first 4), (-1)^(n/2) / n!, and of atan (first 3), (-1)^(n/2) / n. Their
// next terms lie below 2^-60 of the result on the intervals the kernels take.
constexpr std::array<double, 8> series(int first, bool factorial) {
  std::array<double, 8> c{};
  for (int k = 0; k < 8; ++k) {
    const int n = first + 2 * k;
    double divisor = n;
    if (factorial) {
      divisor = 1;
      for (int f = 2; f <= n; ++f) divisor *= f;  // exact: 18! < 2^53
    }
    c[k] = ((n / 2) % 2 == 0 ? 1.0 : -1.0) / divisor;
  }
  return c;
}
constexpr std::array<double, 8> kSinTail = series(3, true), kCosTail = series(4, true), kAtanTail = series(3, false);

// The series at z in Estrin's order: pairs, then pairs of pairs, so that the multiplications of
// one level run at once rather than one after another.
double series_at(const std::array<double, 8>& c, double z) {
  const double z2 = z * z;
  const double low = (c[0] + c[1] * z) + (c[2] + c[3] * z) * z2;
  const double high = (c[4] + c[5] * z) + (c[6] + c[7] * z) * z2;
  return low + high * (z2 * z2);
}

// cos r and sin r for r = hi + lo, |r| <= pi/4. The terms past the first are under a tenth of the
// result, so that their rounding costs a fraction of an ulp.
CosSin kernel(const DoubleDouble& r) {
  const double z = r.hi * r.hi;
  const double sin_rest = r.hi * z * series_at(kSinTail, z) + r.lo * (1 - 0.5 * z);
  const DoubleDouble square = two_product(r.hi, r.hi);
  const DoubleDouble one_less = two_sum(1.0, -0.5 * square.hi);
  const double cos_rest = one_less.lo - (0.5 * square.lo + r.hi * r.lo) + z * z * series_at(kCosTail, z);
  return {one_less.hi + cos_rest, r.hi + sin_rest};
}

// The sine's and cosine's series past their first terms. Fourteen terms: on |r| <= pi/4 the next
// lies below 2^-110.
constexpr std::array<DoubleDouble, 14> kSinTailExtended = extended_series<14>(3),
                                       kCosTailExtended = extended_series<14>(4);

// cos r and sin r as double-doubles for a normalized r, |r| <= pi/4: the series by Horner's rule,
// its terms from r^17 on in double arithmetic (each below 2^-53 of the result, so that double
// rounding there costs under 2^-106), the rest in double-double.
ExtendedCosSin extended_kernel(const DoubleDouble& r) {
  const DoubleDouble z = r * r;
  double sin_small = kSinTailExtended.back().hi, cos_small = kCosTailExtended.back().hi;
  for (int k = 12; k >= 7; --k) {
    sin_small = sin_small * z.hi + kSinTailExtended[k].hi;
    cos_small = cos_small * z.hi + kCosTailExtended[k].hi;
  }
  DoubleDouble sin_tail = sin_small, cos_tail = cos_small;
  for (int k = 6; k >= 0; --k) {
    sin_tail = sin_tail * z + kSinTailExtended[k];
    cos_tail = cos_tail * z + kCosTailExtended[k];
  }
  return {DoubleDouble(1) - z * 0.5 + z * z * cos_tail, r + r * z * sin_tail};
}

// 64 bits of the 256-bit p (p[0] the lowest word) from bit `from` up.
u64 bits_at(const std::array<u64, 4>& p, int from) {
  const int word = from / 64, shift = from % 64;
  const u64 low = word < 4 ? p[word] >> shift : 0;
  const u64 high = shift != 0 && word + 1 < 4 ? p[word + 1] << (64 - shift) : 0;
  return low | high;
}

struct Reduced {
  DoubleDouble r;
  unsigned quadrant = 0;
};

// angle = quadrant pi/2 + r, for |angle| < 2^20, by the nearest multiple k of pi/2 taken away in
// parts (Cody and Waite): the first two parts exactly, the third with its rounding error kept, the
// fourth rounded. The result is within 2^-136 of the exact r, and no double's r is smaller than
// 2^-62 (Muller, "Elementary Functions", chapter 11). Either sign, and no branch: game angles fall
// on both sides of every threshold at random.
Reduced reduce_near(double angle) {
  const double k = (angle * kTwoOverPiNearest + 0x1.8p52) - 0x1.8p52;                   // rounds to an integer
  const DoubleDouble r = two_sum(angle - k * kHalfPiParts[0], -(k * kHalfPiParts[1]));  // Sterbenz: exact
  const DoubleDouble s = two_sum(r.hi, -(k * kHalfPiParts[2]));
  // Not renormalized: the kernel needs lo only as a first-order correction, and the high part is
  // ready sooner.
  Reduced out;
  out.r = {s.hi, s.lo + r.lo - k * kHalfPiParts[3]};
  out.quadrant = static_cast<unsigned>(static_cast<std::int64_t>(k) & 3);
  return out;
}

// angle = quadrant pi/2 + r (mod 2 pi), |r| <= pi/4, for any finite angle beyond pi/4: |angle| 2/pi
// mod 4 from the product of the angle's 53-bit significand with 192 bits of 2/pi, exact to 2^-137.
// The bits of 2/pi before those add multiples of 4; the bits after, less than 2^-137.
Reduced reduce_far(double angle) {
  const double magnitude = std::abs(angle);
  const u64 bits = bit_copy<u64>(magnitude);
  const int exponent = static_cast<int>(bits >> 52) - 1075;  // magnitude = significand 2^exponent
  const u64 significand = (bits & ((u64{1} << 52) - 1)) | (u64{1} << 52);
  const int skipped = std::max(0, exponent - 2);
  const int word = skipped / 64, shift = skipped % 64;
  const auto window = [&](int k) {  // the window's k-th word from the top
    const u64 a = kTwoOverPi[word + k], b = kTwoOverPi[word + k + 1];
    return shift == 0 ? a : (a << shift) | (b >> (64 - shift));
  };
  std::array<u64, 4> product{};
  u128 carry = 0;
  for (int k = 0; k < 3; ++k) {
    const u128 t = u128{significand} * window(2 - k) + carry;
    product[k] = static_cast<u64>(t);
    carry = t >> 64;
  }
  product[3] = static_cast<u64>(carry);
  const int point = 192 - (exponent - skipped);  // the binary point of magnitude 2/pi in product
  Reduced out;
  out.quadrant = static_cast<unsigned>(bits_at(product, point)) & 3;
  u64 high = bits_at(product, point - 64), low = bits_at(product, point - 128);
  const bool past_half = high >> 63 != 0;  // reduce to the nearer multiple: r < 0
  if (past_half) {
    out.quadrant += 1;
    high = ~high + (low == 0 ? 1 : 0);
    low = -low;
  }
  if (angle < 0) out.quadrant = 4 - (out.quadrant & 3);
  if ((high | low) == 0) return out;
  // The fraction's leading 106 bits as a double-double, times pi/2.
  const int lead = high != 0 ? std::countl_zero(high) : 64 + std::countl_zero(low);
  const u128 fraction = ((u128{high} << 64) | low) << lead;
  const double hi = std::ldexp(static_cast<double>(static_cast<u64>(fraction >> 75)), -53 - lead);
  const double lo =
      std::ldexp(static_cast<double>(static_cast<u64>(fraction >> 22) & ((u64{1} << 53) - 1)), -106 - lead);
  DoubleDouble r = two_product(hi, kHalfPi.hi);
  r = fast_two_sum(r.hi, r.lo + hi * kHalfPi.lo + lo * kHalfPi.hi);
  out.r = past_half != (angle < 0) ? DoubleDouble{-r.hi, -r.lo} : r;
  return out;
}

// atan(small / big) as a double-double, 0 <= small <= big, both finite and big > 0:
// atan(i/8) + atan(u) with u = (z - i/8) / (1 + z i/8) and i/8 the eighth nearest z.
DoubleDouble atan_ratio(double small, double big) {
  const double quotient = small / big;
  if (quotient < 0x1p-27) return {quotient, 0.0};  // atan z = z (1 - z^2/3 ...) rounds to z
  // Both within 2^27 of each other: scaled by one power of 2 so that no product below underflows.
  const double scale = big > 0x1p990 ? 0x1p-30 : big < 0x1p-900 ? 0x1p1000 : 1.0;
  const DoubleDouble z = DoubleDouble(small * scale) / DoubleDouble(big * scale);
  const int i = static_cast<int>(z.hi * 8 + 0.5);
  const double c = i / 8.0;
  DoubleDouble u = z;
  if (i > 0) {
    const DoubleDouble zc = two_product(z.hi, c);
    DoubleDouble denominator = fast_two_sum(1.0, zc.hi);
    denominator.lo += zc.lo + z.lo * c;
    u = two_sum(z.hi - c, z.lo) / denominator;  // z.hi - c is exact (Sterbenz)
  }
  const double w = u.hi * u.hi;
  const DoubleDouble sum = fast_two_sum(kAtanEighths[i].hi, u.hi);
  return fast_two_sum(sum.hi, sum.lo + kAtanEighths[i].lo + u.lo + u.hi * w * series_at(kAtanTail, w));
}

// cos and sin of quadrant pi/2 + r from those of r: swapped on odd quadrants and negated by the
// quadrant's signs, picked by index rather than by branches.
template <class Out, class Real>
Out turned(Real c, Real s, unsigned quadrant) {
  const std::array<Real, 2> both{c, s};
  const unsigned odd = quadrant & 1;
  constexpr std::array<double, 2> kSign{1.0, -1.0};
  return {both[odd] * kSign[((quadrant + 1) >> 1) & 1], both[odd ^ 1] * kSign[(quadrant >> 1) & 1]};
}

// |angle| <= 2^20 by parts, beyond by the bits of 2/pi.
Reduced reduce(double angle) { return std::abs(angle) < 0x1p20 ? reduce_near(angle) : reduce_far(angle); }

constexpr ExtendedCosSin kNaN{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};

}  // namespace

CosSin cos_sin(double angle) {
  const double magnitude = std::abs(angle);
  if (magnitude < 0x1p-27) return {1.0, angle};  // 1 - angle^2/2 rounds to 1; sin keeps the sign of 0
  if (!finite(angle)) return {kNaN.c.hi, kNaN.s.hi};
  const Reduced x = reduce(angle);
  const CosSin k = kernel(x.r);
  return turned<CosSin>(k.c, k.s, x.quadrant);
}

ExtendedCosSin cos_sin_extended(double angle) {
  if (!finite(angle)) return kNaN;
  const Reduced x = reduce(angle);
  const ExtendedCosSin k = extended_kernel(fast_two_sum(x.r.hi, x.r.lo));
  return turned<ExtendedCosSin>(k.c, k.s, x.quadrant);
}

double arc_tangent(double y, double x) {
  if (std::isnan(x) || std::isnan(y)) return x + y;
  const double ax = std::abs(x), ay = std::abs(y);
  // The angle is base + sign atan(z) with z = min / max in [0, 1], base 0, pi/2 or pi.
  const bool steep = ay > ax, behind = std::signbit(x);
  const double small = steep ? ax : ay, big = steep ? ay : ax;
  DoubleDouble a{0.0, 0.0};
  if (std::isinf(small)) {
    a = kAtanEighths[8];
  } else if (big > 0) {
    a = atan_ratio(small, big);
  }
  DoubleDouble base{0.0, 0.0};
  double sign = 1;
  if (steep) {
    base = kHalfPi;
    sign = behind ? 1 : -1;
  } else if (behind) {
    base = kExtendedPi;
    sign = -1;
  }
  const DoubleDouble sum = two_sum(base.hi, sign * a.hi);
  return std::copysign(sum.hi + (sum.lo + (base.lo + sign * a.lo)), y);
}

DoubleDouble arc_tangent_extended(const DoubleDouble& y, const DoubleDouble& x) {
  const double t = arc_tangent(y.hi, x.hi);
  const ExtendedCosSin r = cos_sin_extended(t);
  // (x, y) turned back by t lies within an ulp's angle of the x axis, where atan z is z to 2^-150.
  return DoubleDouble(t) + (y * r.c - x * r.s) / (x * r.c + y * r.s);
}

double hypotenuse(double x, double y) {
  double big = std::abs(x), small = std::abs(y);
  if (std::isinf(big) || std::isinf(small)) return std::numeric_limits<double>::infinity();
  if (std::isnan(big) || std::isnan(small)) return x + y;
  if (small > big) std::swap(small, big);
  if (small <= big * 0x1p-27) return big;  // big sqrt(1 + t^2), t <= 2^-27, rounds to big
  // Within 2^27 of each other: one power of 2 keeps both squares and their errors in range.
  const double scale = big > 0x1p500 ? 0x1p-600 : small < 0x1p-500 ? 0x1p600 : 1.0;
  big *= scale;
  small *= scale;
  const DoubleDouble b2 = two_product(big, big), s2 = two_product(small, small);
  const DoubleDouble sum = two_sum(b2.hi, s2.hi);
  const double root = std::sqrt(sum.hi);
  const DoubleDouble r2 = two_product(root, root);
  const double correction = ((sum.hi - r2.hi) - r2.lo + (sum.lo + b2.lo + s2.lo)) / (2 * root);
  return (root + correction) / scale;
}

}  // namespace collide2d::detail
