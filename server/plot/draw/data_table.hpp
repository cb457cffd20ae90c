#pragma once
/// The numbers a line plot draws, as CSV: what the analyst reads off the picture, exactly (every
/// number in the shortest text that reads back as the same double), and where each point was drawn
/// on the image (px), so that a program can check the picture against the numbers.
///
///   # notes, one per line (the title, the units, the axes' ticks and their px positions)
///   column,column,..
///   value,value,..

#include <string>
#include <vector>

namespace saasgaps::plot {

class DataTable {
 public:
  explicit DataTable(std::vector<std::string> columns) : columns_(std::move(columns)) {}

  void note(std::string line) { notes_.push_back(std::move(line)); }
  /// Appends a row; it must have one cell per column.
  void add_row(std::vector<std::string> cells);

  /// Shortest round-trip text of a double; "" for NaN (a point with no value).
  static std::string number(double value);

  std::string csv() const;

 private:
  std::vector<std::string> columns_;
  std::vector<std::string> notes_;
  std::vector<std::vector<std::string>> rows_;
};

}  // namespace saasgaps::plot
