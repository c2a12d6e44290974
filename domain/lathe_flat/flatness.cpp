#include "domain/lathe_flat/flatness.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "domain/common/golden_section.h"

namespace cutcalc::domain::lathe_flat {
namespace {

// The F14 procedure: 65 samples per segment, then a golden-section search on the two intervals
// beside the best sample until the bracket is below 1e-13 (at most 100 steps).
constexpr int kSamplesPerSegment = 64;
constexpr double kBracketWidth = 1e-13;
constexpr int kMaxGoldenSteps = 100;
// F16: error(N) was seen non-increasing for N = 1..40 only; above that N is found by bisection
// over the error's C/N^2 decrease.
constexpr int kScannedSteps = 40;

constexpr double kOutsideFace = -std::numeric_limits<double>::infinity();

// One block between step points i and i + 1 (F10).
struct Segment {
  double x_from_mm;  // X_i
  double x_to_mm;    // X_(i+1)
  double a_from;     // alpha_i
  double a_to;       // alpha_(i+1)
};

// F10-F13: the height of material the block leaves at parameter s above the flat, below the
// cylinder; kOutsideFace beyond the finished face.
double height_left_mm(const FlatSection& flat, double half_face_mm, const Segment& seg, double s) {
  const double r = seg.x_from_mm + s * (seg.x_to_mm - seg.x_from_mm);
  const double a = seg.a_from + s * (seg.a_to - seg.a_from);
  const double cos_a = std::cos(a);
  const double sin_a = std::sin(a);
  double qx = r * cos_a;  // c(s), F10
  double qy = -r * sin_a;
  if (flat.tool_radius_mm > 0.0) {  // F12: offset by R along the normal towards the axis
    const double dr = seg.x_to_mm - seg.x_from_mm;
    const double da = seg.a_to - seg.a_from;
    const double tx = dr * cos_a - r * da * sin_a;  // c'(s)
    const double ty = -dr * sin_a - r * da * cos_a;
    const double length = std::hypot(tx, ty);
    double nx = ty / length;
    double ny = -tx / length;
    if (nx > 0.0) {
      nx = -nx;
      ny = -ny;
    }
    qx += flat.tool_radius_mm * nx;
    qy += flat.tool_radius_mm * ny;
  }
  const double u = qy;
  if (std::fabs(u) > half_face_mm) return kOutsideFace;
  const double r2 = flat.part_radius_mm;
  const double e = qx - flat.axis_distance_mm;
  const double uncut =
      std::sqrt(std::max(0.0, (r2 - u) * (r2 + u))) - flat.axis_distance_mm;  // F13
  return std::min(e, uncut);
}

double segment_maximum(const FlatSection& flat, double half_face_mm, const Segment& seg) {
  const auto height = [&](double s) { return height_left_mm(flat, half_face_mm, seg, s); };
  int best_k = 0;
  double best = kOutsideFace;
  for (int k = 0; k <= kSamplesPerSegment; ++k) {
    const double h = height(static_cast<double>(k) / kSamplesPerSegment);
    if (h > best) {
      best = h;
      best_k = k;
    }
  }
  if (best == kOutsideFace) return best;
  const double from = static_cast<double>(std::max(best_k - 1, 0)) / kSamplesPerSegment;
  const double to =
      static_cast<double>(std::min(best_k + 1, kSamplesPerSegment)) / kSamplesPerSegment;
  const GoldenSection search = golden_section_minimum([&](double s) { return -height(s); }, from,
                                                      to, kBracketWidth, kMaxGoldenSteps);
  return std::max(best, -search.smallest_value());
}

}  // namespace

double flatness_error_mm(const FlatSection& flat, double face_width_mm, int steps) {
  const double alpha_e = engagement_half_angle_rad(flat);
  double worst = 0.0;
  // The second half mirrors the first (F14).
  for (int i = 0; i < steps; ++i) {
    const double a_from = step_angle_rad(alpha_e, steps, i);
    const double a_to = step_angle_rad(alpha_e, steps, i + 1);
    const Segment seg{tool_radius_position_mm(flat, a_from), tool_radius_position_mm(flat, a_to),
                      a_from, a_to};
    worst = std::max(worst, segment_maximum(flat, face_width_mm / 2.0, seg));
  }
  return worst;
}

double flatness_error_estimate_mm(const FlatSection& flat, int steps) {
  const double alpha_e = engagement_half_angle_rad(flat);
  const double step = alpha_e / steps;
  const double tan_e = std::tan(alpha_e);
  return (flat.axis_distance_mm + flat.tool_radius_mm) * step * step * (1.0 + 2.0 * tan_e * tan_e) /
         8.0;
}

std::optional<int> steps_for_tolerance(const FlatSection& flat, double face_width_mm,
                                       double tolerance_mm) {
  const auto meets = [&](int n) {
    return flatness_error_mm(flat, face_width_mm, n) <= tolerance_mm;
  };
  for (int n = 1; n <= kScannedSteps; ++n) {
    if (meets(n)) return n;
  }
  if (!meets(kMaxSteps)) return std::nullopt;
  int failing = kScannedSteps;
  int meeting = kMaxSteps;
  while (meeting - failing > 1) {
    const int middle = (failing + meeting) / 2;
    (meets(middle) ? meeting : failing) = middle;
  }
  return meeting;
}

}  // namespace cutcalc::domain::lathe_flat
