#pragma once
// Test oracle for the entry-length family: the closed forms E13-E22 of
// shared/domain/entry-and-main-time.md, written from the specification only (independently of
// domain/entry/*.cpp, which evaluates the unified formula E10-E12).
//
// Internal frame (spec section 3): x along the feed (+ downstream), y lateral, y = 0 the strip's
// symmetry line (straight, concave, wall) or the arc axis (both arcs). The cutter axis runs at y =
// K. Every function returns std::nullopt when the cutter band misses the workpiece (E2: W <= 0,
// tangency included).

#include <optional>

namespace cutcalc::test::entry_oracle {

// E1: s(u) = sqrt(r^2 - u^2) = sqrt((r - u)(r + u)), tiny negative products clamped to 0.
double half_chord(double r, double u);

// cot(alpha) for alpha in degrees, exactly 0 at 90 (spec 6.2). Computed as 1/tan, not cos/sin.
double cot_deg(double alpha_deg);

// E2: the steady band [a, b] = [K - r, K + r] clipped to [lo, hi] (lo = -h, hi = h for a whole
// contour), with the exact u = y - K at each end (u = -r / +r where the disc edge bounds the band,
// else lo - K / hi - K), as spec section 5 demands.
struct Band {
  double a = 0.0;
  double b = 0.0;
  double ua = 0.0;
  double ub = 0.0;
  double width = 0.0;  // W = min(K + r, hi) - max(K - r, lo)
};
std::optional<Band> steady_band(double r, double K, double lo, double hi);

struct EntryForm {
  double engagement_mm = 0.0;    // L_vr1 (E6)
  double start_x_mm = 0.0;       // X_n (E7)
  double start_y_mm = 0.0;       // Y_n (section 3)
  double steady_width_mm = 0.0;  // W (E2)
  double saturation_x_mm = 0.0;  // x_cs = L_vr1 + L_pod - X_n (for E23)
};

struct ExitForm {
  double end_x_mm = 0.0;  // X_k (E8)
  double end_y_mm = 0.0;  // Y_k (section 3)
};

// ---- 6.1 straight edge, alpha = 90 (E13)
// ----------------------------------------------------------
enum class StraightCase { S1, S2, S3, S4 };
// Sub-case of the table in 6.1 (assumes contact).
StraightCase straight90_case(double r, double h, double K);
std::optional<EntryForm> straight90_entry(double D, double B, double K, double approach);
std::optional<ExitForm> straight90_exit(double D, double B, double K);

// ---- 6.2 straight edge at any angle (E14-E16)
// -------------------------------------------------------
std::optional<EntryForm> straight_entry(double D, double B, double K, double alpha_deg,
                                        double approach);  // E14
// E15; only meaningful when |K| + r <= h (returns nullopt otherwise).
std::optional<EntryForm> straight_entry_band_inside(double D, double B, double K, double alpha_deg,
                                                    double approach);
std::optional<ExitForm> straight_exit(double D, double B, double K, double alpha_x_deg);  // E16
// E16 band-inside form; nullopt unless |K| + r <= h.
std::optional<ExitForm> straight_exit_band_inside(double D, double B, double K, double alpha_x_deg);

// ---- 6.3 convex arc (E17-E19)
// -----------------------------------------------------------------------
enum class ConvexCase { A, B, C, D };
// Case of E18 (full width), assuming contact.
ConvexCase convex_full_case(double r, double R, double K);
// E18 full width (h = R): the case table A-D.
std::optional<EntryForm> convex_full_entry(double D, double R, double K, double approach);
// E19 full width closed form.
std::optional<ExitForm> convex_full_exit(double D, double R, double K);
// E17 for a part of width B <= 2R (h = B/2).
std::optional<EntryForm> convex_entry(double D, double R, double B, double K, double approach);
// E19 general (max of phi over {a, b, y_c}) for a part of width B <= 2R.
std::optional<ExitForm> convex_exit(double D, double R, double B, double K);
// E17 / E19 on an explicit band clip [lo, hi] (multi-pass arcs, spec 7.2, inferred).
std::optional<EntryForm> convex_entry_on(double D, double R, double K, double lo, double hi,
                                         double approach);
std::optional<ExitForm> convex_exit_on(double D, double R, double K, double lo, double hi);

// ---- 6.4 concave arc (E20-E21)
// ----------------------------------------------------------------------
std::optional<EntryForm> concave_entry(double D, double R, double B, double K, double approach);
std::optional<ExitForm> concave_exit(double D, double R, double B, double K);
// True when the maximum of psi (E20) is at the interior point y_c rather than at a band end.
bool concave_entry_max_is_interior(double D, double R, double B, double K);

// ---- 6.5 wall exit (E22)
// ----------------------------------------------------------------------------
std::optional<ExitForm> wall_exit(double D, double B, double K);

}  // namespace cutcalc::test::entry_oracle
