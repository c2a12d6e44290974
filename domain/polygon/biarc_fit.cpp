// P18-P21 of spec polygon-holes.md: knots, equal-tangent biarcs, the deviation sampling rule,
// the smallest m, the junction parameters and the merged blocks of one loop.

#include "domain/polygon/biarc_fit.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>

#include "domain/common/interruption.h"
#include "domain/polygon/small_angle.h"

namespace cutcalc::domain::polygon::detail {

namespace {

constexpr int kPathSamples = 300;         // P20
constexpr int kArcSamples = 150;          // P20, per arc
constexpr int kGoldenMaxIterations = 80;  // P21

using PathSamples = std::array<Eigen::Vector2d, kPathSamples>;

// (cos, sin) of a0 + k h for k = 0, 1, 2, ... by rotation, re-anchored on the exact values every
// 32 steps (the recurrence alone drifts by about k ulp).
class AngleSteps {
 public:
  AngleSteps(double a0, double h) : a0_(a0), h_(h), cos_h_(std::cos(h)), sin_h_(std::sin(h)) {}

  // The values for step k; k must go 0, 1, 2, ... in order.
  Eigen::Vector2d next(int k) {
    if (k % 32 == 0) {
      const double angle = a0_ + k * h_;
      value_ = Eigen::Vector2d(std::cos(angle), std::sin(angle));
    } else {
      value_ = Eigen::Vector2d(value_.x() * cos_h_ - value_.y() * sin_h_,
                               value_.y() * cos_h_ + value_.x() * sin_h_);
    }
    return value_;
  }

 private:
  double a0_;
  double h_;
  double cos_h_;
  double sin_h_;
  Eigen::Vector2d value_ = Eigen::Vector2d::Zero();
};

// The segments of the path samples' polyline, each with its vector and squared length computed
// once: every arc sample measures itself against several of them.
class Polyline {
 public:
  static constexpr int kLastSegment = kPathSamples - 2;

  explicit Polyline(const PathSamples& samples) : points_(samples) {
    for (std::size_t i = 0; i + 1 < samples.size(); ++i) {
      ab_[i] = samples[i + 1] - samples[i];
      length2_[i] = ab_[i].squaredNorm();
    }
  }
  // segment_distance(P, sample i, sample i + 1) squared.
  [[nodiscard]] double distance_squared(const Eigen::Vector2d& P, int i) const {
    const auto j = static_cast<std::size_t>(i);
    return segment_distance_squared(P, points_[j], ab_[j], length2_[j]);
  }

