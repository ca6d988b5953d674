// SlidingWindow's optimisation: the factor graph its states make (ProblemBuilder, the one list
// of factors both the solve and the marginalisation use), the solve, and the marginalisation of
// the oldest keyframe into the prior. SlidingWindow.cpp keeps the states themselves.
#include "dynslam/estimator/SlidingWindow.h"

#include "dynslam/estimator/Marginalizer.h"
#include "dynslam/estimator/StateBlocks.h"
#include "dynslam/estimator/factors/CalibrationPriorFactor.h"
#include "dynslam/estimator/factors/CameraPosePriorFactor.h"
#include "dynslam/estimator/factors/GnssPositionFactor.h"
#include "dynslam/estimator/factors/GyroRotationFactor.h"
#include "dynslam/estimator/factors/ImuFactor.h"
#include "dynslam/estimator/factors/NonRigidConstantVelocityFactor.h"
#include "dynslam/estimator/factors/NonRigidDepthFactor.h"
#include "dynslam/estimator/factors/RigidObjectDepthFactor.h"
#include "dynslam/estimator/factors/RigidObjectReprojectionFactor.h"
#include "dynslam/estimator/factors/RigidSmoothMotionFactor.h"
#include "dynslam/estimator/factors/StaticReprojectionFactor.h"
#include "dynslam/estimator/factors/TransferredDepthFactor.h"

#include <ceres/ceres.h>

#include <cmath>
#include <functional>
#include <memory>
#include <set>

namespace dynslam::estimator {

/// Observations putting a point nearer than this to the camera (m, along the optical axis) are
/// left out of the problem: the reprojection factors cannot be evaluated there.
constexpr double kMinLandmarkDepth = 0.05;

using FactorSink = std::function<void(std::shared_ptr<const ceres::CostFunction>,
                                      const ceres::LossFunction*, std::vector<double*>)>;

/// Lists the window's factors: all of them (for a solve) or only those touching one keyframe
/// (for its marginalisation), so the two cannot disagree on what the graph holds.
class SlidingWindow::ProblemBuilder {
 public:
  /// `free_calibration`: every estimated calibration state free, also where the window's motion
  /// holds it (for its covariance).
  explicit ProblemBuilder(SlidingWindow& w, bool free_calibration = false)
      : w_(w),
        huber_(w.params_.huber_sigmas),
        gnss_huber_(w.params_.gnss_huber_sigmas),
        free_calibration_(free_calibration) {}

  /// `only`: a keyframe id, or -1 for every factor. Returns the landmarks given factors, and in
  /// `objects` the rigid objects given factors.
  int forEachFactor(std::int64_t only, const FactorSink& sink, int* objects = nullptr) {
    int landmarks = 0;
    for (auto& [id, l] : w_.landmarks_.all()) landmarks += landmarkFactors(l, only, sink);
    for (auto& [id, p] : w_.nonrigid_) landmarks += nonRigidFactors(p, only, sink);
    // Rigid objects: none when marginalising (SlidingWindow.h: they are dropped, not kept).
    if (only < 0)
      for (auto& [id, o] : w_.objects_.all()) {
        const bool used = rigidObjectFactors(o, sink);
        if (objects) *objects += used;
      }
    for (size_t k = 1; k < w_.keyframes_.size(); ++k) {
      Keyframe& a = w_.keyframes_[k - 1];
      Keyframe& b = w_.keyframes_[k];
      if (w_.params_.use_imu && b.preintegration) {
        if (only < 0 || only == a.id || only == b.id)
          sink(std::make_shared<ImuFactor>(b.preintegration), nullptr,
               {a.pose, a.speed_bias, b.pose, b.speed_bias, w_.gravity_});
      } else if (!w_.params_.use_imu) {
        if (k >= 2) {
          Keyframe& z = w_.keyframes_[k - 2];
          if (only < 0 || only == z.id || only == a.id || only == b.id)
            sink(
                std::make_shared<RigidSmoothMotionFactor>(w_.params_.motion_prior_sigma_translation,
                                                          w_.params_.motion_prior_sigma_rotation),
                nullptr, {z.pose, a.pose, b.pose});
        }
        // An IMU not yet initialized still gives the rotation (GyroRotationFactor.h).
        if (b.preintegration && w_.params_.gyro_rotation_sigma > 0 &&
            (only < 0 || only == a.id || only == b.id)) {
          const double sigma = w_.params_.gyro_rotation_sigma * b.preintegration->sumDt();
          sink(std::make_shared<GyroRotationFactor>(b.preintegration->gamma(),
                                                    sigma * sigma * Eigen::Matrix3d::Identity()),
               nullptr, {a.pose, b.pose});
        }
      }
    }
    for (Keyframe& k : w_.keyframes_)
      if (k.gnss && (only < 0 || only == k.id))
        sink(std::make_shared<GnssPositionFactor>(k.gnss->world, w_.params_.gnss_lever_arm,
                                                  k.gnss->covariance),
             &gnss_huber_, {k.pose});
    if (w_.prior_.factor) sink(w_.prior_.factor, nullptr, w_.prior_.blocks);
    // The gauge by the first keyframe's camera (CameraPosePriorFactor.h), marginalised with it.
    if (w_.camera_anchor_ && (only < 0 || only == w_.keyframes_.front().id)) {
      constexpr double kAnchorSigma = 1e-5;  // m and rad: held, as a constant pose would be
      sink(std::make_shared<CameraPosePriorFactor>(*w_.camera_anchor_, kAnchorSigma, kAnchorSigma),
           nullptr, {w_.keyframes_.front().pose, w_.extrinsic_});
    }
    if (only < 0) calibrationPriors(sink);
    return landmarks;
  }

