#include "dynslam/estimator/ImuInitializer.h"

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>
#include <utility>

namespace dynslam::estimator {
namespace {

enum : int { kR = 3, kBg = 12 };  // ImuPreintegration's error-state blocks

Eigen::Vector3d rotationLog(const Eigen::Quaterniond& q) {
  const Eigen::AngleAxisd aa(q.normalized());
  return aa.angle() * aa.axis();
}

/// The linear system of step 2 / 3 for the unknowns x = [v_0 .. v_{N-1}, y] with gravity
/// g = g0 + G y: G = I3, g0 = 0 for the free solve; G = a tangent basis (3x2) for a refinement
/// step; G empty for velocities alone at a fixed g0. `displacement` holds the visual
/// p_j - p_i in the position rows (0 elsewhere): b contains it once, at scale 1.
struct AlignmentSystem {
  Eigen::MatrixXd A;
  Eigen::VectorXd b, displacement;
};

AlignmentSystem buildAlignment(const std::vector<ImuInitKeyframe>& keyframes,
                               const std::vector<ImuPreintegration*>& pre,
                               const Eigen::Vector3d& g0, const Eigen::MatrixXd& G) {
  const int n = int(keyframes.size()), m = int(G.cols());
  const int rows = 6 * (n - 1);
  AlignmentSystem sys{Eigen::MatrixXd::Zero(rows, 3 * n + m), Eigen::VectorXd(rows),
                      Eigen::VectorXd::Zero(rows)};
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  for (int k = 0; k + 1 < n; ++k) {
    const ImuPreintegration& p = *pre[k];
    const double T = p.sumDt();
    const Eigen::Matrix3d Ri = keyframes[k].T_world_body.rotation();
    const Eigen::Vector3d dp =
        keyframes[k + 1].T_world_body.translation() - keyframes[k].T_world_body.translation();
    const Eigen::Vector3d alpha = p.deltaPosition(p.linearizedBa(), p.linearizedBg());
    const Eigen::Vector3d beta = p.deltaVelocity(p.linearizedBa(), p.linearizedBg());
    const int r = 6 * k;
    sys.A.block<3, 3>(r, 3 * k) = T * I;
    if (m > 0) sys.A.block(r, 3 * n, 3, m) = 0.5 * T * T * G;
    sys.b.segment<3>(r) = dp - Ri * alpha - 0.5 * T * T * g0;
    sys.displacement.segment<3>(r) = dp;
    sys.A.block<3, 3>(r + 3, 3 * k) = -I;
    sys.A.block<3, 3>(r + 3, 3 * k + 3) = I;
    if (m > 0) sys.A.block(r + 3, 3 * n, 3, m) = -T * G;
    sys.b.segment<3>(r + 3) = Ri * beta + T * g0;
  }
  return sys;
}

/// The velocities and gravity solved from an AlignmentSystem and the residuals they leave.
struct Alignment {
  std::vector<Eigen::Vector3d> velocities;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  double position_rms = 0, velocity_rms = 0;
};

Alignment solveAlignment(const std::vector<ImuInitKeyframe>& keyframes,
                         const std::vector<ImuPreintegration*>& pre, const Eigen::Vector3d& g0,
                         const Eigen::MatrixXd& G) {
  const AlignmentSystem sys = buildAlignment(keyframes, pre, g0, G);
  const int n = int(keyframes.size()), m = int(G.cols());
  const Eigen::VectorXd x = sys.A.colPivHouseholderQr().solve(sys.b);
  const Eigen::VectorXd residual = sys.A * x - sys.b;
  Alignment out;
  out.velocities.resize(n);
  for (int k = 0; k < n; ++k) out.velocities[k] = x.segment<3>(3 * k);
  out.gravity = g0;
  if (m > 0) out.gravity += G * x.tail(m);
  double sp = 0, sv = 0;
  for (int k = 0; k + 1 < n; ++k) {
    sp += residual.segment<3>(6 * k).squaredNorm();
    sv += residual.segment<3>(6 * k + 3).squaredNorm();
  }
  out.position_rms = std::sqrt(sp / (n - 1));
  out.velocity_rms = std::sqrt(sv / (n - 1));
  return out;
}

/// The scale s at which the IMU sees the visual displacements (s dp replacing dp in the free
/// system, VINS's monocular unknown) and its standard error. Unlike the main solve this one is
/// weighted: each pair's six rows are whitened by the preintegration's [alpha, beta] covariance
/// plus the visual position noise, because the standard error must be right for the check to
/// be fair (unweighted, with the noise pooled over position and velocity rows, it came out 1.4x
/// too small in the noisy test: 4 % of correct sequences refused at 3 sigma). The model's noise
/// is a floor: a residual larger than it scales the error up, a smaller one is not trusted to
/// scale it down (with 10 keyframes its estimate varies by +-16 %, and a model that adds noise
/// the data lack, e.g. visual noise on exact poses, is wrong in shape, not in level). The
/// velocities and g are eliminated by a Schur
/// complement on s. NaN when the motion leaves s unobservable (still or constant velocity: the
/// velocities absorb any scale).
std::pair<double, double> estimateVisualScale(const std::vector<ImuInitKeyframe>& keyframes,
                                              const std::vector<ImuPreintegration*>& pre,
                                              double visual_position_noise) {
  AlignmentSystem sys =
      buildAlignment(keyframes, pre, Eigen::Vector3d::Zero(), Eigen::MatrixXd::Identity(3, 3));
  for (size_t k = 0; k < pre.size(); ++k) {
    const Eigen::Matrix3d Ri = keyframes[k].T_world_body.rotation();
    Eigen::Matrix<double, 6, 6> R6 = Eigen::Matrix<double, 6, 6>::Zero();
    R6.block<3, 3>(0, 0) = Ri;
    R6.block<3, 3>(3, 3) = -Ri;  // the velocity rows carry -R_i beta
    Eigen::Matrix<double, 6, 6> P;
    const Matrix15d& C = pre[k]->covariance();
    P << C.block<3, 3>(0, 0), C.block<3, 3>(0, 6), C.block<3, 3>(6, 0), C.block<3, 3>(6, 6);
    P = R6 * P * R6.transpose();
    P.block<3, 3>(0, 0).diagonal().array() += 2 * visual_position_noise * visual_position_noise;
    P.diagonal().array() += 1e-12;  // a noiseless IMU model stays invertible
    const Eigen::LLT<Eigen::Matrix<double, 6, 6>> L(P);
    const int r = 6 * int(k);
    sys.A.middleRows<6>(r) = L.matrixL().solve(sys.A.middleRows<6>(r));
    sys.b.segment<6>(r) = L.matrixL().solve(sys.b.segment<6>(r));
    sys.displacement.segment<6>(r) = L.matrixL().solve(sys.displacement.segment<6>(r));
  }
  const Eigen::VectorXd c = -sys.displacement, r0 = sys.b - sys.displacement;
  const auto N = (sys.A.transpose() * sys.A).ldlt();
  const Eigen::VectorXd Atc = sys.A.transpose() * c, Atr = sys.A.transpose() * r0;
  const double S = c.squaredNorm() - Atc.dot(N.solve(Atc));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (!(S > 1e-9 * c.squaredNorm()) || !(S > 1e-12)) return {nan, nan};
  const double s = (c.dot(r0) - Atc.dot(N.solve(Atr))) / S;
  const Eigen::VectorXd x = N.solve(Atr - Atc * s);
  const int dof = int(sys.A.rows() - sys.A.cols()) - 1;  // 3N - 10 > 0 for N >= 4
  const double noise = (sys.A * x + c * s - r0).squaredNorm() / std::max(1, dof);
  return {s, std::sqrt(std::max(1.0, noise) / S)};
}

/// Two unit vectors spanning the plane orthogonal to the unit vector `n`.
Eigen::Matrix<double, 3, 2> tangentBasis(const Eigen::Vector3d& n) {
  const Eigen::Vector3d helper =
      std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d b1 = (helper - n * n.dot(helper)).normalized();
  Eigen::Matrix<double, 3, 2> B;
  B << b1, n.cross(b1);
  return B;
}

/// The input contract; "" when it holds.
std::string checkInput(const std::vector<ImuInitKeyframe>& keyframes,
                       const std::vector<ImuPreintegration*>& pre,
                       const ImuInitializerOptions& options) {
  std::ostringstream why;
  if (keyframes.size() < 4) {
    why << "needs at least 4 keyframes, got " << keyframes.size();
  } else if (pre.size() + 1 != keyframes.size()) {
    why << "needs one preintegration per consecutive pair: " << keyframes.size() << " keyframes, "
        << pre.size() << " preintegrations";
  } else if (!(options.gravity_magnitude > 0)) {
    why << "gravity_magnitude must be > 0";
  } else {
    for (size_t k = 0; k < pre.size() && why.tellp() == 0; ++k) {
      if (!pre[k] || !(pre[k]->sumDt() > 0)) {
        why << "preintegration " << k << " is missing or empty";
      } else if (!keyframes[k].T_world_body.matrix().allFinite() ||
                 !keyframes[k + 1].T_world_body.matrix().allFinite()) {
        why << "keyframe pose " << k << " or " << k + 1 << " is not finite";
      } else {
        const double gap = keyframes[k + 1].t - keyframes[k].t;
        if (std::abs(gap - pre[k]->sumDt()) > options.max_interval_mismatch)
          why << "keyframes " << k << "-" << k + 1 << " are " << gap
              << " s apart but their preintegration covers " << pre[k]->sumDt() << " s";
      }
    }
  }
  return why.str();
}

/// The excitation measure: RMS over the intervals of the mean world acceleration,
/// R_i beta / T + g.
double accelerationRms(const std::vector<ImuInitKeyframe>& keyframes,
                       const std::vector<ImuPreintegration*>& pre, const Eigen::Vector3d& bg,
                       const Eigen::Vector3d& gravity) {
  double sa = 0;
  for (size_t k = 0; k < pre.size(); ++k) {
    const Eigen::Vector3d beta = pre[k]->deltaVelocity(pre[k]->linearizedBa(), bg);
    const Eigen::Vector3d a =
        keyframes[k].T_world_body.rotation() * beta / pre[k]->sumDt() + gravity;
    sa += a.squaredNorm();
  }
  return std::sqrt(sa / pre.size());
}

/// The checks of the header on a solved alignment: every one that fails is named, with its
/// numbers ("" when all pass).
std::string failedChecks(const ImuInitialization& out, const ImuInitializerOptions& options) {
  const double G = options.gravity_magnitude;
  std::ostringstream why;
  const auto fail = [&why](const std::string& text) {
    if (why.tellp() > 0) why << "; ";
    why << text;
  };
  const auto num = [](double v) {
    std::ostringstream s;
    s.precision(3);
    s << v;
    return s.str();
  };
  if (std::abs(out.free_gravity_norm - G) > options.max_gravity_norm_error)
    fail("inconsistent: the free alignment's |g| is " + num(out.free_gravity_norm) +
         " m/s^2, expected " + num(G) + " +- " + num(options.max_gravity_norm_error) +
         " (visual scale, time offset or IMU data wrong?)");
  if (out.position_rms > options.max_position_rms)
    fail("inconsistent: position residual RMS " + num(out.position_rms) + " m > " +
         num(options.max_position_rms));
  if (out.velocity_rms > options.max_velocity_rms)
    fail("inconsistent: velocity residual RMS " + num(out.velocity_rms) + " m/s > " +
         num(options.max_velocity_rms));
  const double scaleError = std::abs(out.visual_scale - 1.0);
  if (scaleError > options.max_scale_error &&
      scaleError > options.scale_significance * out.visual_scale_sigma)  // false for NaN
    fail("inconsistent: the IMU sees the visual positions at scale " + num(out.visual_scale) +
         " +- " + num(out.visual_scale_sigma) + " (depth scale or units wrong?)");
  if (out.acceleration_rms < options.min_acceleration_rms)
    fail("not excited: acceleration RMS " + num(out.acceleration_rms) + " m/s^2 < " +
         num(options.min_acceleration_rms) + " (still or constant-velocity motion)");
  return why.str();
}

}  // namespace

Eigen::Vector3d estimateGyroBias(const std::vector<ImuInitKeyframe>& keyframes,
                                 const std::vector<ImuPreintegration*>& pre, int iterations) {
  if (pre.empty() || keyframes.size() != pre.size() + 1) return Eigen::Vector3d::Zero();
  Eigen::Vector3d bg = pre.front()->linearizedBg();
  for (int it = 0; it < iterations; ++it) {
    // gamma_k(bg + d) ~ gamma_k(bg) Exp(J_k d) = R_i^T R_j  =>  J_k d = Log(gamma_k^-1 R_i^T R_j).
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    for (size_t k = 0; k < pre.size(); ++k) {
      const Eigen::Quaterniond qi(keyframes[k].T_world_body.rotation());
      const Eigen::Quaterniond qj(keyframes[k + 1].T_world_body.rotation());
      const Eigen::Matrix3d J = pre[k]->jacobian().block<3, 3>(kR, kBg);
      const Eigen::Vector3d r =
          rotationLog(pre[k]->deltaRotation(bg).inverse() * qi.inverse() * qj);
      H += J.transpose() * J;
      g += J.transpose() * r;
    }
    const Eigen::Vector3d step = H.ldlt().solve(g);
    bg += step;
    // The Jacobians are exact only at the linearisation point: integrate again at the new bias.
    for (ImuPreintegration* p : pre) p->repropagate(p->linearizedBa(), bg);
    if (step.norm() < 1e-10) break;
  }
  return bg;
}

Eigen::Matrix3d rotationToGravityFrame(const Eigen::Vector3d& gravity_world) {
  return Eigen::Quaterniond::FromTwoVectors(gravity_world, -Eigen::Vector3d::UnitZ())
      .toRotationMatrix();
}

ImuInitialization initializeImu(const std::vector<ImuInitKeyframe>& keyframes,
                                const std::vector<ImuPreintegration*>& pre,
                                const ImuInitializerOptions& options) {
  ImuInitialization out;
  out.reason = checkInput(keyframes, pre, options);
  if (!out.reason.empty()) return out;

  // 1. Gyro bias (the preintegrations are repropagated at it).
  out.gyro_bias = estimateGyroBias(keyframes, pre, std::max(1, options.gyro_bias_iterations));

  // 2. Free linear alignment: velocities and an unconstrained g.
  const Alignment unconstrained =
      solveAlignment(keyframes, pre, Eigen::Vector3d::Zero(), Eigen::MatrixXd::Identity(3, 3));
  out.free_gravity_norm = unconstrained.gravity.norm();
  if (!(out.free_gravity_norm > 1e-6)) {
    out.reason =
        "the free alignment gives no gravity (|g| = " + std::to_string(out.free_gravity_norm) +
        " m/s^2)";
    return out;
  }

  // 3. Refinement on the sphere |g| = gravity_magnitude, then velocities at that g.
  const double G = options.gravity_magnitude;
  Eigen::Vector3d direction = unconstrained.gravity.normalized();
  for (int it = 0; it < options.gravity_refine_iterations; ++it) {
    const Alignment step = solveAlignment(keyframes, pre, G * direction, tangentBasis(direction));
    direction = step.gravity.normalized();
  }
  const Alignment fixed = solveAlignment(keyframes, pre, G * direction, Eigen::MatrixXd(3, 0));
  out.gravity_world = fixed.gravity;
  out.velocities_world = fixed.velocities;
  out.position_rms = fixed.position_rms;
  out.velocity_rms = fixed.velocity_rms;
  out.R_gravity_world = rotationToGravityFrame(out.gravity_world);

  std::tie(out.visual_scale, out.visual_scale_sigma) =
      estimateVisualScale(keyframes, pre, options.visual_position_noise);

  out.acceleration_rms = accelerationRms(keyframes, pre, out.gyro_bias, out.gravity_world);
  out.reason = failedChecks(out, options);
  out.success = out.reason.empty();
  return out;
}

}  // namespace dynslam::estimator