 private:
  const PathSamples& points_;
  std::array<Eigen::Vector2d, kPathSamples - 1> ab_;
  std::array<double, kPathSamples - 1> length2_;
};

// Distance from P to the polyline of the path samples, by a local descent from segment `hint`
// (the arc samples advance along the path, so the nearest segment moves monotonically); `hint`
// is updated to the nearest segment found.
double polyline_distance(const Eigen::Vector2d& P, const Polyline& polyline, int& hint) {
  constexpr int last_segment = Polyline::kLastSegment;
  // The descent compares distances d = sqrt(d2). sqrt is monotone, so d2 >= best2 settles
  // "not nearer" without a root; only a smaller square needs both roots, to see whether they
  // still differ once rounded. The decisions, and so the segments visited, are those of the
  // comparison of the roots themselves.
  // The segment the walk forward left behind is the first the walk back reads.
  int kept = -1;
  double kept2 = 0.0;
  auto distance2 = [&](int i) { return i == kept ? kept2 : polyline.distance_squared(P, i); };
  int best = std::clamp(hint, 0, last_segment);
  double best2 = distance2(best);
  double best_root = -1.0;  // sqrt(best2) once needed
  auto nearer = [&](double d2, double& root) {
    if (!(d2 < best2)) {
      return false;
    }
    if (best_root < 0.0) {
      best_root = std::sqrt(best2);
    }
    root = std::sqrt(d2);
    return root < best_root;
  };
  double root = 0.0;
  while (best < last_segment) {
    const double next2 = distance2(best + 1);
    if (!nearer(next2, root)) {
      break;
    }
    kept = best;
    kept2 = best2;
    ++best;
    best2 = next2;
    best_root = root;
  }
  while (best > 0) {
    const double previous2 = distance2(best - 1);
    if (!nearer(previous2, root)) {
      break;
    }
    --best;
    best2 = previous2;
    best_root = root;
  }
  // The neighbours once more guard the descent against ties at a shared vertex. The smaller
  // square has the smaller root, so the minimum is taken before the one root.
  if (best > 1) {
    best2 = std::min(best2, distance2(best - 2));
  }
  if (best < last_segment - 1) {
    best2 = std::min(best2, distance2(best + 2));
  }
  hint = best;
  return std::sqrt(best2);
}

// std::min(biarc.first.distance_to(P), biarc.second.distance_to(P)), the same value. A path sample
// lies on one arc's span and far outside the other's: the far arc's distance, a root of its
// squared distance to an end, loses whenever that square exceeds four times the near one's
// squared distance, which settles the comparison without the root.
double nearer_arc_distance(const Biarc& biarc, const Eigen::Vector2d& P) {
  const FittedArc::DistanceParts a = biarc.first.distance_parts(P);
  const FittedArc::DistanceParts b = biarc.second.distance_parts(P);
  constexpr double kSquareSafe = 1e-150;  // d above it: d * d is a normal number
  if (a.radial && !b.radial) {
    const double d1 = a.distance(biarc.first.radius);
    if (d1 >= kSquareSafe && b.squared > 4.0 * (d1 * d1)) {
      return d1;
    }
    return std::min(d1, b.distance(biarc.second.radius));
  }
  if (!a.radial && b.radial) {
    const double d2 = b.distance(biarc.second.radius);
    if (d2 >= kSquareSafe && a.squared > 4.0 * (d2 * d2)) {
      return d2;
    }
    return std::min(a.distance(biarc.first.radius), d2);
  }
  return std::min(a.distance(biarc.first.radius), b.distance(biarc.second.radius));
}

// The squared distance f(theta) = |point_in_phase(0, theta) - J|^2 as a value with an error
// bound, from a Taylor expansion of the ellipse about the bracket's middle (P7:
// c(psi_c + x) = c(psi_c) + sin(x) c'(psi_c) + (1 - cos x) c''(psi_c) exactly), and exactly
// (a cosine and a sine) only where a comparison needs it.
class JunctionDistance {
 public:
  JunctionDistance(const CentrePath& path, const Eigen::Vector2d& J, double theta0, double theta1)
      : path_(path), J_(J), half_delta_(0.5 * path.shape().delta) {
    const PolygonShape& shape = path.shape();
    const CentrePath::Frame& frame = path.frame(0);
    psi_c_ = 0.5 * (theta0 + theta1) - half_delta_;
    const double c = std::cos(psi_c_);
    const double s = std::sin(psi_c_);
    point_ = frame.V - shape.A * c * frame.w - shape.B * s * frame.t;
    d1_ = shape.A * s * frame.w - shape.B * c * frame.t;
    d2_ = shape.A * c * frame.w + shape.B * s * frame.t;
    // Both points, exact and expanded, lie within a few roundings of |V| + A + B of the ellipse.
    point_error_ = 64.0 * kUnitRoundoff * (frame.V.norm() + shape.A + shape.B);
    usable_ = std::abs(theta1 - theta0) <= 0.2;
  }

  struct Value {
    double theta = 0.0;
    double approx = 0.0;
    double error = std::numeric_limits<double>::infinity();
    std::optional<double> exact;
  };

  [[nodiscard]] Value at(double theta) const {
    Value value;
    value.theta = theta;
    if (usable_) {
      const double x = (theta - half_delta_) - psi_c_;
      const Eigen::Vector2d p = point_ + sin_small(x) * d1_ + one_minus_cos_small(x) * d2_;
      value.approx = (p - J_).squaredNorm();
      const double distance = std::sqrt(value.approx);
      value.error =
          4.0 * point_error_ * (distance + point_error_) + 16.0 * kUnitRoundoff * value.approx;
    }
    return value;
  }
  [[nodiscard]] double exact(Value& value) const {
    if (!value.exact) {
      value.exact = (path_.point_in_phase(0, value.theta) - J_).squaredNorm();
    }
    return *value.exact;
  }
  // f(a.theta) < f(b.theta) for the exact values, from the bounds where they settle it.
  bool less(Value& a, Value& b) const {
    if (a.approx + a.error < b.approx - b.error) {
      return true;
    }
    if (a.approx - a.error >= b.approx + b.error) {
      return false;
    }
    return exact(a) < exact(b);
  }

