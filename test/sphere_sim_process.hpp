#pragma once
// Runs the built sphere_sim executable in a directory and captures its exit status, stdout and
// stderr, and reads back the CSV it writes (for the CLI gtests); SphereSimFixture, their gtest
// fixture: a directory of each test's own and the path of its output file.

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace sphere_sim_test {

struct Process {
  int status = -1;  ///< exit status, -1 if the process did not exit normally or did not start
  std::string out;
  std::string err;
};

inline std::string readFile(const std::filesystem::path& path) {
  std::ifstream file(path);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

/// `executable args...` run in `work_dir` (default: `dir`), stdout and stderr captured through
/// files in `dir` (stdout.txt, stderr.txt).
inline Process runIn(const std::string& executable, const std::vector<std::string>& args,
                     const std::filesystem::path& dir, std::filesystem::path work_dir = {}) {
  if (work_dir.empty()) work_dir = dir;
  std::vector<std::string> argv_text = {executable};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& arg : argv_text) argv.push_back(arg.data());
  argv.push_back(nullptr);
  const std::filesystem::path out_path = dir / "stdout.txt";
  const std::filesystem::path err_path = dir / "stderr.txt";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, work_dir.c_str());
  posix_spawn_file_actions_addopen(&actions, 1, out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_addopen(&actions, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  Process process;
  if (spawned != 0) return process;
  int status = 0;
  ::waitpid(pid, &status, 0);
  process.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  process.out = readFile(out_path);
  process.err = readFile(err_path);
  return process;
}

/// A table read back from the CSV: every cell must be a complete, finite number.
struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;

  std::size_t column(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (header[i] == name) return i;
    }
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
  double at(std::size_t row, const std::string& name) const {
    return rows.at(row).at(column(name));
  }
};

inline std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream stream(line);
  for (std::string cell; std::getline(stream, cell, ',');) cells.push_back(cell);
  return cells;
}

inline Csv readCsv(const std::filesystem::path& path) {
  Csv csv;
  std::ifstream file(path);
  std::string line;
  if (!std::getline(file, line)) {
    ADD_FAILURE() << path << " is empty";
    return csv;
  }
  csv.header = split(line);
  while (std::getline(file, line)) {
    std::vector<double> row;
    for (const std::string& cell : split(line)) {
      char* end = nullptr;
      const double value = std::strtod(cell.c_str(), &end);
      EXPECT_TRUE(!cell.empty() && *end == '\0' && std::isfinite(value))
          << "cell '" << cell << "' in row " << csv.rows.size() << " is not a finite number";
      row.push_back(value);
    }
    EXPECT_EQ(row.size(), csv.header.size()) << "row " << csv.rows.size();
    csv.rows.push_back(row);
  }
  return csv;
}

/// The fixture of the sphere_sim gtests (which define SPHERE_SIM_EXECUTABLE, the built
/// executable): each test runs in a fresh directory dir_, removed after it, and sphere_sim writes
/// its output to out_ in it.
class SphereSimFixture : public ::testing::Test {
 protected:
  /// dir_ is <temp>/<prefix>.XXXXXX, out_ is dir_/<output>.
  SphereSimFixture(std::string prefix, std::string output)
      : prefix_(std::move(prefix)), output_(std::move(output)) {}

  void SetUp() override {
    std::string pattern =
        (std::filesystem::temp_directory_path() / (prefix_ + ".XXXXXX")).string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
    out_ = dir_ / output_;
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  /// `sphere_sim args...` run in directory cwd (default: dir_); a process that cannot start or
  /// finish is a test failure.
  Process run(const std::vector<std::string>& args, const std::filesystem::path& cwd = {}) const {
    const Process process = runIn(SPHERE_SIM_EXECUTABLE, args, dir_, cwd);
    if (process.status == -1) ADD_FAILURE() << "cannot start or finish " << SPHERE_SIM_EXECUTABLE;
    return process;
  }

  std::filesystem::path dir_;
  std::filesystem::path out_;

 private:
  std::string prefix_;
  std::string output_;
};

}  // namespace sphere_sim_test
