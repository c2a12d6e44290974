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

const char* position_name(domain::entry::SchemePositionKind kind) {
  using domain::entry::SchemePositionKind;
  switch (kind) {
    case SchemePositionKind::start:
      return "start";
    case SchemePositionKind::first_contact:
      return "first_contact";
    case SchemePositionKind::saturation:
      return "saturation";
    case SchemePositionKind::end:
      return "end";
  }
  return "start";
}

nlohmann::json to_json(const std::vector<domain::entry::Position>& points) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& point : points) {
    out.push_back(entry::to_json(point));
  }
  return out;
}

nlohmann::json to_json(const domain::entry::LateralRange& range) {
  return {{"y_min_mm", range.y_min_mm}, {"y_max_mm", range.y_max_mm}};
}

nlohmann::json to_json(const domain::entry::SchemeSide& side) {
  nlohmann::json positions = nlohmann::json::array();
  for (const auto& position : side.positions) {
    positions.push_back({{"name", position_name(position.kind)},
                         {"x_mm", position.axis.x_mm},
                         {"y_mm", position.axis.y_mm}});
  }
  return {{"contour", to_json(side.contour)},
          {"workpiece_outline", to_json(side.workpiece_outline)},
          {"strip", to_json(side.strip)},
          {"band", to_json(side.band)},
          {"positions", std::move(positions)}};
}

}  // namespace

nlohmann::json to_json(const domain::entry::EntryScheme& scheme) {
  nlohmann::json out = {{"cutter_radius_mm", scheme.cutter_radius_mm},
                        {"entry", to_json(scheme.entry)}};
  if (scheme.exit) {
    out["exit"] = to_json(*scheme.exit);
  }
  return out;
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
