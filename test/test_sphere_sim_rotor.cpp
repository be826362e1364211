// `sphere_sim rotor-step`, `rotor-plan` and `rotor-execute`, run as the built executable: the JSON
// against the paper's published solutions (Svinin et al., section IV: k = 2.5, h/R = 1, a1 and
// a2 with their γ), the executed run's CSV against the plan's target (where the sphere must come
// to rest, back at the south pole: attitude R_zᵀ(ψ), eq 2), and the command-line contract (exit
// statuses 0/2/3/4, output file only when the run succeeds or has no solution, errors naming the
// parameter).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "sphere_sim_process.hpp"

namespace {

namespace fs = std::filesystem;
using sphere_sim_test::Csv;
using sphere_sim_test::Process;
using sphere_sim_test::readCsv;
using sphere_sim_test::readFile;

/// Every number written as `"key": number` in order of appearance.
std::vector<double> numbersOf(const std::string& json, const std::string& key) {
  const std::regex member("\"" + key + "\": (-?[0-9][0-9.eE+-]*)");
  std::vector<double> values;
  for (auto it = std::sregex_iterator(json.begin(), json.end(), member); it != std::sregex_iterator();
       ++it) {
    values.push_back(std::stod((*it)[1].str()));
  }
  return values;
}

class SphereSimRotorTest : public sphere_sim_test::SphereSimFixture {
 protected:
  SphereSimRotorTest() : SphereSimFixture("sphere_sim_rotor", "out.json") {}

  /// sphere_sim with args and --out out_.
  Process run(std::vector<std::string> args) const {
    args.push_back("--out");
    args.push_back(out_.string());
    return SphereSimFixture::run(args);
  }

  std::string output() const { return readFile(out_); }

  /// A command line sphere_sim must refuse: its exit status and a needle of its message.
  struct BadInput {
    std::vector<std::string> args;
    int status;
    std::string needle;
  };

  /// Each case exits with its status, says its needle on stderr and writes no file.
  void expectRefused(const std::vector<BadInput>& cases) {
    for (const BadInput& c : cases) {
      fs::remove(out_);
      const Process p = run(c.args);
      EXPECT_EQ(p.status, c.status) << c.args[0] << " " << c.args[1] << " " << c.args[2] << ": "
                                    << p.err;
      EXPECT_NE(p.err.find(c.needle), std::string::npos) << p.err;
      EXPECT_FALSE(fs::exists(out_)) << c.needle;
    }
  }
};

TEST_F(SphereSimRotorTest, StepWithThePublishedFirstSolutionMovesAlongV) {
  // k = 2.5, a = b = a1 = 0.300429, γ = 0.931883: h/R = 1 along +v_a (section IV).
  const Process p =
      run({"rotor-step", "--k", "2.5", "--a", "0.300429", "--b", "0.300429", "--gamma", "0.931883"});
  ASSERT_EQ(p.status, 0) << p.err;
  const std::string json = output();
  const std::vector<double> u = numbersOf(json, "u"), v = numbersOf(json, "v"),
                            psi = numbersOf(json, "psi");
  ASSERT_EQ(u.size(), 2u) << json;
  ASSERT_EQ(v.size(), 2u);
  ASSERT_EQ(psi.size(), 2u);
  EXPECT_NEAR(u[1], 0.0, 5e-6);
  EXPECT_NEAR(v[1], 1.0, 5e-6);
  EXPECT_NEAR(psi[1], 0.0, 1e-10);  // a = b: the leaves' turns cancel
  EXPECT_NE(json.find("\"half\""), std::string::npos);
  EXPECT_NE(json.find("\"full\""), std::string::npos);
  EXPECT_NE(p.out.find("rotor-step"), std::string::npos);
}

TEST_F(SphereSimRotorTest, StepGammaDefaultsToZeroAndTurnsThePathRigidly) {
  ASSERT_EQ(run({"rotor-step", "--k", "1.5", "--a", "0.4", "--b", "0.25"}).status, 0);
  const std::string plain = output();
  ASSERT_EQ(run({"rotor-step", "--k", "1.5", "--a", "0.4", "--b", "0.25", "--gamma", "0"}).status,
            0);
  EXPECT_EQ(output(), plain);
  ASSERT_EQ(run({"rotor-step", "--k", "1.5", "--a", "0.4", "--b", "0.25", "--gamma", "-1"}).status,
            0);
  const std::string turned = output();
  const std::vector<double> u0 = numbersOf(plain, "u"), v0 = numbersOf(plain, "v");
  const std::vector<double> u1 = numbersOf(turned, "u"), v1 = numbersOf(turned, "v");
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(u1[i], std::cos(-1.0) * u0[i] - std::sin(-1.0) * v0[i], 1e-10);
    EXPECT_NEAR(v1[i], std::sin(-1.0) * u0[i] + std::cos(-1.0) * v0[i], 1e-10);
  }
  const std::vector<double> psi0 = numbersOf(plain, "psi"), psi1 = numbersOf(turned, "psi");
  for (std::size_t i = 0; i < 2; ++i) EXPECT_NEAR(psi1[i], psi0[i], 1e-10);
}