  /// Puts the window's blocks and every factor into `problem`, holds the gauges and bounds the
  /// inverse depths. The builder must outlive the solve (its losses are in the problem).
  SolveReport fill(ceres::Problem& problem, PoseManifold& manifold,
                   std::vector<std::shared_ptr<const ceres::CostFunction>>& keep) {
    for (auto& k : w_.keyframes_) {
      problem.AddParameterBlock(k.pose, 7, &manifold);
      if (w_.params_.use_imu) problem.AddParameterBlock(k.speed_bias, 9);
    }
    problem.AddParameterBlock(w_.extrinsic_, 7, &manifold);
    if (!(free_calibration_ ? w_.estimatesExtrinsic() : w_.extrinsicFree()))
      problem.SetParameterBlockConstant(w_.extrinsic_);
    if (w_.params_.use_imu) {
      problem.AddParameterBlock(w_.gravity_, 3, &sphere_);  // its norm stays the initializer's
      if (!(free_calibration_ ? w_.estimatesExtrinsic() : w_.gravityFree()))
        problem.SetParameterBlockConstant(w_.gravity_);
    }
    problem.AddParameterBlock(w_.time_offset_, 1);
    if (!(free_calibration_ ? w_.estimatesTimeOffset() : w_.timeOffsetFree()))
      problem.SetParameterBlockConstant(w_.time_offset_);
    std::set<const double*> objectPoses;  // pose blocks too: they need the manifold
    for (auto& [id, o] : w_.objects_.all())
      for (auto& [kf, L] : o.poses) objectPoses.insert(L.data());
    SolveReport report;
    report.landmarks = forEachFactor(
        -1,
        [&](std::shared_ptr<const ceres::CostFunction> f, const ceres::LossFunction* loss,
            std::vector<double*> blocks) {
          for (double* b : blocks)
            if (objectPoses.count(b) && !problem.HasParameterBlock(b))
              problem.AddParameterBlock(b, kPoseSize, &manifold);
          problem.AddResidualBlock(const_cast<ceres::CostFunction*>(f.get()),
                                   const_cast<ceres::LossFunction*>(loss), blocks);
          keep.push_back(std::move(f));
        },
        &report.rigid_objects);
    // Each object's frame (a gauge freedom): its oldest L in the problem is held.
    for (auto& [id, o] : w_.objects_.all())
      for (auto& [kf, L] : o.poses)
        if (problem.HasParameterBlock(L.data())) {
          problem.SetParameterBlockConstant(L.data());
          break;
        }
    for (auto& [id, l] : w_.landmarks_.all())
      if (problem.HasParameterBlock(&l.inverse_depth))
        problem.SetParameterLowerBound(&l.inverse_depth, 0, 1e-3);
    // Gauge: without a prior the first keyframe is held (with an IMU, roll and pitch would be
    // observable, but yaw and position are not).
    if (!w_.prior_.factor && !w_.camera_anchor_)
      problem.SetParameterBlockConstant(w_.keyframes_.front().pose);
    return report;
  }

