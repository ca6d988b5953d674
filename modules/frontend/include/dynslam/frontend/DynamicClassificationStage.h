#pragma once
// The DynamicClassification stage (ini section [DynamicClassification]): runs a
// DynamicClassifier (scene-flow classification and adaptive rigid point sets, method.md
// sections 3-4) on every frame. Runs after the perception stages (masks and tracks) and
// FeatureTracking (features with ids, pixels and depths); writes each feature's class and
// object id, Frame::object_motions and Frame::rigid_sets.
#include <dynslam/core/Options.h>
#include <dynslam/core/Stage.h>
#include <dynslam/frontend/DynamicClassifier.h>

#include <memory>

namespace dynslam::frontend {

/// [DynamicClassification]: every key, its range and meaning in describe()
/// (DynamicClassificationStage.cpp).
struct DynamicClassificationOptions : core::Options {
  DynamicClassifierParams classifier;

  void describe(core::OptionVisitor& v) override;
};

class DynamicClassificationStage : public core::Stage {
 public:
  void configure(const core::IniConfig& cfg, const std::string& section) override;
  void process(core::Frame& frame) override;
  void finish() override;
  /// frames, features, object_features, dynamic_object_frames, rigid_sets and the frames whose
  /// camera motion came from each source (camera_motion_<source>).
  std::vector<std::pair<std::string, double>> statistics() const override;

  const DynamicClassificationOptions& options() const { return options_; }
  /// The classifier after configure() (for benches: the last camera motion, counters).
  const DynamicClassifier* classifier() const { return classifier_.get(); }

 private:
  DynamicClassificationOptions options_;
  std::unique_ptr<DynamicClassifier> classifier_;
};

}  // namespace dynslam::frontend
