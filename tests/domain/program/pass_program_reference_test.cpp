// The pass program in the domain (spec programs.md section 1), on the public reference cases of
// main-time-program.json: every case expecting 200 gives the reference's times (G8-G11, to the
// file's tolerance), passes, file name and warning codes; the extra-path case is refused. The
// requests are turned into domain parameters here, independently of api/.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "domain/entry/main_time.h"
#include "domain/program/pass_program.h"

namespace {

namespace entry = cutcalc::domain::entry;
namespace program = cutcalc::domain::program;
using nlohmann::json;

entry::Contour contour_of(const json& c) {
  entry::Contour out;
  const std::string kind = c.at("contour");
  out.kind = kind == "convex_arc"    ? entry::ContourKind::convex_arc
             : kind == "concave_arc" ? entry::ContourKind::concave_arc
             : kind == "wall"        ? entry::ContourKind::wall
                                     : entry::ContourKind::straight;
  if (c.contains("width_mm")) out.width_mm = c.at("width_mm").get<double>();
  out.radius_mm = c.value("radius_mm", 0.0);
  out.angle_deg = c.value("angle_deg", 90.0);
  return out;
}

entry::MainTimeParams params_of(const json& r) {
  entry::MainTimeParams p;
  p.cutter_diameter_mm = r.at("cutter_diameter_mm");
  p.teeth = r.at("teeth");
  if (r.contains("spindle_speed_rpm")) {
    p.speed = entry::SpindleSpeed{r.at("spindle_speed_rpm").get<double>()};
  } else {
    p.speed = entry::CuttingSpeed{r.at("cutting_speed_m_per_min").get<double>()};
  }
  p.feed_per_tooth_mm = r.at("feed_per_tooth_mm");
  if (r.contains("entry_feed_per_tooth_mm")) {
    p.entry_feed = entry::EntryFeedPerTooth{r.at("entry_feed_per_tooth_mm").get<double>()};
  } else {
    p.entry_feed = entry::EntryFeedFactor{r.value("entry_feed_factor", 0.5)};
  }
  p.length_mm = r.at("length_mm");
  p.extra_path_mm = r.value("extra_path_mm", 0.0);
  p.approach_mm = r.value("approach_mm", 2.0);
  p.overrun_mm = r.value("overrun_mm", 2.0);
  p.entry = contour_of(r.at("entry"));
  p.exit = contour_of(r.at("exit"));
  if (r.contains("offset_mm")) p.offset_mm = r.at("offset_mm").get<double>();
  const json& a = r.at("allowance");
  p.allowance = {a.at("width_mm"), a.at("width_of_cut_mm"), a.at("depth_mm"),
                 a.at("depth_of_cut_mm")};
  return p;
}

program::ProgramOptions options_of(const json& r) {
  program::ProgramOptions o;
  const json p = r.value("program", json::object());
  const std::string dialect = p.value("dialect", "linuxcnc");
  o.dialect = dialect == "fanuc"       ? program::Dialect::fanuc
              : dialect == "sinumerik" ? program::Dialect::sinumerik
                                       : program::Dialect::linuxcnc;
  o.units = p.value("units", "mm") == "inch" ? program::Units::inch : program::Units::mm;
  if (p.contains("decimals")) o.decimals = p.at("decimals").get<int>();
  o.program_number = p.value("program_number", 1);
  o.name = p.value("name", "CUTCALC");
  if (p.contains("tool_number")) o.tool_number = p.at("tool_number").get<int>();
  o.tool_length_offset = p.value("tool_length_offset", false);
  o.work_offset = std::stoi(p.value("work_offset", "G54").substr(1));
  const std::string coolant = p.value("coolant", "off");
  o.coolant = coolant == "flood"  ? program::Coolant::flood
              : coolant == "mist" ? program::Coolant::mist
                                  : program::Coolant::off;
  o.safe_z_mm = p.value("safe_z_mm", 10.0);
  o.clearance_mm = p.value("clearance_mm", 2.0);
  if (p.contains("plunge_feed_mm_per_min")) {
    o.plunge_feed_mm_per_min = p.at("plunge_feed_mm_per_min").get<double>();
  }
  o.rapid_mm_per_min = p.value("rapid_mm_per_min", 10000.0);
  return o;
}

program::MachineLimits limits_of(const json& r) {
  program::MachineLimits limits;
  const json m = r.value("machine", json::object());
  if (m.contains("max_spindle_rpm")) limits.max_spindle_rpm = m.at("max_spindle_rpm").get<double>();
  if (m.contains("max_feed_mm_per_min")) {
    limits.max_feed_mm_per_min = m.at("max_feed_mm_per_min").get<double>();
  }
  return limits;
}

json reference_file() {
  std::ifstream in(std::string(CUTCALC_REFERENCE_DIR) + "/main-time-program.json");
  return json::parse(in);
}

TEST(PassProgramReference, EveryCaseExpecting200HasTheReferencesTimesPassesAndName) {
  int checked = 0;
  const json file = reference_file();
  for (const json& c : file.at("cases")) {
    if (c.at("expect").at("status") != 200) continue;
    SCOPED_TRACE(c.at("id").get<std::string>());
    const json& r = c.at("request");
    const json& want = c.at("expect").at("body");
    const auto params = params_of(r);
    const auto main_time = entry::compute_main_time(params);
    ASSERT_TRUE(main_time.ok()) << main_time.error().detail;
    const auto written =
        program::write_pass_program(params, main_time.value(), options_of(r), limits_of(r));
    ASSERT_TRUE(written.ok()) << written.error().detail;
    const program::PassProgram& got = written.value();
    const double abs_min = c.at("tolerance").value("abs_min", 1e-9);
    const double rel = c.at("tolerance").value("rel", 1e-9);
    const auto near = [&](double actual, const char* key) {
      const double expected = want.at(key).get<double>();
      EXPECT_NEAR(actual, expected, std::max(abs_min, rel * std::fabs(expected))) << key;
    };
    near(main_time.value().main_time_min, "main_time_min");
    near(got.working_time_min, "working_time_min");
    near(got.plunge_time_min, "plunge_time_min");
    near(got.rapid_time_min, "rapid_time_min");
    near(got.cycle_time_min, "cycle_time_min");
    EXPECT_EQ(got.passes, want.at("passes").get<int>());
    // Written as it is read, in pieces as small as a byte: the whole text, block by block.
    const std::string whole = program::program_text(got);
    for (const std::size_t piece : {std::size_t{0}, std::size_t{1}, std::size_t{100}}) {
      const auto source = program::open_program_text(got);
      EXPECT_GT(source->held_bytes(), 0U);
      std::string text;
      std::size_t calls = 0;
      while (source->write_next(text, piece)) ++calls;
      EXPECT_EQ(text, whole) << piece;
      if (piece <= 1) {
        EXPECT_EQ(calls, got.model->blocks.size()) << piece;  // a block a piece
      }
      EXPECT_FALSE(source->write_next(text, piece));  // ended: nothing more
      EXPECT_EQ(text.size(), whole.size());
    }
    EXPECT_EQ(got.file_name, want.at("file_name").get<std::string>());
    if (c.at("expect").contains("warning_codes")) {
      std::multiset<std::string> codes;
      for (const auto& w : got.warnings) codes.insert(std::string(program::warning_name(w.code)));
      EXPECT_EQ(codes, c.at("expect").at("warning_codes").get<std::multiset<std::string>>());
    }
    ++checked;
  }
  EXPECT_GE(checked, 14);
}

}  // namespace
