#pragma once
// TempYaml: a YAML file with the given text in the test's temp directory, removed when it goes,
// for the tests of the config/ readers.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace spherical_robots::test_support {

class TempYaml {
 public:
  explicit TempYaml(const std::string& text) {
    static int counter = 0;
    path_ = ::testing::TempDir() + "parameters_" + std::to_string(::getpid()) + "_" +
            std::to_string(counter++) + ".yaml";
    std::ofstream(path_) << text;
  }
  ~TempYaml() { std::remove(path_.c_str()); }
  TempYaml(const TempYaml&) = delete;
  TempYaml& operator=(const TempYaml&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace spherical_robots::test_support
