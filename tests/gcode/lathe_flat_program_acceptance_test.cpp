// Acceptance of the lathe flat programs (spec lathe-flat.md sections 6.5 and 6.6): for every
// reference case of next/lathe-flat.json that answers 200, in LinuxCNC and Sinumerik, mm and
// inch, the program as the service writes it (the api handler, the same path as HTTP):
//  - follows the dialect's text rules (support/program_text_rules.h) and, translated to LinuxCNC
//    (section 6.5), is accepted by rs274 -g (a tool table with tools 1-99);
//  - every G1 block with a C word is under G93 and has its own F word, their count is
//    cut_blocks, and no spindle word (S, M3/M4/M5) is written (section 6.2);
//  - its time read from the printed words (each G93 block 1/F, each G94 G1 |dX|/2/F) equals
//    machining_time_min within the printing bound of section 6.6;
//  - its time from rs274's canonical moves (sum over STRAIGHT_FEED of L / rate: a G93 block's
//    SET_FEED_RATE is L x F, L the XYZ length, or the C length when X does not move) equals
//    machining_time_min within that bound plus canon's own 4-decimal rounding;
//  - with the same `decimals`, sinumerik gives the same STRAIGHT_TRAVERSE / STRAIGHT_FEED /
//    SET_FEED_RATE / SET_FEED_MODE sequence as linuxcnc (within 1.5e-4).
// The reference case's own program facts are the replay's (tools/contract/replay.mjs).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "api/lathe_flat/lathe_flat_endpoint.h"
#include "gcode/lathe_program_runs.h"
#include "gcode/program_text.h"
#include "gcode/rs274_runner.h"
#include "support/program_text_rules.h"

