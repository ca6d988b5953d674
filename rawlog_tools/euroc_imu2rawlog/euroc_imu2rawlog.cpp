// euroc_imu2rawlog: converts an EuRoC MAV imu.csv (and optionally groundtruth.csv) into an
// observations-only MRPT rawlog of IMU observations (+ <stem>.gt.tum).
#include <dynslam/core/CommandLine.h>
#include <dynslam/core/TrajectoryFile.h>
#include <dynslam/rawlog_tools/ConversionError.h>
#include <dynslam/rawlog_tools/ObservationBuilders.h>
#include <dynslam/rawlog_tools/OutputPaths.h>
#include <dynslam/rawlog_tools/RawlogWriter.h>
#include <dynslam/rawlog_tools/SensorLabels.h>
#include <dynslam/rawlog_tools/TextTables.h>
#include <dynslam/rawlog_tools/Timestamps.h>
#include <mrpt/obs/CObservationIMU.h>

#include <iostream>
#include <optional>

using namespace dynslam::rawlog_tools;
using dynslam::core::CommandLine;

namespace {

constexpr const char* kUsage =
    R"(Usage: euroc_imu2rawlog --imu imu.csv [--gt groundtruth.csv] --out FILE.rawlog
       euroc_imu2rawlog -h | --help

Converts EuRoC MAV IMU data (csv: t[ns], gyro x y z [rad/s], acc x y z [m/s^2]) into an MRPT
rawlog of CObservationIMU ("IMU") observations with gyro (IMU_WX..WZ) and acc
(IMU_X_ACC..Z_ACC) set, stamped to the 100 ns tick. With --gt, the body (IMU) pose of
groundtruth.csv (t[ns], p x y z, q w x y z, ...) is written as TUM to <stem>.gt.tum.
Every number must be finite and time stamps strictly increasing; otherwise the error names
the file, line and column.

Options:
  --imu FILE          EuRoC imu.csv
  --gt FILE           EuRoC groundtruth.csv (optional)
  --out FILE.rawlog   output rawlog
  -h, --help          print this text and exit

Outputs: FILE.rawlog; with --gt, <stem>.gt.tum beside it (the IMU's pose per groundtruth.csv
row, TUM, stamps in seconds).
Exit codes: 0 written, 1 bad input (the error names the file, line and column), 2 usage.
)";

/// Rejects a stamp that does not follow the previous one (EuRoC stamps strictly increase;
/// a repeated stamp would give a zero integration interval).
class MonotonicStamps {
 public:
  void check(const TableSource& source, const TableRow& row, int64_t stamp) {
    if (previous_ && stamp <= *previous_)
      throw ConversionError(source.file + " line " + std::to_string(row.line) + ": time stamp " +
                            std::to_string(stamp) +
                            (stamp == *previous_ ? " repeats" : " goes backwards from") +
                            " the one on line " + std::to_string(previousLine_) + " (" +
                            std::to_string(*previous_) + ")");
    previous_ = stamp;
    previousLine_ = row.line;
  }

 private:
  std::optional<int64_t> previous_;
  size_t previousLine_ = 0;
};

size_t convertImu(const std::string& imuFile, RawlogWriter& writer) {
  MonotonicStamps stamps;
  forEachTableRow(imuFile, ',', [&](const TableSource& source, const TableRow& row) {
    requireFieldCount(source, row, 7);
    const int64_t t = parseInteger64(source, row, 0);
    std::array<double, 3> gyro{}, acc{};
    for (size_t i = 0; i < 3; ++i) {
      gyro[i] = parseFiniteDouble(source, row, 1 + i);
      acc[i] = parseFiniteDouble(source, row, 4 + i);
    }
    stamps.check(source, row, t);
    writer.write(*makeImuObservation(timeFromNanoseconds(t), kImuLabel, gyro, acc));
  });
  return writer.written();
}

dynslam::core::Trajectory readGroundTruth(const std::string& gtFile) {
  dynslam::core::Trajectory trajectory;
  MonotonicStamps stamps;
  forEachTableRow(gtFile, ',', [&](const TableSource& source, const TableRow& row) {
    requireFieldCount(source, row, 8, /*atLeast=*/true);
    const int64_t t = parseInteger64(source, row, 0);
    double v[7];
    for (size_t i = 0; i < 7; ++i) v[i] = parseFiniteDouble(source, row, 1 + i);
    stamps.check(source, row, t);
    // EuRoC stores the quaternion as w x y z.
    const Eigen::Quaterniond q(v[3], v[4], v[5], v[6]);
    if (std::abs(q.norm() - 1.0) > 1e-3)
      throw ConversionError(source.file + " line " + std::to_string(row.line) +
                            ": quaternion (w x y z) has norm " + std::to_string(q.norm()));
    dynslam::core::StampedPose pose;
    pose.t = secondsFromNanoseconds(t);
    pose.T_world_body = Eigen::Isometry3d::Identity();
    pose.T_world_body.linear() = q.normalized().toRotationMatrix();
    pose.T_world_body.translation() = Eigen::Vector3d(v[0], v[1], v[2]);
    trajectory.push_back(pose);
  });
  return trajectory;
}

int convert(const CommandLine& args) {
  const std::string imuFile = args.required("--imu");
  const RawlogOutputPaths out = rawlogOutputPaths(args.required("--out"));
  // Ground truth is read first so a bad file fails before the (longer) IMU conversion.
  std::optional<dynslam::core::Trajectory> groundTruth;
  if (args.has("--gt")) groundTruth = readGroundTruth(args.required("--gt"));

  RawlogWriter writer(out.rawlog);
  const size_t samples = convertImu(imuFile, writer);
  if (samples == 0) throw ConversionError(imuFile + " holds no IMU samples");
  writer.close();
  std::cout << "wrote " << samples << " " << kImuLabel << " observations to " << out.rawlog << "\n";
  if (groundTruth) {
    dynslam::core::writeTum(out.groundTruth, *groundTruth);
    std::cout << "ground truth: " << groundTruth->size() << " poses to " << out.groundTruth << "\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return dynslam::core::runProgram("euroc_imu2rawlog", [&] {
    CommandLine args({"--imu", "--gt", "--out"}, {});
    args.parse(argc, argv);
    if (args.helpRequested()) {
      std::cout << kUsage;
      return 0;
    }
    return convert(args);
  });
}
