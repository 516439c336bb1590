// A point or vector in the plane, in font units (y up).
#pragma once

#include <cmath>
#include <numbers>

namespace gf {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  friend constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
  friend constexpr Vec2 operator*(Vec2 a, double s) { return {a.x * s, a.y * s}; }
  friend constexpr Vec2 operator*(double s, Vec2 a) { return {a.x * s, a.y * s}; }
  friend constexpr Vec2 operator/(Vec2 a, double s) { return {a.x / s, a.y / s}; }
  friend constexpr bool operator==(Vec2 a, Vec2 b) = default;
  constexpr Vec2& operator+=(Vec2 b) { x += b.x; y += b.y; return *this; }
  constexpr Vec2& operator-=(Vec2 b) { x -= b.x; y -= b.y; return *this; }
};

constexpr double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
/// z-component of the 3-D cross product: positive when b turns left of a.
constexpr double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
constexpr Vec2 lerp(Vec2 a, Vec2 b, double t) { return a + (b - a) * t; }
constexpr Vec2 perpendicular(Vec2 a) { return {-a.y, a.x}; }
// Not std::hypot: font coordinates never come near overflow, and hypot cost 8 % of a whole-font run.
inline double norm(Vec2 a) { return std::sqrt(a.x * a.x + a.y * a.y); }
inline double distance(Vec2 a, Vec2 b) { return norm(a - b); }
/// The direction of a, radians in (−π, π].
inline double angle_of(Vec2 a) { return std::atan2(a.y, a.x); }
/// The unit vector at `angle` radians: the inverse of angle_of.
inline Vec2 direction_of(double angle) { return {std::cos(angle), std::sin(angle)}; }
/// The angle a less whole turns, in (−π, π].
inline double wrapped_angle(double a) {
  const double r = std::remainder(a, 2.0 * std::numbers::pi);
  return r <= -std::numbers::pi ? r + 2.0 * std::numbers::pi : r;
}
/// An angle given in degrees, in radians.
constexpr double radians(double deg) { return deg * std::numbers::pi / 180.0; }
/// An angle given in radians, in degrees.
constexpr double degrees(double rad) { return rad * 180.0 / std::numbers::pi; }
/// Signed angle in (-pi, pi] that turns direction a into direction b (left positive).
inline double turning_angle(Vec2 a, Vec2 b) { return std::atan2(cross(a, b), dot(a, b)); }

}  // namespace gf
