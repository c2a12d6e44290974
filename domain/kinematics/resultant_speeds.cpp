// compute_resultant_speeds (spec resultant-speeds.md V1-V14): the engagement arc, the check of
// the requested contact angles against it, then each point in the order given.

#include "domain/kinematics/resultant_speeds.h"

#include <cstddef>
#include <vector>

#include "domain/kinematics/contact_point.h"
#include "domain/kinematics/engagement_arc.h"

namespace cutcalc::domain::kinematics {

Result<ResultantSpeedsResult> compute_resultant_speeds(const ResultantSpeedsParams& params) {
  const auto arc =
      detail::engagement_arc(params.tool_radius_mm, params.workpiece_radius_mm, params.placement);
  if (!arc) {
    return make_error(ErrorCode::no_contact);
  }
  const double rho_e = arc->half_angle_deg;  // rho_e (V3b)
  // Section 3: entry, middle, exit (or arc_samples angles from entry to exit), with the very
  // rho_e reported, so the ends lie on the arc.
  std::vector<double> generated_angles;
  if (params.arc_samples) {
    generated_angles = detail::evenly_spaced_contact_angles(rho_e, *params.arc_samples);
  } else if (!params.contact_angles_deg) {
    generated_angles = {rho_e, 0.0, -rho_e};
  }
  const std::vector<double>& angles = params.contact_angles_deg && !params.arc_samples
                                          ? *params.contact_angles_deg
                                          : generated_angles;

  for (std::size_t i = 0; i < angles.size(); ++i) {
    if (!detail::inside_arc(angles[i], rho_e)) {
      DomainError error = make_error(ErrorCode::contact_angle_outside_arc);
      error.index = i;
      return error;
    }
  }

  const detail::Kinematics kinematics = detail::make_kinematics(params, arc->center_distance_mm);
  ResultantSpeedsResult result;
  result.engagement_half_angle_deg = rho_e;
  result.points.reserve(angles.size());
  for (const double rho : angles) {
    result.points.push_back(detail::contact_point_speeds(kinematics, rho));
  }
  return result;
}

}  // namespace cutcalc::domain::kinematics
