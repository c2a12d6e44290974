// Every 200 case of shared/reference/polygon-hole.json through the domain function: expect.body
// within tolerance.abs + tolerance.rel |want|, expect.max / expect.min bounds, the warning codes,
// and the program checks loops, layers, z_min, g95_flat_F, g94_F and last_C (rs274 itself is run
// by the LinuxCNC checker in tests/gcode). The 422 cases are request validation (api layer).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "polygon_test_support.h"

namespace {

using cutcalc::domain::polygon::predicted_overcut_mm;
using cutcalc::test::polygon::arc_lines;
using cutcalc::test::polygon::Line;
using cutcalc::test::polygon::parse_program;
using cutcalc::test::polygon::PolygonHoleParams;
using cutcalc::test::polygon::PolygonHoleResult;
using cutcalc::test::polygon::Synchronization;
using nlohmann::json;

json load_cases() {
  std::ifstream in(std::string(CUTCALC_REFERENCE_DIR) + "/polygon-hole.json");
  EXPECT_TRUE(in.good()) << "cannot read " << CUTCALC_REFERENCE_DIR << "/polygon-hole.json";
  return in.good() ? json::parse(in) : json::object();
}

PolygonHoleParams params_from(const json& request) {
  PolygonHoleParams p;
  p.faces = request.at("faces").get<int>();
  p.inscribed_diameter_mm = request.at("inscribed_diameter_mm").get<double>();
  p.depth_mm = request.at("depth_mm").get<double>();
  p.step_down_mm = request.at("step_down_mm").get<double>();
  p.spindle_speed_rpm = request.at("spindle_speed_rpm").get<double>();
  p.tolerance_mm = request.value("tolerance_mm", 0.001);
  p.synchronization = request.value("synchronization", std::string("feed_per_rev")) == "c_axis"
                          ? Synchronization::c_axis
                          : Synchronization::feed_per_rev;
  if (request.contains("loops_per_layer")) {
    p.loops_per_layer = request.at("loops_per_layer").get<int>();
  }
  p.safe_z_mm = request.value("safe_z_mm", 5.0);
  p.block_time_ms = request.value("block_time_ms", 2.0);
  return p;
}

std::optional<double> field(const PolygonHoleResult& r, const std::string& name) {
  if (name == "blocks_per_loop") return r.blocks_per_loop;
  if (name == "loop_length_mm") return r.loop_length_mm;
  if (name == "feed_per_rev_mm") return r.feed_per_rev_mm;
  if (name == "eccentricity_mm") return r.eccentricity_mm;
  if (name == "max_path_deviation_mm") return r.max_path_deviation_mm;
  if (name == "predicted_overcut_mm") return predicted_overcut_mm(r);
  if (name == "uncut_corner_area_mm2") return r.uncut_corner_area_mm2;
  if (name == "corner_gap_mm") return r.corner_gap_mm;
  if (name == "max_feed_by_block_rate_mm_per_min") return r.max_feed_by_block_rate_mm_per_min;
  return std::nullopt;
}

void check_program(const json& expect, const PolygonHoleParams& params,
                   const PolygonHoleResult& result) {
  const std::vector<Line> lines = parse_program(cutcalc::domain::polygon::program_text(result));
  const std::vector<Line> arcs = arc_lines(lines);
  ASSERT_GT(result.blocks_per_loop, 0);
  if (expect.contains("loops")) {
    EXPECT_EQ(arcs.size() % static_cast<std::size_t>(result.blocks_per_loop), 0U);
    EXPECT_EQ(static_cast<int>(arcs.size()) / result.blocks_per_loop, expect["loops"].get<int>());
  }
  std::optional<std::string> deepest;
  double deepest_value = 0.0;
  std::set<std::string> ramp_ends;
  for (std::size_t b = 0; b < arcs.size(); ++b) {
    if (const auto z = arcs[b].find('Z')) {
      if (z->number() < deepest_value) {
        deepest_value = z->number();
        deepest = z->value;
      }
      const bool loop_end = (b + 1) % static_cast<std::size_t>(result.blocks_per_loop) == 0;
      if (loop_end) {
        ramp_ends.insert(z->value);
      }
    }
  }
  if (expect.contains("layers")) {
    const int n = expect["layers"].get<int>();
    EXPECT_EQ(static_cast<int>(ramp_ends.size()), n);
    for (int k = 1; k <= n; ++k) {
      EXPECT_EQ(ramp_ends.count(cutcalc::test::polygon::four_decimals(-k * params.depth_mm / n)),
                1U)
          << "layer " << k;
    }
  }
  if (expect.contains("z_min")) {
    ASSERT_TRUE(deepest.has_value());
    EXPECT_EQ(*deepest, expect["z_min"].get<std::string>());
  }
  // F words: the modal F in force on every flat arc block (G95), the G94 F word (c_axis).
  std::string feed;
  std::set<std::string> flat_feeds;
  std::set<std::string> g94_feeds;
  for (const Line& line : lines) {
    if (line.comment || line.words.empty()) {
      continue;
    }
    if (const auto f = line.find('F')) {
      feed = f->value;
      if (line.words[0].value == "94") {
        g94_feeds.insert(f->value);
      }
    }
    if (line.is_arc() && !line.has('Z')) {
      flat_feeds.insert(feed);
    }
  }
  if (expect.contains("g95_flat_F")) {
    EXPECT_EQ(flat_feeds, std::set<std::string>{expect["g95_flat_F"].get<std::string>()});
  }
  if (expect.contains("g94_F")) {
    EXPECT_EQ(g94_feeds, std::set<std::string>{expect["g94_F"].get<std::string>()});
  }
  if (expect.contains("last_C")) {
    ASSERT_FALSE(arcs.empty());
    ASSERT_TRUE(arcs.back().has('C'));
    EXPECT_EQ(arcs.back().find('C')->value, expect["last_C"].get<std::string>());
  }
}

TEST(PolygonReference, EveryCaseOfTheReferenceFile) {
  const json file = load_cases();
  ASSERT_TRUE(file.contains("cases"));
  int checked = 0;
  for (const json& c : file["cases"]) {
    const json& expect = c["expect"];
    if (expect["status"].get<int>() != 200) {
      continue;
    }
    SCOPED_TRACE(c["id"].get<std::string>());
    const PolygonHoleParams params = params_from(c["request"]);
    const auto generated = cutcalc::domain::polygon::generate_polygon_hole(params);
    ASSERT_TRUE(generated.ok()) << generated.error().detail;
    const PolygonHoleResult& result = generated.value();
    const double abs_tol = c["tolerance"]["abs"].get<double>();
    const double rel_tol = c["tolerance"]["rel"].get<double>();
    for (const auto& [name, want] : expect["body"].items()) {
      const auto got = field(result, name);
      ASSERT_TRUE(got.has_value()) << name;
      EXPECT_NEAR(*got, want.get<double>(), abs_tol + rel_tol * std::abs(want.get<double>()))
          << name;
    }
    const json upper = expect.value("max", json::object());
    for (const auto& [name, bound] : upper.items()) {
      const auto got = field(result, name);
      ASSERT_TRUE(got.has_value()) << name;
      EXPECT_LE(*got, bound.get<double>()) << name;
    }
    const json lower = expect.value("min", json::object());
    for (const auto& [name, bound] : lower.items()) {
      const auto got = field(result, name);
      ASSERT_TRUE(got.has_value()) << name;
      EXPECT_GE(*got, bound.get<double>()) << name;
    }
    std::multiset<std::string> codes;
    for (const auto& warning : result.warnings) {
      codes.emplace(cutcalc::domain::program::warning_name(warning.code));
    }
    std::multiset<std::string> want_codes;
    for (const auto& code : expect["warning_codes"]) {
      want_codes.insert(code.get<std::string>());
    }
    EXPECT_EQ(codes, want_codes);
    if (expect.contains("program")) {
      check_program(expect["program"], params, result);
    }
    // info (not checked by the replay): the research values, printed with 6 significant digits.
    const json& info = c["info"];
    for (const auto& [got, name] :
         {std::pair{result.max_path_deviation_mm, "fit_deviation_mm"},
          std::pair{predicted_overcut_mm(result), "predicted_overcut_mm"},
          std::pair{result.max_feed_by_block_rate_mm_per_min, "max_feed_by_block_rate_mm_per_min"},
          std::pair{params.spindle_speed_rpm * result.feed_per_rev_mm,
                    "programmed_feed_mm_per_min"}}) {
      const double want = info[name].get<double>();
      EXPECT_NEAR(got, want, 5e-6 * std::abs(want) + 1e-10) << name;
    }
    ++checked;
  }
  EXPECT_EQ(checked, 7);
}

}  // namespace