namespace {

using cutcalc::test::gcode::CanonCall;
using cutcalc::test::gcode::expect_same_motion;
using cutcalc::test::gcode::kCanonStep;
using cutcalc::test::gcode::LatheRun;
using cutcalc::test::gcode::ok_reference_cases;
using cutcalc::test::gcode::request_with_program;
using cutcalc::test::gcode::words_of;
using cutcalc::test::gcode::write_and_run;
using nlohmann::json;

const std::vector<std::string> kLatheFlatDialects = {"linuxcnc", "sinumerik"};
const std::vector<std::string> kLatheFlatUnits = {"mm", "inch"};

// A G1 block of the translated program, from its printed words.
struct FeedBlock {
  bool inverse_time = false;  // under G93
  bool own_f = false;         // an F word in this block
  bool c_word = false;
  double from_x = 0, x = 0;  // diameters, program units
  double from_c = 0, c = 0;  // deg
  double f = 0;              // the F in force
};

struct ProgramText {
  std::vector<FeedBlock> feeds;
  int spindle_words = 0;  // S, M3, M4, M5 (section 6.2: none)
};

ProgramText read_text(const std::string& linuxcnc) {
  ProgramText out;
  bool inverse_time = false;
  int motion = -1;
  double x = 0, c = 0, f = 0;
  for (const auto& block : words_of(linuxcnc, "linuxcnc")) {
    FeedBlock feed;
    feed.from_x = x;
    feed.from_c = c;
    for (const std::string& word : block) {
      const double value = std::strtod(word.c_str() + 1, nullptr);
      if (word == "G93") inverse_time = true;
      if (word == "G94") inverse_time = false;
      if (word == "G0" || word == "G1") motion = word == "G1" ? 1 : 0;
      if (word == "M3" || word == "M4" || word == "M5" || word[0] == 'S') ++out.spindle_words;
      if (word[0] == 'X') x = value;
      if (word[0] == 'C') {
        c = value;
        feed.c_word = true;
      }
      if (word[0] == 'F') {
        f = value;
        feed.own_f = true;
      }
    }
    const bool moves = std::any_of(block.begin(), block.end(), [](const std::string& w) {
      return w[0] == 'X' || w[0] == 'Z' || w[0] == 'C';
    });
    if (motion == 1 && moves) {
      feed.inverse_time = inverse_time;
      feed.x = x;
      feed.c = c;
      feed.f = f;
      out.feeds.push_back(feed);
    }
  }
  return out;
}

// Section 6.2 and 6.6 on the printed words; returns the text time and its bound.
void check_text(const json& request, const LatheRun& got, double& time_min, double& bound_min) {
  const json& body = got.body;
  const double e = 0.5 * std::pow(10.0, -body.at("decimals").get<int>());
  const ProgramText text = read_text(got.linuxcnc);
  EXPECT_EQ(text.spindle_words, 0) << "a spindle word in the flat program";
  int c_steps = 0;
  time_min = 0.0;
  bound_min = 0.0;
  for (const FeedBlock& feed : text.feeds) {
    if (feed.c_word) {
      ++c_steps;
      EXPECT_TRUE(feed.inverse_time) << "a G1 with C outside G93: C" << feed.c;
      EXPECT_TRUE(feed.own_f) << "a G93 block without its own F: C" << feed.c;
    }
    if (feed.inverse_time) {
      time_min += 1.0 / feed.f;
      bound_min += e / (feed.f * (feed.f - e));
    } else {
      const double length = std::fabs(feed.x - feed.from_x) / 2.0;  // radial, program units
      time_min += length / feed.f;
      bound_min += e / (feed.f - e) + length * e / (feed.f * (feed.f - e));
    }
  }
  EXPECT_EQ(c_steps, body.at("cut_blocks").get<int>());
  // Flat 1's final layer (the L-th run of 2N C steps) goes through the step table's points:
  // C = c_deg, X = the diameter 2 x_mm, rows i = 1..2N (row 0 is the G0 C and the G94 approach).
  const json& table = body.at("steps_table");
  const int layers = body.at("layers").get<int>();
  const std::size_t run = table.size() - 1;  // 2N
  const double unit = body.at("units") == "inch" ? 25.4 : 1.0;
  std::vector<FeedBlock> steps;
  for (const FeedBlock& feed : text.feeds) {
    if (feed.c_word) steps.push_back(feed);
  }
  ASSERT_GE(steps.size(), run * static_cast<std::size_t>(layers));
  const std::size_t first = run * static_cast<std::size_t>(layers - 1);
  EXPECT_NEAR(steps[first].from_c, table.at(0).at("c_deg").get<double>(), e);
  for (std::size_t i = 1; i <= run; ++i) {
    const FeedBlock& step = steps[first + i - 1];
    EXPECT_NEAR(step.c, table.at(i).at("c_deg").get<double>(), e) << "row " << i;
    EXPECT_NEAR(step.x, 2 * table.at(i).at("x_mm").get<double>() / unit, e) << "row " << i;
  }
  // One G94 approach block per flat and layer besides the C steps.
  EXPECT_EQ(static_cast<int>(text.feeds.size()),
            c_steps + request.value("flats", 1) * body.at("layers").get<int>());
  EXPECT_NEAR(time_min, body.at("machining_time_min").get<double>(), bound_min)
      << "the printed program's time (section 6.6)";
}

// LinuxCNC's interpreter sets a G93 block's rate to MAX(0.1, L x F) (interp_inverse.cc,
// inverse_time_rate_straight; program units per minute): a block with L x F < 0.1 runs at 0.1,
// faster than its 1/F.
constexpr double kLinuxcncInverseTimeFloor = 0.1;

struct CanonTime {
  int floored = 0;         // G93 blocks LinuxCNC runs at its 0.1 floor, not in 1/F
  double floored_min = 0;  // their time by the text (1/F)
};

// The canonical time: sum over STRAIGHT_FEED of L / rate, L in canon's coordinates (X a radius,
// C in degrees; rs274 takes the C length when the block's XYZ length is zero), each paired with
// its G1 block of the text. Canon rounds every coordinate and rate to kCanonStep / 2, so L is off
// by <= kCanonStep and the rate by half of it. A G93 block's rate is MAX(0.1, L x F), F as
// printed. When the printed X moves but canon's XYZ length is below 2 kCanonStep (the middle
// blocks of a fine step), canon cannot resolve L: the block counts with the text's 1/F, as does
// a block at the floor (counted in the result: its time on LinuxCNC is L / 0.1 < 1/F).
CanonTime check_canon(const LatheRun& got, double text_bound_min) {
  CanonTime out;
  const double machining_time = got.body.at("machining_time_min").get<double>();
  const std::vector<FeedBlock> text = read_text(got.linuxcnc).feeds;
  const double rate_error = 0.5 * kCanonStep;
  double x = 0, y = 0, z = 0, c = 0, rate = 0;
  double time_min = 0.0;
  double bound_min = text_bound_min;
  std::size_t feeds = 0;
  int unresolved = 0;
  for (const CanonCall& command : got.canon) {
    if (command.name == "SET_FEED_RATE") {
      rate = command.args.at(0);
      continue;
    }
    if (command.name == "SET_FEED_MODE") continue;
    EXPECT_GE(command.args.size(), 6U) << command.name;
    if (command.args.size() < 6U) return out;
    const double to_x = command.args[0], to_y = command.args[1], to_z = command.args[2];
    const double to_c = command.args[5];
    if (command.name == "STRAIGHT_FEED") {
      EXPECT_LT(feeds, text.size()) << "more STRAIGHT_FEED calls than G1 blocks";
      if (feeds >= text.size()) return out;
      const FeedBlock& block = text[feeds++];
      const double xyz =
          std::sqrt((to_x - x) * (to_x - x) + (to_y - y) * (to_y - y) + (to_z - z) * (to_z - z));
      const bool x_moves = block.x != block.from_x;
      const double length = x_moves ? xyz : std::fabs(to_c - c);
      EXPECT_GT(rate, rate_error) << "feed #" << feeds;
      if (block.inverse_time) {
        EXPECT_NEAR(rate, std::max(kLinuxcncInverseTimeFloor, length * block.f),
                    kCanonStep * block.f + rate_error)
            << "a G93 rate is MAX(0.1, L x F): feed #" << feeds;
        if (rate < kLinuxcncInverseTimeFloor + rate_error) {
          ++out.floored;
          out.floored_min += 1.0 / block.f;
          time_min += 1.0 / block.f;
        } else if (x_moves && xyz < 2 * kCanonStep) {
          ++unresolved;
          time_min += 1.0 / block.f;
        } else {
          time_min += length / rate;
          bound_min += (length + kCanonStep) / (rate - rate_error) - length / rate;
        }
      } else {
        time_min += length / rate;
        bound_min += (length + kCanonStep) / (rate - rate_error) - length / rate;
      }
    }
    x = to_x;
    y = to_y;
    z = to_z;
    c = to_c;
  }
  EXPECT_EQ(feeds, text.size());
  EXPECT_NEAR(time_min, machining_time, bound_min)
      << "rs274's canonical time (" << unresolved << " blocks below its resolution, " << out.floored
      << " at the 0.1 floor); bound " << bound_min / machining_time << " relative";
  return out;
}

TEST(LatheFlatProgramAcceptance, EveryReferenceProgramInBothDialectsAndUnitsIsAcceptedAndTimed) {
  const auto cases = ok_reference_cases("next/lathe-flat.json");
  ASSERT_GE(cases.size(), 11U);
  int checked = 0;
  for (const json& reference : cases) {
    for (const std::string& units : kLatheFlatUnits) {
      for (const std::string& dialect : kLatheFlatDialects) {
        SCOPED_TRACE(reference.at("id").get<std::string>() + " " + dialect + " " + units);
        const json request = request_with_program(reference, dialect, units, std::nullopt);
        const LatheRun got =
            write_and_run(&cutcalc::api::lathe_flat::handle_lathe_flat, request, dialect);
        if (!got.ok) continue;
        double text_time = 0, text_bound = 0;
        check_text(request, got, text_time, text_bound);
        const CanonTime canon = check_canon(got, text_bound);
        if (canon.floored > 0) {
          std::cout << reference.at("id").get<std::string>() << " " << dialect << " " << units
                    << ": " << canon.floored
                    << " G93 blocks at LinuxCNC's 0.1 floor, their text time " << canon.floored_min
                    << " min of " << got.body.at("machining_time_min").get<double>() << "\n";
        }
        if (units == "mm") {
          EXPECT_EQ(canon.floored, 0) << "an mm block at LinuxCNC's 0.1 floor";
        }
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked,
            static_cast<int>(cases.size() * kLatheFlatUnits.size() * kLatheFlatDialects.size()));
}

TEST(LatheFlatProgramAcceptance, SinumerikGivesTheSameCanonicalMotionAsLinuxcnc) {
  constexpr double kTolerance = 1.5e-4;
  for (const json& reference : ok_reference_cases("next/lathe-flat.json")) {
    for (const std::string& units : kLatheFlatUnits) {
      SCOPED_TRACE(reference.at("id").get<std::string>() + " " + units);
      const LatheRun linuxcnc =
          write_and_run(&cutcalc::api::lathe_flat::handle_lathe_flat,
                        request_with_program(reference, "linuxcnc", units, 4), "linuxcnc");
      const LatheRun other =
          write_and_run(&cutcalc::api::lathe_flat::handle_lathe_flat,
                        request_with_program(reference, "sinumerik", units, 4), "sinumerik");
      expect_same_motion(linuxcnc, other, kTolerance);
    }
  }
}

}  // namespace
