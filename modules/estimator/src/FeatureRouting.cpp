#include "dynslam/estimator/FeatureRouting.h"

namespace dynslam::estimator {

RoutedFeatures routeFeatures(const std::vector<core::Feature>& features, DynamicHandling handling,
                             bool nonrigid_factors, bool rigid_factors, double time_offset_s) {
  RoutedFeatures out;
  std::map<int, std::size_t> objectIndex;  // object id -> its entry in out.rigid_objects
  const bool full = handling == DynamicHandling::Full;
  for (const auto& f : features) {
    const Eigen::Vector2d px(f.pixel.x, f.pixel.y);
    // A reading beside a depth edge (Feature::depth_at_edge) is left out: it can switch surfaces.
    const Eigen::Vector2d velocity(f.velocity.x, f.velocity.y);
    const FeatureObservation o{f.id, px, f.depth > 0 && !f.depth_at_edge ? double(f.depth) : 0.0,
                               velocity};
    // remove drops every feature on a detected object, moving or not: Dynamic-VINS masks the
    // detected people and cars out (the paper, section 5: "direct filtering ... reduces the
    // features on people and objects"). Keeping the still ones is the method's own gain (full).
    const bool onObject = f.object_id >= 0;
    const bool landmark =
        handling == DynamicHandling::None || (f.feature_class == core::FeatureClass::Static &&
                                              !(handling == DynamicHandling::Remove && onObject));
    if (landmark) {
      out.landmarks.push_back(o);
      out.pixels[f.id] = px - time_offset_s * velocity;
      continue;
    }
    out.not_landmarks.push_back(f.id);
    if (full && nonrigid_factors && f.feature_class == core::FeatureClass::NonRigid) {
      out.nonrigid.push_back(o);
    } else if (full && rigid_factors && f.feature_class == core::FeatureClass::Rigid &&
               f.object_id >= 0) {
      const auto [it, isNew] = objectIndex.try_emplace(f.object_id, out.rigid_objects.size());
      if (isNew) out.rigid_objects.push_back({f.object_id, {}, std::nullopt});
      out.rigid_objects[it->second].features.push_back(o);
    }
  }
  return out;
}

}  // namespace dynslam::estimator
