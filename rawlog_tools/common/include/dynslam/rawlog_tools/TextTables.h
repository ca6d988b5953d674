#pragma once
// Strict readers for the plain-text tables datasets ship (TUM lists, EuRoC csv, matrices).
// Every number must parse completely and be finite; a failure throws ConversionError naming the
// file, the 1-based line and column, and the offending text.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace dynslam::rawlog_tools {

/// One data line of a table, already split into fields.
struct TableRow {
  size_t line = 0;  ///< 1-based line number in the file
  std::vector<std::string> fields;
};

/// Where a row came from, for error messages and for number parsing.
struct TableSource {
  std::string file;
  std::vector<std::string> columnNames;  ///< from a '#' header line, if the file has one
};

/// Streams a whitespace- (separator = ' ') or comma-separated (separator = ',') file, skipping
/// blank lines and lines starting with '#'. The first '#' line, split by the separator, gives
/// column names. Calls onRow for every data line; never holds the whole file. Throws when the
/// file cannot be opened.
void forEachTableRow(const std::string& file, char separator,
                     const std::function<void(const TableSource&, const TableRow&)>& onRow);

/// Throws unless the row has exactly `count` fields (or at least, with atLeast = true).
void requireFieldCount(const TableSource& source, const TableRow& row, size_t count,
                       bool atLeast = false);

/// Field `column` (0-based) as a finite double; throws naming file, line and column otherwise.
double parseFiniteDouble(const TableSource& source, const TableRow& row, size_t column);

/// Field `column` as a signed 64-bit integer (EuRoC nanosecond stamps); throws likewise.
int64_t parseInteger64(const TableSource& source, const TableRow& row, size_t column);

/// A whole file of whitespace-separated numbers (e.g. a 4x4 matrix), row-major; throws unless
/// it holds exactly `expected` finite numbers.
std::vector<double> readNumberGrid(const std::string& file, size_t expected);

}  // namespace dynslam::rawlog_tools