 private:
  /// The priors of the calibration states the window estimates (never marginalised).
  void calibrationPriors(const FactorSink& sink) {
    const CalibrationParams& c = w_.params_.calibration;
    // While settling (SlidingWindow.cpp), held near where they are by tight priors.
    const bool settling = w_.calibrationSettling();
    constexpr double kSettlingTimeSigma = 1e-4, kSettlingRotationSigma = 1e-4;
    if (w_.estimatesTimeOffset())
      sink(std::make_shared<TimeOffsetPriorFactor>(
               settling ? w_.time_offset_[0] : c.time_offset_s,
               settling ? kSettlingTimeSigma : c.time_offset_sigma_s),
           nullptr, {w_.time_offset_});
    if (w_.estimatesExtrinsic()) {
      // rotation: the translation is held by a prior a hundred times tighter than a millimetre
      // error could matter (one block, one manifold for both modes).
      constexpr double kHeldTranslationSigma = 1e-5;
      const double sigmaP = c.estimate_extrinsic == ExtrinsicEstimation::Full
                                ? c.extrinsic_sigma_translation_m
                                : kHeldTranslationSigma;
      sink(std::make_shared<ExtrinsicPriorFactor>(
               settling ? w_.extrinsic() : w_.extrinsic_prior_,
               settling ? kHeldTranslationSigma : sigmaP,
               settling ? kSettlingRotationSigma : c.extrinsic_sigma_rotation_deg * M_PI / 180),
           nullptr, {w_.extrinsic_});
    }
  }

  /// r_D for one non-rigid point seen in at least two keyframes: the constant-velocity
  /// reprojection and the measured depth in each. With `only`, the point's factors when it was
  /// first seen in that keyframe (it is marginalised with it), none otherwise.
  int nonRigidFactors(NonRigidPoint& p, std::int64_t only, const FactorSink& sink) {
    if (p.observations.size() < 2) return 0;
    if (only >= 0 && p.observations.begin()->first != only) return 0;
    const Eigen::Vector3d position(p.position), velocity(p.velocity);
    std::vector<std::pair<Keyframe*, const LandmarkObservation*>> seen;
    for (auto& [kf, obs] : p.observations) {
      Keyframe* k = w_.keyframe(kf);
      if (!k) continue;
      if (w_.depthIn(*k, position + (k->t - p.t0) * velocity) >= kMinLandmarkDepth)
        seen.emplace_back(k, &obs);
    }
    if (seen.size() < 2) return 0;  // position and velocity need two views
    for (const auto& [k, obs] : seen) {
      const double dt = k->t - p.t0;
      sink(std::make_shared<NonRigidConstantVelocityFactor>(w_.camera_, obs->pixel, dt,
                                                            w_.params_.pixel_sigma),
           &huber_, {k->pose, w_.extrinsic_, p.position, p.velocity});
      if (obs->depth > 0)
        sink(std::make_shared<NonRigidDepthFactor>(dt, obs->depth, w_.params_.depth_noise), &huber_,
             {k->pose, w_.extrinsic_, p.position, p.velocity});
    }
    return 1;
  }

  /// r_O and the depth per observation of each object point seen in two keyframes or more, and
  /// r_om over each three consecutive keyframes holding an L. Observations the current estimate
  /// puts behind a camera are left out. Returns whether the object got a factor.
  bool rigidObjectFactors(RigidObject& o, const FactorSink& sink) {
    bool used = false;
    for (auto& [id, p] : o.points) {
      if (p.observations.size() < 2) continue;
      const Eigen::Vector3d m_obj(p.m_obj);
      for (auto& [kf, obs] : p.observations) {
        Keyframe* k = w_.keyframe(kf);
        double* L = o.poses.at(kf).data();
        if (!k || w_.depthIn(*k, poseFromBlock(L) * m_obj) < kMinLandmarkDepth) continue;
        sink(std::make_shared<RigidObjectReprojectionFactor>(w_.camera_, obs.pixel,
                                                             w_.params_.pixel_sigma),
             &huber_, {k->pose, w_.extrinsic_, L, p.m_obj});
        if (obs.depth > 0)
          sink(std::make_shared<RigidObjectDepthFactor>(obs.depth, w_.params_.depth_noise), &huber_,
               {k->pose, w_.extrinsic_, L, p.m_obj});
        used = true;
      }
    }
    for (auto first = o.poses.begin(); first != o.poses.end(); ++first) {
      const auto second = std::next(first);
      if (second == o.poses.end() || std::next(second) == o.poses.end()) break;
      const auto third = std::next(second);
      if (second->first != first->first + 1 || third->first != second->first + 1) continue;
      sink(std::make_shared<RigidSmoothMotionFactor>(w_.params_.object_motion_sigma_translation,
                                                     w_.params_.object_motion_sigma_rotation),
           nullptr, {first->second.data(), second->second.data(), third->second.data()});
      used = true;
    }
    return used;
  }

