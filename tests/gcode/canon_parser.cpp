#include "gcode/canon_parser.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>

namespace cutcalc::test::gcode {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

struct Command {
  std::string_view name;
  std::string_view args;  // between the parentheses
};

// `   24 N..... NAME(args)`: the identifier just before the first '(' and the text up to the last
// ')'. Lines without one (rs274's banner, blank lines) give nothing.
std::optional<Command> split_command(std::string_view line) {
  const auto open = line.find('(');
  const auto close = line.rfind(')');
  if (open == std::string_view::npos || close == std::string_view::npos || close < open) {
    return std::nullopt;
  }
  std::size_t begin = open;
  while (begin > 0 && (std::isalnum(static_cast<unsigned char>(line[begin - 1])) != 0 ||
                       line[begin - 1] == '_')) {
    --begin;
  }
  if (begin == open) return std::nullopt;
  return Command{line.substr(begin, open - begin), line.substr(open + 1, close - open - 1)};
}

// Comma-separated numbers; nullopt if any field is not a number.
std::optional<std::vector<double>> numbers(std::string_view args) {
  std::vector<double> values;
  while (true) {
    const auto comma = args.find(',');
    const std::string_view field = trim(args.substr(0, comma));
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (ec != std::errc() || ptr != field.data() + field.size()) return std::nullopt;
    values.push_back(value);
    if (comma == std::string_view::npos) break;
    args.remove_prefix(comma + 1);
  }
  return values;
}

}  // namespace

std::vector<CanonMotion> CanonProgram::arcs() const {
  std::vector<CanonMotion> result;
  for (const auto& motion : motions) {
    if (motion.kind == MotionKind::arc) result.push_back(motion);
  }
  return result;
}

CanonProgram parse_canon(std::string_view output) {
  CanonProgram program;
  CanonPose position;  // canonical (machine) coordinates
  CanonPose g5x;       // SET_G5X_OFFSET
  CanonPose g92;       // SET_G92_OFFSET
  double feed_rate = 0.0;
  int feed_mode = 0;
  int line_number = 0;

  const auto to_program = [&](const CanonPose& p) {
    return CanonPose{p.x - g5x.x - g92.x, p.y - g5x.y - g92.y, p.z - g5x.z - g92.z,
                     p.a - g5x.a - g92.a, p.b - g5x.b - g92.b, p.c - g5x.c - g92.c};
  };
  const auto problem = [&](const std::string& what) {
    std::ostringstream text;
    text << "line " << line_number << ": " << what;
    program.problems.push_back(text.str());
  };

  std::size_t pos = 0;
  while (pos <= output.size()) {
    const auto eol = output.find('\n', pos);
    const std::string_view line =
        output.substr(pos, eol == std::string_view::npos ? std::string_view::npos : eol - pos);
    pos = (eol == std::string_view::npos) ? output.size() + 1 : eol + 1;
    ++line_number;
    const auto command = split_command(line);
    if (!command) continue;
    const std::string_view name = command->name;
    if (name == "COMMENT" || name == "MESSAGE") continue;

    if (name == "PROGRAM_END") {
      program.program_end = true;
      continue;
    }
    if (name == "SELECT_PLANE") {
      if (trim(command->args) != "CANON_PLANE_XY") problem("plane is not XY");
      continue;
    }
    if (name == "USE_LENGTH_UNITS") {
      if (trim(command->args) != "CANON_UNITS_MM") problem("units are not mm");
      continue;
    }

    const auto values = numbers(command->args);
    const bool moves = name == "STRAIGHT_TRAVERSE" || name == "STRAIGHT_FEED" || name == "ARC_FEED";
    if (!values) {
      if (moves) problem("unreadable arguments of " + std::string(name));
      continue;
    }
    const std::vector<double>& v = *values;

    if (name == "SET_FEED_RATE" && v.size() == 1) {
      feed_rate = v[0];
    } else if (name == "SET_FEED_MODE" && !v.empty()) {
      feed_mode = static_cast<int>(v.back());  // (spindle, mode) or (mode)
    } else if (name == "SET_XY_ROTATION" && v.size() == 1) {
      if (v[0] != 0.0) problem("XY rotation is not handled");
    } else if ((name == "SET_G5X_OFFSET" && v.size() >= 7) ||
               (name == "SET_G92_OFFSET" && v.size() >= 6)) {
      const std::size_t k = name == "SET_G5X_OFFSET" ? 1 : 0;  // G5X starts with the index
      CanonPose& offset = name == "SET_G5X_OFFSET" ? g5x : g92;
      offset = {v[k], v[k + 1], v[k + 2], v[k + 3], v[k + 4], v[k + 5]};
    } else if ((name == "STRAIGHT_TRAVERSE" || name == "STRAIGHT_FEED") && v.size() >= 6) {
      CanonMotion motion;
      motion.kind = name == "STRAIGHT_FEED" ? MotionKind::feed : MotionKind::traverse;
      motion.output_line = line_number;
      motion.start = to_program(position);
      position = {v[0], v[1], v[2], v[3], v[4], v[5]};
      motion.end = to_program(position);
      motion.feed_rate = feed_rate;
      motion.feed_mode = feed_mode;
      program.motions.push_back(motion);
    } else if (name == "ARC_FEED" && v.size() >= 9) {
      // ARC_FEED(first_end, second_end, first_axis, second_axis, rotation, axis_end, a, b, c, ...)
      CanonMotion motion;
      motion.kind = MotionKind::arc;
      motion.output_line = line_number;
      motion.start = to_program(position);
      position = {v[0], v[1], v[5], v[6], v[7], v[8]};
      motion.end = to_program(position);
      motion.centre = {v[2] - g5x.x - g92.x, v[3] - g5x.y - g92.y};
      motion.turn = static_cast<int>(v[4]);
      motion.feed_rate = feed_rate;
      motion.feed_mode = feed_mode;
      program.motions.push_back(motion);
    } else if (moves) {
      problem("too few arguments of " + std::string(name));
    }
  }
  return program;
}