 private:
  static constexpr double kUnitRoundoff = std::numeric_limits<double>::epsilon() / 2.0;
  const CentrePath& path_;
  Eigen::Vector2d J_;
  double half_delta_;
  double psi_c_ = 0.0;
  Eigen::Vector2d point_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d d1_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d d2_ = Eigen::Vector2d::Zero();
  double point_error_ = 0.0;
  bool usable_ = false;
};

// P21: theta in [theta0, theta1] of the exact point of ellipse arc 0 nearest to J, by golden
// section until the bracket is <= 1e-12 delta (at most 80 iterations). This is
// golden_section_minimum (domain/common/golden_section.h) step for step, the same brackets from
// the same comparisons of the same values, where each comparison reads the exact values only
// when the expansion's bounds leave it open: for the largest fits about 3 of the 47 evaluations
// need their cosine and sine. FitEvaluation.JunctionParameterIsTheGoldenSectionOfTheExactDistance
// holds the two together.
std::optional<double> nearest_path_parameter(const CentrePath& path, const Eigen::Vector2d& J,
                                             double theta0, double theta1) {
  const double bracket = 1e-12 * path.shape().delta;
  const JunctionDistance f(path, J, theta0, theta1);
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = theta0;
  double b = theta1;
  JunctionDistance::Value f1 = f.at(b - ratio * (b - a));
  JunctionDistance::Value f2 = f.at(a + ratio * (b - a));
  for (int iteration = 0; iteration < kGoldenMaxIterations && b - a > bracket; ++iteration) {
    if (f.less(f1, f2)) {
      b = f2.theta;
      f2 = f1;
      f1 = f.at(b - ratio * (b - a));
    } else {
      a = f1.theta;
      f1 = f2;
      f2 = f.at(a + ratio * (b - a));
    }
  }
  if (!(b - a <= bracket)) {
    return std::nullopt;
  }
  return 0.5 * (a + b);
}

// P19 up to the junction: J, the midpoint of the tangent points Q0 = P0 + al T0 and
// Q1 = P1 - al T1, and its tangent. Empty when al is not a positive number.
struct BiarcJoin {
  Eigen::Vector2d J;
  Eigen::Vector2d T_J;
};

std::optional<BiarcJoin> biarc_join(const Eigen::Vector2d& P0, const Eigen::Vector2d& T0,
                                    const Eigen::Vector2d& P1, const Eigen::Vector2d& T1) {
  const Eigen::Vector2d d = P1 - P0;  // the chord vector
  const Eigen::Vector2d v = T0 + T1;
  const double tau = 1.0 - T0.dot(T1);
  const double dv = d.dot(v);
  const double d2 = d.squaredNorm();
  const double al = d2 / (dv + std::sqrt(dv * dv + 2.0 * tau * d2));
  if (!std::isfinite(al) || !(al > 0.0)) {
    return std::nullopt;
  }
  const Eigen::Vector2d Q0 = P0 + al * T0;
  const Eigen::Vector2d Q1 = P1 - al * T1;
  return BiarcJoin{0.5 * (Q0 + Q1), (Q1 - Q0).normalized()};
}

// P18: knot i of ellipse arc 0 for m biarcs: theta_i = i delta / m, the exact point and unit
// tangent. The phase-change knots are the exact points -e u_0 = (0, e) and -e u_1 (P9).
struct Knot {
  Eigen::Vector2d P;
  Eigen::Vector2d T;
};

Knot make_knot(const CentrePath& path, int m, int i) {
  const PolygonShape& shape = path.shape();
  const double theta = i * shape.delta / m;
  const CentrePath::PointAndVelocity exact = path.point_and_velocity_in_phase(0, theta);
  Knot knot{exact.point, exact.velocity.normalized()};
  if (i == 0) {
    knot.P = Eigen::Vector2d(0.0, shape.e);
  } else if (i == m) {
    knot.P = -shape.e * shape.u(1);
  }
  return knot;
}

// P19 for biarc i of m.
Result<Biarc> make_biarc(const CentrePath& path, int m, int i) {
  const Knot k0 = make_knot(path, m, i);
  const Knot k1 = make_knot(path, m, i + 1);
  const auto biarc = fit_biarc(k0.P, k0.T, k1.P, k1.T);
  if (!biarc) {
    return make_error(ErrorCode::not_converged,
                      "the arc fit of the centre path degenerated (m = " + std::to_string(m) + ")");
  }
  return *biarc;
}

// Whether make_biarc(path, m, i) fails for some i < k: fit_biarc's own tests without the arcs'
// angles, each knot computed once.
bool any_biarc_degenerates_before(const CentrePath& path, int m, int k) {
  if (k <= 0) {
    return false;
  }
  Knot k0 = make_knot(path, m, 0);
  for (int i = 0; i < k; ++i) {
    const Knot k1 = make_knot(path, m, i + 1);
    const auto join = biarc_join(k0.P, k0.T, k1.P, k1.T);
    if (!join || !tangent_arc_curvature(k0.P, k0.T, join->J) ||
        !tangent_arc_curvature(join->J, join->T_J, k1.P)) {
      return true;
    }
    k0 = k1;
  }
  return false;
}

// Which samples of P20 a measurement reads first. The deviation is the largest sample either
// way; only where a measurement stops early (at the first sample beyond the limit) does the
// order matter, and only to how soon it stops.
enum class SampleOrder { path_first, arc_first };

double measure_biarc(const CentrePath& path, double theta0, double theta1, const Biarc& biarc,
                     double limit, SampleOrder order, SampleOrder* stopped_in);

// P21's scan of m evaluates biarcs 0, 1, ... in order and stops at the first one beyond the
// tolerance (m fails) or the first one that degenerates (an error). Any biarc k beyond the
// tolerance with none degenerating before it therefore settles "m fails" exactly as the scan
// would, whichever biarc the scan would have stopped at. The worst biarc sits at about the same
// fraction of the ellipse arc for neighbouring m, so probes where the last failure was settle
// nearly every failing m with one or two biarcs instead of the scan's dozens.
class FailingBiarcSearch {
 public:
  FailingBiarcSearch(const CentrePath& path, double tolerance)
      : path_(path), tolerance_(tolerance) {}

