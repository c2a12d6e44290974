#pragma once
// Arc fitting of the centre path, spec polygon-holes.md section 6 (P18-P21): m equal-tangent
// biarcs per ellipse arc, the deviation sampling rule, the smallest m, and the merged blocks of
// one loop. Everything here is in the units of the CentrePath given (the caller uses d = 1).
// Private to domain/polygon.

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "domain/common/result.h"
#include "domain/polygon/centre_path.h"
#include "domain/polygon/fitted_arc.h"

namespace cutcalc::domain::polygon::detail {

// P19: the equal-tangent-length biarc from (P0, T0) to (P1, T1) through the junction J.
struct Biarc {
  FittedArc first;
  FittedArc second;
  Eigen::Vector2d junction = Eigen::Vector2d::Zero();
};

// P19. Empty when an arc degenerates (no printable circle).
std::optional<Biarc> fit_biarc(const Eigen::Vector2d& P0, const Eigen::Vector2d& T0,
                               const Eigen::Vector2d& P1, const Eigen::Vector2d& T1);

// P20: the two-sided deviation of `biarc` from the exact piece [theta0, theta1] of ellipse arc 0.
// Returns early, with a value above `limit`, as soon as one sample exceeds `limit`.
double biarc_deviation(const CentrePath& path, double theta0, double theta1, const Biarc& biarc,
                       double limit);

// P18-P21 for ellipse arc 0: the m biarcs, the path parameter of each junction (nearest exact
// point, golden section) and their deviation (P20, max over the m biarcs).
struct PhaseFit {
  int m = 0;
  std::vector<Biarc> biarcs;
  std::vector<double> junction_theta;  // theta of the exact point nearest to each junction
  double deviation = 0.0;
};

// P21: the smallest m = 1, 2, ... (at most max_m) with deviation <= tolerance. Errors:
// tolerance_unreachable (m > max_m), not_converged (a biarc degenerates).
Result<PhaseFit> fit_ellipse_arc(const CentrePath& path, double tolerance, int max_m = 1000);

// One block of the loop after merging (P21): the arc geometry (centre and radius of its first
// piece, start of the first, end of the last, sweep and length summed), the rotor rotation t and
// the fitted path length s at its ends (s from the loop start).
struct LoopBlock {
  FittedArc arc;
  double t_start = 0.0;
  double t_end = 0.0;
  double s_start = 0.0;
  double s_end = 0.0;
};

// P21: walk the 2 N m arcs of one loop from t = 0 (ellipse arc p = arc 0 turned by 2 pi p / N)
// and merge each arc into the previous block when centres and radii agree within merge_tolerance
// and the sense is the same. The last block ends exactly at the loop start (0, e).
std::vector<LoopBlock> loop_blocks(const CentrePath& path, const PhaseFit& fit,
                                   double merge_tolerance);

}  // namespace cutcalc::domain::polygon::detail
