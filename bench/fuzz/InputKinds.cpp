#include "InputKinds.h"

#include <dynslam/testing/SyntheticObservations.h>
#include <dynslam/testing/SyntheticRoom.h>
#include <dynslam/testing/TestEnv.h>

#include <unistd.h>

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;
namespace dt = dynslam::testing;

namespace dynslam::bench::fuzz {
namespace {

constexpr int kFrames = 10;

std::string encode(const cv::Mat& image, const char* extension) {
  std::vector<uchar> bytes;
  if (!cv::imencode(extension, image, bytes)) throw std::runtime_error("cannot encode a sample");
  return std::string(bytes.begin(), bytes.end());
}

core::CameraIntrinsics smallCamera() {
  core::CameraIntrinsics k;
  k.width = 160;
  k.height = 120;
  k.fx = k.fy = 131.25;
  k.cx = 79.5;
  k.cy = 59.5;
  return k;
}

/// The room seen along the handheld path at 30 Hz, a 200 Hz IMU between frames and one GGA
/// fix: every observation type dynslam reads, with the images inside the rawlog (so mutations
/// reach the image and depth fields, not only an external file name).
std::string roomRawlog(const std::string& scratch, bool gzip) {
  const auto path = dt::handheldPath(kFrames);
  std::vector<mrpt::serialization::CSerializable::Ptr> objects;
  objects.push_back(dt::makeGga(100.0 - 0.05, 48.1, 11.5, 520.0));
  for (int i = 0; i < kFrames; ++i) {
    const double t = 100.0 + i / 30.0;
    for (int j = 1; j <= 6; ++j) objects.push_back(dt::makeImu(t - 1 / 30.0 + j / 200.0));
    objects.push_back(dt::makeRoomScan(t, path[size_t(i)], smallCamera()));
  }
  const std::string file = scratch + (gzip ? "/room_gz.rawlog" : "/room.rawlog");
  {
    std::unique_ptr<mrpt::io::CStream> out;
    if (gzip)
      out = std::make_unique<mrpt::io::CFileGZOutputStream>(file);
    else
      out = std::make_unique<mrpt::io::CFileOutputStream>(file);
    auto archive = mrpt::serialization::archiveFrom(*out);
    for (const auto& o : objects) archive << *o;
  }
  return dt::readTextFile(file);
}

const char* kPipelineIni =
    "[pipeline]\nstages = FeatureTracking, Estimator\n"
    "[FeatureTracking]\nmax_features = 150\n"
    "[Estimator]\ndynamic_handling = none\ngyro_rotation_sigma = 0\nmax_solver_time = 100\n";

std::string tumLine(double t, const Eigen::Isometry3d& T) {
  const Eigen::Quaterniond q(T.rotation());
  char line[256];
  std::snprintf(line, sizeof line, "%.6f %.6f %.6f %.6f %.6f %.6f %.6f %.6f\n", t,
                T.translation().x(), T.translation().y(), T.translation().z(), q.x(), q.y(), q.z(),
                q.w());
  return line;
}

InputKind rawlogKind(const std::string& bin, const std::string& scratch,
                     const std::string& plainRawlog) {
  InputKind k{"rawlog",
              {{"room.rawlog", plainRawlog, false, true},
               {"room_gz.rawlog", roomRawlog(scratch, true), false, true},
               {"fuzz.ini", kPipelineIni, true, false}},
              {}};
  k.command = [bin](const std::string& dir, const std::string& mutated) {
    return std::vector<std::string>{bin + "/dynslam",    "--config", dir + "/fuzz.ini", "--rawlog",
                                    dir + "/" + mutated, "--out",    dir + "/out"};
  };
  return k;
}

/// Every key of every section the pipeline reads, at the values a run would use (dynslam
/// --print-config): mutations reach each option's parsing and range check.
InputKind iniKind(const std::string& bin, const std::string& scratch,
                  const std::string& plainRawlog) {
  const std::string base = scratch + "/base.ini", printed = scratch + "/printed.ini";
  std::ofstream(base) << "[pipeline]\nstages = FeatureTracking, DynamicClassification, "
                         "Segmentation, Tracking, Estimator\n";
  const std::string command =
      bin + "/dynslam --config " + base + " --print-config > " + printed + " 2>/dev/null";
  std::string ini = std::system(command.c_str()) == 0 ? dt::readTextFile(printed) : "";
  if (ini.empty()) ini = kPipelineIni;  // the base case then says what failed
  InputKind k{
      "ini", {{"fuzz.ini", ini, true, true}, {"room.rawlog", plainRawlog, false, false}}, {}};
  k.command = [bin](const std::string& dir, const std::string&) {
    return std::vector<std::string>{bin + "/dynslam", "--config",           dir + "/fuzz.ini",
                                    "--rawlog",       dir + "/room.rawlog", "--out",
                                    dir + "/out",     "--max-frames",       "4"};
  };
  return k;
}

/// Two turns of a rising helix (Umeyama's alignment needs a path that is not a line).
std::vector<Eigen::Isometry3d> helix(int poses) {
  std::vector<Eigen::Isometry3d> path;
  for (int i = 0; i < poses; ++i) {
    const double a = 4 * M_PI * i / poses;
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    T.translation() = Eigen::Vector3d(std::cos(a), std::sin(a), 0.01 * i);
    path.push_back(T);
  }
  return path;
}

InputKind trajectoryKind(const std::string& bin) {
  const auto path = helix(60);
  std::string ref = "# t tx ty tz qx qy qz qw\n", est = ref, kittiRef, kittiEst,
              euroc = "#timestamp [ns],p_x,p_y,p_z,q_w,q_x,q_y,q_z\n";
  for (size_t i = 0; i < path.size(); ++i) {
    const double t = 100.0 + double(i) / 30.0;
    Eigen::Isometry3d noisy = path[i];
    noisy.translation() +=
        Eigen::Vector3d(0.002 * std::sin(double(i)), 0.001, -0.001 * double(i % 3));
    ref += tumLine(t, path[i]);
    est += tumLine(t + 0.001, noisy);
    const Eigen::Isometry3d* pose[] = {&path[i], &noisy};
    std::string* rows[] = {&kittiRef, &kittiEst};
    for (int f = 0; f < 2; ++f) {
      const Eigen::Isometry3d* T = pose[f];
      std::ostringstream row;
      row.precision(9);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) row << (r || c ? " " : "") << T->matrix()(r, c);
      *rows[f] += row.str() + "\n";
    }
    const Eigen::Quaterniond q(path[i].rotation());
    char line[256];
    std::snprintf(line, sizeof line, "%lld,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f\n",
                  static_cast<long long>(t * 1e9), path[i].translation().x(),
                  path[i].translation().y(), path[i].translation().z(), q.w(), q.x(), q.y(), q.z());
    euroc += line;
  }
  InputKind k{"trajectory",
              {{"ref.tum", ref, true, true},
               {"est.tum", est, true, true},
               {"ref.kitti", kittiRef, true, true},
               {"est.kitti", kittiEst, true, true},
               {"ref.csv", euroc, true, true}},
              {}};
  k.command = [bin](const std::string& dir, const std::string& mutated) {
    std::vector<std::string> argv{bin + "/dynslam-eval", mutated == "est.tum" ? "rpe" : "ape"};
    if (mutated.find("kitti") != std::string::npos) {
      argv.insert(argv.end(), {dir + "/ref.kitti", dir + "/est.kitti", "--format", "kitti"});
    } else if (mutated == "ref.csv") {
      argv.insert(argv.end(), {dir + "/ref.csv", dir + "/est.tum", "--ref-format", "euroc"});
    } else {
      argv.insert(argv.end(), {dir + "/ref.tum", dir + "/est.tum"});
    }
    argv.insert(argv.end(),
                {"--align", "sim3", "--json", dir + "/out.json", "--plot", dir + "/out.png"});
    return argv;
  };
  return k;
}

/// A 7-Scenes sequence folder of three 160 x 120 frames (the real ones are 640 x 480).
InputKind sevenScenesKind(const std::string& bin) {
  const auto cam = smallCamera();
  const auto path = dt::handheldPath(3);
  InputKind k{"sevenscenes", {}, {}};
  std::ostringstream intrinsics;
  intrinsics << cam.fx << " 0 " << cam.cx << "\n0 " << cam.fy << " " << cam.cy << "\n0 0 1\n";
  k.files.push_back({"seq/camera-intrinsics.txt", intrinsics.str(), true, true});
  for (int i = 0; i < 3; ++i) {
    cv::Mat rgb, depth, depthMm;
    dt::renderRoom(path[size_t(i)], cam, rgb, depth);
    depth.convertTo(depthMm, CV_16UC1, 1000.0);
    char stem[32];
    std::snprintf(stem, sizeof stem, "seq/frame-%06d", i);
    std::ostringstream pose;
    pose.precision(12);
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) pose << path[size_t(i)].matrix()(r, c) << (c == 3 ? "\n" : " ");
    k.files.push_back({std::string(stem) + ".color.jpg", encode(rgb, ".jpg"), false, true});
    k.files.push_back({std::string(stem) + ".depth.png", encode(depthMm, ".png"), false, true});
    k.files.push_back({std::string(stem) + ".pose.txt", pose.str(), true, true});
  }
  k.command = [bin](const std::string& dir, const std::string&) {
    return std::vector<std::string>{bin + "/sevenscenes2rawlog", "--in", dir + "/seq", "--out",
                                    dir + "/out/seq.rawlog"};
  };
  return k;
}

