// Drawing outlines of spec polygon-holes.md: the posed rotor (P11-P13 with the section 3
// motion) and the cut wall of an uncut corner (P17).

#include "domain/polygon/hole_outline.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>

#include "domain/common/golden_section.h"
#include "domain/polygon/fitted_arc.h"

namespace cutcalc::domain::polygon::detail {

namespace {

constexpr double kPi = std::numbers::pi;
// Normal angles closer than this to an arc's ends are its end points (sampled anyway).
constexpr double kSameNormal = 1e-12;
// P17 sampling of the motion: poses per phase, then golden section around the best pose.
constexpr int kPosesPerPhase = 16;
constexpr int kGoldenIterations = 48;
// A crossing this far behind the vertex is the vertex itself.
constexpr double kBehind = 1e-12;
// Angular slack at the ends of an arc's normal range (rad): the corners shared by two arcs.
constexpr double kRangeSlack = 1e-9;

// x reduced to [0, 2 pi).
double wrap(double x) {
  x = std::fmod(x, 2.0 * kPi);
  return x < 0.0 ? x + 2.0 * kPi : x;
}

// A flank arc (P12): centre, radius and the unit outward normals at its two ends, in the rotor
// frame or placed at a pose. Plain doubles: this is the inner loop of the P17 sampling.
struct ArcPiece {
  double centre_x = 0.0;
  double centre_y = 0.0;
  double radius = 0.0;
  double begin_x = 0.0;  // n(normal_begin)
  double begin_y = 0.0;
  double end_x = 0.0;  // n(normal_end)
  double end_y = 0.0;
};

// Section 4: corner 1 rounds vertex V_0, so only the flank arcs on both sides of it, (0, m) from
// K_0 to K_1 and (1, m) from K_1 to K_2, can reach V_0's corner within one loop; the other
// corners round the other vertices.
std::vector<ArcPiece> arcs_around_corner_1(const PolygonShape& shape, const Rotor& rotor) {
  std::vector<ArcPiece> arcs;
  for (int v = 0; v <= 1; ++v) {
    for (int m = 1; m <= shape.N - 2; ++m) {
      const FlankArc arc = rotor.flank_arc(v % shape.M, m);
      const Eigen::Vector2d begin = unit(arc.normal_begin);
      const Eigen::Vector2d end = unit(arc.normal_end);
      arcs.push_back(
          {arc.centre.x(), arc.centre.y(), arc.radius, begin.x(), begin.y(), end.x(), end.y()});
    }
  }
  return arcs;
}

// Section 3: the rotor at rotation t, axis c(t) (P7), angle phi = -t.
void place(const CentrePath& path, const std::vector<ArcPiece>& arcs, double t,
           std::vector<ArcPiece>& placed) {
  const Eigen::Vector2d c = path.point(t);
  const double cos_phi = std::cos(-t);
  const double sin_phi = std::sin(-t);
  const auto turn_x = [&](double x, double y) { return cos_phi * x - sin_phi * y; };
  const auto turn_y = [&](double x, double y) { return sin_phi * x + cos_phi * y; };
  placed.resize(arcs.size());
  for (std::size_t i = 0; i < arcs.size(); ++i) {
    const ArcPiece& a = arcs[i];
    placed[i] = {c.x() + turn_x(a.centre_x, a.centre_y),
                 c.y() + turn_y(a.centre_x, a.centre_y),
                 a.radius,
                 turn_x(a.begin_x, a.begin_y),
                 turn_y(a.begin_x, a.begin_y),
                 turn_x(a.end_x, a.end_y),
                 turn_y(a.end_x, a.end_y)};
  }
}

// Distance from V along the unit direction u to the first crossing of the placed arcs (the part
// of the rotor's boundary facing V); infinity when the ray misses them. The rotor is convex and V
// outside it (or on it), so the crossing is where the ray enters: the nearer root of the crossing
// arc's circle, with the ray against the arc's outward normal.
double entry_distance(const std::vector<ArcPiece>& placed, const Eigen::Vector2d& V,
                      const Eigen::Vector2d& u) {
  const double Vx = V.x();
  const double Vy = V.y();
  const double ux = u.x();
  const double uy = u.y();
  double best = std::numeric_limits<double>::infinity();
  for (const ArcPiece& arc : placed) {
    const double wx = Vx - arc.centre_x;
    const double wy = Vy - arc.centre_y;
    const double b = ux * wx + uy * wy;
    const double discriminant = b * b - (wx * wx + wy * wy - arc.radius * arc.radius);
    if (discriminant < 0.0) {
      continue;
    }
    const double s = -b - std::sqrt(discriminant);
    if (s < -kBehind || s >= best) {
      continue;
    }
    // The crossing's normal inside [normal_begin, normal_end] (a range narrower than pi).
    const double radial_x = wx + s * ux;
    const double radial_y = wy + s * uy;
    const double slack = kRangeSlack * arc.radius;
    if (arc.begin_x * radial_y - arc.begin_y * radial_x >= -slack &&
        radial_x * arc.end_y - radial_y * arc.end_x >= -slack) {
      best = std::max(s, 0.0);
    }
  }
  return best;
}

// The smallest value of f over one loop of the motion, t in [0, N delta): the sampled poses, then
// golden section between the neighbours of the best one (t below 0 is the end of the previous
// loop; CentrePath continues the phases). f(t, k) evaluates quantity k at rotor rotation t.
template <class F>
std::vector<double> loop_minima(const PolygonShape& shape, std::size_t count, const F& f) {
  const int poses = kPosesPerPhase * shape.N;
  const double step = shape.N * shape.delta / poses;  // one loop is N delta
  std::vector<double> best(count, std::numeric_limits<double>::infinity());
  std::vector<int> best_pose(count, 0);
  for (int k = 0; k < poses; ++k) {
    const double t = k * step;
    for (std::size_t i = 0; i < count; ++i) {
      const double value = f(t, i);
      if (value < best[i]) {
        best[i] = value;
        best_pose[i] = k;
      }
    }
  }
  for (std::size_t i = 0; i < count; ++i) {
    const GoldenSection s =
        golden_section_minimum([&](double t) { return f(t, i); }, (best_pose[i] - 1) * step,
                               (best_pose[i] + 1) * step, 0.0, kGoldenIterations);
    best[i] = std::min(best[i], s.smallest_value());
  }
  return best;
}

// P17: s(gamma) for every gamma inside (0, pi - 2 pi / N).
std::vector<double> wall_distances(const CentrePath& path, const Rotor& rotor,
                                   const std::vector<double>& gammas) {
  const PolygonShape& shape = path.shape();
  const std::vector<ArcPiece> arcs = arcs_around_corner_1(shape, rotor);
  const Eigen::Vector2d V = shape.vertex(0);
  std::vector<Eigen::Vector2d> directions;
  directions.reserve(gammas.size());
  for (const double gamma : gammas) {
    directions.push_back(unit(kPi - gamma));
  }
  std::vector<ArcPiece> placed;
  double placed_at = std::numeric_limits<double>::quiet_NaN();
  return loop_minima(shape, gammas.size(), [&](double t, std::size_t i) {
    if (!(t == placed_at)) {  // the poses are shared by all rays
      place(path, arcs, t, placed);
      placed_at = t;
    }
    return entry_distance(placed, V, directions[i]);
  });
}

// The ends of the corner wall: the points of sides 0 and 1 nearest V_0 that the rotor touches
// during the loop (where the straight middle part of each side begins), as distances from V_0.
// At rotation t the rotor touches side j at its support point for the outward normal
// alpha_j - phi = alpha_j + t (P13).
std::array<double, 2> side_contact_distances(const CentrePath& path, const Rotor& rotor) {
  const PolygonShape& shape = path.shape();
  const Eigen::Vector2d V = shape.vertex(0);
  const std::vector<double> minima = loop_minima(shape, 2, [&](double t, std::size_t j) {
    const Eigen::Vector2d contact =
        path.point(t) +
        Eigen::Rotation2Dd(-t) * rotor.support_point(shape.alpha(static_cast<int>(j)) + t);
    return (contact - V).norm();
  });
  return {minima[0], minima[1]};
}

}  // namespace

std::vector<Eigen::Vector2d> rotor_outline(const PolygonShape& shape, const Rotor& rotor,
                                           const Eigen::Vector2d& axis, double phi,
                                           double max_step) {
  const Eigen::Rotation2Dd turn(phi);
  std::vector<Eigen::Vector2d> outline;
  std::vector<double> normals;  // offsets from the arc's first normal
  for (int v = 0; v < shape.M; ++v) {
    for (int m = 1; m <= shape.N - 2; ++m) {
      const FlankArc arc = rotor.flank_arc(v, m);
      const double width = arc.normal_end - arc.normal_begin;  // delta
      const int steps = std::max(1, static_cast<int>(std::ceil(width / max_step)));
      normals.clear();
      for (int k = 0; k < steps; ++k) {
        normals.push_back(width * k / steps);
      }
      // The contact with side j: outward normal alpha_j in the world, alpha_j - phi here (P13).
      for (int j = 0; j < shape.N; ++j) {
        const double x = wrap(shape.alpha(j) - phi - arc.normal_begin);
        if (x > kSameNormal && x < width - kSameNormal) {
          normals.push_back(x);
        }
      }
      std::sort(normals.begin(), normals.end());
      double previous = -1.0;
      for (const double x : normals) {
        if (x - previous > kSameNormal) {
          outline.push_back(axis + turn * (arc.centre + arc.radius * unit(arc.normal_begin + x)));
          previous = x;
        }
      }
    }
  }
  return outline;
}

double corner_wall_distance(const CentrePath& path, const Rotor& rotor, double gamma) {
  const double interior = kPi - 2.0 * kPi / path.shape().N;
  if (gamma <= 0.0 || gamma >= interior) {
    // Along a side the ray only grazes the rotor: the side's nearest contact instead.
    return side_contact_distances(path, rotor)[gamma <= 0.0 ? 0 : 1];
  }
  return wall_distances(path, rotor, {gamma}).front();
}

std::vector<Eigen::Vector2d> corner_wall(const CentrePath& path, const Rotor& rotor, int samples) {
  const PolygonShape& shape = path.shape();
  const int n = std::max(samples, 2);
  const Eigen::Vector2d V = shape.vertex(0);
  if (shape.N == 3) {
    // Section 4: the lens corners reach the vertices; nothing is left uncut.
    return std::vector<Eigen::Vector2d>(static_cast<std::size_t>(n), V);
  }
  // The wall meets each side tangentially, where s(gamma) falls like sqrt(gamma): angles spaced
  // as 1 - cos (quadratically near both ends) give samples about evenly spaced along the wall.
  const double interior = kPi - 2.0 * kPi / shape.N;  // the polygon's angle at V_0
  std::vector<double> gammas;
  for (int k = 1; k + 1 < n; ++k) {
    gammas.push_back(0.5 * interior * (1.0 - std::cos(kPi * k / (n - 1))));
  }
  const std::vector<double> s = wall_distances(path, rotor, gammas);
  const std::array<double, 2> ends = side_contact_distances(path, rotor);
  std::vector<Eigen::Vector2d> wall;
  wall.reserve(static_cast<std::size_t>(n));
  wall.push_back(V + ends[0] * unit(kPi));  // on side 0
  for (std::size_t k = 0; k < gammas.size(); ++k) {
    wall.push_back(V + s[k] * unit(kPi - gammas[k]));
  }
  wall.push_back(V + ends[1] * unit(kPi - interior));  // on side 1
  return wall;
}

}  // namespace cutcalc::domain::polygon::detail
