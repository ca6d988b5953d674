#pragma once
// Reading the EuRoC csv files of ../shared/data/euroc_v102_imu for the tests on real IMU data:
// imu.csv (t[ns], gyro xyz, acc xyz) and groundtruth.csv (t[ns], p, q(w,x,y,z), v, gyro bias,
// acc bias), one row of numbers per line, '#' header skipped.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace dynslam::estimator::testing {

inline std::vector<std::vector<double>> readEurocCsv(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream s(line);
    std::vector<double> row;
    for (double v; s >> v;) row.push_back(v);
    rows.push_back(row);
  }
  return rows;
}

/// A csv time column (nanoseconds, read as a double) as an exact integer key.
inline long long eurocNanoseconds(double v) { return static_cast<long long>(std::llround(v)); }

}  // namespace dynslam::estimator::testing
