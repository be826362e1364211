// sinCos (core/sin_cos.hpp) against long double sinl/cosl (64-bit significands on x86-64: 11 bits
// more than a double, so their rounding error is ~1/2000 of the double ulp measured here), and
// against std::sin/std::cos where it hands the argument over. The stated bound is 2.5 ulp of the
// exact value plus 1e-26 |x|, the reduction's error (86 bits of pi/64), which shows only where
// the value is tiny: next to multiples of pi/2.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "spherical_robots/core/sin_cos.hpp"

namespace {

using spherical_robots::SinCos;
using spherical_robots::sinCos;

constexpr long double kHalfPi = 1.570796326794896619231321691639751442L;
constexpr double kUlps = 2.5;
constexpr double kReductionErrorPerRadian = 1e-26;

/// The last place of exact rounded to a double.
double ulpOf(long double exact) {
  const double magnitude = std::abs(static_cast<double>(exact));
  return magnitude == 0.0 ? std::numeric_limits<double>::denorm_min()
                          : std::nextafter(magnitude, INFINITY) - magnitude;
}

/// |got - exact| in units of the last place of exact.
double ulpError(double got, long double exact) {
  return static_cast<double>(std::abs(static_cast<long double>(got) - exact) / ulpOf(exact));
}

/// |got - exact| as a fraction of the stated bound at x (below 1: within it).
double boundFraction(double got, long double exact, double x) {
  return static_cast<double>(std::abs(static_cast<long double>(got) - exact) /
                             (kUlps * ulpOf(exact) + kReductionErrorPerRadian * std::abs(x)));
}

struct WorstError {
  double sin = 0.0;  ///< [ulp]
  double cos = 0.0;
  double bound = 0.0;  ///< the largest boundFraction of either
  void add(double x) {
    const SinCos result = sinCos(x);
    const long double exact_sin = sinl(static_cast<long double>(x));
    const long double exact_cos = cosl(static_cast<long double>(x));
    sin = std::max(sin, ulpError(result.sin, exact_sin));
    cos = std::max(cos, ulpError(result.cos, exact_cos));
    bound = std::max({bound, boundFraction(result.sin, exact_sin, x),
                      boundFraction(result.cos, exact_cos, x)});
  }
};

TEST(SinCos, WithinTheBoundOverTheReducedRange) {
  std::mt19937_64 generator(13);
  WorstError worst;
  // From a quarter turn to the largest reduced argument, 2^20 pi/64 = 5.1e4 rad.
  for (const double range : {0.785, 3.2, 20.0, 1e3, 5.1e4}) {
    std::uniform_real_distribution<double> uniform(-range, range);
    for (int i = 0; i < 200000; ++i) worst.add(uniform(generator));
  }
  EXPECT_LT(worst.sin, kUlps);
  EXPECT_LT(worst.cos, kUlps);
  EXPECT_LT(worst.bound, 1.0);
  std::printf("worst error over 1e6 arguments: sin %.3f ulp, cos %.3f ulp\n", worst.sin,
              worst.cos);
}

// Next to a multiple of pi/2 one of the two is tiny, so its ulp is too: there the reduction's
// absolute error, up to 1e-26 |x|, is what is left.
TEST(SinCos, WithinTheBoundNextToMultiplesOfHalfPi) {
  WorstError worst;
  for (long k = -32000; k <= 32000; k += 7) {
    const double nearest = static_cast<double>(k * kHalfPi);
    double below = nearest, above = nearest;
    for (int i = 0; i < 4; ++i) {
      worst.add(below);
      worst.add(above);
      below = std::nextafter(below, -INFINITY);
      above = std::nextafter(above, INFINITY);
    }
    for (const double offset : {1e-12, 1e-9, 1e-7, 1e-5}) {
      worst.add(nearest + offset);
      worst.add(nearest - offset);
    }
  }
  EXPECT_LT(worst.bound, 1.0);
}

TEST(SinCos, QuadrantBoundariesAndSymmetry) {
  for (int k = -8; k <= 8; ++k) {
    for (const double offset : {-1e-9, 0.0, 1e-9, 0.3, -0.3}) {
      const double x = k * static_cast<double>(kHalfPi / 2) + offset;  // multiples of pi/4
      const SinCos result = sinCos(x);
      EXPECT_LT(boundFraction(result.sin, sinl(static_cast<long double>(x)), x), 1.0)
          << "x = " << x;
      EXPECT_LT(boundFraction(result.cos, cosl(static_cast<long double>(x)), x), 1.0)
          << "x = " << x;
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
  for (const double x : {5.2e4, -1.7e6, 3e9, 1e300, std::numeric_limits<double>::max()}) {
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

// The two-argument form is the scalar one in two lanes: the same to the bit, handed-over
// arguments and signed zeros included.
TEST(SinCos, TwoArgumentsAreTheScalarResultsToTheBit) {
  const auto expectSame = [](const SinCos& got, double x) {
    const SinCos scalar = sinCos(x);
    EXPECT_TRUE(std::memcmp(&got.sin, &scalar.sin, sizeof(double)) == 0) << "x = " << x;
    EXPECT_TRUE(std::memcmp(&got.cos, &scalar.cos, sizeof(double)) == 0) << "x = " << x;
  };
  std::mt19937_64 generator(59);
  std::uniform_real_distribution<double> uniform(-5.1e4, 5.1e4);
  std::vector<double> arguments = {0.0, -0.0, 1e-300, -1e-20, 5.2e4, -3e9,
                                   std::numeric_limits<double>::infinity(),
                                   std::numeric_limits<double>::quiet_NaN()};
  for (int i = 0; i < 100000; ++i) arguments.push_back(uniform(generator) / (i % 2 ? 1.0 : 4e3));
  for (std::size_t i = 0; i + 1 < arguments.size(); ++i) {
    const auto [first, second] = sinCos(arguments[i], arguments[i + 1]);
    expectSame(first, arguments[i]);
    expectSame(second, arguments[i + 1]);
  }
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
