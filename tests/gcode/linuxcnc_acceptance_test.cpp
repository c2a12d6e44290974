// Acceptance of the polygon-hole programs by LinuxCNC (spec polygon-holes.md sections 5, 6, 9):
// every generated program is run through rs274 at CENTER_ARC_RADIUS_TOLERANCE_MM = 0.001 and must
// exit 0; its canonical ARC_FEEDs are then checked against the tests' own exact centre path
// (tests/gcode/exact_path.*, shared with nothing in domain/): every interpolated point within
// tolerance + 0.0001 mm of the path, circle tangents continuous within 0.05 deg at every join,
// every loop closed, Z down to -depth, F and C words consistent with the printed loop.
// A missing rs274 fails these tests (CI must install linuxcnc-uspace); it is never a skip.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "domain/polygon/polygon_hole.h"
#include "gcode/canon_parser.h"
#include "gcode/exact_path.h"
#include "gcode/path_checker.h"
#include "gcode/rs274_runner.h"

namespace {

using cutcalc::domain::polygon::generate_polygon_hole;
using cutcalc::domain::polygon::PolygonHoleParams;
using cutcalc::domain::polygon::Synchronization;
using cutcalc::test::gcode::CanonProgram;
using cutcalc::test::gcode::check_program;
using cutcalc::test::gcode::ExactCentrePath;
using cutcalc::test::gcode::FeedCheck;
using cutcalc::test::gcode::kMaxKinkDeg;
using cutcalc::test::gcode::kOutputResolutionMm;
using cutcalc::test::gcode::parse_canon;
using cutcalc::test::gcode::PathCheckReport;
using cutcalc::test::gcode::ProgramLayout;
using cutcalc::test::gcode::Rs274Run;
using cutcalc::test::gcode::run_rs274;

constexpr double kDepthMm = 0.2;
constexpr double kStepDownMm = 0.1;
constexpr double kSpindleRpm = 40.0;

struct MatrixCase {
  int faces;
  double diameter_mm;
  Synchronization sync;
  double tolerance_mm;
  std::optional<int> loops_per_layer;
};

const char* mode_name(Synchronization sync) {
  return sync == Synchronization::c_axis ? "c_axis" : "feed_per_rev";
}

std::string case_name(const MatrixCase& c) {
  char buffer[160];
  std::snprintf(
      buffer, sizeof buffer, "N=%d d=%g %s tol=%g%s", c.faces, c.diameter_mm, mode_name(c.sync),
      c.tolerance_mm,
      c.loops_per_layer ? (" loops_per_layer=" + std::to_string(*c.loops_per_layer)).c_str() : "");
  return buffer;
}

std::vector<MatrixCase> all_n_both_modes(double diameter_mm, std::vector<double> tolerances,
                                         std::optional<int> loops_per_layer = std::nullopt) {
  std::vector<MatrixCase> cases;
  for (int faces = 3; faces <= 12; ++faces) {
    for (Synchronization sync : {Synchronization::feed_per_rev, Synchronization::c_axis}) {
      for (double tolerance : tolerances) {
        cases.push_back({faces, diameter_mm, sync, tolerance, loops_per_layer});
      }
    }
  }
  return cases;
}

// Spec section 6, blocks per loop for d = 20 (N = 4 for the paper's square, d = 16).
std::optional<int> spec_blocks_per_loop(const MatrixCase& c) {
  static const std::map<int, int> five_um = {{3, 25}, {4, 9}, {5, 11}, {6, 1}, {7, 1}, {8, 1}};
  static const std::map<int, int> one_um = {{3, 43}, {4, 25}, {5, 11}, {6, 13}, {7, 15}, {8, 1}};
  const bool tabulated_d = c.faces == 4 ? c.diameter_mm == 16.0 : c.diameter_mm == 20.0;
  if (!tabulated_d) return std::nullopt;
  const auto& table = c.tolerance_mm == 0.005 ? five_um : one_um;
  if (c.tolerance_mm != 0.005 && c.tolerance_mm != 0.001) return std::nullopt;
  if (c.faces >= 9) return 1;
  return table.at(c.faces);
}

struct CaseSummary {
  std::string name;
  bool accepted = false;
  int blocks_per_loop = 0;
  double claimed_deviation_mm = 0.0;
  PathCheckReport report;
  double seconds = 0.0;            // the whole case
  double generator_seconds = 0.0;  // generate_polygon_hole alone
};

// Generates, runs rs274, checks; every failure is an EXPECT naming the case.
CaseSummary run_case(const MatrixCase& c) {
  const auto started = std::chrono::steady_clock::now();
  CaseSummary summary;
  summary.name = case_name(c);
  SCOPED_TRACE(summary.name);

  PolygonHoleParams params;
  params.faces = c.faces;
  params.inscribed_diameter_mm = c.diameter_mm;
  params.depth_mm = kDepthMm;
  params.step_down_mm = kStepDownMm;
  params.spindle_speed_rpm = kSpindleRpm;
  params.tolerance_mm = c.tolerance_mm;
  params.synchronization = c.sync;
  params.loops_per_layer = c.loops_per_layer;
  const auto generated = generate_polygon_hole(params);
  summary.generator_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (!generated.ok()) {
    ADD_FAILURE() << "generate_polygon_hole failed: " << generated.error().detail;
    return summary;
  }
  const auto& result = generated.value();
  summary.blocks_per_loop = result.blocks_per_loop;
  summary.claimed_deviation_mm = result.max_path_deviation_mm;

  const Rs274Run run = run_rs274(cutcalc::domain::polygon::program_text(result));
  if (!run.started) {
    ADD_FAILURE() << "rs274 did not run: " << run.spawn_error;
    return summary;
  }
  EXPECT_FALSE(run.timed_out);
  EXPECT_EQ(run.exit_code, 0) << "rs274 rejected the program:\n" << run.errors;
  summary.accepted = run.exit_code == 0;

  const ExactCentrePath path(c.faces, c.diameter_mm);
  ProgramLayout layout;
  layout.blocks_per_loop = result.blocks_per_loop;
  layout.layers = static_cast<int>(std::ceil(kDepthMm / kStepDownMm - 1e-9));
  layout.loops_per_layer = c.loops_per_layer.value_or(c.faces - 1);
  layout.depth_mm = kDepthMm;
  layout.tolerance_mm = c.tolerance_mm;
  layout.feed_check =
      c.sync == Synchronization::c_axis ? FeedCheck::c_axis : FeedCheck::feed_per_rev;
  layout.spindle_speed_rpm = kSpindleRpm;
  const CanonProgram canon = parse_canon(run.output);
  EXPECT_TRUE(canon.program_end) << "no PROGRAM_END in rs274's output";
  summary.report = check_program(canon, path, layout);
  const PathCheckReport& report = summary.report;

  std::string violations;
  for (const auto& v : report.violations) violations += "  " + v + "\n";
  EXPECT_TRUE(report.violations.empty()) << "checker violations:\n" << violations;
  // The headline limits, spelled out (they are also among the violations above).
  EXPECT_LE(report.max_deviation_mm, c.tolerance_mm + kOutputResolutionMm);
  EXPECT_LE(report.max_kink_deg, kMaxKinkDeg);
  EXPECT_EQ(report.arcs, report.expected_arcs);
  EXPECT_NEAR(report.final_z_mm, -kDepthMm, 1e-9);

  // The generator's own figures against the replay.
  EXPECT_NEAR(result.eccentricity_mm, path.e(), 1e-9 * c.diameter_mm);
  EXPECT_LE(result.max_path_deviation_mm, c.tolerance_mm);
  EXPECT_NEAR(report.max_deviation_mm, result.max_path_deviation_mm, kOutputResolutionMm + 2e-6)
      << "P20 deviation vs the printed arcs";
  EXPECT_NEAR(result.loop_length_mm, report.printed_loop_length_mm, 1e-9);
  EXPECT_NEAR(result.feed_per_rev_mm, (c.faces - 1) * report.printed_loop_length_mm, 1e-9);
  if (const auto blocks = spec_blocks_per_loop(c)) {
    EXPECT_EQ(result.blocks_per_loop, *blocks) << "spec section 6 table";
  }
  summary.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return summary;
}

void run_and_print(const std::vector<MatrixCase>& cases) {
  std::vector<CaseSummary> summaries;
  for (const auto& c : cases) summaries.push_back(run_case(c));
  int accepted = 0;
  double seconds = 0.0;
  double generator_seconds = 0.0;
  std::printf("%-44s %6s %5s %10s %10s %9s %9s %8s %6s %6s\n", "case", "rs274", "blk", "dev_um",
              "claim_um", "kink_deg", "spiral", "C_err", "s", "gen_s");
  for (const auto& s : summaries) {
    accepted += s.accepted ? 1 : 0;
    seconds += s.seconds;
    generator_seconds += s.generator_seconds;
    std::printf("%-44s %6s %5d %10.4f %10.4f %9.5f %9.5f %8.5f %6.2f %6.2f\n", s.name.c_str(),
                s.accepted ? "ok" : "REJ", s.blocks_per_loop, s.report.max_deviation_mm * 1e3,
                s.claimed_deviation_mm * 1e3, s.report.max_kink_deg, s.report.max_spiral_kink_deg,
                s.report.max_c_error_deg, s.seconds, s.generator_seconds);
  }
  std::printf("accepted by rs274: %d of %zu programs, %.1f s (generator %.1f s)\n", accepted,
              summaries.size(), seconds, generator_seconds);
  std::fflush(stdout);
}

TEST(LinuxCncAcceptance, Rs274IsInstalled) {
  const Rs274Run run = run_rs274("%\nG21 G17 G90\nM30\n%\n");
  ASSERT_TRUE(run.started) << run.spawn_error;
  EXPECT_EQ(run.exit_code, 0) << run.errors;
  EXPECT_NE(run.output.find("PROGRAM_END"), std::string::npos) << run.output;
}

// d = 20, all N from 3 to 12, both modes, two tolerances.
TEST(LinuxCncAcceptance, EveryProgramIsAcceptedAtStrictArcTolerance) {
  run_and_print(all_n_both_modes(20.0, {0.001, 0.005}));
}

TEST(LinuxCncAcceptance, OtherDiametersAreAcceptedAndStayOnThePath) {
  std::vector<MatrixCase> cases = all_n_both_modes(16.0, {0.001, 0.005});
  for (const auto& c : all_n_both_modes(7.0, {0.001, 0.005})) cases.push_back(c);
  run_and_print(cases);
}

// The spec's kink bound holds for d >= 5 mm at any tolerance >= 0.0005 mm: its corner case.
TEST(LinuxCncAcceptance, SmallestBoundedHoleAtHalfMicronTolerance) {
  run_and_print(all_n_both_modes(5.0, {0.0005}));
}

// loops_per_layer = 1: a ramp loop per layer with its own F and one more flat loop at -depth.
TEST(LinuxCncAcceptance, OneLoopPerLayerEndsWithAFlatLoop) {
  std::vector<MatrixCase> cases;
  for (int faces : {3, 4, 6, 9}) {
    for (Synchronization sync : {Synchronization::feed_per_rev, Synchronization::c_axis}) {
      cases.push_back({faces, 20.0, sync, 0.001, 1});
    }
  }
  run_and_print(cases);
}

}  // namespace
