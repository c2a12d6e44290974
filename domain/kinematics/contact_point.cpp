// V2, V4, V5 and the vector form V7-V14 of spec resultant-speeds.md. Frame (section 3): O2 at the
// origin, O1 = (a_w, 0), z towards the viewer, CCW positive.

#include "domain/kinematics/contact_point.h"

#include <Eigen/Core>
#include <cmath>
#include <numbers>

#include "domain/kinematics/degrees.h"
#include "domain/kinematics/local_sense.h"

namespace cutcalc::domain::kinematics::detail {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kMmPerM = 1000.0;

// z-component of a x b for vectors in the plane.
double cross_z(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// z x a: a turned by +90 deg, the velocity direction of a point at a on a CCW rotation.
Eigen::Vector2d z_cross(const Eigen::Vector2d& a) { return {-a.y(), a.x()}; }

}  // namespace

// V6
Kinematics make_kinematics(const ResultantSpeedsParams& params, double center_distance_mm) {
  Kinematics k;
  k.tool_radius_mm = params.tool_radius_mm;
  k.center_distance_mm = center_distance_mm;
  k.rotation_sign =
      workpiece_rotation_sign(params.milling, center_distance_mm, params.tool_radius_mm);
  k.omega1 = kTwoPi * params.tool_speed_rpm;
  k.omega2 = k.rotation_sign * kTwoPi * params.workpiece_speed_rpm;
  k.tool_feed_mm_per_min = params.tool_feed_mm_per_min;
  const double lambda = deg_to_rad(params.edge_inclination_deg);  // lambda
  k.cos_lambda = std::cos(lambda);
  k.sin_lambda = std::sin(lambda);
  k.middle_sense = params.milling;
  return k;
}

// V2, V4, V5, V7-V14
ContactPointSpeeds contact_point_speeds(const Kinematics& k, double contact_angle_deg) {
  const double R1 = k.tool_radius_mm;                // R1
  const double a_w = k.center_distance_mm;           // a_w
  const double rho = deg_to_rad(contact_angle_deg);  // rho
  const double sin_rho = std::sin(rho);
  const double cos_rho = std::cos(rho);

  // V2: P - O2; its x is the a_w - R1 cos rho that V4, V5 and v_w all need.
  const Eigen::Vector2d P(a_w - R1 * cos_rho, R1 * sin_rho);
  // V4 via hypot: no cancellation inside the law-of-cosines root.
  const double R2_contact = std::hypot(P.x(), P.y());  // R2'
  // V5: atan2 covers |sigma| > 90 deg, which arcsin (paper eq. 3, erratum E2) cannot; at the
  // workpiece axis (R2' = 0) the direction is undefined and the spec fixes 0.
  const double sigma_deg = R2_contact == 0.0 ? 0.0 : half_open_deg(std::atan2(P.y(), P.x()));

  // V7, V8. v_T = V_T e with the unit edge direction e = z x (P - O1) / R1.
  const double V_T = k.omega1 * R1;                         // V_T
  const Eigen::Vector2d e(-sin_rho, -cos_rho);              // v_T / V_T
  const Eigen::Vector2d v_w = k.omega2 * z_cross(P);        // v_w
  const Eigen::Vector2d v_s1(k.tool_feed_mm_per_min, 0.0);  // v_s1
  const Eigen::Vector2d u_s = v_s1 - v_w;                   // u_s
  // v_e = v_T + u_s resolved along and across the edge: the along part keeps V_T whole and the
  // across part is exactly v_T x u_s / V_T, so a tiny resultant angle is not lost in
  // cancellation of the large V_T terms (V11).
  const double v_e_along = V_T + e.dot(u_s);             // v_T . v_e / V_T
  const double v_e_across = cross_z(e, u_s);             // v_T x v_e / V_T
  const double v_e = std::hypot(v_e_along, v_e_across);  // |v_e| (V10)
  const double v_S2 = std::abs(k.omega2) * R2_contact;   // v_S2 = 2 pi R2' n2 (V8)

  const double g = R1 - a_w * cos_rho;  // g(rho) (V6)

  ContactPointSpeeds out;
  out.contact_angle_deg = contact_angle_deg;
  out.contact_radius_mm = R2_contact;
  out.contact_polar_angle_deg = sigma_deg;
  out.tool_speed_m_per_min = V_T / kMmPerM;
  out.workpiece_speed_m_per_min = v_S2 / kMmPerM;
  out.resultant_feed_mm_per_min = std::hypot(u_s.x(), u_s.y());  // |u_s| (V9)
  out.resultant_speed_m_per_min = v_e / kMmPerM;
  out.resultant_angle_deg = half_open_deg(std::atan2(v_e_across, v_e_along));  // V11
  out.sense = local_sense(k.rotation_sign, g, k.middle_sense);                 // V12
  // V13. A still workpiece (or the workpiece axis itself) has i_k = 0 outright: V_T > 0 in
  // exact arithmetic, but 2 pi R1 n1 can underflow to 0 for subnormal inputs and 0 / 0 is NaN.
  out.kinematic_ratio = v_S2 == 0.0 ? 0.0 : v_S2 / V_T;  // i_k
  // V14: the inclined edge splits |v_e|; the along-edge part carries lambda's sign.
  out.normal_speed_m_per_min = out.resultant_speed_m_per_min * k.cos_lambda;
  out.along_edge_speed_m_per_min = out.resultant_speed_m_per_min * k.sin_lambda;
  return out;
}

}  // namespace cutcalc::domain::kinematics::detail
