#pragma once
// sin and cos of one argument together, inline, with one range reduction: the batch runs' hot
// loops (the terrain closed loop's surface, heading and path at every RK stage, the rotor
// planner's curve and heading at every stage of its integrations) take both of the same angle,
// where two glibc calls reduce the argument twice and cannot be inlined. No ROS.
//
// x = k pi/64 + r, |r| <= pi/128: sin and cos of k pi/64 from a table of the 33 sines of a
// quarter turn (the cosines by symmetry, the other quarters by swapping the two and their
// signs), those of r from Taylor polynomials of degree 7 and 6, and the angle-sum formulas.
// About 70 instructions for both, where fdlibm's reduction to pi/4 and its two kernels of degree
// 13 and 14 took about 105; the terrain closed loop evaluates 4.5 of these per RK stage, at some
// 1,200 instructions a stage.

#include <cmath>

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
constexpr double kSixtyFourOverPi = 0x1.45f306dc9c883p+4;
// pi/64 = kPiOver64Head + kPiOver64Tail + 1.1e-28: the head has 33 significant bits, so that
// k times it is exact for |k| < 2^20 and x - k kPiOver64Head is exact (Sterbenz).
constexpr double kPiOver64Head = 0x1.921fb544p-5;
constexpr double kPiOver64Tail = 0x1.0b4611a626331p-39;
/// Beyond 2^20 pi/64 (5.1e4 rad), and for inf and NaN, std::sin and std::cos.
constexpr double kMaxReduced = 0x1p20 * 0x1.921fb54442d18p-5;

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
  // k = |x| / (pi/64) rounded, by truncation: a conversion that neither the rounding mode nor
  // -ffast-math can change (any k leaving |r| <= pi/128 + 1 ulp will do).
  const int k = static_cast<int>(magnitude * kSixtyFourOverPi + 0.5);
  const double fk = k;
  const double r = (magnitude - fk * kPiOver64Head) - fk * kPiOver64Tail;
  // Taylor to r^7 and r^6: for |r| <= pi/128 the next terms, r^9/9! and r^8/8!, are below
  // 4e-19 of sin r and 4e-18 of cos r.
  const double z = r * r;
  const double sin_r = r + r * z * (-1.0 / 6.0 + z * (1.0 / 120.0 - z * (1.0 / 5040.0)));
  const double cos_r_minus_1 = z * (-0.5 + z * (1.0 / 24.0 - z * (1.0 / 720.0)));
  // k = 32 quadrant + j, j in [0, 32).
  const int j = k & 31;
  const double sin_j = kSines[j];
  const double cos_j = kSines[32 - j];
  // sin and cos of j pi/64 + r, the small corrections added last.
  const double s = sin_j + (sin_j * cos_r_minus_1 + cos_j * sin_r);
  const double c = cos_j + (cos_j * cos_r_minus_1 - sin_j * sin_r);
  const double sign = std::copysign(1.0, x);
  switch ((k >> 5) & 3) {
    case 0:
      return {sign * s, c};
    case 1:
      return {sign * c, -s};
    case 2:
      return {-sign * s, -c};
    default:
      return {-sign * c, s};
  }
}

}  // namespace spherical_robots
