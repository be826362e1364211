#pragma once
// Comma-separated text as the project's files write it (height-map grids, path files): one
// record a line, cells trimmed of blanks, blank lines and lines starting with '#' skipped.

#include <istream>
#include <optional>
#include <string>
#include <vector>

namespace spherical_robots::config {

struct CsvLine {
  int number = 0;                  ///< in the file, from 1, for messages
  std::string text;                ///< the line, trimmed
  std::vector<std::string> cells;  ///< split at every comma, each trimmed ("1,2," has 3)
};

/// Every line of `in` that holds a record.
std::vector<CsvLine> readCsvLines(std::istream& in);

/// The whole cell as a number, or nothing (an empty cell, a trailing word, "1e"); "nan" and
/// "inf" parse: the caller decides, naming what the number is for.
std::optional<double> csvNumber(const std::string& cell);

}  // namespace spherical_robots::config
