#pragma once
// The flatness error of N steps (spec lathe-flat.md section 4, F10-F16): between step points the
// control moves X and C linearly, so the tool reference point runs on an Archimedean spiral and
// leaves a hump above the ideal flat (never a gouge); an end mill leaves that spiral's offset.
// Units: mm, radians.

#include <optional>

#include "domain/lathe_flat/flat_geometry.h"

namespace cutcalc::domain::lathe_flat {

inline constexpr int kMaxSteps = 1000;

// F14: the largest height of material left above the flat over the finished face |u| <= w/2 and
// below the original cylinder, by the normative sampling + golden-section procedure.
double flatness_error_mm(const FlatSection& flat, double face_width_mm, int steps);

// F15: the chord-sag estimate (d + R) (alpha_e/N)^2 (1 + 2 tan^2 alpha_e) / 8.
double flatness_error_estimate_mm(const FlatSection& flat, int steps);

// F16: the smallest N in 1..kMaxSteps with flatness_error_mm(N) <= tolerance, or nullopt.
std::optional<int> steps_for_tolerance(const FlatSection& flat, double face_width_mm,
                                       double tolerance_mm);

}  // namespace cutcalc::domain::lathe_flat
