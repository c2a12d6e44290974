#include "gcode/lathe_program_runs.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string_view>
#include <variant>

#include "gcode/program_text.h"
#include "gcode/rs274_runner.h"
#include "support/program_text_rules.h"

namespace cutcalc::test::gcode {
namespace {

using nlohmann::json;

// The tool table of lathe-flat.md section 6.5: `T{n} P{n} D1 Z0`, n = 1..99 (the turret's tools).
std::string turret_tool_table() {
  std::string table;
  for (int t = 1; t <= 99; ++t) {
    const std::string number = std::to_string(t);
    table.append("T").append(number).append(" P").append(number).append(" D1 Z0\n");
  }
  return table;
}

}  // namespace

std::vector<CanonCall> canon_calls(const std::string& output) {
  std::vector<CanonCall> calls;
  std::istringstream in(output);
  std::string line;
  while (std::getline(in, line)) {
    for (const char* call : {" STRAIGHT_TRAVERSE(", " STRAIGHT_FEED(", " SET_FEED_RATE(",
                             " SET_FEED_MODE(", " DWELL("}) {
      const std::string_view text(call);
      const auto at = line.find(text);
      if (at == std::string::npos) continue;
      CanonCall parsed{std::string(text.substr(1, text.size() - 2)), {}};
      std::istringstream args(line.substr(at + text.size()));
      std::string value;
      while (std::getline(args, value, ','))
        parsed.args.push_back(std::strtod(value.c_str(), nullptr));
      calls.push_back(parsed);
    }
  }
  return calls;
}

std::vector<json> ok_reference_cases(const std::string& file) {
  std::ifstream in(std::string(CUTCALC_REFERENCE_DIR) + "/" + file);
  const json cases_file = json::parse(in);
  std::vector<json> cases;
  for (const json& c : cases_file.at("cases")) {
    if (c.at("expect").at("status") == 200) cases.push_back(c);
  }
  return cases;
}

json request_with_program(const json& reference, const std::string& dialect,
                          const std::string& units, std::optional<int> decimals) {
  json request = reference.at("request");
  json program = request.value("program", json::object());
  program["dialect"] = dialect;
  program["units"] = units;
  if (dialect != "fanuc") program.erase("program_number");
  if (dialect == "sinumerik" && program.value("work_offset", "G54") > "G57") {
    program["work_offset"] = "G54";
  }
  if (decimals) program["decimals"] = *decimals;
  request["program"] = program;
  return request;
}

LatheRun write_and_run(api::JsonHandler handler, const json& request, const std::string& dialect) {
  LatheRun out;
  auto outcome = handler(request);
  auto* both = std::get_if<api::JsonWithText>(&outcome);
  if (both != nullptr) api::write_whole(*both);
  if (both == nullptr) {
    ADD_FAILURE() << "no program for " << request.dump();
    return out;
  }
  out.body = both->json;
  EXPECT_EQ(both->json.at("program"), both->text);
  cutcalc::testing::expect_text_rules(both->text, dialect);
  out.linuxcnc = translate_to_linuxcnc(both->text, dialect);
  const Rs274Run run = run_rs274_with_tools(out.linuxcnc, turret_tool_table());
  EXPECT_TRUE(run.started) << run.spawn_error;
  EXPECT_EQ(run.exit_code, 0) << run.errors << "\n" << out.linuxcnc;
  out.canon = canon_calls(run.output);
  out.ok = run.started && run.exit_code == 0;
  return out;
}

void expect_same_motion(const LatheRun& reference, const LatheRun& other, double tolerance) {
  ASSERT_FALSE(reference.canon.empty());
  ASSERT_EQ(other.canon.size(), reference.canon.size());
  for (std::size_t i = 0; i < other.canon.size(); ++i) {
    const CanonCall& a = reference.canon[i];
    const CanonCall& b = other.canon[i];
    ASSERT_EQ(a.name, b.name) << i;
    ASSERT_EQ(a.args.size(), b.args.size()) << a.name << " #" << i;
    for (std::size_t k = 0; k < a.args.size(); ++k) {
      EXPECT_NEAR(a.args[k], b.args[k], tolerance) << a.name << " #" << i << " arg " << k;
    }
  }
}

}  // namespace cutcalc::test::gcode
