// Broken and extreme roughness requests: the right 4xx and pointer, never a 500, a NaN or an
// infinity.

#include <gtest/gtest.h>

#include <array>
#include <random>

#include "api/roughness/bore_milling_endpoint.h"
#include "api/roughness/groove_wall_endpoint.h"
#include "support/reference_compare.h"
#include "support/sanity_checks.h"
#include "support/test_server.h"

namespace cutcalc::testing {
namespace {

using nlohmann::json;

TEST(GrooveWallBadInput, EveryFieldErrorIsListedWithItsPointer) {
  const JsonReply reply = post("/v1/roughness/groove-wall",
                               R"({"feed_mm": 0, "nose_radius_mm": "0.3",
                                   "minor_edge_angle_deg": 90, "target_rz_um": -1, "extra": 1})");
  EXPECT_EQ(reply.status, 422);
  for (const char* pointer :
       {"/feed_mm", "/nose_radius_mm", "/minor_edge_angle_deg", "/target_rz_um", "/extra"}) {
    EXPECT_TRUE(problem_names_pointer(reply.json, pointer)) << pointer << ": " << reply.body;
  }
}

TEST(BoreMillingBadInput, EveryFieldErrorIsListedWithItsPointer) {
  const JsonReply reply = post("/v1/roughness/bore-milling",
                               R"({"bore_radius_mm": -81, "cutter_radius_mm": null, "teeth": 2.5,
                                   "feed_per_rev_mm": 1e400, "milling": 1})");
  EXPECT_EQ(reply.status, 422) << reply.body;
  // 1e400 stops the parser at its field: the overflow is reported where it stands.
  EXPECT_TRUE(problem_names_pointer(reply.json, "/feed_per_rev_mm")) << reply.body;
  const JsonReply rest = post("/v1/roughness/bore-milling",
                              R"({"bore_radius_mm": -81, "cutter_radius_mm": null, "teeth": 2.5,
                                  "feed_per_rev_mm": 0.2, "milling": 1})");
  for (const char* pointer : {"/bore_radius_mm", "/cutter_radius_mm", "/teeth", "/milling"}) {
    EXPECT_TRUE(problem_names_pointer(rest.json, pointer)) << pointer << ": " << rest.body;
  }
}

TEST(RoughnessBadInput, RandomExtremeRequestsAreAnsweredSanely) {
  std::mt19937_64 engine(7);
  static constexpr std::array<double, 11> kExtremes = {0.0,   1e-300, 1e-9, 0.2,  1.0,  30.0,
                                                       89.99, 90.0,   1e6,  -1.0, 1e300};
  const auto any = [&engine] {
    if (std::uniform_int_distribution<int>(0, 2)(engine) == 0) {
      return kExtremes[std::uniform_int_distribution<std::size_t>(0, kExtremes.size() - 1)(engine)];
    }
    return std::pow(10.0, std::uniform_real_distribution<double>(-6.0, 3.0)(engine));
  };
  int groove_answered = 0;
  int bore_answered = 0;
  for (int i = 0; i < 1500 && !HasFailure(); ++i) {
    json groove = {
        {"feed_mm", any()},
        {"nose_radius_mm", any()},
        {"minor_edge_angle_deg", std::uniform_real_distribution<double>(0.0, 89.999)(engine)}};
    if (i % 2 == 0) {
      groove["target_rz_um"] = any();
    }
    if (expect_sane_answer("/v1/roughness/groove-wall", &api::roughness::handle_groove_wall,
                           groove) == 200) {
      ++groove_answered;
    }
    const double bore = any();
    json milling = {
        {"bore_radius_mm", bore},
        {"cutter_radius_mm", bore * std::uniform_real_distribution<double>(0.0, 1.1)(engine)},
        {"teeth", std::uniform_int_distribution<int>(1, 12)(engine)},
        {"feed_per_rev_mm", any()},
        {"milling", i % 3 == 0 ? "down" : "up"}};
    if (expect_sane_answer("/v1/roughness/bore-milling", &api::roughness::handle_bore_milling,
                           milling) == 200) {
      ++bore_answered;
    }
  }
  EXPECT_GT(groove_answered, 300);
  EXPECT_GT(bore_answered, 300);
}

}  // namespace
}  // namespace cutcalc::testing
