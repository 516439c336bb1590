// The G1 Hermite clothoid (lac-math.md §7.2; Bertolazzi & Frego, arXiv:1305.6644): the one
// Euler spiral κ(s) = κ₀ + κ′s from P0 leaving at θ₀ to P1 arriving at θ₁, with total turning
// below 2π. It starts the curvature-profile Newton (§7.1) and is the G3 segment whose
// curvature is linear.
#pragma once

#include <optional>
#include <string>

#include "geom/vec2.hpp"

namespace gf {

struct ClothoidArc {
  double length;
  double curvature;        ///< κ₀ at P0, left turns positive
  double curvature_slope;  ///< κ′ = dκ/ds, constant
};

struct ClothoidFit {
  std::optional<ClothoidArc> arc;  ///< nullopt: Newton did not reach the tolerance
  int iterations = 0;
  std::string reason;  ///< why not, in one line
  bool ok() const { return arc.has_value(); }
};

/// θ₀ and θ₁ are directions in radians; only their difference from the chord matters
/// (each is wrapped into (−π, π] about it).
ClothoidFit fit_clothoid_g1(Vec2 p0, double theta0, Vec2 p1, double theta1);

/// ∫₀¹ τᵏ exp(i(a τ²/2 + b τ + c)) dτ for k = 0, 1, 2: the generalised Fresnel integrals
/// X_k + i Y_k, by Gauss–Legendre on two panels (enough for |a|, |b| up to a few 2π).
struct FresnelMoments {
  double x[3];
  double y[3];
};
FresnelMoments generalised_fresnel(double a, double b, double c);

}  // namespace gf
