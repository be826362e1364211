// `sphere_sim terrain --path-file` run as an executable: the built-in circle written to a file
// runs as --path circle (within the bound the interpolation error gives, as the stack does with
// the circle sent as a nav_msgs/Path: test/terrain_path_topic.test); the hand-made S-curve of
// config/paths/s_curve.csv tracked by every robot type within the built-in paths' bounds
// (test_terrain_tracking); an untimed line followed at --speed, and a timed file at its own
// times, against closed forms; bad files rejected naming their line, and the usage errors; a
// misspelt key of config/terrain.yaml warned of with its line.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "sphere_sim_process.hpp"

namespace {

namespace fs = std::filesystem;

constexpr double kPi = 3.14159265358979323846;

struct Result : sphere_sim_test::Process, sphere_sim_test::Csv {};

class SphereSimPathFileTest : public sphere_sim_test::SphereSimFixture {
 protected:
  SphereSimPathFileTest() : SphereSimFixture("sphere_sim_path_file", "run.csv") {}

  /// `sphere_sim terrain ARGS --config SOURCE --out DIR/run.csv`, the CSV read back if written.
  Result terrain(const std::string& args) const {
    std::vector<std::string> argv = {"terrain"};
    std::istringstream words(args);
    for (std::string word; words >> word;) argv.push_back(word);
    argv.insert(argv.end(), {"--config", SPHERICAL_ROBOTS_SOURCE_DIR, "--out", out_.string()});
    const sphere_sim_test::Process process = run(argv);
    return {process, fs::exists(out_) ? sphere_sim_test::readCsv(out_) : sphere_sim_test::Csv{}};
  }

  /// A file in the test's directory holding text; its path.
  std::string file(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }

  /// Every run of a bad file: exit 4, stderr naming these words, no output file.
  void expectRejected(const std::string& text, const std::vector<std::string>& words,
                      const std::string& options = "") {
    fs::remove(out_);
    const std::string path = file("bad.csv", text);
    const Result r = terrain("--robot 3R --duration 1 --path-file " + path + " " + options);
    EXPECT_EQ(r.status, 4) << text << "\n" << r.err;
    for (const std::string& word : words) EXPECT_NE(r.err.find(word), std::string::npos) << word << " in: " << r.err;
    EXPECT_FALSE(fs::exists(out_)) << text;
  }
};

TEST_F(SphereSimPathFileTest, TheCircleWrittenToAFileRunsAsTheBuiltInCircle) {
  // config/terrain.yaml's circle, 401 timed rows over one lap (closed: it repeats).
  const double radius = 2.0, rate = 0.05, period = 2.0 * kPi / rate;
  std::ostringstream text;
  text.precision(17);
  text << "t,x,y\n";
  for (int i = 0; i <= 400; ++i) {
    const double t = period * i / 400;
    text << t << ',' << radius * std::cos(rate * t) << ',' << radius * std::sin(rate * t) << '\n';
  }
  const std::string run = "--robot 3R --law smooth --loop sampled --duration 140 --log-rate 50 ";
  const Result built_in = terrain(run + "--path circle");
  ASSERT_EQ(built_in.status, 0) << built_in.err;
  const Result sampled = terrain(run + "--path-file " + file("circle.csv", text.str()));
  ASSERT_EQ(sampled.status, 0) << sampled.err;
  ASSERT_EQ(sampled.rows.size(), built_in.rows.size());
  // The bound test/terrain_path_topic.test derives from the spline's error (2.2e-9 m, 2.3e-8 m/s).
  double largest = 0.0;
  for (const char* column : {"x0", "y0", "z0", "xd", "yd", "zd", "cx", "cy", "cz", "e_norm"}) {
    for (std::size_t i = 0; i < sampled.rows.size(); ++i) {
      largest = std::max(largest, std::abs(sampled.at(i, column) - built_in.at(i, column)));
    }
  }
  std::ostringstream figure;
  figure << largest;
  RecordProperty("largest_difference_m", figure.str());
  std::cout << "[ result   ] circle from a file against the built-in circle: largest difference "
            << largest << " m\n";
  EXPECT_LE(largest, 5e-8);
}

TEST_F(SphereSimPathFileTest, TheHandMadeSCurveIsTrackedWithinTheBuiltInPathsBounds) {
  const std::string s_curve = SPHERICAL_ROBOTS_SOURCE_DIR "/config/paths/s_curve.csv";
  for (const char* robot : {"3R", "2R", "RT", "RS"}) {
    for (const char* law : {"paper", "smooth"}) {
      const Result r = terrain(std::string("--robot ") + robot + " --law " + law +
                               " --duration 110 --path-file " + s_curve + " --speed 0.1");
      ASSERT_EQ(r.status, 0) << r.err;
      double worst = 0.0, sum = 0.0;
      int after = 0;
      for (std::size_t i = 0; i < r.rows.size(); ++i) {
        const double e = r.at(i, "e_norm");
        worst = std::max(worst, e);
        if (r.at(i, "t") >= 40.0) {
          sum += e;
          ++after;
        }
      }
      // test_terrain_tracking's for the circle (mean after 40 s, max), the max here over the
      // whole run: the path starts where the robot stands.
      EXPECT_LT(worst, 0.3) << robot << " " << law;
      EXPECT_LT(sum / after, 0.1) << robot << " " << law;
      std::cout << "[ result   ] S-curve " << robot << " " << law << ": max |e_t| " << worst
                << " m, mean after 40 s " << sum / after << " m\n";
      // The path's end (2, 6.1), held once it is reached at t = its length / 0.1 m/s.
      EXPECT_NEAR(r.at(r.rows.size() - 1, "xd"), 2.0, 1e-12);
      EXPECT_NEAR(r.at(r.rows.size() - 1, "yd"), 6.1, 1e-12);
    }
  }
}

TEST_F(SphereSimPathFileTest, AnUntimedLineIsFollowedAtTheGivenSpeedAndItsEndHeld) {
  const std::string path = file("line.csv", "0,0\n1,0\n\n# a comment\n2,0\n4,0\n");
  const Result r = terrain("--robot 3R --duration 100 --speed 0.05 --path-file " + path);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("path " + path), std::string::npos) << r.out;
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const double t = r.at(i, "t");
    EXPECT_NEAR(r.at(i, "xd"), std::min(0.05 * t, 4.0), 1e-12) << t;
    EXPECT_NEAR(r.at(i, "yd"), 0.0, 1e-12) << t;
  }
}

