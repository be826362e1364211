#pragma once
// sin and cos of one argument together, inline, with one range reduction: the batch runs' hot
// loops (the terrain closed loop's surface, heading and path at every RK stage, the rotor
// planner's curve and heading at every stage of its integrations) take both of the same angle,
// where two glibc calls reduce the argument twice and cannot be inlined. No ROS.
//
// x = k pi/64 + r, |r| <= pi/128: sin and cos of k pi/64 from a table of the 128 sines of a
// whole turn (cos k pi/64 = sin (k + 32) pi/64, so no branch on the quadrant), those of r from
// Taylor polynomials of degree 7 and 6, and the angle-sum formulas. About 50 instructions for
// both (70 with a branch on the quadrant), where fdlibm's reduction to pi/4 and its two kernels
// of degree 13 and 14 took about 105; two arguments at once (the terrain's x and y) share one
// SSE2 vector, which saves 6-17 instructions of the 100 of two calls. The terrain closed loop
// evaluates 4.5 of these per RK stage.

#include <array>
#include <cmath>
#include <limits>

namespace spherical_robots {

/// sin x and cos x of one x.
struct SinCos {
  double sin = 0.0;
  double cos = 1.0;
};

namespace sin_cos_detail {

/// sin(j pi/64), j = 0..32, correctly rounded; cos(j pi/64) = sin((32 - j) pi/64).
inline constexpr double kSines[33] = {
    0x0.0p+0, 0x1.91f65f10dd814p-5, 0x1.917a6bc29b42cp-4,
    0x1.2c8106e8e613ap-3, 0x1.8f8b83c69a60bp-3, 0x1.f19f97b215f1bp-3,
    0x1.294062ed59f06p-2, 0x1.58f9a75ab1fddp-2, 0x1.87de2a6aea963p-2,
    0x1.b5d1009e15cc0p-2, 0x1.e2b5d3806f63bp-2, 0x1.073879922ffeep-1,
    0x1.1c73b39ae68c8p-1, 0x1.30ff7fce17035p-1, 0x1.44cf325091dd6p-1,
    0x1.57d69348ceca0p-1, 0x1.6a09e667f3bcdp-1, 0x1.7b5df226aafafp-1,
    0x1.8bc806b151741p-1, 0x1.9b3e047f38741p-1, 0x1.a9b66290ea1a3p-1,
    0x1.b728345196e3ep-1, 0x1.c38b2f180bdb1p-1, 0x1.ced7af43cc773p-1,
    0x1.d906bcf328d46p-1, 0x1.e212104f686e5p-1, 0x1.e9f4156c62ddap-1,
    0x1.f0a7efb9230d7p-1, 0x1.f6297cff75cb0p-1, 0x1.fa7557f08a517p-1,
    0x1.fd88da3d12526p-1, 0x1.ff621e3796d7ep-1, 0x1.0000000000000p+0,
};
/// sin(j pi/64) for the whole turn, j = 0..127, from kSines by symmetry (exact: only signs and
/// order change). Indexed by k, it gives sin and cos of k pi/64 in every quadrant without a
/// branch on the quadrant: cos(k pi/64) = sin((k + 32) pi/64).
struct Circle {
  double sines[128];
};
constexpr Circle makeCircle() {
  Circle circle{};
  for (int j = 0; j < 128; ++j) {
    const int in_half = j % 64;
    const double magnitude = kSines[in_half <= 32 ? in_half : 64 - in_half];
    circle.sines[j] = j < 64 ? magnitude : -magnitude;
  }
  return circle;
}
inline constexpr Circle kCircle = makeCircle();

constexpr double kSixtyFourOverPi = 0x1.45f306dc9c883p+4;
// pi/64 = kPiOver64Head + kPiOver64Tail + 1.1e-28: the head has 33 significant bits, so that
// k times it is exact for |k| < 2^20 and x - k kPiOver64Head is exact (Sterbenz).
constexpr double kPiOver64Head = 0x1.921fb544p-5;
constexpr double kPiOver64Tail = 0x1.0b4611a626331p-39;
/// Beyond 2^20 pi/64 (5.1e4 rad), and for inf and NaN, std::sin and std::cos.
constexpr double kMaxReduced = 0x1p20 * 0x1.921fb54442d18p-5;

// Two doubles in one SSE2 register (GCC's and Clang's vector extensions: lane-wise operators,
// the same IEEE operations as on one double, so each lane's result is the scalar one to the bit).
using Double2 = double __attribute__((vector_size(16)));
using Bits2 = long long __attribute__((vector_size(16)));
using Int2 = int __attribute__((vector_size(8)));

// The three steps of the kernel that differ between one argument and two.
inline int nearestIndex(double y) { return static_cast<int>(y); }
inline Int2 nearestIndex(Double2 y) { return __builtin_convertvector(y, Int2); }
inline double toReal(int k) { return k; }
inline Double2 toReal(Int2 k) { return __builtin_convertvector(k, Double2); }
inline double sineAt(int k) { return kCircle.sines[k & 127]; }
inline Double2 sineAt(Int2 k) {
  return Double2{kCircle.sines[k[0] & 127], kCircle.sines[k[1] & 127]};
}

/// sin and cos of magnitude in [0, kMaxReduced), for Real = double or Double2.
/// magnitude = k pi/64 + r, |r| <= pi/128: sin and cos of k pi/64 from kCircle, those of r from
/// Taylor polynomials of degree 7 and 6, and the angle-sum formulas.
template <typename Real>
inline void sinCosOfMagnitude(Real magnitude, Real& sin, Real& cos) {
  // k = magnitude / (pi/64) rounded, by truncation: a conversion that neither the rounding mode
  // nor -ffast-math can change (any k leaving |r| <= pi/128 + 1 ulp will do).
  const auto k = nearestIndex(magnitude * kSixtyFourOverPi + 0.5);
  const Real fk = toReal(k);
  const Real r = (magnitude - fk * kPiOver64Head) - fk * kPiOver64Tail;
  // Taylor to r^7 and r^6: for |r| <= pi/128 the next terms, r^9/9! and r^8/8!, are below
  // 4e-19 of sin r and 4e-18 of cos r.
  const Real z = r * r;
  const Real sin_r = r + r * z * (-1.0 / 6.0 + z * (1.0 / 120.0 - z * (1.0 / 5040.0)));
  const Real cos_r_minus_1 = z * (-0.5 + z * (1.0 / 24.0 - z * (1.0 / 720.0)));
  const Real sin_k = sineAt(k);
  const Real cos_k = sineAt(k + 32);
  // The small corrections added last.
  sin = sin_k + (sin_k * cos_r_minus_1 + cos_k * sin_r);
  cos = cos_k + (cos_k * cos_r_minus_1 - sin_k * sin_r);
}

}  // namespace sin_cos_detail

/// sin x and cos x [-] of x [rad] for |x| < 2^20 pi/64 (5.1e4 rad); larger and non-finite x are
/// passed to std::sin and std::cos. Within 2.5 ulp of the exact value (2.0 measured; glibc's and
/// fdlibm's are within 1) plus 1e-26 |x|, the reduction's error (86 bits of pi/64), which shows
/// only where the value is tiny, next to multiples of pi/2; sin is odd and cos even to the bit.
/// test_sin_cos measures it against long double sinl/cosl.
inline SinCos sinCos(double x) {
  using namespace sin_cos_detail;
  const double magnitude = std::abs(x);
  if (!(magnitude < kMaxReduced)) return {std::sin(x), std::cos(x)};
  // Of |x|, so that sin is odd and cos even to the bit; sin takes x's sign at the end.
  double sin = 0.0;
  double cos = 1.0;
  sinCosOfMagnitude(magnitude, sin, cos);
  return {std::copysign(1.0, x) * sin, cos};
}

/// sinCos(x) and sinCos(y), equal to them to the bit, computed together in the two lanes of one
/// vector, for where both are needed (the terrain's two axes): 6-17 instructions fewer than two
/// calls.
inline std::array<SinCos, 2> sinCos(double x, double y) {
  using namespace sin_cos_detail;
  if (!(std::abs(x) < kMaxReduced && std::abs(y) < kMaxReduced)) return {sinCos(x), sinCos(y)};
  const Double2 xy = {x, y};
  const Bits2 sign = reinterpret_cast<Bits2>(xy) & std::numeric_limits<long long>::min();
  const Bits2 magnitude_bits = reinterpret_cast<Bits2>(xy) ^ sign;
  Double2 sin;
  Double2 cos;
  sinCosOfMagnitude(reinterpret_cast<Double2>(magnitude_bits), sin, cos);
  // Flipping the sign bit is the multiplication by copysign(1, x) of the scalar form.
  const Bits2 signed_sin = reinterpret_cast<Bits2>(sin) ^ sign;
  const Double2 result = reinterpret_cast<Double2>(signed_sin);
  return {SinCos{result[0], cos[0]}, SinCos{result[1], cos[1]}};
}

}  // namespace spherical_robots
