// Random valid-shaped requests with extreme numbers through the whole handler pipeline (parse ->
// validate -> domain -> serialise): every answer is 200 or 422, never a 500, a NaN, an infinity
// or a negative length, and every answer matches openapi.yaml.

#include <gtest/gtest.h>

#include <array>
#include <random>
#include <string>

#include "api/entry/entry_length_endpoint.h"
#include "api/entry/main_time_endpoint.h"
#include "api/json_endpoint.h"
#include "support/sanity_checks.h"

namespace cutcalc::api {
namespace {

using nlohmann::json;

class ExtremeNumbers {
 public:
  explicit ExtremeNumbers(std::uint64_t seed) : engine_(seed) {}

  double any() {
    static constexpr std::array<double, 16> kSpecial = {
        0.0,  -0.0, 1e-300,  1e-9,  0.001,      0.5, 1.0,  2.0,
        45.0, 90.0, 179.999, 180.0, 999999.999, 1e6, -1e6, 1e300};
    std::uniform_int_distribution<int> pick(0, 3);
    switch (pick(engine_)) {
      case 0:
        return kSpecial[std::uniform_int_distribution<std::size_t>(0,
                                                                   kSpecial.size() - 1)(engine_)];
      case 1:
        return std::uniform_real_distribution<double>(-200.0, 200.0)(engine_);
      case 2:
        return std::uniform_real_distribution<double>(0.0, 100.0)(engine_);
      default:
        return std::pow(10.0, std::uniform_real_distribution<double>(-12.0, 6.0)(engine_));
    }
  }

  json contour(bool exit) {
    static constexpr std::array<const char*, 4> kKinds = {"straight", "convex_arc", "concave_arc",
                                                          "wall"};
    const char* kind = kKinds[std::uniform_int_distribution<std::size_t>(0, exit ? 3 : 2)(engine_)];
    json out = {{"contour", kind}, {"width_mm", any()}};
    if (std::string(kind) == "straight" && coin()) {
      out["angle_deg"] = any();
    }
    if (std::string(kind).find("arc") != std::string::npos) {
      out["radius_mm"] = any();
      if (std::string(kind) == "convex_arc" && coin()) {
        out.erase("width_mm");
      }
    }
    return out;
  }

  bool coin() { return std::uniform_int_distribution<int>(0, 1)(engine_) == 1; }

 private:
  std::mt19937_64 engine_;
};

void check(const char* path, JsonHandler handler, const json& request, int& answered) {
  if (testing::expect_sane_answer(path, handler, request) == 200) {
    ++answered;
  }
}

TEST(EntryRobustness, ExtremeEntryLengthRequestsAre200Or422WithFiniteNumbers) {
  ExtremeNumbers numbers(20261122);
  int answered = 0;
  for (int i = 0; i < 1500; ++i) {
    json request = {{"cutter_diameter_mm", numbers.any()}, {"entry", numbers.contour(false)}};
    if (numbers.coin()) {
      request["offset_mm"] = numbers.any();
    }
    if (numbers.coin()) {
      request["exit"] = numbers.contour(true);
      request["length_mm"] = numbers.any();
    }
    check("/v1/entry-length", &entry::handle_entry_length, request, answered);
    if (HasFailure()) {
      return;
    }
  }
  EXPECT_GT(answered, 50) << "too few requests were answered to exercise the domain";
}

// A main-time request that the domain can answer, with one field then replaced by an extreme.
json plausible_main_time(ExtremeNumbers& numbers, std::mt19937_64& engine) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double diameter = 1.0 + 99.0 * unit(engine);
  const double width = 2.0 + 198.0 * unit(engine);
  const double cut = std::min(diameter, width) * (0.2 + 0.8 * unit(engine));
  const bool one_pass = numbers.coin();
  json request = {{"cutter_diameter_mm", diameter},
                  {"teeth", 4},
                  {"spindle_speed_rpm", 1000.0 * (0.1 + unit(engine))},
                  {"feed_per_tooth_mm", 0.01 + 0.2 * unit(engine)},
                  {"length_mm", 50.0 + 500.0 * unit(engine)},
                  {"entry", {{"contour", "straight"}, {"width_mm", width}}},
                  {"exit", {{"contour", "straight"}, {"width_mm", width}}},
                  {"allowance",
                   {{"width_mm", one_pass ? cut : width},
                    {"width_of_cut_mm", cut},
                    {"depth_mm", 5.0 * unit(engine) + 0.1},
                    {"depth_of_cut_mm", 0.5 + unit(engine)}}}};
  static constexpr std::array<const char*, 6> kTargets = {"cutter_diameter_mm", "feed_per_tooth_mm",
                                                          "length_mm",          "spindle_speed_rpm",
                                                          "approach_mm",        "overrun_mm"};
  const char* target = kTargets[std::uniform_int_distribution<std::size_t>(0, 5)(engine)];
  request[target] = numbers.any();
  if (numbers.coin()) {
    request["entry"]["angle_deg"] = numbers.any();
  }
  if (numbers.coin()) {
    request["allowance"]["depth_of_cut_mm"] = numbers.any();
  }
  return request;
}

TEST(EntryRobustness, ExtremeMainTimeRequestsAre200Or422WithFiniteNumbers) {
  ExtremeNumbers numbers(42);
  std::mt19937_64 engine(7);
  int answered = 0;
  for (int i = 0; i < 1500; ++i) {
    const json request = plausible_main_time(numbers, engine);
    check("/v1/main-time", &entry::handle_main_time, request, answered);
    if (HasFailure()) {
      return;
    }
  }
  EXPECT_GT(answered, 200) << "too few requests were answered to exercise the domain";
}

}  // namespace
}  // namespace cutcalc::api
