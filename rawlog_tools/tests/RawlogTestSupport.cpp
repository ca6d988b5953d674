#include "RawlogTestSupport.h"

#include <dynslam/testing/TestEnv.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/lazy_load_path.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <stdexcept>

namespace fs = std::filesystem;

namespace dynslam::rawlog_tools::testing {

size_t forEachObservation(const std::string& rawlog,
                          const std::function<void(const mrpt::obs::CObservation::Ptr&)>& onObs) {
  const fs::path path(rawlog);
  mrpt::io::setLazyLoadPathBase((path.parent_path() / (path.stem().string() + "_Images")).string());
  mrpt::io::CFileGZInputStream file;
  if (!file.open(rawlog)) throw std::runtime_error("cannot open " + rawlog);
  auto in = mrpt::serialization::archiveFrom(file);
  mrpt::obs::CActionCollection::Ptr actions;
  mrpt::obs::CSensoryFrame::Ptr frame;
  mrpt::obs::CObservation::Ptr obs;
  size_t entry = 0, count = 0;
  while (
      mrpt::obs::CRawlog::getActionObservationPairOrObservation(in, actions, frame, obs, entry)) {
    if (!obs) continue;  // these rawlogs hold observations only
    onObs(obs);
    ++count;
    obs.reset();
  }
  return count;
}

std::map<std::string, size_t> countByLabel(const std::string& rawlog) {
  std::map<std::string, size_t> counts;
  forEachObservation(rawlog,
                     [&](const mrpt::obs::CObservation::Ptr& o) { ++counts[o->sensorLabel]; });
  return counts;
}

std::string programPath(const std::string& name) {
  return (fs::path(dynslam::testing::binDir()) / name).string();
}

std::string program(const std::string& name) { return shellQuoted(programPath(name)); }

std::string shellQuoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

RawlogEditInfo rawlogEditInfo(const std::string& rawlog) {
  RawlogEditInfo info;
  info.available = dynslam::testing::runCommand("command -v rawlog-edit").exit_code == 0;
  if (!info.available) return info;
  const fs::path path = fs::absolute(rawlog);
  const auto r = dynslam::testing::runCommand("cd " + shellQuoted(path.parent_path().string()) +
                                              " && rawlog-edit --info -i " +
                                              shellQuoted(path.filename().string()));
  info.exitCode = r.exit_code;
  info.output = r.output;
  return info;
}

}  // namespace dynslam::rawlog_tools::testing
