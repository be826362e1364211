// sinCos (core/sin_cos.hpp) against long double sinl/cosl (64-bit significands on x86-64: 11 bits
// more than a double, so their rounding error is ~1/2000 of the double ulp measured here), and
// against std::sin/std::cos where it hands the argument over. The stated bound is 1 ulp.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "spherical_robots/core/sin_cos.hpp"

namespace {

using spherical_robots::SinCos;
using spherical_robots::sinCos;

constexpr long double kHalfPi = 1.570796326794896619231321691639751442L;

/// |got - exact| in units of the last place of exact rounded to a double.
double ulpError(double got, long double exact) {
  const double rounded = static_cast<double>(exact);
  const double magnitude = std::abs(rounded);
  const double ulp = magnitude == 0.0 ? std::numeric_limits<double>::denorm_min()
                                      : std::nextafter(magnitude, INFINITY) - magnitude;
  return static_cast<double>(std::abs(static_cast<long double>(got) - exact) / ulp);
}

struct WorstError {
  double sin = 0.0;
  double cos = 0.0;
  void add(double x) {
    const SinCos result = sinCos(x);
    sin = std::max(sin, ulpError(result.sin, sinl(static_cast<long double>(x))));
    cos = std::max(cos, ulpError(result.cos, cosl(static_cast<long double>(x))));
  }
};

TEST(SinCos, WithinOneUlpOverTheReducedRange) {
  std::mt19937_64 generator(13);
  WorstError worst;
  // From the kernel's own interval to the largest reduced argument, 2^20 pi/2 = 1.6e6 rad.
  for (const double range : {0.785, 3.2, 20.0, 1e3, 1e5, 1.6e6}) {
    std::uniform_real_distribution<double> uniform(-range, range);
    for (int i = 0; i < 200000; ++i) worst.add(uniform(generator));
  }
  EXPECT_LT(worst.sin, 1.0);
  EXPECT_LT(worst.cos, 1.0);
  std::printf("worst error over 1.2e6 arguments: sin %.3f ulp, cos %.3f ulp\n", worst.sin,
              worst.cos);
}

// Next to a multiple of pi/2 one of the two is tiny, so its ulp is too, and the reduction must
// keep the bits that cancel (its second and third parts of pi/2).
TEST(SinCos, WithinOneUlpNextToMultiplesOfHalfPi) {
  WorstError worst;
  for (long k = -600000; k <= 600000; k += 997) {
    const double nearest = static_cast<double>(k * kHalfPi);
    double below = nearest, above = nearest;
    for (int i = 0; i < 4; ++i) {
      worst.add(below);
      worst.add(above);
      below = std::nextafter(below, -INFINITY);
      above = std::nextafter(above, INFINITY);
    }
  }
  EXPECT_LT(worst.sin, 1.0);
  EXPECT_LT(worst.cos, 1.0);
}

TEST(SinCos, QuadrantBoundariesAndSymmetry) {
  for (int k = -8; k <= 8; ++k) {
    for (const double offset : {-1e-9, 0.0, 1e-9, 0.3, -0.3}) {
      const double x = k * static_cast<double>(kHalfPi / 2) + offset;  // multiples of pi/4
      const SinCos result = sinCos(x);
      EXPECT_LT(ulpError(result.sin, sinl(static_cast<long double>(x))), 1.0) << "x = " << x;
      EXPECT_LT(ulpError(result.cos, cosl(static_cast<long double>(x))), 1.0) << "x = " << x;
      const SinCos mirrored = sinCos(-x);
      EXPECT_EQ(mirrored.sin, -result.sin) << "x = " << x;
      EXPECT_EQ(mirrored.cos, result.cos) << "x = " << x;
    }
  }
}

TEST(SinCos, SmallArgumentsAndSignedZero) {
  for (const double x : {1e-300, 1e-20, 1e-9, 2.0 * std::numeric_limits<double>::denorm_min()}) {
    EXPECT_EQ(sinCos(x).sin, x);
    EXPECT_EQ(sinCos(x).cos, 1.0);
  }
  EXPECT_EQ(sinCos(0.0).sin, 0.0);
  EXPECT_FALSE(std::signbit(sinCos(0.0).sin));
  EXPECT_TRUE(std::signbit(sinCos(-0.0).sin));
  EXPECT_EQ(sinCos(-0.0).cos, 1.0);
}

TEST(SinCos, LargeAndNonFiniteArgumentsAreStdSinAndCos) {
  for (const double x : {1.7e6, -3e9, 1e300, std::numeric_limits<double>::max()}) {
    EXPECT_EQ(sinCos(x).sin, std::sin(x)) << "x = " << x;
    EXPECT_EQ(sinCos(x).cos, std::cos(x)) << "x = " << x;
  }
  for (const double x : {std::numeric_limits<double>::infinity(),
                         -std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_TRUE(std::isnan(sinCos(x).sin)) << "x = " << x;
    EXPECT_TRUE(std::isnan(sinCos(x).cos)) << "x = " << x;
  }
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