TEST_F(SphereSimPathFileTest, ATimedFileIsFollowedAtItsTimesFromTheFirstRow) {
  // Collinear at a constant speed of 0.1 m/s from t = 10 s: x_d = 0.1 (t - 0) for t in [0, 30].
  const std::string path = file("timed.csv", "t, x, y\n10,0,1\n15,0.5,1\n25,1.5,1\n40,3,1\n");
  const Result r = terrain("--robot 2R --duration 40 --path-file " + path);
  ASSERT_EQ(r.status, 0) << r.err;
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const double t = r.at(i, "t");
    EXPECT_NEAR(r.at(i, "xd"), std::min(0.1 * t, 3.0), 1e-12) << t;
    EXPECT_NEAR(r.at(i, "yd"), 1.0, 1e-12) << t;
  }
}

TEST_F(SphereSimPathFileTest, BadFilesAreRejectedNamingTheirLine) {
  expectRejected("t,x,y\n0,0,0\n1,0.1,0\n2,nan,0\n", {"bad.csv line 4", "x [m]", "nan"});
  expectRejected("# times\nt,x,y\n0,0,0\n\n2,0.1,0\n1,0.2,0\n",
                 {"line 6", "t [s] must be after point 1's 2", "got 1"});
  expectRejected("0,0,0\n1,0.1,0\n1,0.2,0\n", {"line 3", "after"});
  expectRejected("t,x,y\n0,0,0\n1,abc,0\n", {"line 3", "'abc'", "column x", "not a number"});
  expectRejected("t,x,y\n0,0,0\n1,0\n", {"line 3", "2 cells, expected 3"});
  expectRejected("a,b,c\n0,0,0\n1,1,0\n", {"line 1", "neither a header"});
  expectRejected("0,0,0,0\n", {"line 1", "4 cells"});
  expectRejected("t,x,y\n0,1,1\n", {"at least 2 points", "got 1"});
  expectRejected("", {"holds no rows"});
  expectRejected("x,y\n1,1\n1,1\n", {"at least 2 distinct points"}, "--speed 0.1");
  expectRejected("x,y\n0,0\n1,1\n", {"--speed must be > 0", "got -1"}, "--speed -1");
  const Result missing = terrain("--robot 3R --path-file " + (dir_ / "no_such.csv").string());
  EXPECT_EQ(missing.status, 4);
  EXPECT_NE(missing.err.find("cannot be read"), std::string::npos) << missing.err;
}

TEST_F(SphereSimPathFileTest, AConfigKeyThatNothingReadsIsWarnedOfWithItsLine) {
  const Result shipped = terrain("--robot 3R --path circle --duration 1");
  EXPECT_EQ(shipped.status, 0) << shipped.err;
  EXPECT_EQ(shipped.err, "");  // every key of the shipped file is a parameter
  const fs::path config = dir_ / "misspelt";
  fs::create_directories(config);
  fs::copy(SPHERICAL_ROBOTS_SOURCE_DIR "/config", config / "config", fs::copy_options::recursive);
  fs::copy(SPHERICAL_ROBOTS_SOURCE_DIR "/urdf", config / "urdf", fs::copy_options::recursive);
  std::string yaml = sphere_sim_test::readFile(config / "config/terrain.yaml");
  const std::size_t at = yaml.find("    amplitude:");
  ASSERT_NE(at, std::string::npos);
  yaml.replace(at, 14, "    amplitud: ");
  std::ofstream(config / "config/terrain.yaml") << yaml;
  const int line = 1 + static_cast<int>(std::count(yaml.begin(), yaml.begin() + at, '\n'));
  const sphere_sim_test::Process misspelt =
      run({"terrain", "--robot", "3R", "--path", "circle", "--duration", "1", "--config",
           config.string(), "--out", out_.string()});
  EXPECT_EQ(misspelt.status, 0) << misspelt.err;
  EXPECT_NE(misspelt.err.find("terrain.yaml line " + std::to_string(line) +
                              ": 'terrain/surface/amplitud' is no parameter"),
            std::string::npos)
      << misspelt.err;
}

TEST_F(SphereSimPathFileTest, PathOptionsThatDoNotFitAreUsageErrors) {
  const std::string timed = file("timed.csv", "0,0,0\n1,1,0\n");
  const std::string untimed = file("untimed.csv", "0,0\n1,1\n");
  for (const std::string& args : std::vector<std::string>{
           "--robot 3R", "--robot 3R --path circle --path-file " + timed,
           "--robot 3R --path-file " + untimed, "--robot 3R --path-file " + timed + " --speed 0.1",
           "--robot 3R --path circle --speed 0.1"}) {
    const Result r = terrain(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(out_)) << args;
  }
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
