// EXPECT_INVALID_ARGUMENT can fail: it reports a call that throws nothing, a message without a
// needle, and any other exception, each once, at the caller and with the caller's context.

#include "expect_invalid_argument.hpp"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace {

void rejectRadius(double radius) {
  if (!(radius > 0.0)) {
    throw std::invalid_argument("radius must be > 0 m, got " + std::to_string(radius));
  }
}

TEST(ExpectInvalidArgument, PassesWhenEveryNeedleIsInTheMessage) {
  EXPECT_INVALID_ARGUMENT(rejectRadius(-1.0), "radius");
  EXPECT_INVALID_ARGUMENT(rejectRadius(-1.0), "radius", "> 0 m", "-1.0");
  const std::string needle = "got";  // a temporary std::string is a needle too
  EXPECT_INVALID_ARGUMENT(rejectRadius(0.0), needle + " 0");
}

TEST(ExpectInvalidArgument, FailsWhenNothingIsThrown) {
  EXPECT_NONFATAL_FAILURE(EXPECT_INVALID_ARGUMENT(rejectRadius(1.0), "radius"),
                          "no exception; expected std::invalid_argument containing \"radius\"");
}

TEST(ExpectInvalidArgument, FailsNamingTheMissingNeedleAndShowingTheMessage) {
  EXPECT_NONFATAL_FAILURE(
      EXPECT_INVALID_ARGUMENT(rejectRadius(-1.0), "radius", "diameter"),
      "std::invalid_argument \"radius must be > 0 m, got -1.000000\" does not contain \"diameter\"");
  EXPECT_NONFATAL_FAILURE(EXPECT_INVALID_ARGUMENT(rejectRadius(-1.0), "Radius"), "\"Radius\"");
}

TEST(ExpectInvalidArgument, FailsOnAnotherExceptionType) {
  EXPECT_NONFATAL_FAILURE(EXPECT_INVALID_ARGUMENT(throw std::runtime_error("radius"), "radius"),
                          "other than std::invalid_argument: \"radius\"");
  EXPECT_NONFATAL_FAILURE(EXPECT_INVALID_ARGUMENT(throw 42, "radius"), "not a std::exception");
}

TEST(ExpectInvalidArgument, CallsOnceAndCarriesTheCallersContext) {
  int calls = 0;
  EXPECT_INVALID_ARGUMENT((++calls, rejectRadius(0.0)), "radius");
  EXPECT_EQ(calls, 1);
  EXPECT_NONFATAL_FAILURE(EXPECT_INVALID_ARGUMENT(rejectRadius(2.0), "radius") << "case 7",
                          "case 7");
  EXPECT_NONFATAL_FAILURE(EXPECT_INVALID_ARGUMENT(rejectRadius(2.0), "radius"),
                          "rejectRadius(2.0)");
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
