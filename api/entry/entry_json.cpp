#include "api/entry/entry_json.h"

#include "api/json_fields.h"

namespace cutcalc::api::entry {

nlohmann::json to_json(const domain::entry::Position& position) {
  nlohmann::json position_json = nlohmann::json::object();
  CUTCALC_JSON_FIELDS(position_json, position, x_mm, y_mm);
  return position_json;
}

namespace {

void write_position(JsonWriter& out, const domain::entry::Position& position) {
  out.begin_object();
  out.member("x_mm", position.x_mm);
  out.member("y_mm", position.y_mm);
  out.end_object();
}

}  // namespace

// Written straight to text (the hottest answer), members in key order.
JsonText entry_length_answer(const domain::entry::EntryLengthResult& result,
                             const nlohmann::json* scheme) {
  JsonWriter out;
  out.begin_object();
  if (result.exit) {
    out.key("end");
    write_position(out, result.exit->end);
  }
  out.member("engagement_length_mm", result.engagement_length_mm);
  out.member("entry_length_mm", result.entry_length_mm);
  if (scheme != nullptr) {
    out.key("scheme");
    out.document(*scheme);
  }
  out.key("start");
  write_position(out, result.start);
  out.member("steady_width_mm", result.steady_width_mm);
  if (result.exit) {
    out.member("working_stroke_mm", result.exit->working_stroke_mm);
  }
  out.end_object();
  return std::move(out).finish();
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
  nlohmann::json out = nlohmann::json::object();
  CUTCALC_JSON_FIELDS(out, pass, width_mm, axis_y_mm, offset_mm, strip_width_mm,
                      engagement_length_mm, entry_length_mm, working_stroke_mm, entry_time_min,
                      steady_time_min, time_min);
  out["start"] = entry::to_json(pass.start);
  out["end"] = entry::to_json(pass.end);
  return out;
}

nlohmann::json to_json(const domain::entry::FinishLevel& finish) {
  nlohmann::json passes = nlohmann::json::array();
  for (const auto& times : finish.lateral_passes) {
    passes.push_back({{"entry_time_min", times.entry_time_min},
                      {"steady_time_min", times.steady_time_min},
                      {"time_min", times.time_min}});
  }
  nlohmann::json out = nlohmann::json::object();
  CUTCALC_JSON_FIELDS(out, finish, depth_mm, spindle_speed_rpm, feed_per_rev_mm, feed_mm_per_min,
                      entry_feed_mm_per_min, entry_time_min, steady_time_min, time_min);
  out["lateral_passes"] = std::move(passes);
  return out;
}

}  // namespace

nlohmann::json to_json(const domain::entry::MainTimeResult& result) {
  nlohmann::json passes = nlohmann::json::array();
  for (const auto& pass : result.lateral_passes) {
    passes.push_back(to_json(pass));
  }
  nlohmann::json out = nlohmann::json::object();
  CUTCALC_JSON_FIELDS(out, result, spindle_speed_rpm, feed_per_rev_mm, feed_mm_per_min,
                      entry_feed_mm_per_min, depth_passes_mm, main_time_min, entry_time_min,
                      steady_time_min);
  out["lateral_passes"] = std::move(passes);
  if (result.finish) {
    out["finish"] = to_json(*result.finish);  // E39-E41, only with a finishing level
  }
  return out;
}

}  // namespace cutcalc::api::entry