TEST_F(SphereSimRotorTest, PlanFindsThePublishedSolutionsShortestFirst) {
  const Process p = run({"rotor-plan", "--k", "2.5", "--steps", "1", "--target", "0,1,0"});
  ASSERT_EQ(p.status, 0) << p.err;
  const std::string json = output();
  const std::vector<double> a = numbersOf(json, "a"), b = numbersOf(json, "b"),
                            gamma = numbersOf(json, "gamma"), length = numbersOf(json, "length"),
                            error = numbersOf(json, "final_error");
  ASSERT_GE(a.size(), 4u) << json;
  ASSERT_EQ(b.size(), a.size());
  ASSERT_EQ(gamma.size(), a.size());
  ASSERT_EQ(error.size(), a.size());
  for (std::size_t i = 1; i < length.size(); ++i) EXPECT_LE(length[i - 1], length[i]);
  for (double e : error) EXPECT_LE(e, 1e-8);
  EXPECT_NEAR(a[0], 0.300429, 5e-7);  // a1, the shortest
  EXPECT_NEAR(b[0], 0.300429, 5e-7);
  EXPECT_NEAR(gamma[0], 0.931883, 5e-7);
  EXPECT_NEAR(length[0], 2 * M_PI * 2 * 0.300429, 1e-5);
  bool a2 = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::abs(a[i] - 0.491471) < 5e-7 && std::abs(b[i] - 0.491471) < 5e-7) {
      a2 = true;
      EXPECT_NEAR(gamma[i], -0.69726, 5e-6);
    }
  }
  EXPECT_TRUE(a2) << json;
  EXPECT_EQ(json.find("\"reason\""), std::string::npos);
}

TEST_F(SphereSimRotorTest, PlanWithoutSolutionExits3WithAReason) {
  const Process p = run({"rotor-plan", "--k", "2.5", "--steps", "1", "--target", "100,0,0"});
  EXPECT_EQ(p.status, 3) << p.err;
  const std::string json = output();
  EXPECT_NE(json.find("\"solutions\": []"), std::string::npos) << json;
  EXPECT_NE(json.find("\"reason\": \"no plan"), std::string::npos) << json;
  // 7 rad of accumulated turn is not 7 − 2π: with radii <= 0.5 one step cannot turn 7 rad …
  const Process turn = run({"rotor-plan", "--k", "2", "--steps", "1", "--target", "-0.3,0.2,7",
                            "--max-radius", "0.5"});
  EXPECT_EQ(turn.status, 3) << turn.err;
  // … but can turn 7 − 2π.
  const Process turns = run({"rotor-plan", "--k", "2", "--steps", "1", "--target", "-0.3,0.2,7",
                             "--max-radius", "0.5", "--heading-turns", "1"});
  EXPECT_EQ(turns.status, 0) << turns.err;
  for (double psi : numbersOf(output(), "psi")) EXPECT_NEAR(psi, 7 - 2 * M_PI, 1e-12);
}