  // True when m is settled as failing. False says nothing: the in-order scan decides. The
  // deviations of the biarcs measured within the tolerance are kept in `measured` (index ->
  // deviation) for the scan to reuse.
  bool settles_failure(int m, std::vector<double>& measured) {
    const int half = (m + 1) / 2;
    measured.assign(static_cast<std::size_t>(half), kUnmeasured);
    // Where the last failure was first, then biarc 0 (the worst for small m).
    const int guess = std::clamp(static_cast<int>(guess_fraction_ * m), 0, half - 1);
    for (const int k : {guess, 0, guess - 1, guess + 1}) {
      const bool repeated = k == 0 && guess == 0;
      if (k >= 0 && k < half && !repeated && probe(m, k, measured)) {
        return true;
      }
    }
    return search_worst(m, half, measured);
  }

  static constexpr double kUnmeasured = -1.0;

 private:
  // Biarc k measured (once); true when it settles that m fails.
  bool probe(int m, int k, std::vector<double>& measured) {
    double& slot = measured[static_cast<std::size_t>(k)];
    if (slot != kUnmeasured) {
      return false;  // measured already, within the tolerance
    }
    const double delta = path_.shape().delta;
    const auto biarc = make_biarc(path_, m, k);
    if (!biarc.ok()) {
      return false;  // the scan reports it, or stops earlier
    }
    // The samples that went beyond the tolerance last time are read first: for m just below the
    // answer only a few arc samples do, after all 300 path samples.
    SampleOrder stopped_in = order_;
    const double deviation = measure_biarc(path_, k * delta / m, (k + 1) * delta / m, biarc.value(),
                                           tolerance_, order_, &stopped_in);
    if (!(deviation > tolerance_)) {
      // NaN included: the scan treats it as the original did.
      slot = deviation <= tolerance_ ? deviation : kUnmeasured;
      return false;
    }
    if (any_biarc_degenerates_before(path_, m, k)) {
      return false;
    }
    guess_fraction_ = (k + 0.5) / m;
    order_ = stopped_in;
    return true;
  }