  /// The factors of one landmark: the depth at its anchor, and per later observation the
  /// reprojection and (optionally) the depth there. Observations the current estimate puts
  /// behind a camera are left out (the factor cannot be evaluated there).
  int landmarkFactors(Landmark& l, std::int64_t only, const FactorSink& sink) {
    if (l.observations.size() < 2 || l.inverse_depth <= 0) return 0;
    Keyframe* anchor = w_.keyframe(l.anchor);
    if (!anchor) return 0;
    const bool touchesOnly = only < 0 || only == l.anchor;
    const LandmarkObservation& a = l.anchorObservation();
    const Eigen::Vector2d anchorPixel = w_.atStateTime(a.pixel, a.velocity);
    const Eigen::Vector3d world = w_.landmarkWorld(l);
    int used = 0;
    for (auto& [kf, obs] : l.observations) {
      if (kf == l.anchor) continue;
      Keyframe* k = w_.keyframe(kf);
      if (!k) continue;
      if (w_.depthIn(*k, world) < kMinLandmarkDepth) continue;
      ++used;
      if (!touchesOnly && only != kf) continue;
      sink(std::make_shared<StaticReprojectionFactor>(
               w_.camera_, a.pixel, obs.pixel, w_.params_.pixel_sigma, a.velocity, obs.velocity),
           &huber_, {anchor->pose, k->pose, w_.extrinsic_, &l.inverse_depth, w_.time_offset_});
      if (w_.params_.transferred_depth && obs.depth > 0)
        sink(std::make_shared<TransferredDepthFactor>(
                 w_.camera_, anchorPixel,
                 w_.depthAtStateTime(*k, w_.atStateTime(obs.pixel, obs.velocity), obs.depth),
                 w_.params_.depth_noise),
             &huber_, {anchor->pose, k->pose, w_.extrinsic_, &l.inverse_depth});
    }
    if (used == 0) return 0;
    if (a.depth > 0 && touchesOnly)
      sink(std::make_shared<DepthMeasurementFactor>(
               w_.depthAtStateTime(*anchor, anchorPixel, a.depth), w_.params_.depth_noise),
           &huber_, {&l.inverse_depth});
    return 1;
  }