TEST_F(SphereSimRotorTest, BadInputExitStatuses) {
  expectRefused({
      {{"rotor-step", "--k", "1", "--a", "0.8", "--b", "0.3"}, 4, "0.8"},
      {{"rotor-step", "--k", "nan", "--a", "0.3", "--b", "0.3"}, 4, "k"},
      {{"rotor-step", "--k", "-1", "--a", "0.3", "--b", "0.3"}, 4, "k"},
      {{"rotor-step", "--k", "1", "--a", "0.3"}, 2, "b"},
      {{"rotor-plan", "--k", "1", "--steps", "1.5", "--target", "0,1,0"}, 2, "steps"},
      {{"rotor-plan", "--k", "1", "--steps", "0", "--target", "0,1,0"}, 4, "steps"},
      {{"rotor-plan", "--k", "1", "--steps", "1", "--target", "0,1"}, 2, "target"},
      {{"rotor-plan", "--k", "1", "--steps", "1", "--target", "0,inf,0"}, 4, "target"},
      {{"rotor-plan", "--k", "1", "--steps", "1", "--target", "0,1,0", "--max-radius", "0.72"},
       4,
       "max radius"},
  });
}

/// How far the last row of a rotor-execute CSV is from the target (u, v [m], ψ): the centre on the
/// plane [m] and the attitude's angle to R_zᵀ(ψ) [rad].
std::pair<double, double> endErrors(const Csv& csv, double u, double v, double psi) {
  const std::size_t last = csv.rows.size() - 1;
  const double distance = std::hypot(csv.at(last, "x") - u, csv.at(last, "y") - v);
  // |<q, q_target>| = cos(angle / 2), q_target = (cos ψ/2, 0, 0, −sin ψ/2).
  const double dot = csv.at(last, "qw") * std::cos(0.5 * psi) - csv.at(last, "qz") * std::sin(0.5 * psi);
  return {distance, 2.0 * std::acos(std::min(1.0, std::abs(dot)))};
}

TEST_F(SphereSimRotorTest, ExecuteRunsTheStacksManoeuvreToItsTarget) {
  // The defaults are launch/rotor_stack.launch's: k = 2.5, n = 2, target (0.05 m, 0.03 m, 0.4 rad),
  // ideal rotors, open loop, 20 s.
  const Process p = run({"rotor-execute", "--log-rate", "10"});
  ASSERT_EQ(p.status, 0) << p.err;
  EXPECT_NE(p.out.find("rotor-execute"), std::string::npos) << p.out;
  const Csv csv = readCsv(out_);
  ASSERT_EQ(csv.rows.size(), 201u);  // t = 0, 0.1, ..., 20 s
  EXPECT_EQ(csv.at(0, "t"), 0.0);
  EXPECT_NEAR(csv.at(200, "t"), 20.0, 1e-12);
  const auto [distance, attitude] = endErrors(csv, 0.05, 0.03, 0.4);
  EXPECT_LE(distance, 2e-6);  // measured 1.5e-6 m: the 10 ms holds and the rotors' ramps
  EXPECT_LE(attitude, 2e-5);
  double peak = 0.0;
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    const double qw = csv.at(i, "qw"), qx = csv.at(i, "qx"), qy = csv.at(i, "qy"),
                 qz = csv.at(i, "qz");
    EXPECT_NEAR(qw * qw + qx * qx + qy * qy + qz * qz, 1.0, 1e-12);  // a unit quaternion
    peak = std::max({peak, std::abs(csv.at(i, "command_1")), std::abs(csv.at(i, "command_2"))});
  }
  EXPECT_LE(peak, 25.0);
  EXPECT_GT(peak, 1.0);
  EXPECT_EQ(csv.at(0, "state"), 1.0);    // executing from the first step
  EXPECT_EQ(csv.at(200, "state"), 0.0);  // idle after 13.6 s of manoeuvre and 1 s of settling
  EXPECT_EQ(csv.at(200, "command_1"), 0.0);
  EXPECT_EQ(csv.at(200, "measured_2"), 0.0);
}

