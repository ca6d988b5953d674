#include "dynslam/rawlog_tools/TextTables.h"

#include "dynslam/rawlog_tools/ConversionError.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace dynslam::rawlog_tools {
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> fields;
  if (separator == ' ') {
    std::istringstream in(line);
    for (std::string f; in >> f;) fields.push_back(f);
    return fields;
  }
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, separator)) fields.push_back(trim(field));
  if (!line.empty() && line.back() == separator) fields.push_back("");
  return fields;
}

std::string where(const TableSource& source, const TableRow& row, size_t column) {
  std::string w =
      source.file + " line " + std::to_string(row.line) + ", column " + std::to_string(column + 1);
  if (column < source.columnNames.size() && !source.columnNames[column].empty())
    w += " (" + source.columnNames[column] + ")";
  return w;
}

}  // namespace

void forEachTableRow(const std::string& file, char separator,
                     const std::function<void(const TableSource&, const TableRow&)>& onRow) {
  std::ifstream in(file);
  if (!in) throw ConversionError("cannot open " + file);
  TableSource source{file, {}};
  bool headerSeen = false;
  TableRow row;
  std::string line;
  while (std::getline(in, line)) {
    ++row.line;
    const std::string content = trim(line);
    if (content.empty()) continue;
    if (content[0] == '#') {
      if (!headerSeen) source.columnNames = split(trim(content.substr(1)), separator);
      headerSeen = true;
      continue;
    }
    row.fields = split(content, separator);
    onRow(source, row);
  }
  if (in.bad()) throw ConversionError("read error in " + file);
}

void requireFieldCount(const TableSource& source, const TableRow& row, size_t count, bool atLeast) {
  const bool ok = atLeast ? row.fields.size() >= count : row.fields.size() == count;
  if (!ok)
    throw ConversionError(source.file + " line " + std::to_string(row.line) + ": expected " +
                          (atLeast ? "at least " : "") + std::to_string(count) + " fields, found " +
                          std::to_string(row.fields.size()));
}

double parseFiniteDouble(const TableSource& source, const TableRow& row, size_t column) {
  const std::string& text = row.fields.at(column);
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || errno == ERANGE)
    throw ConversionError(where(source, row, column) + ": '" + text + "' is not a number");
  if (!std::isfinite(v))
    throw ConversionError(where(source, row, column) + ": '" + text + "' is not a finite number");
  return v;
}

int64_t parseInteger64(const TableSource& source, const TableRow& row, size_t column) {
  const std::string& text = row.fields.at(column);
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE)
    throw ConversionError(where(source, row, column) + ": '" + text +
                          "' is not an integer time stamp");
  return static_cast<int64_t>(v);
}

std::vector<double> readNumberGrid(const std::string& file, size_t expected) {
  std::vector<double> values;
  forEachTableRow(file, ' ', [&](const TableSource& source, const TableRow& row) {
    for (size_t c = 0; c < row.fields.size(); ++c)
      values.push_back(parseFiniteDouble(source, row, c));
  });
  if (values.size() != expected)
    throw ConversionError(file + ": expected " + std::to_string(expected) + " numbers, found " +
                          std::to_string(values.size()));
  return values;
}

}  // namespace dynslam::rawlog_tools
