#include "gcode/path_checker.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

namespace cutcalc::test::gcode {

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;
constexpr int kMinSamplesPerArc = 200;
constexpr double kMaxSampleAngle = 0.005;       // rad between arc samples
constexpr int kCoverageSamplesPerPhase = 100;   // exact-path samples for the two-sided check
constexpr double kPrintedPointError = 0.75e-4;  // |rounded - exact| <= sqrt(2) 0.5e-4 per point
constexpr double kSameValue = 1e-9;  // printed numbers that must be identical (read as doubles)

double point_segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double length2 = dot(ab, ab);
  double f = length2 > 0.0 ? dot(p - a, ab) / length2 : 0.0;
  f = std::clamp(f, 0.0, 1.0);
  return norm(p - (a + f * ab));
}

std::string fixed(double value, int digits = 6) {
  std::ostringstream text;
  text.setf(std::ios::fixed);
  text.precision(digits);
  text << value;
  return text.str();
}

}  // namespace

PathCheckReport check_program(const CanonProgram& program, const ExactCentrePath& path,
                              const ProgramLayout& layout) {
  PathCheckReport report;
  auto& violations = report.violations;
  for (const auto& problem : program.problems) violations.push_back("canon: " + problem);

  const std::vector<CanonMotion> arcs = program.arcs();
  report.arcs = arcs.size();
  report.expected_arcs = static_cast<std::size_t>(layout.blocks_per_loop) * layout.loops();
  report.exact_loop_length_mm = path.loop_length();
  if (arcs.empty()) {
    violations.push_back("no ARC_FEED in the output");
    return report;
  }
  if (report.arcs != report.expected_arcs) {
    violations.push_back("arc count " + std::to_string(report.arcs) + ", expected " +
                         std::to_string(report.expected_arcs));
  }

  std::vector<ArcGeometry> geometry;
  for (const auto& arc : arcs) geometry.push_back(arc_geometry(arc));

  // Every loop repeats the first one's XY blocks (spec section 5; the printed numbers are
  // identical, so the doubles are): then the XY checks need the first loop only.
  const std::size_t per_loop = static_cast<std::size_t>(std::max(layout.blocks_per_loop, 1));
  bool repeats = report.arcs == report.expected_arcs;
  if (repeats) {
    for (std::size_t i = per_loop; i < arcs.size(); ++i) {
      const CanonMotion& a = arcs[i];
      const CanonMotion& b = arcs[i % per_loop];
      if (a.start.x != b.start.x || a.start.y != b.start.y || a.end.x != b.end.x ||
          a.end.y != b.end.y || a.centre.x != b.centre.x || a.centre.y != b.centre.y ||
          a.turn != b.turn) {
        repeats = false;
        violations.push_back("loop " + std::to_string(i / per_loop) +
                             " differs in XY from loop 0 at rs274 output line " +
                             std::to_string(a.output_line));
        break;
      }
    }
  }
  const std::size_t measured = repeats ? per_loop : arcs.size();

  // Arc -> path: LinuxCNC's interpolation sampled densely, each sample's distance to the path.
  std::vector<std::vector<Vec2>> samples(arcs.size());
  for (std::size_t i = 0; i < measured; ++i) {
    const int count =
        std::max(kMinSamplesPerArc,
                 static_cast<int>(std::ceil(std::abs(geometry[i].sweep) / kMaxSampleAngle)));
    for (int k = 0; k <= count; ++k) {
      const Vec2 p = arc_point(geometry[i], static_cast<double>(k) / count);
      samples[i].push_back(p);
      const double d = path.distance(p);
      if (d > report.max_deviation_mm) {
        report.max_deviation_mm = d;
        report.worst_arc_line = arcs[i].output_line;
      }
    }
  }
  const double deviation_limit = layout.tolerance_mm + kOutputResolutionMm;
  if (report.max_deviation_mm > deviation_limit) {
    violations.push_back("deviation " + fixed(report.max_deviation_mm) + " mm > " +
                         fixed(deviation_limit) + " mm (rs274 output line " +
                         std::to_string(report.worst_arc_line) + ")");
  }

  // Kinks: consecutive ARC_FEEDs (no other motion between them).
  for (std::size_t m = 0, a = 0; m + 1 < program.motions.size(); ++m) {
    if (program.motions[m].kind != MotionKind::arc) continue;
    const std::size_t this_arc = a++;
    if (program.motions[m + 1].kind != MotionKind::arc) continue;
    const ArcGeometry& before = geometry[this_arc];
    const ArcGeometry& after = geometry[this_arc + 1];
    const double kink =
        std::abs(angle_between(circle_tangent_at_end(before), circle_tangent_at_start(after))) *
        kDeg;
    const double spiral =
        std::abs(angle_between(spiral_tangent(before, 1.0), spiral_tangent(after, 0.0))) * kDeg;
    if (kink > report.max_kink_deg) {
      report.max_kink_deg = kink;
      report.worst_kink_line = program.motions[m + 1].output_line;
    }
    report.max_spiral_kink_deg = std::max(report.max_spiral_kink_deg, spiral);
  }
  if (report.max_kink_deg > kMaxKinkDeg) {
    violations.push_back("tangent kink " + fixed(report.max_kink_deg, 4) + " deg > " +
                         fixed(kMaxKinkDeg, 2) + " deg (before rs274 output line " +
                         std::to_string(report.worst_kink_line) + ")");
  }

  // Start point and Z.
  const Vec2 start = arcs.front().start.xy();
  report.start_offset_mm = norm(start - Vec2{0.0, path.e()});
  if (report.start_offset_mm > kPrintedPointError) {
    violations.push_back("first arc starts " + fixed(report.start_offset_mm) + " mm from (0, e)");
  }
  report.final_z_mm = arcs.back().end.z;
  report.min_z_mm = arcs.front().start.z;
  double previous_z = arcs.front().start.z;
  report.max_z_error_mm = std::abs(arcs.front().start.z);  // the ramp starts at Z0
  for (const auto& arc : arcs) {
    if (arc.end.z > previous_z + kSameValue) report.z_non_increasing = false;
    previous_z = arc.end.z;
    report.min_z_mm = std::min(report.min_z_mm, arc.end.z);
  }
  if (!report.z_non_increasing) violations.push_back("Z rises between arcs");
  if (report.min_z_mm < -layout.depth_mm - kOutputResolutionMm) {
    violations.push_back("Z goes to " + fixed(report.min_z_mm, 4) + ", below -depth");
  }
  if (std::abs(report.final_z_mm + layout.depth_mm) > kOutputResolutionMm) {
    violations.push_back("last arc ends at Z" + fixed(report.final_z_mm, 4) + ", not at -depth");
  }

  // Per loop: closure, printed length, coverage, Z levels and ramps, F and C words.
  if (report.arcs == report.expected_arcs) {
    const double dz = layout.depth_mm / layout.layers;
    const double loop_t = path.loop_parameter();
    const double c_scale = 180.0 / std::numbers::pi;
    report.c_tolerance_deg = kDeg * 2.0 * kPrintedPointError / path.semi_axis_b() + 1e-4;
    double unwrapped_t = 0.0;  // rotor rotation at the current arc end (c_axis check)
    const int coverage_count = path.faces() * kCoverageSamplesPerPhase;

    for (int loop = 0; loop < layout.loops(); ++loop) {
      const std::size_t first = static_cast<std::size_t>(loop) * per_loop;
      const std::size_t last = first + per_loop;  // one past

      double length = 0.0;
      std::vector<double> ends;  // cumulative printed length at each block end
      for (std::size_t i = first; i < last; ++i) {
        length += arc_length_xy(geometry[i]);
        ends.push_back(length);
      }
      if (loop == 0) report.printed_loop_length_mm = length;
      report.loop_length_spread_mm =
          std::max(report.loop_length_spread_mm, std::abs(length - report.printed_loop_length_mm));

      report.max_closure_mm =
          std::max(report.max_closure_mm, norm(arcs[last - 1].end.xy() - start));

      // Two-sided: every exact-path sample near the polyline of this loop's arc samples.
      for (int j = 0; j < (loop == 0 || !repeats ? coverage_count : 0); ++j) {
        const Vec2 p = path.point(loop_t * j / coverage_count);
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t i = first; i < last; ++i) {
          for (std::size_t k = 0; k + 1 < samples[i].size(); ++k) {
            best = std::min(best, point_segment_distance(p, samples[i][k], samples[i][k + 1]));
          }
        }
        report.max_uncovered_mm = std::max(report.max_uncovered_mm, best);
      }

      // Z: loop `loop` belongs to layer k (1-based); the first loop of a layer ramps from
      // -(k-1) dz to -k dz linearly in path length, the others are flat at -k dz.
      const int layer = std::min(loop / layout.loops_per_layer, layout.layers - 1) + 1;
      const bool ramp =
          loop % layout.loops_per_layer == 0 && loop < layout.layers * layout.loops_per_layer;
      const double level = -layer * dz;
      for (std::size_t i = first; i < last; ++i) {
        const double expected = ramp ? -(layer - 1) * dz - dz * ends[i - first] / length : level;
        report.max_z_error_mm = std::max(report.max_z_error_mm, std::abs(arcs[i].end.z - expected));
      }

      // F (P23): flat loops (N-1) L_p per revolution (c_axis: times the rpm, per minute); ramp
      // loops times sqrt(1 + (dz/L_p)^2) (c_axis: either value, the C words hold the phase).
      if (layout.feed_check != FeedCheck::none) {
        const bool c_axis = layout.feed_check == FeedCheck::c_axis;
        const double flat = (path.faces() - 1) * length * (c_axis ? layout.spindle_speed_rpm : 1.0);
        const double ramped = flat * std::sqrt(1.0 + (dz / length) * (dz / length));
        for (std::size_t i = first; i < last; ++i) {
          const double f = arcs[i].feed_rate;
          double error = std::abs(f - (ramp ? ramped : flat));
          if (ramp && c_axis) error = std::min(error, std::abs(f - flat));
          report.max_feed_error = std::max(report.max_feed_error, error);
          if (arcs[i].feed_mode != (c_axis ? 0 : 1)) report.feed_mode_ok = false;
        }
      }

      // C (c_axis): C = -(180/pi) t_end, t_end = rotor rotation at the block end = the parameter
      // of the nearest exact-path point, unwrapped over the loops. feed_per_rev: no C motion.
      for (std::size_t i = first; i < last; ++i) {
        if (layout.feed_check == FeedCheck::c_axis) {
          const double local = path.nearest(arcs[i].end.xy()).t;
          double step = std::fmod(local - std::fmod(unwrapped_t, loop_t), loop_t);
          if (step < 0.0) step += loop_t;
          if (std::abs(geometry[i].sweep) > 1.5 * std::numbers::pi && step < 0.25 * loop_t)
            step += loop_t;
          unwrapped_t += step;
          report.max_c_error_deg =
              std::max(report.max_c_error_deg, std::abs(arcs[i].end.c + c_scale * unwrapped_t));
        } else if (layout.feed_check == FeedCheck::feed_per_rev) {
          report.max_c_error_deg = std::max(report.max_c_error_deg, std::abs(arcs[i].end.c));
        }
      }
    }
    if (layout.feed_check == FeedCheck::c_axis) {
      report.max_c_error_deg = std::max(report.max_c_error_deg, std::abs(arcs.front().start.c));
    }

    if (report.max_closure_mm > kSameValue) {
      violations.push_back("a loop ends " + fixed(report.max_closure_mm) +
                           " mm from the start point");
    }
    if (report.max_uncovered_mm > deviation_limit) {
      violations.push_back("exact path " + fixed(report.max_uncovered_mm) + " mm from the arcs > " +
                           fixed(deviation_limit) + " mm");
    }
    if (report.max_z_error_mm > kOutputResolutionMm) {
      violations.push_back("Z off the layer levels / linear ramps by " +
                           fixed(report.max_z_error_mm) + " mm");
    }
    if (report.loop_length_spread_mm > kSameValue) {
      violations.push_back("loops differ in length by " + fixed(report.loop_length_spread_mm));
    }
    const double length_limit = 2.0 * std::numbers::pi * layout.tolerance_mm +
                                2.0 * kOutputResolutionMm * layout.blocks_per_loop;
    if (std::abs(report.printed_loop_length_mm - report.exact_loop_length_mm) > length_limit) {
      violations.push_back("printed loop length " + fixed(report.printed_loop_length_mm) +
                           " mm, exact " + fixed(report.exact_loop_length_mm) + " mm");
    }
    if (layout.feed_check != FeedCheck::none) {
      if (report.max_feed_error > 0.6 * kOutputResolutionMm) {
        violations.push_back("F off (N-1) L_p by " + fixed(report.max_feed_error));
      }
      if (!report.feed_mode_ok) violations.push_back("wrong feed mode (G94/G95) on an arc");
      const double c_limit =
          layout.feed_check == FeedCheck::c_axis ? report.c_tolerance_deg : kSameValue;
      if (report.max_c_error_deg > c_limit) {
        violations.push_back("C off the rotor phase by " + fixed(report.max_c_error_deg, 4) +
                             " deg > " + fixed(c_limit, 4) + " deg");
      }
    }
  }
  return report;
}

}  // namespace cutcalc::test::gcode
