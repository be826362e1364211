#include "spherical_robots/config/csv_lines.hpp"

#include <charconv>

namespace spherical_robots::config {
namespace {

std::string trimmed(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

}  // namespace

std::vector<CsvLine> readCsvLines(std::istream& in) {
  std::vector<CsvLine> lines;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    line = trimmed(line);
    if (line.empty() || line[0] == '#') continue;
    CsvLine record{number, line, {}};
    std::size_t start = 0;
    for (std::size_t comma; (comma = line.find(',', start)) != std::string::npos; start = comma + 1)
      record.cells.push_back(trimmed(line.substr(start, comma - start)));
    record.cells.push_back(trimmed(line.substr(start)));
    lines.push_back(std::move(record));
  }
  return lines;
}

std::optional<double> csvNumber(const std::string& cell) {
  double value = 0.0;
  const char* last = cell.data() + cell.size();
  const auto [end, error] = std::from_chars(cell.data(), last, value);
  if (cell.empty() || end != last || error != std::errc()) return std::nullopt;
  return value;
}

}  // namespace spherical_robots::config
