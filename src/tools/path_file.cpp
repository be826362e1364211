#include "path_file.hpp"

#include <fstream>
#include <stdexcept>
#include <vector>

#include "spherical_robots/config/csv_lines.hpp"
#include "sphere_sim_cli.hpp"

namespace spherical_robots::sphere_sim {
namespace {

std::string joined(const std::vector<std::string>& cells) {
  std::string text;
  for (const std::string& cell : cells) text += (text.empty() ? "" : ",") + cell;
  return text;
}

}  // namespace

terrain::SampledPath readPathFile(const std::string& file, std::optional<double> speed) {
  std::ifstream in(file);
  if (!in) throw InvalidInput("--path-file " + file + ": cannot be read");
  const auto at_line = [&file](int line) { return file + " line " + std::to_string(line) + ": "; };

  std::vector<std::string> columns;  // t,x,y or x,y
  std::vector<std::vector<double>> rows;
  std::vector<int> row_lines;
  for (const config::CsvLine& line : config::readCsvLines(in)) {
    const std::vector<std::string>& cells = line.cells;
    std::vector<double> values;
    for (const std::string& cell : cells) {
      const std::optional<double> value = config::csvNumber(cell);
      if (!value) break;
      values.push_back(*value);
    }
    if (columns.empty()) {
      if (values.size() != cells.size()) {  // a header
        if (cells != std::vector<std::string>{"t", "x", "y"} &&
            cells != std::vector<std::string>{"x", "y"}) {
          throw InvalidInput(at_line(line.number) + "'" + line.text +
                             "' is neither a header (t,x,y or x,y) nor a row of numbers");
        }
        columns = cells;
        continue;
      }
      if (cells.size() != 2 && cells.size() != 3) {
        throw InvalidInput(at_line(line.number) + std::to_string(cells.size()) +
                           " cells; a row is t,x,y or x,y");
      }
      columns = cells.size() == 3 ? std::vector<std::string>{"t", "x", "y"}
                                  : std::vector<std::string>{"x", "y"};
    }
    if (cells.size() != columns.size()) {
      throw InvalidInput(at_line(line.number) + std::to_string(cells.size()) + " cells, expected " +
                         std::to_string(columns.size()) + " (" + joined(columns) + ")");
    }
    if (values.size() != cells.size()) {
      throw InvalidInput(at_line(line.number) + "'" + cells[values.size()] + "' (column " +
                         columns[values.size()] + ") is not a number");
    }
    rows.push_back(values);
    row_lines.push_back(line.number);
  }

  if (columns.empty()) throw InvalidInput("--path-file " + file + " holds no rows");
  const bool timed = columns.size() == 3;
  if (!timed && !speed) {
    throw UsageError("--path-file " + file + " has x,y rows (an untimed path): give --speed M/S");
  }
  if (timed && speed) {
    throw UsageError("--speed applies to an x,y file; " + file + " has t,x,y rows (a timed path)");
  }
  try {
    if (timed) {
      std::vector<terrain::TimedPoint> points;
      for (const std::vector<double>& row : rows) points.push_back({row[0], {row[1], row[2]}});
      return terrain::SampledPath::timed(points);
    }
    std::vector<Eigen::Vector2d> points;
    for (const std::vector<double>& row : rows) points.emplace_back(row[0], row[1]);
    return terrain::SampledPath::atSpeed(points, *speed);
  } catch (const terrain::InvalidPathPoint& e) {
    throw InvalidInput(at_line(row_lines.at(e.index())) + e.what());
  } catch (const std::invalid_argument& e) {
    throw InvalidInput("--path-file " + file + ": " + e.what());
  }
}

}  // namespace spherical_robots::sphere_sim