TEST_F(SphereSimRotorTest, ExecuteWithCorrectionsMeetsTheCorrectedStacksBounds) {
  // test/rotor_stack_corrected.test: realistic rotors, three corrections at the noise floor; its
  // bounds are 2.5e-4 m and 1e-3 rad, which the open-loop run misses.
  const std::string models = std::string(SPHERICAL_ROBOTS_SOURCE_DIR) +
                             "/config/actuators_realistic.yaml";
  ASSERT_EQ(run({"rotor-execute", "--actuator-models", models}).status, 0);
  const Csv open = readCsv(out_);
  EXPECT_GT(endErrors(open, 0.05, 0.03, 0.4).first, 2.5e-4);
  const Process p = run({"rotor-execute", "--actuator-models", models, "--corrections", "3",
                         "--correction-tolerance", "5e-5", "--correction-tilt-tolerance", "5e-4"});
  ASSERT_EQ(p.status, 0) << p.err;
  const Csv csv = readCsv(out_);
  EXPECT_NEAR(csv.at(csv.rows.size() - 1, "t"), 50.0, 1e-12);  // 20 s + 10 s per correction
  const auto [distance, attitude] = endErrors(csv, 0.05, 0.03, 0.4);
  EXPECT_LE(distance, 2.5e-4);
  EXPECT_LE(attitude, 1e-3);
  bool returned_to_pole = false;
  for (std::size_t i = 0; i < csv.rows.size(); ++i) returned_to_pole |= csv.at(i, "state") == 2.0;
  EXPECT_TRUE(returned_to_pole);  // the open-loop run leaves the contact 1.3e-3 rad off the pole
}

TEST_F(SphereSimRotorTest, ExecuteWithoutAPlanExits3) {
  const Process p = run({"rotor-execute", "--target", "10,0,0"});
  EXPECT_EQ(p.status, 3) << p.err;
  EXPECT_NE(p.out.find("no plan"), std::string::npos) << p.out;
  const Csv csv = readCsv(out_);
  EXPECT_EQ(csv.header.front(), "t");
  EXPECT_TRUE(csv.rows.empty());
}

TEST_F(SphereSimRotorTest, ExecuteBadInputNamesTheOption) {
  const std::string e = "rotor-execute";
  expectRefused({
      {{e, "--k", "0"}, 4, "--k must be > 0, got 0"},
      {{e, "--k", "nan"}, 4, "k"},
      {{e, "--steps", "0"}, 4, "--steps must be >= 1, got 0"},
      {{e, "--steps", "1.5"}, 2, "steps"},
      {{e, "--target", "0.05,0.03"}, 2, "target"},
      {{e, "--curve-rate", "-1"}, 4, "--curve-rate must be > 0, got -1"},
      {{e, "--max-rotor-speed", "-25"}, 4, "--max-rotor-speed must be >= 0, got -25"},
      {{e, "--corrections", "-1"}, 4, "--corrections must be >= 0, got -1"},
      {{e, "--correction-tolerance", "0"}, 4, "--correction-tolerance must be > 0, got 0"},
      {{e, "--log-rate", "3"}, 4, "--log-rate 3 Hz"},
      {{e, "--duration", "20.01"}, 4, "--duration 20.01 s is not a whole number of log periods"},
      {{e, "--actuator-models", "/no/such/models.yaml"}, 4, "/no/such/models.yaml"},
  });
}

TEST_F(SphereSimRotorTest, HelpDescribesTheConventions) {
  for (const char* command : {"rotor-step", "rotor-plan", "rotor-execute"}) {
    std::vector<std::string> args = {command, "--help"};
    args.insert(args.begin(), SPHERE_SIM_EXECUTABLE);
    std::vector<char*> argv;
    for (std::string& arg : args) argv.push_back(arg.data());
    argv.push_back(nullptr);
    const fs::path out_path = dir_ / "help.txt";
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    pid_t pid = 0;
    ASSERT_EQ(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&actions);
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_EQ(WEXITSTATUS(status), 0);
    const std::string help = readFile(out_path);
    if (std::string(command) == "rotor-execute") {
      EXPECT_NE(help.find("rotor_stack.launch"), std::string::npos) << help;
      EXPECT_NE(help.find("returning to pole"), std::string::npos) << help;
      continue;
    }
    EXPECT_NE(help.find("Euclidean radius"), std::string::npos) << help;
    EXPECT_NE(help.find("gamma"), std::string::npos);
  }
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