ArcGeometry arc_geometry(const CanonMotion& arc) {
  ArcGeometry g;
  g.centre = arc.centre;
  const Vec2 from = arc.start.xy() - arc.centre;
  const Vec2 to = arc.end.xy() - arc.centre;
  g.start_radius = norm(from);
  g.end_radius = norm(to);
  g.start_angle = std::atan2(from.y, from.x);
  const double end_angle = std::atan2(to.y, to.x);
  const int extra_turns = arc.turn == 0 ? 0 : std::abs(arc.turn) - 1;
  if (arc.turn >= 0) {
    double sweep = end_angle - g.start_angle;
    while (sweep <= 0.0) sweep += 2.0 * std::numbers::pi;  // end = start: a full circle
    while (sweep > 2.0 * std::numbers::pi) sweep -= 2.0 * std::numbers::pi;
    g.sweep = sweep + 2.0 * std::numbers::pi * extra_turns;
  } else {
    double sweep = g.start_angle - end_angle;
    while (sweep <= 0.0) sweep += 2.0 * std::numbers::pi;
    while (sweep > 2.0 * std::numbers::pi) sweep -= 2.0 * std::numbers::pi;
    g.sweep = -(sweep + 2.0 * std::numbers::pi * extra_turns);
  }
  g.start_z = arc.start.z;
  g.end_z = arc.end.z;
  return g;
}

Vec2 arc_point(const ArcGeometry& arc, double f) {
  const double radius = arc.start_radius + f * (arc.end_radius - arc.start_radius);
  return arc.centre + radius * unit_at(arc.start_angle + f * arc.sweep);
}

double arc_length_xy(const ArcGeometry& arc) {
  return std::abs(arc.sweep) * (arc.start_radius + arc.end_radius) / 2.0;
}

Vec2 circle_tangent_at_start(const ArcGeometry& arc) {
  const Vec2 radial = unit_at(arc.start_angle);
  return arc.sweep >= 0.0 ? left_normal(radial) : -1.0 * left_normal(radial);
}

Vec2 circle_tangent_at_end(const ArcGeometry& arc) {
  const Vec2 radial = unit_at(arc.start_angle + arc.sweep);
  return arc.sweep >= 0.0 ? left_normal(radial) : -1.0 * left_normal(radial);
}

Vec2 spiral_tangent(const ArcGeometry& arc, double f) {
  const double angle = arc.start_angle + f * arc.sweep;
  const double radius = arc.start_radius + f * (arc.end_radius - arc.start_radius);
  const Vec2 d = (arc.end_radius - arc.start_radius) * unit_at(angle) +
                 (radius * arc.sweep) * left_normal(unit_at(angle));
  return (1.0 / norm(d)) * d;
}

}  // namespace cutcalc::test::gcode
