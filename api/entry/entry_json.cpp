#include "api/entry/entry_json.h"

namespace cutcalc::api::entry {

nlohmann::json to_json(const domain::entry::Position& position) {
  return {{"x_mm", position.x_mm}, {"y_mm", position.y_mm}};
}

nlohmann::json to_json(const domain::entry::EntryLengthResult& result) {
  nlohmann::json body = {{"engagement_length_mm", result.engagement_length_mm},
                         {"entry_length_mm", result.entry_length_mm},
                         {"start", to_json(result.start)},
                         {"steady_width_mm", result.steady_width_mm}};
  if (result.exit) {
    body["end"] = to_json(result.exit->end);
    body["working_stroke_mm"] = result.exit->working_stroke_mm;
  }
  return body;
}

namespace {

nlohmann::json to_json(const domain::entry::LateralPass& pass) {
  return {{"width_mm", pass.width_mm},
          {"axis_y_mm", pass.axis_y_mm},
          {"offset_mm", pass.offset_mm},
          {"strip_width_mm", pass.strip_width_mm},
          {"engagement_length_mm", pass.engagement_length_mm},
          {"entry_length_mm", pass.entry_length_mm},
          {"start", entry::to_json(pass.start)},
          {"end", entry::to_json(pass.end)},
          {"working_stroke_mm", pass.working_stroke_mm},
          {"entry_time_min", pass.entry_time_min},
          {"steady_time_min", pass.steady_time_min},
          {"time_min", pass.time_min}};
}

}  // namespace

nlohmann::json to_json(const domain::entry::MainTimeResult& result) {
  nlohmann::json passes = nlohmann::json::array();
  for (const auto& pass : result.lateral_passes) {
    passes.push_back(to_json(pass));
  }
  return {{"spindle_speed_rpm", result.spindle_speed_rpm},
          {"feed_per_rev_mm", result.feed_per_rev_mm},
          {"feed_mm_per_min", result.feed_mm_per_min},
          {"entry_feed_mm_per_min", result.entry_feed_mm_per_min},
          {"depth_passes_mm", result.depth_passes_mm},
          {"lateral_passes", std::move(passes)},
          {"main_time_min", result.main_time_min},
          {"entry_time_min", result.entry_time_min},
          {"steady_time_min", result.steady_time_min}};
}

}  // namespace cutcalc::api::entry
