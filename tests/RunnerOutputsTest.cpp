// What `dynslam --out DIR` leaves besides the trajectory (issue 7): map.3Dscene, timing.csv,
// keyframes.csv, the APE in summary.json with --gt, and the annotated video with --frames; on two
// seconds of the simulator's indoor_people_high scenario run through the full system
// (params/sim_vio.ini, ground-truth detector, dynamic_handling = full so the estimator follows
// objects).
#include <dynslam/core/TrajectoryFile.h>
#include <dynslam/evaluation/Alignment.h>
#include <dynslam/evaluation/Association.h>
#include <dynslam/testing/TestEnv.h>

#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CPointCloudColoured.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;
using dynslam::testing::binDir;
using dynslam::testing::readTextFile;
using dynslam::testing::runCommand;
using dynslam::testing::sourceDir;

namespace {

constexpr size_t kFrames = 61;  // 2 s at 30 Hz, both ends included

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  for (std::string field; std::getline(in, field, separator);) fields.push_back(field);
  return fields;
}

/// The number after "key": in a JSON text (the first occurrence after `from`).
double jsonNumber(const std::string& json, const std::string& key, size_t from = 0) {
  const auto at = json.find("\"" + key + "\": ", from);
  if (at == std::string::npos) return std::nan("");
  return std::stod(json.substr(at + key.size() + 4));
}

void checkMapScene(const std::string& sim, const std::string& out) {
  mrpt::opengl::COpenGLScene scene;
  ASSERT_TRUE(scene.loadFromFile(out + "/map.3Dscene"));

  auto camera =
      std::dynamic_pointer_cast<mrpt::opengl::CSetOfLines>(scene.getByName("camera_trajectory"));
  ASSERT_TRUE(camera) << "a CSetOfLines named camera_trajectory";
  EXPECT_EQ(camera->getLineCount(), kFrames - 1) << "one segment between consecutive poses";

  // Every objects/<id>.tum has its polyline object_<id>, through the same positions.
  size_t tracks = 0;
  for (const auto& file : fs::directory_iterator(out + "/objects")) {
    if (file.path().extension() != ".tum") continue;  // states.csv
    const std::string id = file.path().stem().string();
    const auto poses = dynslam::core::readTum(file.path().string());
    auto lines =
        std::dynamic_pointer_cast<mrpt::opengl::CSetOfLines>(scene.getByName("object_" + id));
    ASSERT_TRUE(lines) << "no object_" << id << " for " << file.path();
    ASSERT_EQ(lines->getLineCount(), std::max<size_t>(1, poses.size() - 1)) << id;
    double x0, y0, z0, x1, y1, z1;
    lines->getLineByIndex(lines->getLineCount() - 1, x0, y0, z0, x1, y1, z1);
    const Eigen::Vector3d last = poses.back().T_world_body.translation();
    EXPECT_LT((Eigen::Vector3d(x1, y1, z1) - last).norm(), 1e-5) << id;
    ++tracks;
  }
  EXPECT_GE(tracks, 1u) << "the estimator followed at least one person in 2 s";

  auto cloud =
      std::dynamic_pointer_cast<mrpt::opengl::CPointCloudColoured>(scene.getByName("static_map"));
  ASSERT_TRUE(cloud) << "a CPointCloudColoured named static_map";
  ASSERT_GT(cloud->size(), 5000u);
  EXPECT_EQ(cloud->size(),
            static_cast<size_t>(jsonNumber(readTextFile(out + "/summary.json"), "map_points")));
  // Put the map into the simulator's world by the first pose (the positions of 2 s of path are
  // too close to a line for an SE(3) fit to fix the roll about it): the static points then lie
  // in the 5 m x 6 m x 2.8 m room centred on the origin, floor at z = 0.
  auto pairs =
      dynslam::evaluation::associateByTime(dynslam::core::readTum(sim + "/groundtruth.tum"),
                                           dynslam::core::readTum(out + "/trajectory.tum"));
  const auto alignment = dynslam::evaluation::alignTrajectory(
      pairs.first, pairs.second, dynslam::evaluation::AlignmentMode::None, true);
  size_t outside = 0;
  for (size_t i = 0; i < cloud->size(); ++i) {
    const auto& p = cloud->getPoint3Df(i);
    const Eigen::Vector3d q = alignment.origin_transform * Eigen::Vector3d(p.x, p.y, p.z);
    outside += std::abs(q.x()) > 2.6 || std::abs(q.y()) > 3.1 || q.z() < -0.1 || q.z() > 2.9;
  }
  EXPECT_LT(outside, cloud->size() / 100) << "points outside the room";
}

