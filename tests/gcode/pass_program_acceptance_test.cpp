// Acceptance of the pass programs (spec programs.md section 1.3, "Verification"): for every
// reference case of main-time-program.json that answers 200, in every dialect, the program as the
// service writes it (the api handler, the same path as HTTP):
//  - translated to LinuxCNC (section 3) is accepted by rs274 -g;
//  - has as many constant-Z feed moves in rs274's canonical output as in its text, one or two per
//    pass (the entry move, and the steady move unless it prints equal);
//  - on its TEXT: the sum of length / F over the constant-Z feed moves equals main_time_min within
//    the bound that printing implies, and each pass's first such move (its entry move) is as long
//    as the pass's entry_length_mm within 10^-decimals (program units);
//  - with the same `decimals`, fanuc and sinumerik give the same canonical motion sequence
//    (STRAIGHT_TRAVERSE, STRAIGHT_FEED, SET_FEED_RATE) as linuxcnc.
// The same checks run on the section 15 requests (entry-and-main-time.md E37-E41: pass_split
// equal, a finishing level with its own feeds and speed) of next/main-time.json, in mm and inch:
// their feed time is their main time.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "api/entry/main_time_program_endpoint.h"
#include "gcode/program_text.h"
#include "gcode/rs274_runner.h"

namespace {

using cutcalc::test::gcode::kMmPerInch;
using cutcalc::test::gcode::moves_of;
using cutcalc::test::gcode::Rs274Run;
using cutcalc::test::gcode::run_rs274;
using cutcalc::test::gcode::TextMove;
using cutcalc::test::gcode::translate_to_linuxcnc;
using nlohmann::json;

const std::vector<std::string> kPassDialects = {"linuxcnc", "fanuc", "sinumerik"};

std::vector<json> ok_cases() {
  std::ifstream in(std::string(CUTCALC_REFERENCE_DIR) + "/main-time-program.json");
  const json file = json::parse(in);
  std::vector<json> cases;
  for (const json& c : file.at("cases")) {
    if (c.at("expect").at("status") == 200) cases.push_back(c);
  }
  return cases;
}

// The 200 cases of next/main-time.json (pass_split, finish) as program cases in `units`: the
// program's working time must be their main time (G8 = E41).
std::vector<json> section15_cases(const std::string& units) {
  std::ifstream in(std::string(CUTCALC_REFERENCE_DIR) + "/next/main-time.json");
  const json file = json::parse(in);
  std::vector<json> cases;
  for (const json& c : file.at("cases")) {
    if (c.at("expect").at("status") != 200) continue;
    json request = c.at("request");
    request.erase("extra_path_mm");  // 0 in every case; a program needs a straight path
    request["program"] = {{"units", units}};
    cases.push_back(
        {{"id", c.at("id").get<std::string>() + " " + units},
         {"request", request},
         {"expect",
          {{"body", {{"working_time_min", c.at("expect").at("body").at("main_time_min")}}}}}});
  }
  return cases;
}

// The service's answer (JSON form) and the program text for `request`.
struct Answer {
  json body;
  std::string program;
};

Answer answer(const json& request) {
  auto outcome = cutcalc::api::entry::handle_main_time_program(request);
  auto* both = std::get_if<cutcalc::api::JsonWithText>(&outcome);
  if (both != nullptr) cutcalc::api::write_whole(*both);
  if (both == nullptr) {
    ADD_FAILURE() << "no program for " << request.dump();
    return {};
  }
  return {both->json, both->text};
}

// The motion commands of rs274's output, without line numbers.
std::vector<std::string> canonical_motion(const std::string& output) {
  std::vector<std::string> commands;
  std::istringstream in(output);
  std::string line;
  while (std::getline(in, line)) {
    for (const char* name : {"STRAIGHT_TRAVERSE(", "STRAIGHT_FEED(", "SET_FEED_RATE("}) {
      const auto at = line.find(name);
      if (at != std::string::npos) commands.push_back(line.substr(at));
    }
  }
  return commands;
}

std::size_t constant_z_feeds_in_canon(const std::vector<std::string>& commands) {
  std::size_t count = 0;
  double last_z = 0.0;
  for (const std::string& command : commands) {
    std::vector<double> values;
    std::istringstream args(command.substr(command.find('(') + 1));
    std::string value;
    while (std::getline(args, value, ',')) values.push_back(std::strtod(value.c_str(), nullptr));
    if (command.rfind("SET_FEED_RATE", 0) == 0 || values.size() < 3) continue;
    if (command.rfind("STRAIGHT_FEED", 0) == 0 && values[2] == last_z) ++count;
    last_z = values[2];
  }
  return count;
}

void check_program(const json& reference, const std::string& dialect, std::optional<int> decimals,
                   std::vector<std::string>* canon_out) {
  json request = reference.at("request");
  request["program"] = request.value("program", json::object());
  request["program"]["dialect"] = dialect;
  request["program"].erase("program_number");
  if (dialect != "sinumerik") request["program"].erase("name");
  if (dialect == "sinumerik" && request["program"].value("work_offset", "G54") > "G57") {
    request["program"]["work_offset"] = "G54";
  }
  if (decimals) request["program"]["decimals"] = *decimals;
  SCOPED_TRACE(reference.at("id").get<std::string>() + " " + dialect +
               (decimals ? " decimals " + std::to_string(*decimals) : ""));
  const Answer got = answer(request);
  ASSERT_FALSE(got.program.empty());
  const bool inch = got.body.at("units") == "inch";
  const double unit = inch ? kMmPerInch : 1.0;
  const int places = decimals.value_or(dialect == "linuxcnc" ? (inch ? 5 : 4) : (inch ? 4 : 3));

  const std::string linuxcnc = translate_to_linuxcnc(got.program, dialect);
  const Rs274Run run = run_rs274(linuxcnc);
  ASSERT_TRUE(run.started) << run.spawn_error;
  ASSERT_EQ(run.exit_code, 0) << run.errors << "\n" << linuxcnc;
  const std::vector<std::string> canon = canonical_motion(run.output);
  if (canon_out != nullptr) *canon_out = canon;

  // Constant-Z feed moves on the text: per pass 1 or 2, the first being the entry move.
  const std::vector<TextMove> moves = moves_of(linuxcnc);
  const json& lateral = got.body.at("main_time").at("lateral_passes");
  const double e = 0.5 * std::pow(10.0, -places);
  double time_min = 0.0;
  double bound_min = 0.0;
  std::size_t feeds = 0;
  std::size_t pass = 0;
  bool in_pass = false;
  std::size_t in_this_pass = 0;
  for (const TextMove& move : moves) {
    const bool constant_z = move.feed && move.z == move.from_z;
    if (move.feed && !constant_z) {  // a plunge starts a pass
      in_pass = true;
      in_this_pass = 0;
      continue;
    }
    if (!constant_z) {
      if (in_pass) {
        EXPECT_TRUE(in_this_pass == 1 || in_this_pass == 2) << in_this_pass;
        ++pass;
      }
      in_pass = false;
      continue;
    }
    const double length = std::hypot(move.x - move.from_x, move.y - move.from_y);
    time_min += length / move.f;
    bound_min += (2 * e * move.f + length * e) / (move.f * (move.f - e));
    ++feeds;
    if (in_this_pass++ == 0) {
      const double entry = lateral.at(pass % lateral.size()).at("entry_length_mm").get<double>();
      EXPECT_NEAR(length, entry / unit, std::pow(10.0, -places)) << "entry move of pass " << pass;
    }
  }
  EXPECT_EQ(pass, static_cast<std::size_t>(got.body.at("passes").get<int>()));
  EXPECT_EQ(feeds, constant_z_feeds_in_canon(canon));
  EXPECT_NEAR(time_min, got.body.at("main_time_min").get<double>(), bound_min);
  // The JSON times are the reference's (to 1e-9), whatever the printing.
  EXPECT_NEAR(got.body.at("working_time_min").get<double>(),
              reference.at("expect").at("body").at("working_time_min").get<double>(), 1e-9);
}

TEST(PassProgramAcceptance, EveryReferenceProgramInEveryDialectIsAcceptedAndTimed) {
  const auto cases = ok_cases();
  ASSERT_GE(cases.size(), 10U);
  for (const json& reference : cases) {
    for (const std::string& dialect : kPassDialects) check_program(reference, dialect, {}, nullptr);
  }
}

TEST(PassProgramAcceptance, EqualPassesAndFinishingLevelsInEveryDialectAndUnitAreTimed) {
  int checked = 0;
  for (const std::string units : {"mm", "inch"}) {
    const auto cases = section15_cases(units);
    ASSERT_GE(cases.size(), 7U);
    for (const json& reference : cases) {
      for (const std::string& dialect : kPassDialects) {
        check_program(reference, dialect, {}, nullptr);
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 42);
}

TEST(PassProgramAcceptance, FinishingLevelsGiveTheSameCanonicalMotionInEveryDialect) {
  for (const json& reference : section15_cases("mm")) {
    std::vector<std::string> linuxcnc;
    check_program(reference, "linuxcnc", 4, &linuxcnc);
    for (const std::string dialect : {"fanuc", "sinumerik"}) {
      std::vector<std::string> other;
      check_program(reference, dialect, 4, &other);
      EXPECT_EQ(other, linuxcnc) << reference.at("id") << " " << dialect;
    }
  }
}

TEST(PassProgramAcceptance, DialectsGiveTheSameCanonicalMotionAsLinuxcnc) {
  for (const json& reference : ok_cases()) {
    std::vector<std::string> linuxcnc;
    check_program(reference, "linuxcnc", 4, &linuxcnc);
    for (const std::string dialect : {"fanuc", "sinumerik"}) {
      std::vector<std::string> other;
      check_program(reference, dialect, 4, &other);
      EXPECT_EQ(other, linuxcnc) << reference.at("id") << " " << dialect;
    }
  }
}

}  // namespace