  // Golden-section search over the biarc index for the largest deviation (the deviation along
  // the ellipse arc has one hump), stopping at the first biarc beyond the tolerance. Nothing
  // depends on the hump being single: a miss only leaves m to the scan.
  bool search_worst(int m, int half, std::vector<double>& measured) {
    auto deviation_of = [&](int k, bool& settled) {
      settled = probe(m, k, measured);
      return settled ? std::numeric_limits<double>::infinity()
                     : measured[static_cast<std::size_t>(k)];
    };
    int lo = 0;
    int hi = half - 1;
    bool settled = false;
    while (hi - lo > 2) {
      const int x1 = lo + static_cast<int>(0.382 * (hi - lo));
      const int x2 = std::max(x1 + 1, hi - static_cast<int>(0.382 * (hi - lo)));
      const double f1 = deviation_of(x1, settled);
      if (settled) {
        return true;
      }
      const double f2 = deviation_of(x2, settled);
      if (settled) {
        return true;
      }
      if (f1 < f2) {
        lo = x1 + 1;
      } else {
        hi = x2 - 1;
      }
    }
    for (int k = lo; k <= hi; ++k) {
      deviation_of(k, settled);
      if (settled) {
        return true;
      }
    }
    return false;
  }

  const CentrePath& path_;
  double tolerance_;
  double guess_fraction_ = 0.0;  // (k + 1/2) / m of the last biarc that settled a failure
  SampleOrder order_ = SampleOrder::path_first;
};

}  // namespace

// P19
std::optional<Biarc> fit_biarc(const Eigen::Vector2d& P0, const Eigen::Vector2d& T0,
                               const Eigen::Vector2d& P1, const Eigen::Vector2d& T1) {
  const auto join = biarc_join(P0, T0, P1, T1);
  if (!join) {
    return std::nullopt;
  }
  const auto first = arc_from_tangent(P0, T0, join->J);
  const auto second = arc_from_tangent(join->J, join->T_J, P1);
  if (!first || !second) {
    return std::nullopt;
  }
  return Biarc{*first, *second, join->J};
}

namespace {

// P20 as biarc_deviation, reading the path samples' distances or the arc samples' first.
double measure_biarc(const CentrePath& path, double theta0, double theta1, const Biarc& biarc,
                     double limit, SampleOrder order, SampleOrder* stopped_in) {
  PathSamples samples;
  const double step = (theta1 - theta0) / (kPathSamples - 1);
  AngleSteps psi(theta0 - 0.5 * path.shape().delta, step);
  double deviation = 0.0;
  // Path samples t_k = t_i + k (t_{i+1} - t_i) / 299 to the biarc.
  auto path_part = [&](bool placed) {
    for (int k = 0; k < kPathSamples; ++k) {
      auto& P = samples[static_cast<std::size_t>(k)];
      if (!placed) {
        const Eigen::Vector2d cs = psi.next(k);
        P = path.point_at_psi(0, cs.x(), cs.y());
      }
      deviation = std::max(deviation, nearer_arc_distance(biarc, P));
      if (deviation > limit) {
        *stopped_in = SampleOrder::path_first;
        return true;
      }
    }
    return false;
  };
  // Arc samples (equally spaced in angle, both ends) to the polyline of the path samples.
  auto arc_part = [&]() {
    const Polyline polyline(samples);
    int hint = 0;
    for (const FittedArc* arc : {&biarc.first, &biarc.second}) {
      AngleSteps angle(arc->start_angle, arc->sweep / (kArcSamples - 1));
      for (int k = 0; k < kArcSamples; ++k) {
        const Eigen::Vector2d P = arc->centre + arc->radius * angle.next(k);
        deviation = std::max(deviation, polyline_distance(P, polyline, hint));
        if (deviation > limit) {
          *stopped_in = SampleOrder::arc_first;
          return true;
        }
      }
    }
    return false;
  };
  if (order == SampleOrder::path_first) {
    if (!path_part(false)) {
      arc_part();
    }
  } else {
    for (int k = 0; k < kPathSamples; ++k) {
      const Eigen::Vector2d cs = psi.next(k);
      samples[static_cast<std::size_t>(k)] = path.point_at_psi(0, cs.x(), cs.y());
    }
    if (!arc_part()) {
      path_part(true);
    }
  }
  return deviation;
}

}  // namespace

// P20
double biarc_deviation(const CentrePath& path, double theta0, double theta1, const Biarc& biarc,
                       double limit) {
  SampleOrder stopped_in = SampleOrder::path_first;
  return measure_biarc(path, theta0, theta1, biarc, limit, SampleOrder::path_first, &stopped_in);
}

// P18-P21
Result<PhaseFit> fit_ellipse_arc(const CentrePath& path, double tolerance, int max_m) {
  const double delta = path.shape().delta;
  FailingBiarcSearch search(path, tolerance);
  std::vector<double> measured;
  for (int m = 1; m <= max_m; ++m) {
    interruption_point();
    if (search.settles_failure(m, measured)) {
      continue;
    }
    PhaseFit fit;
    fit.m = m;
    fit.biarcs.reserve(static_cast<std::size_t>(m));
    // The ellipse arc is mirror-symmetric about its mid-phase line, and so are the knots and
    // the sampling rule: biarc m-1-i is the mirror image of biarc i with the same deviation.
    // A failing m stops at its first biarc beyond the tolerance.
    bool within = true;
    for (int i = 0; i < (m + 1) / 2 && within; ++i) {
      auto biarc = make_biarc(path, m, i);
      if (!biarc.ok()) {
        return biarc.error();
      }
      // A deviation the search measured is the same function of the same biarc.
      const double known = measured[static_cast<std::size_t>(i)];
      const double deviation =
          known != FailingBiarcSearch::kUnmeasured
              ? known
              : biarc_deviation(path, i * delta / m, (i + 1) * delta / m, biarc.value(), tolerance);
      fit.deviation = std::max(fit.deviation, deviation);
      within = deviation <= tolerance;
      fit.biarcs.push_back(biarc.value());
    }
    if (!within) {
      continue;
    }
    for (int i = (m + 1) / 2; i < m; ++i) {
      auto biarc = make_biarc(path, m, i);
      if (!biarc.ok()) {
        return biarc.error();
      }
      fit.biarcs.push_back(biarc.value());
    }
    for (int i = 0; i < m; ++i) {
      const auto theta =
          nearest_path_parameter(path, fit.biarcs[static_cast<std::size_t>(i)].junction,
                                 i * delta / m, (i + 1) * delta / m);
      if (!theta) {
        return make_error(ErrorCode::not_converged,
                          "the nearest path point to a biarc junction did not converge");
      }
      fit.junction_theta.push_back(*theta);
    }
    return fit;
  }
  return make_limit_error(ErrorCode::tolerance_unreachable, max_m);
}

// P21
std::vector<LoopBlock> loop_blocks(const CentrePath& path, const PhaseFit& fit,
                                   double merge_tolerance) {
  const PolygonShape& shape = path.shape();
  const int m = fit.m;
  std::vector<LoopBlock> blocks;
  double s = 0.0;
  auto add = [&](const FittedArc& arc, double t_end) {
    if (!blocks.empty()) {
      LoopBlock& block = blocks.back();
      const bool same_circle = (arc.centre - block.arc.centre).norm() <= merge_tolerance &&
                               std::abs(arc.radius - block.arc.radius) <= merge_tolerance &&
                               (arc.sweep > 0.0) == (block.arc.sweep > 0.0);
      if (same_circle) {
        block.arc.end = arc.end;
        block.arc.sweep += arc.sweep;
        block.arc.length += arc.length;
        block.t_end = t_end;
        s += arc.length;
        block.s_end = s;
        return;
      }
    }
    const double t_start = blocks.empty() ? 0.0 : blocks.back().t_end;
    const double s_start = s;
    s += arc.length;
    blocks.push_back(LoopBlock{arc, t_start, t_end, s_start, s});
  };
  blocks.reserve(2 * static_cast<std::size_t>(shape.N) * static_cast<std::size_t>(m));
  for (int p = 0; p < shape.N; ++p) {
    const double turn = 2.0 * std::numbers::pi * p / shape.N;
    const Eigen::Matrix2d rotation = Eigen::Rotation2Dd(turn).toRotationMatrix();
    for (int i = 0; i < m; ++i) {
      const Biarc& biarc = fit.biarcs[static_cast<std::size_t>(i)];
      add(biarc.first.rotated(rotation, turn),
          p * shape.delta + fit.junction_theta[static_cast<std::size_t>(i)]);
      add(biarc.second.rotated(rotation, turn),
          static_cast<double>(p * m + i + 1) * shape.delta / m);
    }
  }
  blocks.back().arc.end = Eigen::Vector2d(0.0, shape.e);
  return blocks;
}

}  // namespace cutcalc::domain::polygon::detail
