#pragma once
// r_O (method.md section 5, paper Eqs. 18-20): a feature on a rigid object l seen at keyframe n.
// The paper predicts the feature's world position at n from its position at n-1,
// m_n = L_n L_{n-1}^-1 m_{n-1}. We keep instead one state per feature, its position in the
// object frame m_obj, so m_{n-1} = L_{n-1} m_obj and the same prediction reads
//
//   m_n = L_n m_obj
//   r   = (u_n - pi(T_bc^-1 T_wb(n)^-1 m_n)) / sigma_pixel                         (2 residuals)
//
// Why: with m_{n-1} as the state, each frame would need its own copy of every feature (or the
// factor at the reference frame would list the same L twice, which Ceres refuses); with m_obj
// every observation has the same four blocks and a feature is one 3-vector for the whole window.
// The information is the same: observations at n-1 and n still tie L_{n-1} and L_n through the
// shared m_obj. Both forms leave the object frame free (L_n -> L_n G, m_obj -> G^-1 m_obj for all
// n): the window fixes it, e.g. by holding the object's first L constant or by a prior.
//
// Blocks: pose_n (body, 7), extrinsic T_body_camera (7), object pose L_n = T_world_object (7),
// m_obj (3). Pixels and the behind-the-camera rule as StaticReprojectionFactor.h.
#include <dynslam/estimator/factors/PinholeProjection.h>

#include <ceres/sized_cost_function.h>

#include <Eigen/Core>

namespace dynslam::estimator {

class RigidObjectReprojectionFactor : public ceres::SizedCostFunction<2, 7, 7, 7, 3> {
 public:
  RigidObjectReprojectionFactor(const PinholeCamera& camera, const Eigen::Vector2d& pixel_n,
                                double sigma_pixel);

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  PinholeCamera camera_;
  Eigen::Vector2d pixel_n_;
  double inv_sigma_;
};

}  // namespace dynslam::estimator
