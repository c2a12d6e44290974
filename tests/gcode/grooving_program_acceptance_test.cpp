// Acceptance of the grooving-cycle programs (spec grooving-cycle.md sections 5.3 and 5.4): for
// every reference case of next/grooving-cycle.json that answers 200, in every dialect and unit,
// the program as the service writes it (the api handler, the same path as HTTP):
//  - follows the dialect's text rules (support/program_text_rules.h) and, translated to LinuxCNC
//    (section 5.4), is accepted by rs274 -g (a tool table with tools 1-99);
//  - has feed_moves = N + 2 G1 blocks (and STRAIGHT_FEED calls), z_feed_moves = shifts of them
//    with a Z word, its smallest printed X = Db, sum |dX| over G1 = D_a - Db and sum |dZ| =
//    shifts x X2 (program units, within feed_moves x 10^-decimals), one DWELL of the printed
//    seconds when n_d > 0;
//  - its feed time re-integrated from the canonical motion, sum over STRAIGHT_FEED of (L/F) x
//    M(D1, D2) (L in radius space: canon prints X as a radius in G7; F as printed; M of K16),
//    equals approach + plunge + shift + final_shift time within the printing error;
//  - with the same `decimals`, fanuc and sinumerik give the same STRAIGHT_TRAVERSE /
//    STRAIGHT_FEED / SET_FEED_RATE / DWELL sequence as linuxcnc (within 1.5e-4), and the same
//    SET_FEED_MODE (feed per revolution in all three).
// The reference case's own program facts (section 5.5) are the replay's
// (tools/contract/replay.mjs), checked over HTTP for every consumer.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "api/grooving/grooving_cycle_endpoint.h"
#include "domain/grooving/revolution_time.h"
#include "gcode/lathe_program_runs.h"
#include "gcode/program_text.h"
#include "gcode/rs274_runner.h"
#include "support/program_text_rules.h"

