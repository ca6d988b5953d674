#pragma once
// Reading rawlogs back in the converter tests: streaming observations, running rawlog-edit.
#include <mrpt/obs/CObservation.h>

#include <functional>
#include <map>
#include <string>

namespace dynslam::rawlog_tools::testing {

/// Streams every observation of an observations-only rawlog with
/// CRawlog::getActionObservationPairOrObservation. Externally stored images resolve against
/// <dir>/<stem>_Images. Returns the number of observations.
size_t forEachObservation(const std::string& rawlog,
                          const std::function<void(const mrpt::obs::CObservation::Ptr&)>& onObs);

/// Observations per sensor label.
std::map<std::string, size_t> countByLabel(const std::string& rawlog);

/// `rawlog-edit --info -i <name>` run from the rawlog's folder (MRPT's images-folder bug).
struct RawlogEditInfo {
  bool available = false;  ///< rawlog-edit is installed
  int exitCode = -1;
  std::string output;
};
RawlogEditInfo rawlogEditInfo(const std::string& rawlog);

/// Shell-quoted path of a converter program in dynslam::testing::binDir().
std::string program(const std::string& name);
/// The same path, unquoted.
std::string programPath(const std::string& name);

/// Shell-quotes a path for runCommand.
std::string shellQuoted(const std::string& s);

}  // namespace dynslam::rawlog_tools::testing
