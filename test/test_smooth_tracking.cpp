// The smooth law (docs/conventions.md) on the 16 batch cases (4 robots x 2 paths x 2 contact
// models; the shipped config/terrain.yaml, R = 0.2 m, RK4 with dt = 5 ms, 200 s), against issue
// 13's criteria, which come from the hardware, not from this code:
//  * after 40 s a commanded rate changes sign (both neighbours above 0.01 rad/s in magnitude) on
//    fewer than 1 % of the steps; on the diamond the 5 s after each vertex are left out and
//    reported on their own;
//  * after 40 s no commanded rate changes by more than the stacks' actuator acceleration limit
//    allows in one step, 50 rad/s^2 x 5 ms = 0.25 rad/s;
//  * the RS tilt does not sit on its +-pi/3 limit on the circle;
//  * on the circle mean |e_t| after 40 s <= 5 mm and max <= 20 mm, every type, both models;
//  * the first |e_t| < 0.1 m comes no later than 1.2 x the paper's law's.
// The commands are logged at every 5 ms step as a sampled controller would send them: the law
// evaluated at the step's start. Every case also prints a `[ table ]` line for both laws
// (docs/results.md, "Pursuit laws: paper against smooth").

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "spherical_robots/config/terrain_config.hpp"
#include "spherical_robots/terrain/pursuit_law.hpp"
#include "spherical_robots/terrain/terrain_kinematics.hpp"
#include "spherical_robots/terrain/terrain_simulation.hpp"
#include "shipped_config.hpp"
#include "terrain_test_support.hpp"