void checkTimingCsv(const std::string& out) {
  std::ifstream in(out + "/timing.csv");
  std::string header;
  ASSERT_TRUE(std::getline(in, header));
  EXPECT_EQ(header,
            "frame,t_s,Detection_ms,Segmentation_ms,Tracking_ms,Retrack_ms,PredictedBoxes_ms,"
            "FeatureTracking_ms,FloorRemoval_ms,DynamicClassification_ms,Estimator_ms,"
            "ObjectStates_ms,pipeline_ms");
  size_t rows = 0;
  for (std::string line; std::getline(in, line); ++rows) {
    const auto fields = split(line, ',');
    ASSERT_EQ(fields.size(), 13u) << line;
    EXPECT_EQ(std::stoul(fields[0]), rows) << line;
    const double total = std::stod(fields.back());
    for (size_t i = 2; i + 1 < fields.size(); ++i) {
      const double ms = std::stod(fields[i]);
      EXPECT_GE(ms, 0.0) << line;
      EXPECT_LE(ms, total) << "a stage took longer than the whole pipeline: " << line;
    }
  }
  EXPECT_EQ(rows, kFrames);
}

// Every object state of every frame; each id has its objects/<id>.tum with a pose per row.
void checkObjectStatesCsv(const std::string& out) {
  std::ifstream in(out + "/objects/states.csv");
  std::string header;
  ASSERT_TRUE(std::getline(in, header));
  EXPECT_EQ(header,
            "t_s,id,track_id,category,measured,moving,x,y,z,vx,vy,vz,width,depth,height,"
            "sigma_x,sigma_y,sigma_z,sigma_vx,sigma_vy,sigma_vz,up_x,up_y,up_z");
  std::map<std::string, size_t> rowsById;
  for (std::string line; std::getline(in, line);) {
    const auto fields = split(line, ',');
    ASSERT_EQ(fields.size(), 24u) << line;
    EXPECT_EQ(fields[3], "person") << line;
    ++rowsById[fields[1]];
    const double speed = std::hypot(std::stod(fields[9]), std::stod(fields[10]));
    EXPECT_LT(speed, 3.0) << "a walker's speed: " << line;
    EXPECT_GT(std::stod(fields[14]), 0.3) << "a person's height: " << line;
  }
  EXPECT_GE(rowsById.size(), 1u);
  for (const auto& [id, rows] : rowsById)
    EXPECT_EQ(dynslam::core::readTum(out + "/objects/" + id + ".tum").size(), rows) << id;
}

void checkKeyframesCsv(const std::string& out) {
  std::ifstream in(out + "/keyframes.csv");
  std::string header;
  ASSERT_TRUE(std::getline(in, header));
  EXPECT_EQ(header,
            "frame,t_s,reason,static_features,shared_features,nonrigid_features,rigid_objects,"
            "solve_ms,iterations,restarted,visual_inertial,vx,vy,vz,acc_bias_x,acc_bias_y,"
            "acc_bias_z,gyro_bias_x,gyro_bias_y,gyro_bias_z,time_offset_ms,"
            "extrinsic_rotation_change_x_deg,extrinsic_rotation_change_y_deg,"
            "extrinsic_rotation_change_z_deg,extrinsic_translation_change_x,"
            "extrinsic_translation_change_y,extrinsic_translation_change_z,time_offset_free,"
            "extrinsic_free");
  size_t rows = 0;
  long lastFrame = -1;
  for (std::string line; std::getline(in, line); ++rows) {
    const auto fields = split(line, ',');
    ASSERT_EQ(fields.size(), 29u) << line;
    // Neither the time offset nor the extrinsic is estimated by params/sim_vio.ini.
    for (size_t c = 20; c < 29; ++c) EXPECT_EQ(std::stod(fields[c]), 0.0) << line;
    const long frame = std::stol(fields[0]);
    EXPECT_GT(frame, lastFrame) << line;
    EXPECT_LT(frame, static_cast<long>(kFrames)) << line;
    lastFrame = frame;
    const std::string& reason = fields[2];
    EXPECT_EQ(reason == "first", rows == 0) << line;
    EXPECT_TRUE(reason == "first" || reason == "parallax" || reason == "interval" ||
                reason == "few_shared")
        << line;
    EXPECT_GE(std::stoi(fields[3]), std::stoi(fields[4])) << "shared among the static: " << line;
    EXPECT_GE(std::stod(fields[7]), 0.0) << line;
    EXPECT_TRUE(fields[10] == "0" || fields[10] == "1") << line;
  }
  EXPECT_GE(rows, 5u) << "keyframes in 2 s";
  EXPECT_EQ(static_cast<double>(rows),
            jsonNumber(readTextFile(out + "/summary.json"), "keyframes"));
}