namespace {

using cutcalc::domain::grooving::mean_minutes_per_revolution;
using cutcalc::domain::grooving::SpindleMode;
using cutcalc::test::gcode::CanonCall;
using cutcalc::test::gcode::expect_same_motion;
using cutcalc::test::gcode::kCanonStep;
using cutcalc::test::gcode::kMmPerInch;
using cutcalc::test::gcode::LatheRun;
using cutcalc::test::gcode::moves_of;
using cutcalc::test::gcode::ok_reference_cases;
using cutcalc::test::gcode::request_with_program;
using cutcalc::test::gcode::TextMove;
using cutcalc::test::gcode::write_and_run;
using nlohmann::json;

const std::vector<std::string> kGroovingDialects = {"linuxcnc", "fanuc", "sinumerik"};
const std::vector<std::string> kGroovingUnits = {"mm", "inch"};

SpindleMode spindle_of(const json& request) {
  SpindleMode spindle;
  if (request.contains("spindle_speed_rpm"))
    spindle.spindle_speed_rpm = request["spindle_speed_rpm"];
  if (request.contains("cutting_speed_m_per_min")) {
    spindle.cutting_speed_m_per_min = request["cutting_speed_m_per_min"];
  }
  if (request.contains("max_spindle_rpm")) spindle.max_spindle_rpm = request["max_spindle_rpm"];
  return spindle;
}

// Section 5.3 on one program: the text facts, the canonical counts, the dwell and the feed time.
void check_facts(const json& request, const LatheRun& got) {
  const json& body = got.body;
  const bool inch = body.at("units") == "inch";
  const double unit = inch ? kMmPerInch : 1.0;  // mm per program unit
  const int decimals = body.at("decimals").get<int>();
  const double step = std::pow(10.0, -decimals);
  const int n = body.at("revolutions").get<int>();
  const int shifts = body.at("shifts").get<int>();

  // The text: G1 blocks, their Z words, the smallest X, the travels.
  const std::vector<TextMove> moves = moves_of(got.linuxcnc);
  int feed_moves = 0;
  int z_feed_moves = 0;
  double min_x = 1e300;
  double x_travel = 0.0;
  double z_travel = 0.0;
  for (const TextMove& move : moves) {
    min_x = std::min(min_x, move.x);
    if (!move.feed) continue;
    ++feed_moves;
    if (move.z != move.from_z) ++z_feed_moves;
    x_travel += std::fabs(move.x - move.from_x);
    z_travel += std::fabs(move.z - move.from_z);
  }
  // The tool's left corner stays between z_L and z_R = z_L + X2 (else the tool, B = W - X2 wide,
  // cuts into a wall), and the final shift crosses the whole shift to the other wall.
  const double z_left = request.at("groove_left_z_mm").get<double>() / unit;
  const double shift = body.at("shift_mm").get<double>() / unit;
  for (const TextMove& move : moves) {
    if (!move.feed) continue;
    EXPECT_GE(move.z, z_left - 0.5 * step) << "a feed move left of the groove";
    EXPECT_LE(move.z, z_left + shift + step) << "a feed move right of the groove";
  }
  const auto last_feed =
      std::find_if(moves.rbegin(), moves.rend(), [](const TextMove& move) { return move.feed; });
  ASSERT_NE(last_feed, moves.rend());
  EXPECT_NEAR(std::fabs(last_feed->z - last_feed->from_z), shift, step) << "the final shift";
  EXPECT_EQ(feed_moves, n + 2);
  EXPECT_EQ(z_feed_moves, shifts);
  EXPECT_NEAR(min_x, body.at("bottom_diameter_mm").get<double>() / unit, 0.5 * step);
  const double travel_bound = feed_moves * step;
  EXPECT_NEAR(x_travel,
              (body.at("approach_diameter_mm").get<double>() -
               body.at("bottom_diameter_mm").get<double>()) /
                  unit,
              travel_bound);
  EXPECT_NEAR(z_travel, shifts * body.at("shift_mm").get<double>() / unit, travel_bound);

  // The canonical motion: as many STRAIGHT_FEED calls, one DWELL of the printed seconds when
  // n_d > 0, and the feed time.
  const double dwell_s = body.at("dwell_time_min").get<double>() * 60.0;
  const SpindleMode spindle = spindle_of(request);
  // The printing error of canon's numbers: X (a radius) from a diameter printed to 0.5 step, Z
  // and F printed to 0.5 step; canon rounds again to 4 decimals (X / 2 may need a fifth).
  const double canon_round = 0.5 * kCanonStep;
  const double e_x = 0.25 * step + (decimals >= 4 ? canon_round : 0.0);
  const double e_z = 0.5 * step + (decimals > 4 ? canon_round : 0.0);
  const double e_f = 0.5 * step + (decimals > 4 ? canon_round : 0.0);
  int canon_feeds = 0;
  int dwells = 0;
  bool per_revolution = false;
  int per_minute_feeds = 0;
  double x = 0, z = 0, f = 0;  // canon: X a radius, program units
  double time_min = 0.0;
  double bound_min = 0.0;
  // First order in the point errors: a point shared by two feed moves moves both lengths, so
  // its error enters through the difference of their gradients (u M / F).
  double open_gx = 0.0, open_gz = 0.0;  // gradient at the current point from the move ending there
  const auto close_point = [&](double gx, double gz) {
    bound_min += std::fabs(gx) * e_x + std::fabs(gz) * e_z;
  };
  for (const CanonCall& c : got.canon) {
    if (c.name == "DWELL") {
      ++dwells;
      EXPECT_NEAR(c.args.at(0), dwell_s, 0.5e-3 + 1e-9);
    } else if (c.name == "SET_FEED_RATE") {
      f = c.args.at(0);
    } else if (c.name == "SET_FEED_MODE") {
      per_revolution = c.args.size() == 2 && c.args[1] == 1.0;  // (spindle, 1 = units per rev)
    } else if (c.args.size() >= 3) {
      const double to_x = c.args[0];
      const double to_z = c.args[2];
      if (c.name == "STRAIGHT_FEED") {
        ++canon_feeds;
        if (!per_revolution) ++per_minute_feeds;
        const double length = std::hypot(to_x - x, to_z - z);
        const double d1_mm = 2 * x * unit;
        const double d2_mm = 2 * to_x * unit;
        const double m = mean_minutes_per_revolution(spindle, d1_mm, d2_mm);
        const double t = length / f * m;
        time_min += t;
        // F within e_f; M through D (G96: M ~ D) within 2 e_x / D relative.
        bound_min += t * (e_f / (f - e_f) + 2 * e_x * unit / std::min(d1_mm, d2_mm));
        const double gx = length > 0 ? (to_x - x) / length * m / f : 0.0;
        const double gz = length > 0 ? (to_z - z) / length * m / f : 0.0;
        close_point(open_gx - gx, open_gz - gz);  // the start: this move pulls the other way
        open_gx = gx;
        open_gz = gz;
      } else {
        close_point(open_gx, open_gz);
        open_gx = open_gz = 0.0;
      }
      x = to_x;
      z = to_z;
    }
  }
  close_point(open_gx, open_gz);
  EXPECT_EQ(canon_feeds, n + 2);
  EXPECT_EQ(per_minute_feeds, 0) << "feed moves not in feed per revolution (G95)";
  EXPECT_EQ(dwells, dwell_s > 0 ? 1 : 0);
  const double feed_time =
      body.at("approach_time_min").get<double>() + body.at("plunge_time_min").get<double>() +
      body.at("shift_time_min").get<double>() + body.at("final_shift_time_min").get<double>();
  EXPECT_NEAR(time_min, feed_time, bound_min) << "bound " << bound_min / feed_time << " relative";
}

TEST(GroovingProgramAcceptance, EveryReferenceProgramInEveryDialectAndUnitIsAcceptedAndTimed) {
  const auto cases = ok_reference_cases("next/grooving-cycle.json");
  ASSERT_GE(cases.size(), 9U);
  int checked = 0;
  for (const json& reference : cases) {
    for (const std::string& units : kGroovingUnits) {
      for (const std::string& dialect : kGroovingDialects) {
        SCOPED_TRACE(reference.at("id").get<std::string>() + " " + dialect + " " + units);
        const json request = request_with_program(reference, dialect, units, std::nullopt);
        const LatheRun got =
            write_and_run(&cutcalc::api::grooving::handle_grooving_cycle, request, dialect);
        if (!got.ok) continue;
        check_facts(request, got);
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked,
            static_cast<int>(cases.size() * kGroovingUnits.size() * kGroovingDialects.size()));
}

TEST(GroovingProgramAcceptance, DialectsGiveTheSameCanonicalMotionAsLinuxcnc) {
  constexpr double kTolerance = 1.5e-4;
  for (const json& reference : ok_reference_cases("next/grooving-cycle.json")) {
    for (const std::string& units : kGroovingUnits) {
      const LatheRun linuxcnc =
          write_and_run(&cutcalc::api::grooving::handle_grooving_cycle,
                        request_with_program(reference, "linuxcnc", units, 4), "linuxcnc");
      ASSERT_FALSE(linuxcnc.canon.empty());
      for (const std::string dialect : {"fanuc", "sinumerik"}) {
        SCOPED_TRACE(reference.at("id").get<std::string>() + " " + dialect + " " + units);
        const LatheRun other =
            write_and_run(&cutcalc::api::grooving::handle_grooving_cycle,
                          request_with_program(reference, dialect, units, 4), dialect);
        expect_same_motion(linuxcnc, other, kTolerance);
      }
    }
  }
}

}  // namespace
