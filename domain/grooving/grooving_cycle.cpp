#include "domain/grooving/grooving_cycle.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "domain/common/cutting_speed.h"
#include "domain/common/numeric.h"
#include "domain/program/program_options.h"

namespace cutcalc::domain::grooving {
namespace {

using program::number_text;
using program::Warning;
using program::WarningCode;

// K5: the shifts the paper tested ("0.3-0.5 mm, chosen only for free chip flow").
constexpr double kPaperShiftMinMm = 0.3;
constexpr double kPaperShiftMaxMm = 0.5;
// K3 default: the paper's experiment, and at most a third of the groove so that B >= 2 X2.
constexpr double kDefaultShiftMm = 0.4;
// K23: below this many revolutions no wall has two corner passes 4 s apart.
constexpr int kRepeatedPatternRevolutions = 5;

struct Widths {
  double shift_mm;       // X2
  double tool_width_mm;  // B
};

// K3, K4.
Result<Widths> widths(const GroovingCycleParams& p) {
  const double w = p.groove_width_mm;
  if (p.shift_mm && *p.shift_mm >= w) return make_error(ErrorCode::shift_too_wide);
  if (p.tool_width_mm && *p.tool_width_mm >= w) return make_error(ErrorCode::tool_too_wide);
  Widths out{};
  if (p.shift_mm && p.tool_width_mm) {
    if (std::fabs(*p.tool_width_mm + *p.shift_mm - w) > 1e-9 * w) {
      return make_error(ErrorCode::tool_and_shift_mismatch);
    }
    out = {*p.shift_mm, *p.tool_width_mm};
  } else if (p.tool_width_mm) {
    out = {w - *p.tool_width_mm, *p.tool_width_mm};
  } else {
    const double x2 = p.shift_mm.value_or(std::min(kDefaultShiftMm, w / 3.0));
    out = {x2, w - x2};
  }
  if (out.tool_width_mm <= out.shift_mm) return make_error(ErrorCode::tool_not_wider_than_shift);
  return out;
}

// K1: h and Db from whichever is given.
Result<std::pair<double, double>> depth_and_bottom(const GroovingCycleParams& p) {
  const double d0 = p.start_diameter_mm;
  if (p.bottom_diameter_mm) {
    if (*p.bottom_diameter_mm >= d0) return make_error(ErrorCode::bottom_not_below_start);
    return std::pair{(d0 - *p.bottom_diameter_mm) / 2.0, *p.bottom_diameter_mm};
  }
  const double h = p.groove_depth_mm.value_or(0.0);
  if (2.0 * h >= d0) return make_error(ErrorCode::groove_too_deep);
  return std::pair{h, d0 - 2.0 * h};
}

// K9-K12: D_k and the side each revolution ends on.
std::vector<PatternBlock> pattern(double d0, double db, double h, int n) {
  std::vector<PatternBlock> out;
  out.reserve(static_cast<std::size_t>(n));
  for (int k = 1; k <= n; ++k) {
    PatternBlock block;
    block.diameter_mm = k == n ? db : d0 - 2.0 * h * k / n;  // D_N = Db exactly
    block.shifts = k % 2 == 0;
    block.side = k % 4 == 2 || k % 4 == 3 ? Side::right : Side::left;
    out.push_back(block);
  }
  return out;
}

// K15-K20.
void times(const GroovingCycleParams& p, GroovingCycleResult& r) {
  const SpindleMode& spindle = p.spindle;
  const double s = r.infeed_per_revolution_mm;
  r.approach_time_min =
      (p.approach_clearance_mm / s) *
      mean_minutes_per_revolution(spindle, p.start_diameter_mm, r.approach_diameter_mm);
  double from = p.start_diameter_mm;
  for (const PatternBlock& block : r.pattern) {
    const double t = mean_minutes_per_revolution(spindle, from, block.diameter_mm);
    (block.shifts ? r.shift_time_min : r.plunge_time_min) += t;
    from = block.diameter_mm;
  }
  const double at_bottom = minutes_per_revolution(spindle, r.bottom_diameter_mm);
  r.dwell_time_min = p.dwell_revolutions * at_bottom;
  r.dwell_seconds = r.dwell_time_min * 60.0;
  r.final_shift_time_min = r.final_shift_revolutions * at_bottom;
  r.retract_time_min = (r.approach_diameter_mm - r.bottom_diameter_mm) / 2.0 / p.rapid_mm_per_min;
  r.cycle_time_min = r.approach_time_min + r.plunge_time_min + r.shift_time_min + r.dwell_time_min +
                     r.final_shift_time_min + r.retract_time_min;
  r.spindle_speed_at_start_rpm = 1.0 / minutes_per_revolution(spindle, p.start_diameter_mm);
  r.spindle_speed_at_bottom_rpm = 1.0 / at_bottom;
}

// K21: Rz_p of roughness.md R3-R5 at pitch S.
Result<roughness::GrooveWallResult> wall_rz(const GroovingCycleParams& p, double pitch_mm) {
  return roughness::compute_groove_wall_roughness(
      {pitch_mm, p.nose_radius_mm, p.minor_edge_angle_deg, std::nullopt});
}

// K5, K23, in the order of section 3.7 (spindle_speed_rounded is the Fanuc program's).
std::vector<Warning> warnings(const GroovingCycleParams& p, const GroovingCycleResult& r) {
  std::vector<Warning> out;
  const SpindleMode& spindle = p.spindle;
  if (spindle.spindle_speed_rpm) {
    out = program::limit_warnings(*spindle.spindle_speed_rpm, {}, {spindle.max_spindle_rpm, {}});
  } else if (spindle_speed_rpm_at(*spindle.cutting_speed_m_per_min, r.bottom_diameter_mm) >
             *spindle.max_spindle_rpm) {
    out.push_back({WarningCode::spindle_speed_limited,
                   "G96 reaches the " + number_text(*spindle.max_spindle_rpm) +
                       " rpm limit below diameter " + number_text(clamp_diameter_mm(spindle)) +
                       " mm: the cutting speed falls below " +
                       number_text(*spindle.cutting_speed_m_per_min) + " m/min there"});
  }
  if (r.shift_mm < kPaperShiftMinMm || r.shift_mm > kPaperShiftMaxMm) {
    out.push_back(
        {WarningCode::shift_outside_paper_range,
         "shift X2 = " + number_text(r.shift_mm) + " mm is outside the paper's tested 0.3-0.5 mm"});
  }
  if (r.revolutions < kRepeatedPatternRevolutions) {
    out.push_back({WarningCode::pattern_not_repeated,
                   std::to_string(r.revolutions) +
                       " revolutions: no wall has two corner passes 4 s apart, the wall Rz is "
                       "that of the developed pattern"});
  }
  return out;
}

}  // namespace

std::string_view side_name(Side side) { return side == Side::left ? "left" : "right"; }

double side_z_mm(const GroovingCycleParams& params, const GroovingCycleResult& cycle, Side side) {
  return side == Side::left ? params.groove_left_z_mm : cycle.right_z_mm;
}

Result<GroovingCycleResult> compute_grooving_cycle(const GroovingCycleParams& params) {
  const auto depth = depth_and_bottom(params);
  if (!depth.ok()) return depth.error();
  const auto width = widths(params);
  if (!width.ok()) return width.error();
  const double s0 = params.feed_per_rev_mm;
  const auto [h, db] = depth.value();
  const double revolutions = ceil_count(h / s0);  // K7
  if (revolutions > kMaxRevolutions) {
    return make_limit_error(ErrorCode::too_many_revolutions, kMaxRevolutions);
  }

  GroovingCycleResult r;
  r.shift_mm = width.value().shift_mm;
  r.tool_width_mm = width.value().tool_width_mm;
  r.groove_depth_mm = h;
  r.bottom_diameter_mm = db;
  r.approach_diameter_mm = params.start_diameter_mm + 2.0 * params.approach_clearance_mm;  // K2
  r.right_z_mm = params.groove_left_z_mm + r.shift_mm;                                     // K11
  r.revolutions = static_cast<int>(revolutions);
  r.shift_revolutions = r.revolutions / 2;
  r.radial_revolutions = r.revolutions - r.shift_revolutions;
  r.shifts = r.shift_revolutions + 1;
  const double s = h / r.revolutions;  // K8
  r.infeed_per_revolution_mm = s;
  r.shift_feed_mm_per_rev = std::hypot(s, r.shift_mm);  // K10
  r.final_shift_revolutions = r.shift_mm / s;
  r.spindle_revolutions = params.approach_clearance_mm / s + r.revolutions +
                          params.dwell_revolutions + r.final_shift_revolutions;
  r.pattern = pattern(params.start_diameter_mm, db, h, r.revolutions);
  r.pattern_end_side = r.pattern.back().side;  // K12
  r.end_side = r.pattern_end_side == Side::left ? Side::right : Side::left;
  times(params, r);

  r.chip_thickness_mm = s;  // K22
  const double phi1 = deg_times_pi_over_180(params.minor_edge_angle_deg);
  r.side_chip_thickness_mm = std::max(0.0, r.shift_mm * std::cos(phi1) - s * std::sin(phi1));
  r.wall_pitch_mm = 4.0 * s;  // K21
  const auto wall = wall_rz(params, r.wall_pitch_mm);
  if (!wall.ok()) return wall.error();
  r.wall_rz_um = wall.value().rz_um;
  r.wall_rz_branch = wall.value().branch;
  const auto plain = wall_rz(params, s0);
  if (!plain.ok()) return plain.error();
  r.plain_plunge_rz_um = plain.value().rz_um;
  r.warnings = warnings(params, r);
  return r;
}

}  // namespace cutcalc::domain::grooving
