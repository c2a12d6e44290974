// The flat's geometry and step table (lathe-flat.md section 3, F2-F9): the engagement half-angle
// and width, the tool positions touching the flat, the step table of the worked example (section
// 9), its symmetry and sums.

#include "domain/lathe_flat/flat_geometry.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "domain/lathe_flat/lathe_flat_settings.h"

namespace cutcalc::domain::lathe_flat {
namespace {

// Section 9: D32, t = 1 (d = 15).
using settings::kPaper;
using settings::kPaperR5;

double degrees(double rad) { return rad * 180.0 / std::numbers::pi; }

TEST(FlatGeometry, EngagementAngleAndWidthOfTheWorkedExample) {
  // F2, F3: alpha_e = arccos(d/R2) = 20.364135 deg, b = 2 sqrt(31) = 11.135529 mm.
  EXPECT_NEAR(degrees(engagement_half_angle_rad(kPaper)), 20.364135, 0.5e-6);
  EXPECT_NEAR(engagement_half_angle_rad(kPaper), std::acos(15.0 / 16.0), 1e-14);
  EXPECT_NEAR(flat_width_mm(kPaper), 11.135529, 0.5e-6);
  EXPECT_NEAR(flat_width_mm(kPaper), 2.0 * std::sqrt(1.0 * (32.0 - 1.0)), 1e-13);
  // The tool radius changes neither.
  EXPECT_EQ(engagement_half_angle_rad(kPaperR5), engagement_half_angle_rad(kPaper));
  EXPECT_EQ(flat_width_mm(kPaperR5), flat_width_mm(kPaper));
}

TEST(FlatGeometry, AngleIsAccurateForAFlatThroughTheAxisAndAShallowOne) {
  // The atan2 form: 90 deg at d = 0 and small angles near d = R2 without the arccos cancellation.
  EXPECT_NEAR(engagement_half_angle_rad({10.0, 0.0, 0.0}), std::numbers::pi / 2.0, 1e-15);
  EXPECT_NEAR(flat_width_mm({10.0, 0.0, 0.0}), 20.0, 1e-13);
  const FlatSection shallow{10.0, 10.0 - 1e-11, 0.0};
  const double t = 10.0 - shallow.axis_distance_mm;  // exact (Sterbenz)
  const double half_width = std::sqrt(t * (20.0 - t));
  // arccos(d/R2) would lose ~5 digits here; asin of the half-chord over R2 does not.
  EXPECT_NEAR(engagement_half_angle_rad(shallow), std::asin(half_width / 10.0), 1e-12 * 1.4e-6);
  EXPECT_NEAR(flat_width_mm(shallow), 2.0 * half_width, 1e-12 * 2.8e-5);
}

TEST(FlatGeometry, ToolPositionTouchesTheFlatPlane) {
  // F5: the tool circle of radius R centred at radius X on the ray alpha is tangent to the plane
  // at distance d: X cos(alpha) - R = d.
  for (const FlatSection& flat : {kPaper, kPaperR5, FlatSection{25.0, 7.0, 3.0}}) {
    for (const double alpha : {0.0, 0.1, -0.3, 1.2}) {
      const double x = tool_radius_position_mm(flat, alpha);
      EXPECT_NEAR(x * std::cos(alpha) - flat.tool_radius_mm, flat.axis_distance_mm, 1e-12);
    }
  }
  // Start point clear of the part when R > 0: X(alpha_e) = R2 + R R2/d.
  const double alpha_e = engagement_half_angle_rad(kPaperR5);
  EXPECT_NEAR(tool_radius_position_mm(kPaperR5, alpha_e), 16.0 + 5.0 * 16.0 / 15.0, 1e-12);
}

TEST(FlatGeometry, StepAnglesRunFromPlusToMinusAlphaE) {
  // F6: alpha_i = alpha_e (1 - i/N), i = 0..2N.
  EXPECT_DOUBLE_EQ(step_angle_rad(0.5, 4, 0), 0.5);
  EXPECT_DOUBLE_EQ(step_angle_rad(0.5, 4, 1), 0.375);
  EXPECT_EQ(step_angle_rad(0.5, 4, 4), 0.0);
  EXPECT_DOUBLE_EQ(step_angle_rad(0.5, 4, 8), -0.5);
}

TEST(FlatGeometry, StepTableOfTheWorkedExamplePointTool) {
  // Section 9: the ten dX of the first half, sum 1 (= t for R = 0).
  constexpr std::array<double, 10> kDx = {0.19844, 0.17408, 0.15095, 0.12886, 0.10764,
                                          0.08714, 0.06720, 0.04770, 0.02850, 0.00948};
  const auto rows = step_table(kPaper, 10);
  ASSERT_EQ(rows.size(), 21U);
  double travel = 0.0;
  for (std::size_t i = 0; i < kDx.size(); ++i) {
    EXPECT_NEAR(rows[i].dx_mm, kDx[i], 0.5e-5) << i;
    travel += rows[i].dx_mm;
  }
  EXPECT_NEAR(travel, 1.0, 1e-12);
  EXPECT_NEAR(rows.front().c_deg, 20.364135, 0.5e-6);
  EXPECT_NEAR(rows.front().x_mm, 16.0, 1e-12);  // a point tool starts on the flat's edge
  EXPECT_EQ(rows[10].c_deg, 0.0);
  EXPECT_NEAR(rows[10].x_mm, 15.0, 1e-12);
  EXPECT_NEAR(rows.back().c_deg, -20.364135, 0.5e-6);
}

TEST(FlatGeometry, StepTableOfTheWorkedExampleEndMill) {
  // Section 9: R = 5, N = 4; sum of the first half (d + R)(1/cos alpha_e - 1) = 4/3.
  constexpr std::array<double, 4> kDx = {0.60110, 0.41222, 0.24081, 0.07921};
  const auto rows = step_table(kPaperR5, 4);
  ASSERT_EQ(rows.size(), 9U);
  double travel = 0.0;
  for (std::size_t i = 0; i < kDx.size(); ++i) {
    EXPECT_NEAR(rows[i].dx_mm, kDx[i], 0.5e-5) << i;
    travel += rows[i].dx_mm;
  }
  EXPECT_NEAR(travel, 4.0 / 3.0, 1e-12);
}

TEST(FlatGeometry, StepTableIsSymmetricWithChordsAlongTheOffsetLineAndAZeroLastRow) {
  for (const FlatSection& flat : {kPaper, kPaperR5, FlatSection{25.0, 7.0, 3.0}}) {
    for (const int n : {1, 3, 10}) {
      SCOPED_TRACE(testing::Message()
                   << "d " << flat.axis_distance_mm << " R " << flat.tool_radius_mm << " N " << n);
      const auto rows = step_table(flat, n);
      ASSERT_EQ(rows.size(), static_cast<std::size_t>(2 * n + 1));
      const double reach = flat.axis_distance_mm + flat.tool_radius_mm;
      double chords = 0.0;
      double dx_sum = 0.0;
      for (int i = 0; i <= 2 * n; ++i) {
        const auto& row = rows[static_cast<std::size_t>(i)];
        const auto& mirror = rows[static_cast<std::size_t>(2 * n - i)];
        EXPECT_EQ(row.i, i);
        EXPECT_NEAR(row.c_deg, -mirror.c_deg, 1e-12);  // F7: C symmetric about the middle
        EXPECT_NEAR(row.x_mm, mirror.x_mm, 1e-12);
        if (i == 2 * n) break;
        const auto& next = rows[static_cast<std::size_t>(i + 1)];
        EXPECT_NEAR(row.dx_mm, row.x_mm - next.x_mm, 1e-12);  // F8
        EXPECT_EQ(row.dx_mm > 0.0, i < n) << i;  // down in the first half, up in the second
        EXPECT_NEAR(row.dx_mm, -rows[static_cast<std::size_t>(2 * n - 1 - i)].dx_mm, 1e-12);
        // F9: the chord between the two points of the line at d + R, from their coordinates.
        const double a0 = row.c_deg * std::numbers::pi / 180.0;
        const double a1 = next.c_deg * std::numbers::pi / 180.0;
        const double chord = std::hypot(row.x_mm * std::cos(a0) - next.x_mm * std::cos(a1),
                                        row.x_mm * std::sin(a0) - next.x_mm * std::sin(a1));
        EXPECT_NEAR(row.chord_mm, chord, 1e-11);
        chords += row.chord_mm;
        dx_sum += row.dx_mm;
      }
      EXPECT_EQ(rows.back().dx_mm, 0.0);
      EXPECT_EQ(rows.back().chord_mm, 0.0);
      const double alpha_e = engagement_half_angle_rad(flat);
      EXPECT_NEAR(chords, 2.0 * reach * std::tan(alpha_e), 1e-11);  // the chords telescope
      EXPECT_NEAR(dx_sum, 0.0, 1e-12);
      EXPECT_NEAR(rows.front().c_deg, degrees(alpha_e), 1e-12);
    }
  }
}

}  // namespace
}  // namespace cutcalc::domain::lathe_flat
