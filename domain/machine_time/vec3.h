#pragma once
// Three-vectors for the planner's path geometry (X, Y, Z in mm).

#include <cmath>

namespace cutcalc::domain::machine_time {

struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double k, Vec3 a) { return {k * a.x, k * a.y, k * a.z}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }
// a / |a|, or the zero vector for a zero vector.
inline Vec3 unit(Vec3 a) {
  const double n = norm(a);
  return n > 0.0 ? (1.0 / n) * a : Vec3{};
}

}  // namespace cutcalc::domain::machine_time
