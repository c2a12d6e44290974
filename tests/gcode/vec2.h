#pragma once
// A plane vector for the G-code checker (kept apart from the domain's types on purpose).

#include <cmath>

namespace cutcalc::test::gcode {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;
};

inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
inline double norm(Vec2 a) { return std::hypot(a.x, a.y); }
inline Vec2 unit_at(double angle) { return {std::cos(angle), std::sin(angle)}; }
inline Vec2 left_normal(Vec2 a) { return {-a.y, a.x}; }  // a turned by +90 degrees
// Angle from a to b in (-pi, pi].
inline double angle_between(Vec2 a, Vec2 b) { return std::atan2(cross(a, b), dot(a, b)); }

}  // namespace cutcalc::test::gcode
