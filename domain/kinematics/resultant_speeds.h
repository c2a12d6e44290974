#pragma once
// Resultant cutting speeds of a rotating tool on a rotating workpiece, turn-milling a flat
// (spec resultant-speeds.md V1-V15; paper 000).
// Units: mm, rev/min, degrees; speeds in m/min except the resultant feed in mm/min.
// Inputs are range-checked by the caller (each field on its own); this function checks what
// depends on several inputs together.

#include <optional>
#include <variant>
#include <vector>

#include "domain/common/milling_sense.h"
#include "domain/common/result.h"

namespace cutcalc::domain::kinematics {

struct CenterDistance {
  double mm = 0.0;  // a_w
};
struct FlatDepth {
  double mm = 0.0;  // t; a_w = R2 - t + R1 (V1)
};

struct ResultantSpeedsParams {
  double tool_radius_mm = 0.0;       // R1 > 0
  double workpiece_radius_mm = 0.0;  // R2 > 0
  std::variant<CenterDistance, FlatDepth> placement;
  double tool_speed_rpm = 0.0;              // n1 > 0; the tool turns counter-clockwise
  double workpiece_speed_rpm = 0.0;         // n2 >= 0; its sense follows from `milling` (V6)
  MillingSense milling = MillingSense::up;  // the sense at the middle of the arc, rho = 0
  double tool_feed_mm_per_min = 0.0;        // v_s1, signed, + away from the workpiece axis
  std::optional<std::vector<double>> contact_angles_deg;  // rho_i; default +rho_e, 0, -rho_e
  // n >= 2 contact angles evenly spaced over the whole arc, +rho_e (entry) to -rho_e (exit)
  // inclusive. Exclusive with contact_angles_deg: the caller gives at most one of the two (were
  // both set, arc_samples would be used).
  std::optional<int> arc_samples;
  double edge_inclination_deg = 0.0;  // lambda, -90 < lambda < 90
};

struct ContactPointSpeeds {
  double contact_angle_deg = 0.0;           // rho
  double contact_radius_mm = 0.0;           // R2' (V4)
  double contact_polar_angle_deg = 0.0;     // sigma (V5)
  double tool_speed_m_per_min = 0.0;        // V_T (V8)
  double workpiece_speed_m_per_min = 0.0;   // v_S2 (V8)
  double resultant_feed_mm_per_min = 0.0;   // |u_s| (V9)
  double resultant_speed_m_per_min = 0.0;   // |v_e| (V10)
  double resultant_angle_deg = 0.0;         // angle from v_T to v_e, CCW + (V11)
  MillingSense sense = MillingSense::up;    // local milling sense (V12)
  double kinematic_ratio = 0.0;             // i_k (V13)
  double normal_speed_m_per_min = 0.0;      // v_N (V14)
  double along_edge_speed_m_per_min = 0.0;  // along the edge, signed like lambda (V14)
};

struct ResultantSpeedsResult {
  double engagement_half_angle_deg = 0.0;  // rho_e (V3)
  std::vector<ContactPointSpeeds> points;  // in the order of the requested angles
};

// V1-V14 at the requested contact angles: contact_angles_deg as given, or arc_samples angles
// evenly spaced over the engagement arc (section 3: entry +rho_e first, exit -rho_e last), or the
// default entry, middle, exit. Errors: no_contact (no engagement arc, V3 / section 5),
// contact_angle_outside_arc (index = the angle's position in contact_angles_deg).
Result<ResultantSpeedsResult> compute_resultant_speeds(const ResultantSpeedsParams& params);

}  // namespace cutcalc::domain::kinematics
