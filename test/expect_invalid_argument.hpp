#pragma once
// EXPECT_INVALID_ARGUMENT(call, needle, ...): `call` throws std::invalid_argument whose what()
// contains every needle. Every core function rejects bad input with an error naming the
// parameter, the value and the limit (sphere_sim prints it and exits 4), so a bad-input test
// checks the words, not only the type: a message that lost the parameter's name is a regression
// although the exception still flies. Failures are non-fatal, at the caller's line, and accept
// `<< context` like any EXPECT_*.

#include <gtest/gtest.h>

#include <exception>
#include <initializer_list>
#include <stdexcept>
#include <string_view>

namespace spherical_robots::test_support {

/// Success iff `call()` throws std::invalid_argument whose what() contains every one of
/// `needles`; otherwise the failure says what was thrown (and its what()) or that nothing was.
template <typename Call>
::testing::AssertionResult throwsInvalidArgumentNaming(Call&& call,
                                                       std::initializer_list<std::string_view> needles) {
  try {
    call();
  } catch (const std::invalid_argument& error) {
    const std::string_view what = error.what();
    for (const std::string_view needle : needles) {
      if (what.find(needle) == std::string_view::npos) {
        return ::testing::AssertionFailure()
               << "std::invalid_argument \"" << what << "\" does not contain \"" << needle << "\"";
      }
    }
    return ::testing::AssertionSuccess();
  } catch (const std::exception& error) {
    return ::testing::AssertionFailure()
           << "threw an exception other than std::invalid_argument: \"" << error.what() << "\"";
  } catch (...) {
    return ::testing::AssertionFailure() << "threw something that is not a std::exception";
  }
  ::testing::AssertionResult result = ::testing::AssertionFailure();
  result << "no exception; expected std::invalid_argument containing";
  for (const std::string_view needle : needles) result << " \"" << needle << "\"";
  return result;
}

}  // namespace spherical_robots::test_support

// `(void)(call)` makes `call` an expression: `Type(name);` alone would declare a variable.
#define EXPECT_INVALID_ARGUMENT(call, ...)                                  \
  EXPECT_TRUE(::spherical_robots::test_support::throwsInvalidArgumentNaming( \
      [&] { (void)(call); }, {__VA_ARGS__}))
