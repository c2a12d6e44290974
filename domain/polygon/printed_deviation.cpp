#include "domain/polygon/printed_deviation.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "domain/common/interruption.h"
#include "domain/polygon/small_angle.h"

// The deviation is the largest of about 650 distances per block (3223 blocks for the largest
// request), each a sine and cosine and an atan2 or a search over 48 segments. It is computed here
// in three tiers, with the same result to the last bit:
//  A. per block, an upper bound on all its distances from the closed form of the exact path (a
//     degree-2 trigonometric polynomial in psi), without sampling;
//  B. for the blocks whose bound reaches the largest distance known so far, every distance
//     approximated from a Taylor expansion of the path, with a bound on its error;
//  C. the distances whose approximation could still reach that largest distance computed exactly
//     as before (the same expressions), the largest of which is the result.
// A block or distance is skipped only when a bound shows it stays below a distance that was
// computed exactly, so the maximum is the one the sample-by-sample evaluation finds. Blocks the
// bounds do not cover (a turn or more, a phase change twice, large spans) are computed in full.

namespace cutcalc::domain::polygon::detail {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Samples per block: of the exact path (its polyline's chords sag far below any printed digit)
// and of the printed arc.
constexpr int kDeviationPathSamples = 512;
constexpr int kDeviationArcSamples = 128;
// Printed-arc samples are compared with the exact path near the same fraction of the block.
constexpr int kSearchWindow = 24;
constexpr int kPathPerArcSample = kDeviationPathSamples / kDeviationArcSamples;

constexpr double kUnitRoundoff = std::numeric_limits<double>::epsilon() / 2.0;
// Every error bound below is a multiple of the unit roundoff times the magnitudes involved; the
// multiples are several times what the operation counts give, so that no bound is tight.
constexpr double kRoundoffMultiple = 128.0;
// Tier A's subintervals of a phase piece (see PhasePiece::squared_radius_gap_bounds).
constexpr int kSubintervals = 16;

// The printed numbers are [-]digits[.digits] with 13 digits at most: for up to 15 digits,
// mantissa / 10^k, both exact doubles, is correctly rounded by the one division, exactly as
// from_chars rounds the decimal. Anything else goes to from_chars.
double parse_number(const std::string& text) {
  constexpr std::array<double, 16> kPowers{1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                           1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
  std::size_t i = 0;
  const bool negative = !text.empty() && text[0] == '-';
  i += negative ? 1 : 0;
  std::uint64_t mantissa = 0;
  int digits = 0;
  int decimals = -1;
  bool plain = i < text.size();
  for (; i < text.size() && plain; ++i) {
    const char c = text[i];
    if (c >= '0' && c <= '9') {
      mantissa = mantissa * 10 + static_cast<std::uint64_t>(c - '0');
      ++digits;
      decimals += decimals >= 0 ? 1 : 0;
    } else if (c == '.' && decimals < 0) {
      decimals = 0;
    } else {
      plain = false;
    }
  }
  if (plain && digits > 0 && digits <= 15) {
    const double value =
        static_cast<double>(mantissa) / kPowers[static_cast<std::size_t>(std::max(decimals, 0))];
    return negative ? -value : value;
  }
  double value = 0.0;
  std::from_chars(text.data(), text.data() + text.size(), value);
  return value;
}

// One printed block: a spiral from S to E around C, counter-clockwise (G3), as P23 reads it.
struct PrintedArc {
  Eigen::Vector2d S, E, C;
  double r0 = 0.0, r1 = 0.0, a0 = 0.0, sweep = kTwoPi;

  PrintedArc(const Eigen::Vector2d& start, const Eigen::Vector2d& end,
             const Eigen::Vector2d& centre)
      : S(start), E(end), C(centre), r0((start - centre).norm()), r1((end - centre).norm()) {
    a0 = std::atan2(S.y() - C.y(), S.x() - C.x());
    if (E != S) {
      sweep = std::atan2(E.y() - C.y(), E.x() - C.x()) - a0;
      while (sweep <= 0.0) {
        sweep += kTwoPi;
      }
      while (sweep > kTwoPi) {
        sweep -= kTwoPi;
      }
    }
  }
  [[nodiscard]] Eigen::Vector2d at(double f) const {
    const double a = a0 + f * sweep;
    return C + (r0 + f * (r1 - r0)) * Eigen::Vector2d(std::cos(a), std::sin(a));
  }
  // The distance from p to the spiral: radial where p's angle lies on it, else to an end.
  [[nodiscard]] double distance(const Eigen::Vector2d& p) const {
    double angle = std::atan2(p.y() - C.y(), p.x() - C.x()) - a0;
    while (angle < 0.0) {
      angle += kTwoPi;
    }
    while (angle >= kTwoPi) {
      angle -= kTwoPi;
    }
    const double f = angle / sweep;
    if (f <= 1.0) {
      return std::fabs((p - C).norm() - (r0 + f * (r1 - r0)));
    }
    return std::min((p - S).norm(), (p - E).norm());
  }
};

// One block with its exact-path parameter range.
struct Block {
  PrintedArc arc;
  double t0 = 0.0;
  double t1 = 0.0;

  // t of path sample j, as the sampling loop computes it.
  [[nodiscard]] double t(int j) const { return t0 + (t1 - t0) * j / kDeviationPathSamples; }
  // The printed-arc sample k's window of polyline segments [begin, end).
  [[nodiscard]] static int window_begin(int k) {
    return std::max(0, k * kPathPerArcSample - kSearchWindow);
  }
  [[nodiscard]] static int window_end(int k) {
    return std::min(kDeviationPathSamples, k * kPathPerArcSample + kSearchWindow);
  }
};

// Path sample j of a block, exactly: computed on first use.
class ExactPoints {
 public:
  ExactPoints(const CentrePath& path, double d_mm, const Block& block)
      : path_(path), d_mm_(d_mm), block_(block) {
    known_.fill(false);
  }
  const Eigen::Vector2d& operator()(int j) {
    const auto i = static_cast<std::size_t>(j);
    if (!known_[i]) {
      points_[i] = d_mm_ * path_.point(block_.t(j));
      known_[i] = true;
    }
    return points_[i];
  }

 private:
  const CentrePath& path_;
  double d_mm_;
  const Block& block_;
  std::array<Eigen::Vector2d, kDeviationPathSamples + 1> points_;
  std::array<bool, kDeviationPathSamples + 1> known_;
};

// Tier C for path sample j: the exact path point to the printed arc.
double exact_path_distance(const Block& block, ExactPoints& exact, int j) {
  return block.arc.distance(exact(j));
}

// The whole block sample by sample, as the deviation was always computed.
double exact_block_deviation(const Block& block, ExactPoints& exact) {
  double worst = 0.0;
  for (int j = 0; j <= kDeviationPathSamples; ++j) {
    worst = std::max(worst, exact_path_distance(block, exact, j));
  }
  for (int k = 0; k <= kDeviationArcSamples; ++k) {
    const double f = static_cast<double>(k) / kDeviationArcSamples;
    const Eigen::Vector2d q = block.arc.at(f);
    double nearest = std::numeric_limits<double>::infinity();
    for (int j = Block::window_begin(k); j < Block::window_end(k); ++j) {
      nearest = std::min(nearest, segment_distance(q, exact(j), exact(j + 1)));
    }
    worst = std::max(worst, nearest);
  }
  return worst;
}

// The exact path over the part of a block in one phase, about psi_c, relative to the printed
// centre C, in mm: p(psi_c + x) - C = P + sin(x) D1 + (1 - cos x) D2 exactly (P7), with
// D1 = p'(psi_c) and D2 = p''(psi_c); every derivative of p is +-D1 or +-D2 at psi_c.
struct PhasePiece {
  int phase = 0;
  int j_first = 0;  // the samples j_first..j_last are evaluated in this phase
  int j_last = 0;
  double psi_c = 0.0;
  double x_lo = 0.0;  // the piece covers psi_c + [x_lo, x_hi]
  double x_hi = 0.0;
  Eigen::Vector2d P = Eigen::Vector2d::Zero();
  Eigen::Vector2d D1 = Eigen::Vector2d::Zero();
  Eigen::Vector2d D2 = Eigen::Vector2d::Zero();
  double derivative_bound = 0.0;  // >= |p^(k)| for k >= 1 on the piece
  // Tier A's bounds on F (below) on each of kSubintervals equal parts of [x_lo, x_hi].
  std::array<double, kSubintervals> F_abs{};  // >= |F|

  [[nodiscard]] double subinterval_width() const { return (x_hi - x_lo) / kSubintervals; }

  [[nodiscard]] double half_width() const { return std::max(-x_lo, x_hi); }
  [[nodiscard]] Eigen::Vector2d relative_point(double x) const {
    return P + sin_small(x) * D1 + one_minus_cos_small(x) * D2;
  }
};

// Bounds on F(x) = |p(psi_c + x) - C|^2 - r(x)^2 over a piece, r(x) = r_c + r_s x linear.
struct Interval {
  double lo = 0.0;
  double hi = 0.0;
};

// F's Taylor polynomial to x^4 about 0, its remainder bound on |x| <= X, and on each of
// kSubintervals subintervals the quadratic Taylor polynomial about the subinterval's middle, whose
// extremes are exact, with the cubic and quartic terms bounded: F is then bounded to a few parts
// in a thousand of its own size (a sampled maximum would not be a bound).
Interval squared_radius_gap_bounds(PhasePiece& piece, double r_c, double r_s, double point_error) {
  const Eigen::Vector2d& P = piece.P;
  const Eigen::Vector2d& D1 = piece.D1;
  const Eigen::Vector2d& D2 = piece.D2;
  const double rho = P.norm();
  // d^n/dx^n |P(x)|^2 at 0: sum C(n, k) P^(k).P^(n-k), P' = D1, P'' = D2, P''' = -D1, P'''' = -D2.
  const double pd1 = P.dot(D1);
  const double pd2 = P.dot(D2);
  const double d11 = D1.squaredNorm();
  const double d12 = D1.dot(D2);
  const double d22 = D2.squaredNorm();
  std::array<double, 5> F{};  // F^(n)(0)
  F[0] = (rho - r_c) * (rho + r_c);
  F[1] = 2.0 * pd1 - 2.0 * r_c * r_s;
  F[2] = 2.0 * pd2 + 2.0 * d11 - 2.0 * r_s * r_s;
  F[3] = -2.0 * pd1 + 6.0 * d12;
  F[4] = -2.0 * pd2 - 8.0 * d11 + 6.0 * d22;
  const double X = piece.half_width();
  const double M = piece.derivative_bound;
  const double rho_max = rho + X * D1.norm() + 0.5 * X * X * D2.norm();
  // |F^(5)| <= 2 |P| M + (5 + 5 + 10 + 10) M^2 (r is linear: no fifth derivative).
  const double remainder = (2.0 * rho_max * M + 30.0 * M * M) * (X * X * X * X * X) / 120.0;
  // Rounding: the terms F[n] x^n / n! are sums of products of magnitude <= these (the n-th
  // carries x^n), and P, D1, D2 themselves are off by at most point_error.
  const double magnitude = rho * rho + r_c * r_c + 2.0 * (rho + r_c) * M * X +
                           (2.0 * rho * M + 8.0 * M * M + r_c * r_c) * X * X;
  const double rounding = kRoundoffMultiple * kUnitRoundoff * magnitude +
                          2.0 * (rho_max + r_c) * point_error + point_error * point_error;
  const double width = (piece.x_hi - piece.x_lo) / kSubintervals;
  const double h = 0.5 * width;
  // The quartic sum F[n] x^n / n! and its derivatives, coefficients divided out once.
  const double c2 = F[2] / 2.0, c3 = F[3] / 6.0, c4 = F[4] / 24.0;
  const double d2 = F[3] / 2.0, d3 = F[4] / 6.0;
  const double e2 = F[4] / 2.0;
  Interval bounds{std::numeric_limits<double>::infinity(),
                  -std::numeric_limits<double>::infinity()};
  for (int i = 0; i < kSubintervals; ++i) {
    const double m = piece.x_lo + (i + 0.5) * width;
    // The quartic's value and first two derivatives at m: about m it is
    // q0 + q1 y + q2 y^2 / 2 + (F[3] + m F[4]) y^3 / 6 + F[4] y^4 / 24 exactly.
    const double q0 = F[0] + m * (F[1] + m * (c2 + m * (c3 + m * c4)));
    const double q1 = F[1] + m * (F[2] + m * (d2 + m * d3));
    const double q2 = F[2] + m * (F[3] + m * e2);
    // q0 + q1 y + q2 y^2 / 2 on |y| <= h: at the ends and at the vertex if inside.
    const double left = q0 - q1 * h + 0.5 * q2 * h * h;
    const double right = q0 + q1 * h + 0.5 * q2 * h * h;
    double top = std::max(left, right);
    double bottom = std::min(left, right);
    if (std::abs(q1) < std::abs(q2) * h) {
      const double vertex = q0 - q1 * q1 / (2.0 * q2);
      top = std::max(top, vertex);
      bottom = std::min(bottom, vertex);
    }
    const double q3 = std::abs(F[3] + m * F[4]) * (h * h * h / 6.0);
    const double slack = q3 + std::abs(F[4]) * (h * h * h * h / 24.0) + remainder + rounding;
    bounds.lo = std::min(bounds.lo, bottom - slack);
    bounds.hi = std::max(bounds.hi, top + slack);
    piece.F_abs[static_cast<std::size_t>(i)] =
        std::max(std::abs(bottom - slack), std::abs(top + slack));
  }
  return bounds;
}

// Everything tiers A and B know about a block.
struct BlockModel {
  bool covered = false;  // false: the bounds below do not hold; compute the block exactly
  std::array<PhasePiece, 2> pieces;
  int piece_count = 0;
  double slack = 0.0;         // bound on |approximation - exact| of one distance, mm
  double radial_gap = 0.0;    // >= | |p - C| - r_lin | on the whole block (r_lin below)
  double fraction_gap = 0.0;  // >= |f - lambda|: printed-arc fraction vs t fraction
  double sag = 0.0;           // >= distance of the exact path from the samples' polyline
  double start_bound = 0.0;   // >= the distance of the samples that may lie before S
  double end_bound = 0.0;     // ... and after E
  int inside_first = 0;       // samples inside_first..inside_last lie within the arc's span
  int inside_last = 0;
  double gap_per_F = 0.0;  // | |p - C| - r_lin | <= |F| gap_per_F (+ slack)
  // The printed-arc sample k's ray meets the path at t* with t* - t0 in
  // [(k sweep / 128 - ray_offset_hi) / omega_hi, (k sweep / 128 - ray_offset_lo) / omega_lo].
  double ray_offset_lo = 0.0;
  double ray_offset_hi = 0.0;
  double omega_lo = 0.0;
  double omega_hi = 0.0;
  double upper = std::numeric_limits<double>::infinity();  // >= every distance of the block
};

// Tier A. The bounds follow the sample-by-sample evaluation: a path sample inside the arc's
// angular span measures | |p - C| - r(f) |, f its angle's fraction of the sweep; one outside
// measures to the nearer end; a printed-arc sample measures to the nearest segment of its window.
// With the path turning monotonically about C (omega = dphi/dt > 0), t and f advance together:
// the radial part is | |p - C| - r_lin(t) | + |r1 - r0| |f - lambda(t)|, lambda the t fraction,
// and a printed-arc sample's ray meets the exact path at some t* whose chord is in its window
// (checked), so its distance is at most the radial part at t* plus the chord's sag.
BlockModel analyse_block(const CentrePath& path, double d_mm, const Block& block) {
  BlockModel model;
  const PrintedArc& arc = block.arc;
  const PolygonShape& shape = path.shape();
  const double T = block.t1 - block.t0;
  if (!(T > 0.0) || !(arc.sweep <= 2.0 * kMaxSmallAngle) || !(arc.r0 > 0.0) || !(arc.r1 > 0.0)) {
    return model;
  }
  // The phases of the samples (non-decreasing in j): at most one phase change is covered.
  const int phase0 = path.phase_of(block.t(0));
  const int phase1 = path.phase_of(block.t(kDeviationPathSamples));
  if (phase1 != phase0 && phase1 != phase0 + 1) {
    return model;
  }
  int first_of_next = kDeviationPathSamples + 1;
  if (phase1 != phase0) {
    int lo = 0;  // phase0 at lo, phase1 at hi
    int hi = kDeviationPathSamples;
    while (hi - lo > 1) {
      const int mid = (lo + hi) / 2;
      (path.phase_of(block.t(mid)) == phase0 ? lo : hi) = mid;
    }
    first_of_next = hi;
  }
  auto psi_of = [&](int j, int phase) {  // as CentrePath::point computes it
    return (block.t(j) - phase * shape.delta) - 0.5 * shape.delta;
  };
  const double half_delta = 0.5 * shape.delta;
  const double scale_d = d_mm * (shape.R_c + shape.A + shape.B);
  double scale = scale_d + arc.C.norm() + std::max(arc.r0, arc.r1);
  for (int piece_index = 0; piece_index < (phase1 != phase0 ? 2 : 1); ++piece_index) {
    PhasePiece& piece = model.pieces[static_cast<std::size_t>(piece_index)];
    piece.phase = piece_index == 0 ? phase0 : phase1;
    piece.j_first = piece_index == 0 ? 0 : first_of_next;
    piece.j_last = piece_index == 0 ? std::min(first_of_next - 1, kDeviationPathSamples)
                                    : kDeviationPathSamples;
    double psi_lo = psi_of(piece.j_first, piece.phase);
    double psi_hi = psi_of(piece.j_last, piece.phase);
    // Between the last sample of one phase and the first of the next the path runs to the
    // phase change at psi = +-delta/2 of either ellipse.
    if (phase1 != phase0) {
      if (piece_index == 0) {
        psi_hi = std::max(psi_hi, half_delta);
      } else {
        psi_lo = std::min(psi_lo, -half_delta);
      }
    }
    piece.psi_c = 0.5 * (psi_lo + psi_hi);
    piece.x_lo = psi_lo - piece.psi_c;
    piece.x_hi = psi_hi - piece.psi_c;
    if (!(piece.half_width() <= kMaxSmallAngle)) {
      return model;
    }
    const CentrePath::Frame& frame = path.frame(piece.phase);
    const double c = std::cos(piece.psi_c);
    const double s = std::sin(piece.psi_c);
    const Eigen::Vector2d Aw = (d_mm * shape.A) * frame.w;
    const Eigen::Vector2d Bt = (d_mm * shape.B) * frame.t;
    piece.P = (d_mm * frame.V - c * Aw - s * Bt) - arc.C;
    piece.D1 = s * Aw - c * Bt;
    piece.D2 = c * Aw + s * Bt;
    // |p'|^2 = d^2 (A^2 sin^2 + B^2 cos^2), |p''|^2 = d^2 (A^2 cos^2 + B^2 sin^2).
    piece.derivative_bound = d_mm * std::max(shape.A, shape.B);
    scale = std::max(scale, scale_d + arc.C.norm());
  }
  model.piece_count = phase1 != phase0 ? 2 : 1;
  const double E = kRoundoffMultiple * kUnitRoundoff * scale;
  model.slack = E;

  // r_lin(t) = r0 + (r1 - r0) (t - t0) / T, as a function of x in each piece.
  const double dr = arc.r1 - arc.r0;
  Interval F{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  double r_lin_min = std::min(arc.r0, arc.r1);
  double omega_num_lo = std::numeric_limits<double>::infinity();
  double omega_num_hi = -std::numeric_limits<double>::infinity();
  double sag_acceleration = 0.0;
  for (int i = 0; i < model.piece_count; ++i) {
    PhasePiece& piece = model.pieces[static_cast<std::size_t>(i)];
    const double t_c = piece.psi_c + half_delta + piece.phase * shape.delta;
    const double r_c = arc.r0 + dr * ((t_c - block.t0) / T);
    const double r_s = dr / T;
    const Interval piece_F = squared_radius_gap_bounds(piece, r_c, r_s, E);
    F.lo = std::min(F.lo, piece_F.lo);
    F.hi = std::max(F.hi, piece_F.hi);
    // omega |p - C|^2 = (p - C) x p'; its derivative (p - C) x p'' is at most |p - C| M.
    const double X = piece.half_width();
    const double rho_max = piece.P.norm() + X * piece.D1.norm() + 0.5 * X * X * piece.D2.norm();
    const double g0 = cross(piece.P, piece.D1);
    const double spread = rho_max * piece.derivative_bound * X +
                          kRoundoffMultiple * kUnitRoundoff * rho_max * piece.derivative_bound;
    omega_num_lo = std::min(omega_num_lo, g0 - spread);
    omega_num_hi = std::max(omega_num_hi, g0 + spread);
    sag_acceleration = std::max(sag_acceleration, piece.derivative_bound);
  }
  // |p - C|^2 = F + r_lin^2.
  const double r_lin_max = std::max(arc.r0, arc.r1);
  const double rho2_lo = F.lo + r_lin_min * r_lin_min;
  const double rho2_hi = F.hi + r_lin_max * r_lin_max;
  if (!(rho2_lo > 0.0) || !(omega_num_lo > 0.0)) {
    return model;
  }
  const double omega_lo = omega_num_lo / rho2_hi;
  const double omega_hi = omega_num_hi / rho2_lo;
  // | |p - C| - r_lin | = |F| / (|p - C| + r_lin).
  model.gap_per_F = 1.0 / (std::sqrt(rho2_lo) + r_lin_min) * (1.0 + 1e-12);
  model.radial_gap = std::max(std::abs(F.lo), std::abs(F.hi)) * model.gap_per_F + E;
  model.omega_lo = omega_lo;
  model.omega_hi = omega_hi;

  // Where the path starts and ends relative to the arc: beta0 from S, beta1 from E, about C.
  const PhasePiece& first = model.pieces[0];
  const PhasePiece& last = model.pieces[static_cast<std::size_t>(model.piece_count - 1)];
  const Eigen::Vector2d p_start =
      first.relative_point(psi_of(0, first.phase) - first.psi_c);  // p(t0) - C
  const Eigen::Vector2d p_end =
      last.relative_point(psi_of(kDeviationPathSamples, last.phase) - last.psi_c);
  const Eigen::Vector2d s_dir = arc.S - arc.C;
  const Eigen::Vector2d e_dir = arc.E - arc.C;
  const double rho_lo = std::sqrt(rho2_lo);
  // Angle slack: the points' errors seen from C, and the rounding of every angle (atan2, a0,
  // a0 + f sweep, the 2 pi steps).
  const double angle_slack = 4.0 * E / rho_lo + 64.0 * kUnitRoundoff * kTwoPi;
  // The angle from u to v is atan(z), z = (u x v) / (u . v) for u . v > 0, and
  // |atan z - z| <= |z|^3 / 3 for |z| <= 1: bounds without the atan2.
  struct AngleBounds {
    double lo = 0.0;
    double hi = 0.0;
    bool ok = false;
  };
  auto angle_between = [&](const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
    const double along = u.dot(v);
    const double z = cross(u, v) / along;
    if (!(along > 0.0) || !(std::abs(z) <= 1.0)) {
      return AngleBounds{};
    }
    const double spread = std::abs(z) * z * z / 3.0 + 4.0 * kUnitRoundoff * std::abs(z);
    return AngleBounds{z - spread - angle_slack, z + spread + angle_slack, true};
  };
  const AngleBounds beta0 = angle_between(s_dir, p_start);
  const AngleBounds beta1 = angle_between(e_dir, p_end);
  if (!beta0.ok || !beta1.ok) {
    return model;
  }
  const double beta0_hi = beta0.hi;
  const double beta0_lo = beta0.lo;
  const double beta1_hi = beta1.hi;
  const double beta1_lo = beta1.lo;
  model.ray_offset_lo = beta0_lo - angle_slack;
  model.ray_offset_hi = beta0_hi + angle_slack;
  model.fraction_gap =
      (std::max(std::abs(beta0_lo), std::abs(beta0_hi)) +
       std::max(std::abs(beta1_lo), std::abs(beta1_hi)) + T * (omega_hi - omega_lo) + angle_slack) /
      arc.sweep;

  // Path samples surely inside the span: angle from S >= angle_slack and <= sweep - slack.
  // t_j - t0 = j dt up to a few roundings; the margins below are far wider.
  const double dt = T / kDeviationPathSamples;
  const double tau0 = std::max(0.0, (angle_slack - beta0_lo) / omega_lo);
  const double tau1 = std::max(0.0, (beta1_hi + angle_slack) / omega_lo);
  const double j0 = std::ceil(tau0 / dt * (1.0 + 1e-9) + 1e-9);
  const double j1 = std::ceil(tau1 / dt * (1.0 + 1e-9) + 1e-9);
  if (!(j0 + j1 < kDeviationPathSamples)) {
    return model;
  }
  model.inside_first = static_cast<int>(j0);
  model.inside_last = kDeviationPathSamples - static_cast<int>(j1);
  // Only samples within tau0 of t0 may lie before S; one that does measures to S (or E, if
  // nearer): at most |p(t) - p(t0)| + |p(t0) - S| <= max|p'| tau0 + |p(t0) - S|. Likewise at E.
  const double speed = std::max(first.derivative_bound, last.derivative_bound);
  model.start_bound = speed * tau0 * (1.0 + 1e-8) + (p_start - s_dir).norm() + 2.0 * E;
  model.end_bound = speed * tau1 * (1.0 + 1e-8) + (p_end - e_dir).norm() + 2.0 * E;

  // Printed-arc samples 1..127: the ray at a0 + f_k sweep meets the path at t* with
  // t* - t0 in [(f_k sweep - beta0 - s) / omega_hi, (f_k sweep - beta0 + s) / omega_lo]; the
  // segment j* holding t* (t_j* <= t* <= t_j*+1, so (t* - t0) / dt - 1 <= j* <= (t* - t0) / dt)
  // must lie in the window [4k - 24, 4k + 24). Both ends are affine in k: checking k = 1 and
  // k = 127 checks every k between.
  for (const int k : {1, kDeviationArcSamples - 1}) {
    const double along = static_cast<double>(k) / kDeviationArcSamples * arc.sweep;
    const double t_lo = (along - model.ray_offset_hi) / omega_hi;
    const double t_hi = (along - model.ray_offset_lo) / omega_lo;
    const double back = ((arc.sweep - along) + beta1_lo - angle_slack) / omega_hi;
    if (!(t_lo > 0.0) || !(back > 0.0)) {
      return model;
    }
    const double j_lo = t_lo / dt * (1.0 - 1e-9) - 1e-6;
    const double j_hi = t_hi / dt * (1.0 + 1e-9) + 1e-6;
    if (!(j_lo - 1.0 >= k * kPathPerArcSample - kSearchWindow) ||
        !(j_hi < k * kPathPerArcSample + kSearchWindow - 1)) {
      return model;
    }
  }
  // The chord of a C1 path between t_j and t_j+1 is within (t_j+1 - t_j)^2 / 8 max|p''|.
  model.sag = dt * dt * (1.0 + 1e-9) / 8.0 * sag_acceleration;

  const double radial = model.radial_gap + std::abs(dr) * model.fraction_gap;
  // Printed-arc samples 0 and 128 are S and E: their distance is at most to the first or the
  // last sample's point.
  const std::array<double, 5> parts{radial + model.sag, model.start_bound, model.end_bound,
                                    (p_start - s_dir).norm(), (p_end - e_dir).norm()};
  if (!std::all_of(parts.begin(), parts.end(), [](double x) { return std::isfinite(x); })) {
    return model;
  }
  model.upper = *std::max_element(parts.begin(), parts.end()) + 4.0 * E;
  model.covered = true;
  return model;
}

// Tiers B and C for a covered block: the largest of `worst` and the block's distances.
double refine_block(const CentrePath& path, double d_mm, const Block& block,
                    const BlockModel& model, double worst) {
  const PrintedArc& arc = block.arc;
  const double E = model.slack;
  const double dr = arc.r1 - arc.r0;
  const double delta = path.shape().delta;
  const double half_delta = 0.5 * delta;
  const double radial_extra = std::abs(dr) * model.fraction_gap + 2.0 * E;
  // A path sample's radial gap | |p - C| - r | is |D| / (|p - C| + r), D = |p - C|^2 - r^2, and
  // |p - C| + r lies within 2 r +- G, G >= the gap (tier A's bound, widened by the
  // approximation): the gap is bounded both ways by multiples of |D|, no root or division per
  // sample.
  const double r_lo = std::min(arc.r0, arc.r1);
  const double r_hi = std::max(arc.r0, arc.r1);
  const double G = model.radial_gap + std::abs(dr) + 4.0 * E;
  if (!(2.0 * r_lo > G)) {
    ExactPoints exact(path, d_mm, block);
    return exact_block_deviation(block, exact);
  }
  const double gap_per_D_hi = 1.0 / (2.0 * r_lo - G) * (1.0 + 1e-12);
  const double gap_per_D_lo = 1.0 / (2.0 * r_hi + G) * (1.0 - 1e-12);
  const Eigen::Vector2d s_dir = arc.S - arc.C;
  const Eigen::Vector2d e_dir = arc.E - arc.C;

  // Which samples tier B reads: those near a subinterval of a piece whose bound on the radial
  // gap can reach `worst` (the samples at the ends always). Within a piece, psi - psi_c runs
  // from x_first in steps of dt, so a subinterval's samples form a range of j; the path meets a
  // printed-arc sample's ray at t* with t* - t0 in an interval affine in k, so a subinterval's
  // arc samples form a range of k. Every range is widened by two for roundings.
  const double dt = (block.t1 - block.t0) / kDeviationPathSamples;
  std::array<bool, kDeviationPathSamples + 1> path_hot{};
  std::array<bool, kDeviationArcSamples + 1> arc_hot{};
  auto mark = [](auto& hot, double from, double to) {
    // Written so that a NaN bound widens the range to the end instead of skipping it.
    const double last = static_cast<double>(hot.size() - 1);
    double lo = std::floor(from) - 2.0;
    double hi = std::ceil(to) + 2.0;
    lo = lo >= 0.0 ? std::min(lo, last + 1.0) : 0.0;
    hi = hi <= last ? hi : last;
    for (auto i = static_cast<std::size_t>(lo); static_cast<double>(i) <= hi; ++i) {
      hot[i] = true;
    }
  };
  for (int j = 0; j < model.inside_first; ++j) {
    path_hot[static_cast<std::size_t>(j)] = true;
  }
  for (int j = model.inside_last + 1; j <= kDeviationPathSamples; ++j) {
    path_hot[static_cast<std::size_t>(j)] = true;
  }
  arc_hot[0] = true;
  arc_hot[kDeviationArcSamples] = true;
  const double sweep_per_k = arc.sweep / kDeviationArcSamples;
  for (int i = 0; i < model.piece_count; ++i) {
    const PhasePiece& piece = model.pieces[static_cast<std::size_t>(i)];
    const double x_first =
        ((block.t(piece.j_first) - piece.phase * delta) - half_delta) - piece.psi_c;
    const double t_c = piece.psi_c + half_delta + piece.phase * delta;  // t at x = 0
    const double w = piece.subinterval_width();
    for (int sub = 0; sub < kSubintervals; ++sub) {
      const double gap = piece.F_abs[static_cast<std::size_t>(sub)] * model.gap_per_F + E;
      const double x_from = piece.x_lo + sub * w;
      const double x_to = x_from + w;
      if (gap + radial_extra >= worst) {
        mark(path_hot, piece.j_first + (x_from - x_first) / dt,
             piece.j_first + (x_to - x_first) / dt);
      }
      if (gap + radial_extra + model.sag + 2.0 * E >= worst) {
        // t* - t0 within [x_from, x_to] + (t_c - t0): k from the affine bounds on t*.
        const double u_from = x_from + (t_c - block.t0);
        const double u_to = x_to + (t_c - block.t0);
        mark(arc_hot, (u_from * model.omega_lo + model.ray_offset_lo) / sweep_per_k,
             (u_to * model.omega_hi + model.ray_offset_hi) / sweep_per_k);
      }
    }
  }

  // Path samples relative to C, approximated on first use.
  std::array<Eigen::Vector2d, kDeviationPathSamples + 1> approx;
  std::array<bool, kDeviationPathSamples + 1> approximated{};
  auto point = [&](int j) -> const Eigen::Vector2d& {
    const auto i = static_cast<std::size_t>(j);
    if (!approximated[i]) {
      const PhasePiece& piece =
          model.pieces[j < model.pieces[0].j_first || j > model.pieces[0].j_last ? 1 : 0];
      const double psi = (block.t(j) - piece.phase * delta) - half_delta;
      approx[i] = piece.relative_point(psi - piece.psi_c);
      approximated[i] = true;
    }
    return approx[i];
  };

  // Tier B for the path samples: |D| as a bound on the gap (the larger of both branches where
  // either may apply).
  std::array<double, kDeviationPathSamples + 1> path_upper;
  path_upper.fill(-1.0);
  double largest_inside_D = -1.0;
  for (int j = 0; j <= kDeviationPathSamples; ++j) {
    const auto i = static_cast<std::size_t>(j);
    if (!path_hot[i]) {
      continue;
    }
    const bool inside = j >= model.inside_first && j <= model.inside_last;
    const Eigen::Vector2d& v = point(j);
    const double r = arc.r0 + static_cast<double>(j) / kDeviationPathSamples * dr;
    const double D = std::abs(v.squaredNorm() - r * r);
    double upper = D * gap_per_D_hi + radial_extra;
    if (inside) {
      largest_inside_D = std::max(largest_inside_D, D);
    } else {
      const double to_end =
          std::sqrt(std::min((v - s_dir).squaredNorm(), (v - e_dir).squaredNorm()));
      upper = std::max(upper, to_end + 2.0 * E);
    }
    path_upper[i] = upper;
  }
  if (largest_inside_D >= 0.0) {
    // Some path sample is at least this far from the arc.
    worst = std::max(worst, largest_inside_D * gap_per_D_lo - radial_extra);
  }

  // Tier B for the printed-arc samples: the approximate distance to the segments beside the
  // same fraction of the path.
  const double a_mid = arc.a0 + 0.5 * arc.sweep;
  const double cos_mid = std::cos(a_mid);
  const double sin_mid = std::sin(a_mid);
  auto approx_segment2 = [&](const Eigen::Vector2d& q, int j) {
    const Eigen::Vector2d& a = point(j);
    const Eigen::Vector2d ab = point(j + 1) - a;
    return segment_distance_squared(q, a, ab, ab.squaredNorm());
  };
  auto arc_point = [&](int k) {
    const double f = static_cast<double>(k) / kDeviationArcSamples;
    const double y = (f - 0.5) * arc.sweep;
    const double cy = 1.0 - one_minus_cos_small(y);
    const double sy = sin_small(y);
    return Eigen::Vector2d((arc.r0 + f * dr) * Eigen::Vector2d(cos_mid * cy - sin_mid * sy,
                                                               sin_mid * cy + cos_mid * sy));
  };
  std::array<double, kDeviationArcSamples + 1> arc_upper;
  arc_upper.fill(-1.0);
  for (int k = 0; k <= kDeviationArcSamples; ++k) {
    if (!arc_hot[static_cast<std::size_t>(k)]) {
      continue;
    }
    const Eigen::Vector2d q = arc_point(k);
    // Any segment of the window bounds the nearest from above; the one at the same fraction
    // and its neighbours are nearly always the nearest.
    const int centre = k * kPathPerArcSample;
    double nearest2 = std::numeric_limits<double>::infinity();
    for (int j = std::max(Block::window_begin(k), centre - 2);
         j < std::min(Block::window_end(k), centre + 2); ++j) {
      nearest2 = std::min(nearest2, approx_segment2(q, j));
    }
    arc_upper[static_cast<std::size_t>(k)] = std::sqrt(nearest2) + 2.0 * E;
  }

  // Tier C: exactly where the bounds reach the largest distance known.
  ExactPoints exact(path, d_mm, block);
  double result = 0.0;  // the largest exact distance of this block found
  for (int j = 0; j <= kDeviationPathSamples; ++j) {
    if (path_upper[static_cast<std::size_t>(j)] >= worst) {
      const double distance = exact_path_distance(block, exact, j);
      result = std::max(result, distance);
      worst = std::max(worst, distance);
    }
  }
  for (int k = 0; k <= kDeviationArcSamples; ++k) {
    if (!(arc_upper[static_cast<std::size_t>(k)] >= worst)) {
      continue;
    }
    const double f = static_cast<double>(k) / kDeviationArcSamples;
    const Eigen::Vector2d q = arc.at(f);
    const Eigen::Vector2d q_approx = arc_point(k);
    // The nearest segment by approximation first, then every other whose approximate distance
    // does not rule it out against the nearest found so far.
    const int begin = Block::window_begin(k);
    const int end = Block::window_end(k);
    std::array<double, static_cast<std::size_t>(2 * kSearchWindow)> approx_distance{};
    int best_j = begin;
    for (int j = begin; j < end; ++j) {
      approx_distance[static_cast<std::size_t>(j - begin)] =
          std::sqrt(approx_segment2(q_approx, j));
      if (approx_distance[static_cast<std::size_t>(j - begin)] <
          approx_distance[static_cast<std::size_t>(best_j - begin)]) {
        best_j = j;
      }
    }
    double nearest = segment_distance(q, exact(best_j), exact(best_j + 1));
    for (int j = begin; j < end; ++j) {
      if (j != best_j &&
          !(approx_distance[static_cast<std::size_t>(j - begin)] - 2.0 * E > nearest)) {
        nearest = std::min(nearest, segment_distance(q, exact(j), exact(j + 1)));
      }
    }
    result = std::max(result, nearest);
    worst = std::max(worst, nearest);
  }
  return result;
}

}  // namespace

double printed_path_deviation_mm(const CentrePath& path, double d_mm,
                                 const std::vector<LoopBlock>& blocks, const PrintedLoop& loop,
                                 double mm_per_unit) {
  const auto point = [&](const std::string& x, const std::string& y) -> Eigen::Vector2d {
    return Eigen::Vector2d(parse_number(x), parse_number(y)) * mm_per_unit;
  };
  const std::size_t count = std::min(blocks.size(), loop.blocks.size());
  std::vector<Block> printed;
  printed.reserve(count);
  Eigen::Vector2d S = point(loop.start_X, loop.start_Y);
  for (std::size_t b = 0; b < count; ++b) {
    const PrintedBlock& block = loop.blocks[b];
    const Eigen::Vector2d E = point(block.X, block.Y);
    printed.push_back(
        Block{PrintedArc(S, E, S + point(block.I, block.J)), blocks[b].t_start, blocks[b].t_end});
    S = E;
  }
  // Tier A for every block, then the blocks from the largest bound down: once a bound is below
  // the largest distance found, so are all the rest.
  std::vector<double> upper(count);
  std::vector<std::size_t> order(count);
  for (std::size_t b = 0; b < count; ++b) {
    if (b % 256 == 0) {
      interruption_point();
    }
    upper[b] = analyse_block(path, d_mm, printed[b]).upper;
    order[b] = b;
  }
  std::sort(order.begin(), order.end(),
            [&](std::size_t x, std::size_t y) { return upper[x] > upper[y]; });
  double worst = 0.0;
  for (const std::size_t b : order) {
    if (upper[b] < worst) {
      break;
    }
    interruption_point();
    const BlockModel model = analyse_block(path, d_mm, printed[b]);
    double deviation = 0.0;
    if (model.covered) {
      deviation = refine_block(path, d_mm, printed[b], model, worst);
    } else {
      ExactPoints exact(path, d_mm, printed[b]);
      deviation = exact_block_deviation(printed[b], exact);
    }
    worst = std::max(worst, deviation);
  }
  return worst;
}

}  // namespace cutcalc::domain::polygon::detail
