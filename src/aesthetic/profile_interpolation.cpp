#include "aesthetic/profile_interpolation.hpp"

#include <cmath>
#include <numbers>
#include <optional>

#include <Eigen/Dense>

#include "aesthetic/clothoid_g1.hpp"
#include "geom/damped_newton.hpp"

namespace gf {

namespace {

// The direction of travel a → b → c of the circle through them: at the middle point b
// parallel to the chord a → c; at the end a, the chord a → b turned away from the chord a → c
// by the angle between them (tangent–chord theorem). Collinear points give the line.
double circle_tangent_at_middle(Vec2 a, Vec2 c) { return angle_of(c - a); }
double circle_tangent_at_start(Vec2 a, Vec2 b, Vec2 c) {
  const double to_middle = angle_of(b - a);
  return to_middle + wrapped_angle(to_middle - angle_of(c - a));
}

// Each span's G1 clothoid between the tangents θ, in order, up to the first span that has none.
std::vector<ClothoidArc> span_clothoids(std::span<const InterpolationPoint> points, const std::vector<double>& theta) {
  std::vector<ClothoidArc> out;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const ClothoidFit c = fit_clothoid_g1(points[i].point, theta[i], points[i + 1].point, theta[i + 1]);
    if (!c.ok()) break;
    out.push_back(*c.arc);
  }
  return out;
}

// The chosen tangents, moved so that the G1 clothoids of the spans come nearest the given
// curvatures at their ends (Gauss–Newton, least squares over κ·chord, geom/damped_newton.hpp):
// a span whose clothoid already bends as asked leaves its profile little to do. Where the
// least squares stall, the tangents stay where they got to.
void settle_tangents(std::span<const InterpolationPoint> points, std::vector<double>& theta) {
  const std::size_t n = points.size();
  std::vector<std::size_t> free;
  for (std::size_t i = 0; i < n; ++i)
    if (!points[i].tangent_angle) free.push_back(i);
  if (free.empty()) return;
  const auto with = [&](const Eigen::VectorXd& x) {
    std::vector<double> th = theta;
    for (std::size_t j = 0; j < free.size(); ++j) th[free[j]] = x[static_cast<Eigen::Index>(j)];
    return th;
  };
  // Infinite where a span has no clothoid: the step is shortened past it.
  const auto residuals = [&](const Eigen::VectorXd& x) {
    const std::vector<ClothoidArc> arcs = span_clothoids(points, with(x));
    Eigen::VectorXd r = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(2 * (n - 1)), HUGE_VAL);
    if (arcs.size() + 1 < n) return r;
    for (std::size_t i = 0; i + 1 < n; ++i) {
      const double chord = distance(points[i].point, points[i + 1].point);
      const ClothoidArc& a = arcs[i];
      r[static_cast<Eigen::Index>(2 * i)] = (a.curvature - points[i].curvature) * chord;
      r[static_cast<Eigen::Index>(2 * i + 1)] = (a.curvature + a.curvature_slope * a.length - points[i + 1].curvature) * chord;
    }
    return r;
  };
  const auto jacobian = [&](const Eigen::VectorXd& x, const Eigen::VectorXd& r) {
    return forward_difference_jacobian(residuals, x, r);
  };
  Eigen::VectorXd x(static_cast<Eigen::Index>(free.size()));
  for (std::size_t j = 0; j < free.size(); ++j) x[static_cast<Eigen::Index>(j)] = theta[free[j]];
  damped_newton(x, residuals, jacobian, [](const Eigen::VectorXd&) { return true; }, 1e-12, 30);
  theta = with(x);
}

}  // namespace

ProfileSpline interpolate_curvature_profiles(std::span<const InterpolationPoint> points) {
  ProfileSpline out;
  const std::size_t n = points.size();
  if (n < 2) {
    out.reason = "at least two points are needed";
    return out;
  }
  for (std::size_t i = 0; i + 1 < n; ++i)
    if (distance(points[i].point, points[i + 1].point) == 0.0) {
      out.reason = "points " + std::to_string(i) + " and " + std::to_string(i + 1) + " coincide";
      return out;
    }
  // Tangents.
  std::vector<double> theta(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (points[i].tangent_angle) {
      theta[i] = *points[i].tangent_angle;
    } else if (n == 2) {
      theta[i] = angle_of(points[1].point - points[0].point);
    } else if (i == 0) {
      theta[i] = circle_tangent_at_start(points[0].point, points[1].point, points[2].point);
    } else if (i + 1 == n) {
      // The end of the reversed run, turned round.
      theta[i] = circle_tangent_at_start(points[n - 1].point, points[n - 2].point, points[n - 3].point) + std::numbers::pi;
    } else {
      theta[i] = circle_tangent_at_middle(points[i - 1].point, points[i + 1].point);
    }
  }
  // Each span turns as its chord says: unwrap so θᵢ₊₁ − θᵢ is that turning.
  for (std::size_t i = 1; i < n; ++i) {
    const double chord = angle_of(points[i].point - points[i - 1].point);
    const double leave = wrapped_angle(theta[i - 1] - chord);
    const double arrive = wrapped_angle(theta[i] - chord);
    theta[i] = theta[i - 1] + (arrive - leave);
  }
  settle_tangents(points, theta);
  // Curvature slopes from the secants over the clothoid lengths.
  const std::vector<ClothoidArc> arcs = span_clothoids(points, theta);
  if (arcs.size() + 1 < n) {
    out.reason = "span " + std::to_string(arcs.size()) + ": no G1 clothoid joins its tangents";
    return out;
  }
  std::vector<double> secant(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) secant[i] = (points[i + 1].curvature - points[i].curvature) / arcs[i].length;
  for (std::size_t i = 0; i < n; ++i) {
    double slope = 0.0;
    if (points[i].curvature_slope) {
      slope = *points[i].curvature_slope;
    } else if (i == 0) {
      slope = secant.front();
    } else if (i + 1 == n) {
      slope = secant.back();
    } else if (secant[i - 1] * secant[i] > 0.0) {
      slope = 2.0 * secant[i - 1] * secant[i] / (secant[i - 1] + secant[i]);
    }
    out.ends.push_back({points[i].point, theta[i], points[i].curvature, slope});
  }
  std::vector<InterpolationSpan> segments;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    ProfileFit profile = fit_curvature_profile(out.ends[i], out.ends[i + 1]);
    if (profile.ok()) {
      segments.emplace_back(std::move(*profile.segment));
      continue;
    }
    SpiralFit spiral = fit_polynomial_spiral(out.ends[i], out.ends[i + 1]);
    if (!spiral.ok()) {
      out.reason = "span " + std::to_string(i) + ": " + profile.reason + "; " + spiral.reason;
      return out;
    }
    segments.emplace_back(std::move(*spiral.spiral));
  }
  out.segments = std::move(segments);
  return out;
}

}  // namespace gf
