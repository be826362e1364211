#pragma once
// sin and cos of one argument together, inline, with one range reduction: the batch runs' hot
// loops (the terrain closed loop's surface, heading and path at every RK stage, the rotor
// planner's curve and heading at every stage of its integrations) take both of the same angle,
// where two glibc calls reduce the argument twice and cannot be inlined. No ROS.
//
// The range reduction (Cody-Waite with pi/2 in three parts) and the two kernel polynomials on
// [-pi/4, pi/4] are fdlibm's (e_rem_pio2.c "medium" case, k_sin.c, k_cos.c), in musl's form:
// ====================================================
// Copyright (C) 1993 by Sun Microsystems, Inc. All rights reserved.
//
// Developed at SunPro, a Sun Microsystems, Inc. business.
// Permission to use, copy, modify, and distribute this
// software is freely granted, provided that this notice
// is preserved.
// ====================================================

#include <cmath>
#include <cstdint>
#include <cstring>

namespace spherical_robots {

/// sin x and cos x of one x.
struct SinCos {
  double sin = 0.0;
  double cos = 1.0;
};

namespace sin_cos_detail {

// fdlibm's coefficients, as hexadecimal literals of its bit patterns.
constexpr double kS1 = -0x1.5555555555549p-3;
constexpr double kS2 = 0x1.111111110f8a6p-7;
constexpr double kS3 = -0x1.a01a019c161d5p-13;
constexpr double kS4 = 0x1.71de357b1fe7dp-19;
constexpr double kS5 = -0x1.ae5e68a2b9cebp-26;
constexpr double kS6 = 0x1.5d93a5acfd57cp-33;
constexpr double kC1 = 0x1.555555555554cp-5;
constexpr double kC2 = -0x1.6c16c16c15177p-10;
constexpr double kC3 = 0x1.a01a019cb159p-16;
constexpr double kC4 = -0x1.27e4f809c52adp-22;
constexpr double kC5 = 0x1.1ee9ebdb4b1c4p-29;
constexpr double kC6 = -0x1.8fae9be8838d4p-37;
constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
// pi/2 = kPio2_1 + kPio2_2 + kPio2_3 + ..., each part with 33 significant bits so that n times it
// is exact for |n| < 2^20; kPio2_*t is the rest after each part.
constexpr double kPio2_1 = 0x1.921fb544p+0;
constexpr double kPio2_1t = 0x1.0b4611a626331p-34;
constexpr double kPio2_2 = 0x1.0b4611a6p-34;
constexpr double kPio2_2t = 0x1.3198a2e037073p-69;
constexpr double kPio2_3 = 0x1.3198a2ep-69;
constexpr double kPio2_3t = 0x1.b839a252049c1p-104;
/// The reduction is exact below 2^20 pi/2; beyond it (and for inf, NaN) std::sin/std::cos.
constexpr double kMaxReduced = 0x1p20 * 0x1.921fb54442d18p+0;

inline int biasedExponent(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return static_cast<int>((bits >> 52) & 0x7ff);
}

/// sin(x + y) for |x + y| <= ~pi/4, y the tail of the reduced argument (k_sin.c).
inline double kernelSin(double x, double y) {
  const double z = x * x;
  const double w = z * z;
  const double r = kS2 + z * (kS3 + z * kS4) + z * w * (kS5 + z * kS6);
  const double v = z * x;
  return x - ((z * (0.5 * y - v * r) - y) - v * kS1);
}

/// cos(x + y) for |x + y| <= ~pi/4 (k_cos.c).
inline double kernelCos(double x, double y) {
  const double z = x * x;
  const double w = z * z;
  const double r = z * (kC1 + z * (kC2 + z * kC3)) + w * w * (kC4 + z * (kC5 + z * kC6));
  const double hz = 0.5 * z;
  const double one_minus_hz = 1.0 - hz;
  return one_minus_hz + (((1.0 - one_minus_hz) - hz) + (z * r - x * y));
}

}  // namespace sin_cos_detail

/// sin x and cos x [-] of x [rad], each within 1 ulp of the exact value (fdlibm's bound;
/// test_sin_cos measures it against long double sinl/cosl) for |x| < 2^20 pi/2 (1.6e6 rad);
/// larger and non-finite x are passed to std::sin and std::cos. The result can differ from
/// glibc's in the last bit.
inline SinCos sinCos(double x) {
  using namespace sin_cos_detail;
  const double magnitude = std::abs(x);
  if (!(magnitude < kMaxReduced)) return {std::sin(x), std::cos(x)};
  double head = x;
  double tail = 0.0;
  int quadrant = 0;
  if (magnitude > 0x1.921fb54442d18p-1) {  // pi/4
    // n = x / (pi/2) rounded (half away from zero, by truncation: a conversion that neither the
    // rounding mode nor -ffast-math can change; any n leaving |r| <= pi/4 + 1 ulp will do).
    const int n = static_cast<int>(x * kTwoOverPi + std::copysign(0.5, x));
    const double fn = n;
    double r = x - fn * kPio2_1;
    double w = fn * kPio2_1t;
    head = r - w;
    // Cancellation (x near a multiple of pi/2) leaves fewer bits: subtract the next part of pi/2.
    const int exponent = biasedExponent(x);
    if (exponent - biasedExponent(head) > 16) {
      double t = r;
      w = fn * kPio2_2;
      r = t - w;
      w = fn * kPio2_2t - ((t - r) - w);
      head = r - w;
      if (exponent - biasedExponent(head) > 49) {
        t = r;
        w = fn * kPio2_3;
        r = t - w;
        w = fn * kPio2_3t - ((t - r) - w);
        head = r - w;
      }
    }
    tail = (r - head) - w;
    quadrant = n & 3;
  }
  const double s = kernelSin(head, tail);
  const double c = kernelCos(head, tail);
  switch (quadrant) {
    case 0:
      return {s, c};
    case 1:
      return {c, -s};
    case 2:
      return {-s, -c};
    default:
      return {-c, s};
  }
}

}  // namespace spherical_robots
