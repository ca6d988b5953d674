#include <dynslam/rawlog_tools/ConversionError.h>
#include <dynslam/rawlog_tools/TextTables.h>
#include <dynslam/testing/TestEnv.h>
#include <gtest/gtest.h>

#include <fstream>

using namespace dynslam::rawlog_tools;

namespace {
std::string writeFile(const std::string& name, const std::string& text) {
  const std::string path = dynslam::testing::scratchDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}
std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const ConversionError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(RawlogToolsTextTables, SkipsCommentsAndNamesColumnsFromTheHeader) {
  const std::string file = writeFile("t.csv", "#t,x , y\n\n1,2.5,-3\n# later comment\n4,5,6\n");
  std::vector<size_t> lines;
  std::vector<double> values;
  forEachTableRow(file, ',', [&](const TableSource& source, const TableRow& row) {
    EXPECT_EQ(source.columnNames, (std::vector<std::string>{"t", "x", "y"}));
    lines.push_back(row.line);
    for (size_t c = 0; c < row.fields.size(); ++c)
      values.push_back(parseFiniteDouble(source, row, c));
  });
  EXPECT_EQ(lines, (std::vector<size_t>{3, 5}));
  EXPECT_EQ(values, (std::vector<double>{1, 2.5, -3, 4, 5, 6}));
}

TEST(RawlogToolsTextTables, ErrorsNameFileLineColumnAndText) {
  const std::string file = writeFile("bad.csv", "#t,x,y\n1,2,3\n2,inf,3\n3,4,\n");
  std::vector<std::string> errors;
  forEachTableRow(file, ',', [&](const TableSource& source, const TableRow& row) {
    for (size_t c = 0; c < row.fields.size(); ++c)
      errors.push_back(errorOf([&] { parseFiniteDouble(source, row, c); }));
  });
  ASSERT_EQ(errors.size(), 9u);
  EXPECT_EQ(errors[4], file + " line 3, column 2 (x): 'inf' is not a finite number");
  EXPECT_EQ(errors[8], file + " line 4, column 3 (y): '' is not a number");
  EXPECT_EQ(errorOf([] { forEachTableRow("/nonexistent.csv", ',', [](auto&, auto&) {}); }),
            "cannot open /nonexistent.csv");
}

TEST(RawlogToolsTextTables, NumberGridCountsNumbers) {
  EXPECT_EQ(readNumberGrid(writeFile("k.txt", "1 0 2\n0 3 4\n0 0 1\n"), 9).at(5), 4.0);
  EXPECT_NE(errorOf([] { readNumberGrid(writeFile("k.txt", "1 0 2\n"), 9); }).find("expected 9"),
            std::string::npos);
}
