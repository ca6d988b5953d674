#pragma once
// What a run is configured with: the stages of [pipeline] and [SensorSync], built from the ini
// with the strict rules (unknown stage classes, sections and keys are errors); and
// `dynslam --print-config`, the same configuration written out as an ini.
#include <dynslam/core/Config.h>
#include <dynslam/core/Pipeline.h>
#include <dynslam/io/SensorSync.h>

#include <ostream>
#include <string>
#include <vector>

namespace dynslam::system {

struct RunConfiguration {
  core::Pipeline pipeline;
  io::SensorSyncOptions sync;
};

/// Creates and configures the built-in stages [pipeline] lists and reads [SensorSync]; throws
/// core::ConfigError for an unknown stage class, key, or a section nothing reads.
RunConfiguration configureRun(const core::IniConfig& cfg);

/// Configures the pipeline of `config` with `overrides` applied, as a run would (the same
/// errors for unknown stages, sections and keys), and writes every section the run reads with
/// every key at the value it would use, `key = value // meaning`: the ini's values and the
/// defaults of whatever it leaves out. Stages configured apart (Class:Section) each get their
/// section.
void printEffectiveConfig(const std::string& config, const std::vector<std::string>& overrides,
                          std::ostream& out);

}  // namespace dynslam::system