namespace {

using namespace spherical_robots::terrain;  // NOLINT: test file
namespace config = spherical_robots::config;

constexpr double kRadius = 0.2;  // urdf/terrain_robot.urdf
constexpr double kDt = 0.005;
constexpr int kSteps = 40000;  // 200 s
constexpr double kSettle = 40.0;
constexpr double kConverged = 0.1;          // [m]
constexpr double kSignFloor = 0.01;         // [rad/s]: both neighbours above it
constexpr double kMaxSignChanges = 0.01;    // fraction of the steps
constexpr double kMaxRateStep = 50.0 * kDt;  // [rad/s]: hardware acceleration limit x one step
constexpr double kCornerSpan = 5.0;         // [s] after each diamond vertex
constexpr double kCircleMean = 0.005;       // [m]
constexpr double kCircleMax = 0.020;        // [m]
constexpr double kTimeRatio = 1.2;          // against the paper's law

using spherical_robots::test_support::shippedTerrainConfig;

using Case = spherical_robots::test_support::BatchCase;

bool isDiamond(const Case& c) { return std::string(c.path) == "diamond"; }

/// One logged run: every step's time, |e_t|, commanded rates and RS tilt.
struct RunLog {
  std::vector<double> t, error, tilt;
  std::vector<std::array<double, 3>> commanded;
};

RunLog runLogged(const Case& c, PursuitLaw law, const TerrainState& start = {}) {
  const config::TerrainConfig cfg = shippedTerrainConfig();
  const auto surface = config::makeSurface(cfg.surface);
  const auto path = config::makePath(c.path, cfg);
  const TerrainKinematics kinematics(*surface, c.type, kRadius, c.model, cfg.tilt_limit);
  const auto controller = config::makePursuitController(law, c.type, cfg, kRadius);
  TerrainSimulation simulation(kinematics, *controller, *path, start);
  RunLog log;
  for (int i = 0;; ++i) {
    const TerrainSample s = simulation.sample();
    const DriveRates sent = keepActuated(
        c.type, controller->command(s.geometry, s.state.phi, s.error, s.desired.velocity));
    log.t.push_back(s.t);
    log.error.push_back(s.error.norm);
    log.tilt.push_back(s.state.phi);
    log.commanded.push_back({sent.roll_rate, sent.lateral_rate, sent.turn_rate});
    if (i == kSteps) break;
    simulation.step(kDt);
  }
  return log;
}

/// The figures the criteria speak of, over the steps after 40 s of one part of the run.
struct Figures {
  long steps = 0;
  long sign_changes = 0;  ///< steps on which some commanded rate changes sign
  long clipped = 0;       ///< steps on which some commanded rate changes by more than 0.25 rad/s
  double largest_step = 0.0;  ///< [rad/s]
  double largest_rate = 0.0;  ///< [rad/s]
};

struct Summary {
  Figures steady;   ///< circle: all steps after 40 s; diamond: outside the corners
  Figures corners;  ///< diamond: the 5 s after each vertex
  double first_converged = std::numeric_limits<double>::quiet_NaN();
  double mean_error = 0.0, max_error = 0.0;  ///< after 40 s
  long tilt_at_limit = 0;                    ///< steps after 40 s with |phi| at the limit
};

Summary summarise(const Case& c, const RunLog& log) {
  const config::TerrainConfig cfg = shippedTerrainConfig();
  const double edge_time = std::sqrt(2.0) * cfg.diamond_half_diagonal / cfg.diamond_speed;
  Summary s;
  long settled = 0;
  for (std::size_t i = 0; i < log.t.size(); ++i) {
    if (std::isnan(s.first_converged) && log.error[i] < kConverged) s.first_converged = log.t[i];
    if (log.t[i] < kSettle) continue;
    ++settled;
    s.mean_error += log.error[i];
    s.max_error = std::max(s.max_error, log.error[i]);
    if (std::abs(log.tilt[i]) >= cfg.tilt_limit - 1e-12) ++s.tilt_at_limit;
    const bool corner = isDiamond(c) && std::fmod(log.t[i], edge_time) < kCornerSpan;
    Figures& f = corner ? s.corners : s.steady;
    ++f.steps;
    bool sign_change = false, clipped = false;
    for (int k = 0; k < 3; ++k) {
      const double before = log.commanded[i - 1][k], now = log.commanded[i][k];
      sign_change |= before * now < 0.0 && std::abs(before) > kSignFloor && std::abs(now) > kSignFloor;
      clipped |= std::abs(now - before) > kMaxRateStep;
      f.largest_step = std::max(f.largest_step, std::abs(now - before));
      f.largest_rate = std::max(f.largest_rate, std::abs(now));
    }
    f.sign_changes += sign_change;
    f.clipped += clipped;
  }
  s.mean_error /= settled;
  return s;
}

void printRow(const Case& c, PursuitLaw law, const Summary& s) {
  std::printf("[ table    ] | %s | %s | %s | %s | %ld / %ld | %.2f | %.3f | %ld | %.4f | %.4f | %.2f |",
              toString(c.type).c_str(), c.path, toString(c.model).c_str(), toString(law).c_str(),
              s.steady.sign_changes, s.steady.steps, s.steady.largest_rate, s.steady.largest_step,
              s.steady.clipped, s.mean_error, s.max_error, s.first_converged);
  if (isDiamond(c)) {
    std::printf(" %ld / %ld, %.3f rad/s |", s.corners.sign_changes, s.corners.steps,
                s.corners.largest_step);
  }
  std::printf("\n");
}

class SmoothLawCriteria : public ::testing::TestWithParam<Case> {};

TEST_P(SmoothLawCriteria, MeetsIssue13sCriteria) {
  const Case c = GetParam();
  const Summary paper = summarise(c, runLogged(c, PursuitLaw::Paper));
  const Summary smooth = summarise(c, runLogged(c, PursuitLaw::Smooth));
  printRow(c, PursuitLaw::Paper, paper);
  printRow(c, PursuitLaw::Smooth, smooth);

  EXPECT_LT(smooth.steady.sign_changes, kMaxSignChanges * smooth.steady.steps);
  EXPECT_LE(smooth.steady.largest_step, kMaxRateStep);
  EXPECT_EQ(smooth.steady.clipped, 0);
  // At a vertex the path's velocity turns by 90 degrees at once; the law's window spreads that
  // over a second, so the commands stay within the actuators' limit there too.
  EXPECT_EQ(smooth.corners.sign_changes, 0);
  EXPECT_LE(smooth.corners.largest_step, kMaxRateStep);
  ASSERT_FALSE(std::isnan(paper.first_converged));
  ASSERT_FALSE(std::isnan(smooth.first_converged));
  EXPECT_LE(smooth.first_converged, kTimeRatio * paper.first_converged);
  if (!isDiamond(c)) {
    EXPECT_LE(smooth.mean_error, kCircleMean);
    EXPECT_LE(smooth.max_error, kCircleMax);
    EXPECT_EQ(smooth.tilt_at_limit, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(RobotsPathsModels, SmoothLawCriteria,
                         ::testing::ValuesIn(spherical_robots::test_support::allBatchCases()),
                         spherical_robots::test_support::batchCaseName);

// Insensitive to rounding: moving the start by 1e-12 m (thousands of ulps of the state, far more
// than a compiler's reordering of one operation) moves the smooth law's tracking figures by less
// than 1e-9 m and its time to 0.1 m not at all. (The paper's law is printed for comparison: where
// it chatters, rounding decides its trajectory; docs/results.md.)
class SmoothLawRounding : public ::testing::TestWithParam<Case> {};

TEST_P(SmoothLawRounding, APerturbedStartGivesTheSameTrackingFigures) {
  const Case c = GetParam();
  const TerrainState nudged{1e-12, -1e-12, 0.0, 0.0};
  const Summary smooth = summarise(c, runLogged(c, PursuitLaw::Smooth));
  const Summary smooth_nudged = summarise(c, runLogged(c, PursuitLaw::Smooth, nudged));
  const Summary paper = summarise(c, runLogged(c, PursuitLaw::Paper));
  const Summary paper_nudged = summarise(c, runLogged(c, PursuitLaw::Paper, nudged));
  std::printf("[ rounding ] %s %s %s: smooth mean %.1e m, max %.1e m; paper mean %.1e m, max %.1e m\n",
              toString(c.type).c_str(), c.path, toString(c.model).c_str(),
              std::abs(smooth.mean_error - smooth_nudged.mean_error),
              std::abs(smooth.max_error - smooth_nudged.max_error),
              std::abs(paper.mean_error - paper_nudged.mean_error),
              std::abs(paper.max_error - paper_nudged.max_error));
  EXPECT_LT(std::abs(smooth.mean_error - smooth_nudged.mean_error), 1e-9);
  EXPECT_LT(std::abs(smooth.max_error - smooth_nudged.max_error), 1e-9);
  EXPECT_EQ(smooth.first_converged, smooth_nudged.first_converged);
}

INSTANTIATE_TEST_SUITE_P(RobotsPathsModels, SmoothLawRounding,
                         ::testing::ValuesIn(spherical_robots::test_support::allBatchCases()),
                         spherical_robots::test_support::batchCaseName);

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