void checkSummaryApe(const std::string& sim, const std::string& out, const std::string& log) {
  EXPECT_NE(log.find("dynslam: APE RMSE "), std::string::npos) << log;
  const std::string summary = readTextFile(out + "/summary.json");
  const auto ape = summary.find("\"ape\": {");
  ASSERT_NE(ape, std::string::npos) << summary;
  EXPECT_EQ(jsonNumber(summary, "pairs", ape), static_cast<double>(kFrames));
  const auto eval = runCommand(binDir() + "/dynslam-eval ape " + sim + "/groundtruth.tum " + out +
                               "/trajectory.tum --align se3 --json " + out + "/ape_eval.json");
  ASSERT_EQ(eval.exit_code, 0) << eval.output;
  const std::string reference = readTextFile(out + "/ape_eval.json");
  for (const char* key : {"rmse", "mean", "median", "std", "min", "max"})
    EXPECT_NEAR(jsonNumber(summary, key, ape), jsonNumber(reference, key), 1e-12) << key;
  // The simulator's camera: the full system stays within centimetres on it.
  EXPECT_LT(jsonNumber(summary, "rmse", ape), 0.1);
  EXPECT_NE(summary.find("\"median_ms\""), std::string::npos);
  EXPECT_GT(jsonNumber(summary, "fps"), 0.0);
  // The cores the run kept busy: some work, and no more than its threads could do (reader,
  // pipeline, and at most the machine's cores for OpenCV and Ceres).
  const double cores = jsonNumber(summary, "cpu_cores");
  EXPECT_GT(cores, 0.05);
  EXPECT_LE(cores, std::max(3.0, 1.0 + std::thread::hardware_concurrency()));
  EXPECT_NEAR(jsonNumber(summary, "cpu_time_s"), cores * jsonNumber(summary, "wall_time_s"), 0.01);
}

void checkFramesAndVideo(const std::string& frames) {
  EXPECT_TRUE(fs::exists(frames + "/000000.png"));
  EXPECT_TRUE(fs::exists(frames + "/000060.png"));
  cv::VideoCapture video(frames + "/annotated.avi");
  ASSERT_TRUE(video.isOpened());
  EXPECT_EQ(video.get(cv::CAP_PROP_FRAME_COUNT), static_cast<double>(kFrames));
  EXPECT_NEAR(video.get(cv::CAP_PROP_FPS), 30.0, 0.01);
  cv::Mat first;
  ASSERT_TRUE(video.read(first));
  EXPECT_EQ(first.size(), cv::Size(640, 480));
}

}  // namespace

// One run for all the checks (a simulated sequence and the full system take ~10 s).
TEST(RunnerOutputs, TheFullSystemOnTwoSimulatedSecondsLeavesEveryOutput) {
  const std::string dir = dynslam::testing::scratchDir();
  const std::string sim = dir + "/sim", out = dir + "/out", frames = dir + "/frames";
  const auto render = runCommand(binDir() + "/dynslam-sim --config " + sourceDir() +
                                 "/params/sim/indoor_people_high.ini --out " + sim +
                                 " --set Scenario.duration=2 --quiet");
  ASSERT_EQ(render.exit_code, 0) << render.output;
  const auto run =
      runCommand(binDir() + "/dynslam --config " + sourceDir() + "/params/sim_vio.ini --rawlog " +
                 sim + "/sim.rawlog --out " + out + " --set Detection.objects=" + sim +
                 "/objects.txt --set Estimator.dynamic_handling=full --gt " + sim +
                 "/groundtruth.tum --frames " + frames + " --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  {
    SCOPED_TRACE("map.3Dscene");
    checkMapScene(sim, out);
  }
  {
    SCOPED_TRACE("timing.csv");
    checkTimingCsv(out);
  }
  {
    SCOPED_TRACE("keyframes.csv");
    checkKeyframesCsv(out);
  }
  {
    SCOPED_TRACE("objects/states.csv");
    checkObjectStatesCsv(out);
  }
  {
    SCOPED_TRACE("summary.json's APE");
    checkSummaryApe(sim, out, run.output);
  }
  {
    SCOPED_TRACE("--frames");
    checkFramesAndVideo(frames);
  }
}

TEST(RunnerGroundTruth, AMissingGroundTruthFileIsNamedBeforeTheRun) {
  const std::string dir = dynslam::testing::scratchDir();
  const auto r =
      runCommand(binDir() + "/dynslam --config " + sourceDir() + "/params/sim_vio.ini --rawlog " +
                 dir + "/none.rawlog --out " + dir + "/out --gt " + dir + "/nope.tum --quiet");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find(dir + "/nope.tum"), std::string::npos) << r.output;
}
