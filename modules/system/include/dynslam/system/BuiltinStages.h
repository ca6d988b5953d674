#pragma once
// Every stage class the programs can create by name from [pipeline] stages.
namespace dynslam::core {
class StageRegistry;
}

namespace dynslam::system {

/// Registers the stages of every module linked into the programs.
void registerBuiltinStages(core::StageRegistry& registry);

}  // namespace dynslam::system
