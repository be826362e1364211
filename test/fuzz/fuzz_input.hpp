#pragma once
// What every fuzz target shares: numbers read from the input as text, the input as a file for
// the readers that take a path, and the rule of what may escape an entry point.
//
// Numbers come as text (whitespace- or comma-separated, parsed by strtod) rather than raw bytes:
// the seeds in corpus/ are then the shipped configuration's values, readable and editable by hand,
// and libFuzzer still reaches nan, inf, hex floats, subnormals and huge exponents by mutation.

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace spherical_robots::fuzz {

class FuzzNumbers {
 public:
  FuzzNumbers(const std::uint8_t* data, std::size_t size)
      : text_(reinterpret_cast<const char*>(data), size) {}

  /// The next number of the input; 0 once it is exhausted or where a token is not a number.
  double next() {
    while (position_ < text_.size() && separator(text_[position_])) ++position_;
    if (position_ >= text_.size()) return 0.0;
    const char* begin = text_.c_str() + position_;
    char* end = nullptr;
    const double value = std::strtod(begin, &end);
    if (end == begin) {  // not a number: skip the token
      while (position_ < text_.size() && !separator(text_[position_])) ++position_;
      return 0.0;
    }
    position_ += static_cast<std::size_t>(end - begin);
    return value;
  }

  /// The next number as a count or an index in [0, limit]: its whole part when finite and in
  /// range, else limit, so that the harness itself never converts out of range.
  int nextCount(int limit) {
    const double value = next();
    return value >= 0.0 && value <= limit ? static_cast<int>(value) : limit;
  }

  /// The next number as an int, through the same guard (INT_MIN, INT_MAX for values beyond).
  int nextInt() {
    const double value = next();
    if (!(value == value)) return 0;
    if (value >= 2147483647.0) return 2147483647;
    if (value <= -2147483648.0) return -2147483647 - 1;
    return static_cast<int>(value);
  }

 private:
  static bool separator(char c) {
    return c == ' ' || c == ',' || c == '\n' || c == '\t' || c == '\r' || c == ';';
  }
  std::string text_;
  std::size_t position_ = 0;
};

/// A directory of this process's own, removed when it exits: in memory (/dev/shm) where there is
/// one, as the readers under test open their files thousands of times a second.
inline const std::string& scratchDirectory() {
  struct Scratch {
    std::string path;
    Scratch() {
      const std::filesystem::path shm("/dev/shm");
      path = ((std::filesystem::is_directory(shm) ? shm : std::filesystem::temp_directory_path()) /
              ("spherical_robots_fuzz_" + std::to_string(getpid())))
                 .string();
      std::filesystem::create_directories(path);
    }
    ~Scratch() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Scratch scratch;
  return scratch.path;
}

/// The input written to scratchDirectory()/name, for the readers that take a path; rewritten on
/// every call.
inline std::string inputFile(const std::uint8_t* data, std::size_t size, const std::string& name) {
  const std::string path = scratchDirectory() + "/" + name;
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!file.flush()) {
    std::fprintf(stderr, "fuzz harness: cannot write %s\n", path.c_str());
    std::abort();
  }
  return path;
}

/// A reader's error must name the file it read (README, "Bad files"): else the harness aborts,
/// and libFuzzer keeps the input that showed it.
inline void requireNamesFile(const std::exception& error, const std::string& path) {
  if (std::string(error.what()).find(path) == std::string::npos) {
    std::fprintf(stderr, "error without the file's name %s: %s\n", path.c_str(), error.what());
    std::abort();
  }
}

/// The input as the file `name`, given to `read` (a reader that takes a path), whose
/// std::invalid_argument must name the file.
template <typename Read>
void readInputFile(const std::uint8_t* data, std::size_t size, const std::string& name, Read read) {
  const std::string path = inputFile(data, size, name);
  try {
    read(path);
  } catch (const std::invalid_argument& error) {
    requireNamesFile(error, path);
  }
}

}  // namespace spherical_robots::fuzz