/// A TUM RGB-D folder: lists, PNGs, accelerometer and ground truth, four frames.
InputKind tumKind(const std::string& bin) {
  const auto cam = smallCamera();
  const auto path = dt::handheldPath(4);
  const std::string seq = "rgbd_dataset_freiburg1_fuzz/";
  InputKind k{"tum", {}, {}};
  std::string rgbList = "# color images\n# timestamp filename\n";
  std::string depthList = "# depth maps\n# timestamp filename\n";
  std::string acc = "# accelerometer data\n# timestamp ax ay az\n";
  std::string gt = "# ground truth trajectory\n# timestamp tx ty tz qx qy qz qw\n";
  for (int i = 0; i < 4; ++i) {
    cv::Mat rgb, depth, depth5k;
    dt::renderRoom(path[size_t(i)], cam, rgb, depth);
    depth.convertTo(depth5k, CV_16UC1, 5000.0);
    char t[32], td[32];
    std::snprintf(t, sizeof t, "%.6f", 100.0 + i / 30.0);
    std::snprintf(td, sizeof td, "%.6f", 100.0 + i / 30.0 + 0.004);
    rgbList += std::string(t) + " rgb/" + t + ".png\n";
    depthList += std::string(td) + " depth/" + td + ".png\n";
    k.files.push_back({seq + "rgb/" + t + ".png", encode(rgb, ".png"), false, true});
    k.files.push_back({seq + "depth/" + td + ".png", encode(depth5k, ".png"), false, true});
    acc += std::string(t) + " 0.1 -9.8 0.2\n";
    gt += tumLine(100.0 + i / 30.0, path[size_t(i)]);
  }
  k.files.push_back({seq + "rgb.txt", rgbList, true, true});
  k.files.push_back({seq + "depth.txt", depthList, true, true});
  k.files.push_back({seq + "accelerometer.txt", acc, true, true});
  k.files.push_back({seq + "groundtruth.txt", gt, true, true});
  k.command = [bin, seq](const std::string& dir, const std::string&) {
    return std::vector<std::string>{bin + "/tum2rawlog", "--in", dir + "/" + seq, "--out",
                                    dir + "/out/seq.rawlog"};
  };
  return k;
}

}  // namespace

std::vector<InputKind> makeInputKinds(const std::string& bin,
                                      const std::vector<std::string>& only) {
  const auto wanted = [&](const char* name) {
    return only.empty() || std::find(only.begin(), only.end(), name) != only.end();
  };
  const std::string scratch =
      (fs::temp_directory_path() / ("fuzz-base-" + std::to_string(::getpid()))).string();
  fs::create_directories(scratch);
  std::vector<InputKind> kinds;
  const std::string plainRawlog =
      wanted("rawlog") || wanted("ini") ? roomRawlog(scratch, false) : "";  // both use it
  if (wanted("rawlog")) kinds.push_back(rawlogKind(bin, scratch, plainRawlog));
  if (wanted("ini")) kinds.push_back(iniKind(bin, scratch, plainRawlog));
  if (wanted("trajectory")) kinds.push_back(trajectoryKind(bin));
  if (wanted("sevenscenes")) kinds.push_back(sevenScenesKind(bin));
  if (wanted("tum")) kinds.push_back(tumKind(bin));
  fs::remove_all(scratch);
  return kinds;
}

}  // namespace dynslam::bench::fuzz
