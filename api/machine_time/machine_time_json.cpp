#include "api/machine_time/machine_time_json.h"

#include <string>

#include "api/program/program_reader.h"

namespace cutcalc::api::machine_time {
namespace {

namespace mt = domain::machine_time;

constexpr double kSecondsPerMinute = 60.0;

double minutes(double seconds) { return seconds / kSecondsPerMinute; }

ErrorCode code_of(mt::Refusal refusal) {
  switch (refusal) {
    case mt::Refusal::parameter:
      return ErrorCode::gcode_parameter;
    case mt::Refusal::expression:
      return ErrorCode::gcode_expression;
    case mt::Refusal::subroutine_or_loop:
      return ErrorCode::gcode_subroutine;
    case mt::Refusal::cutter_compensation:
      return ErrorCode::gcode_cutter_compensation;
    case mt::Refusal::canned_cycle:
      return ErrorCode::gcode_canned_cycle;
    case mt::Refusal::unsupported_word:
      return ErrorCode::gcode_unsupported_word;
    case mt::Refusal::malformed:
      return ErrorCode::gcode_malformed;
    case mt::Refusal::arc_geometry:
      return ErrorCode::gcode_arc_geometry;
    case mt::Refusal::missing_feed:
      return ErrorCode::gcode_missing_feed;
  }
  return ErrorCode::gcode_unsupported_word;
}

}  // namespace

nlohmann::json to_json(const mt::ProgramTime& time) {
  nlohmann::json out = nlohmann::json::object();
  out["estimated_time_min"] = minutes(time.estimated_s);
  out["nominal_time_min"] = minutes(time.nominal_s);
  out["feed_time_min"] = minutes(time.feed_s);
  out["rapid_time_min"] = minutes(time.rapid_s);
  out["dwell_time_min"] = minutes(time.dwell_s);
  out["dynamics_time_min"] = minutes(time.estimated_s - time.nominal_s);
  out["blocks"] = time.blocks;
  out["moves"] = time.moves;
  out["feed_length_mm"] = time.feed_length_mm;
  out["rapid_length_mm"] = time.rapid_length_mm;
  out["rotary_deg"] = time.rotary_deg;
  nlohmann::json slowest = nlohmann::json::array();
  for (const mt::SlowBlock& block : time.slowest_blocks) {
    nlohmann::json row = nlohmann::json::object();
    row["line"] = block.line;
    row["lost_min"] = minutes(block.lost_s);
    row["limited_by"] = mt::limit_name(block.limited_by);
    slowest.push_back(std::move(row));
  }
  out["slowest_blocks"] = std::move(slowest);
  out["warnings"] = program::to_json(time.warnings);
  if (!time.profile.empty()) {
    nlohmann::json profile = nlohmann::json::array();
    for (const mt::ProfilePoint& point : time.profile) {
      nlohmann::json row = nlohmann::json::object();
      row["t_min"] = minutes(point.t_s);
      row["velocity_mm_per_min"] = point.velocity_per_s * kSecondsPerMinute;
      profile.push_back(std::move(row));
    }
    out["profile"] = std::move(profile);
  }
  return out;
}

Problem to_problem(const mt::ReadError& error, const std::string& program_pointer) {
  nlohmann::json params = nlohmann::json::object();
  params["line"] = error.line;
  params["column"] = error.column;
  params["word"] = error.word;
  return invalid_input({{program_pointer, code_of(error.refusal), std::move(params)}});
}

Problem to_problem(const mt::AxisNotDescribed& missing) {
  nlohmann::json params = nlohmann::json::object();
  params["axis"] = std::string(1, mt::axis_letter(missing.axis));
  params["line"] = missing.line;
  return invalid_input({{"/machine/axes", ErrorCode::axis_not_described, std::move(params)}});
}

}  // namespace cutcalc::api::machine_time