  SlidingWindow& w_;
  ceres::HuberLoss huber_;
  ceres::HuberLoss gnss_huber_;
  const bool free_calibration_;
  ceres::SphereManifold<3> sphere_;
};

void SlidingWindow::repropagatePreintegrations() {
  for (size_t k = 1; k < keyframes_.size(); ++k) {
    auto& pre = keyframes_[k].preintegration;
    const double* sb = keyframes_[k - 1].speed_bias;
    const Eigen::Vector3d ba(sb[3], sb[4], sb[5]), bg(sb[6], sb[7], sb[8]);
    if (pre && pre->needsRepropagation(ba, bg)) pre->repropagate(ba, bg);
  }
}

/// The window's problems own nothing: the factors are shared with the marginalisation and the
/// losses and the manifold live in the builder and the caller.
static ceres::Problem::Options unownedProblemOptions() {
  ceres::Problem::Options options;
  options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  return options;
}

SolveReport SlidingWindow::solve() {
  // Bias estimates that moved far from a preintegration's linearisation point: integrate again.
  if (params_.use_imu) repropagatePreintegrations();
  updateExcitation();
  // With the extrinsic estimated, the window's gauge is the first keyframe's camera, as the
  // first solve after the last prior-free start has it.
  if (!prior_.factor && !camera_anchor_ && estimatesExtrinsic() && !keyframes_.empty())
    camera_anchor_ = poseFromBlock(keyframes_.front().pose) * extrinsic();
  ceres::Problem problem(unownedProblemOptions());
  PoseManifold manifold;
  std::vector<std::shared_ptr<const ceres::CostFunction>> keep;  // alive until Solve returns
  ProblemBuilder builder(*this);
  SolveReport report = builder.fill(problem, manifold, keep);
  if (keyframes_.size() < 2) return report;

  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_SCHUR;
  solver.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  solver.max_num_iterations = params_.max_iterations;
  solver.max_solver_time_in_seconds = params_.max_solver_time_s;
  // One thread (Ceres's default): with more the Schur sums' order varies, and the tiny
  // differences change later keyframe and restart decisions (docs/notes/estimator.md,
  // 2026-11-28 (solver_threads)).
  solver.max_num_line_search_step_size_iterations = params_.line_search_steps;
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  report.iterations = int(summary.iterations.size());
  report.solve_ms = 1000.0 * summary.total_time_in_seconds;
  report.final_cost = summary.final_cost;
  report.usable = summary.IsSolutionUsable();
  if (!report.usable) report.message = summary.message;
  return report;
}

void SlidingWindow::marginalizeOldest() {
  Keyframe& oldest = keyframes_.front();
  Marginalizer marginalizer;
  for (auto& k : keyframes_) marginalizer.setPoseBlock(k.pose);
  // As the last solve had them: a state its motion held stays out of the prior.
  if (extrinsicFree())
    marginalizer.setPoseBlock(extrinsic_);
  else
    marginalizer.setConstantBlock(extrinsic_);
  if (!timeOffsetFree()) marginalizer.setConstantBlock(time_offset_);
  if (!gravityFree()) marginalizer.setConstantBlock(gravity_);
  // The first marginalisation: the solves held the oldest pose fixed (the gauge), so the prior
  // is conditioned on it rather than eliminating it; otherwise the prior would carry no absolute
  // information and the window would drift in the unobservable directions (VINS-Fusion instead
  // moves the whole window back after each solve).
  if (!prior_.factor && !camera_anchor_) marginalizer.setConstantBlock(oldest.pose);
  ProblemBuilder builder(*this);
  std::set<const double*> leaving = {oldest.pose, oldest.speed_bias};
  builder.forEachFactor(
      oldest.id,
      [&](std::shared_ptr<const ceres::CostFunction> f, const ceres::LossFunction* loss,
          std::vector<double*> blocks) { marginalizer.addFactor(std::move(f), loss, blocks); });
  for (auto& [id, l] : landmarks_.all())
    if (l.anchor == oldest.id) leaving.insert(&l.inverse_depth);
  for (auto& [id, p] : nonrigid_)
    if (p.observations.begin()->first == oldest.id) {
      leaving.insert(p.position);
      leaving.insert(p.velocity);
    }
  const auto prior = marginalizer.marginalize(leaving);
  prior_ = {prior.factor, prior.blocks};
  camera_anchor_.reset();  // in the prior now, with the keyframe it held

  // Landmarks anchored at the oldest keyframe move their anchor (LandmarkReanchoring).
  landmarks_.removeKeyframe(
      oldest.id,
      [&](const Landmark& l, std::int64_t next) {
        const Eigen::Vector3d world = landmarkWorld(l);
        const Keyframe* k = keyframe(next);
        const double z = depthIn(*k, world);
        return z > kMinLandmarkDepth ? 1.0 / z : 1.0 / 3.0;
      },
      params_.landmark_reanchoring == LandmarkReanchoring::Newest);
  // The objects' poses and observations there are dropped (SlidingWindow.h).
  objects_.removeKeyframe(oldest.id);
  // Non-rigid points first seen in the oldest keyframe went into the prior with it.
  for (auto it = nonrigid_.begin(); it != nonrigid_.end();)
    it = it->second.observations.begin()->first == oldest.id ? nonrigid_.erase(it) : std::next(it);
  keyframes_.pop_front();
}

CalibrationEstimate SlidingWindow::calibration(bool with_sigma) {
  CalibrationEstimate out;
  out.time_offset_s = time_offset_[0];
  out.T_body_camera = extrinsic();
  const bool td = estimatesTimeOffset(), extrinsic = estimatesExtrinsic();
  if (!with_sigma || keyframes_.size() < 2 || !(td || extrinsic)) return out;
  ceres::Problem problem(unownedProblemOptions());
  PoseManifold manifold;
  std::vector<std::shared_ptr<const ceres::CostFunction>> keep;
  ProblemBuilder builder(*this, /*free_calibration=*/true);
  builder.fill(problem, manifold, keep);
  std::vector<std::pair<const double*, const double*>> blocks;
  if (td) blocks.emplace_back(time_offset_, time_offset_);
  if (extrinsic) blocks.emplace_back(extrinsic_, extrinsic_);
  // Sparse QR; when the window's information is rank-deficient (a landmark along its ray with
  // no depth), a dense SVD's pseudo-inverse still gives the calibration blocks.
  ceres::Covariance::Options sparse, dense;
  dense.algorithm_type = ceres::DENSE_SVD;
  dense.null_space_rank = -1;
  for (const ceres::Covariance::Options& options : {sparse, dense}) {
    ceres::Covariance covariance(options);
    if (!covariance.Compute(blocks, &problem)) continue;
    if (td) {
      double variance = 0;
      covariance.GetCovarianceBlock(time_offset_, time_offset_, &variance);
      out.time_offset_sigma_s = std::sqrt(std::max(variance, 0.0));
    }
    if (extrinsic) {
      Eigen::Matrix<double, 6, 6, Eigen::RowMajor> C;
      covariance.GetCovarianceBlockInTangentSpace(extrinsic_, extrinsic_, C.data());
      out.extrinsic_sigma = C.diagonal().cwiseMax(0.0).cwiseSqrt();
    }
    break;
  }
  return out;
}

}  // namespace dynslam::estimator
