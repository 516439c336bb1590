// Uniform cubic B-spline bases over u ∈ [0, 1]: clamped (the curve starts and ends on its end
// controls) and periodic (a closed curve, C2 everywhere), and the Bézier form of their spans.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "geom/bezier.hpp"

namespace gf {

class BSplineBasis {
 public:
  BSplineBasis(int spans, bool periodic);

  int spans() const { return spans_; }
  bool periodic() const { return periodic_; }
  /// spans + 3 controls when clamped, spans when periodic.
  int control_count() const { return periodic_ ? spans_ : spans_ + 3; }
  /// The index of control k of a span's four (wrapping when periodic).
  int control(int k) const { return periodic_ ? k % spans_ : k; }

  /// The four non-zero basis values at u, on controls first … first + 3 (through `control`).
  struct Weights {
    int first;
    std::array<double, 4> w;
  };
  Weights at(double u) const;

  Vec2 point_at(std::span<const Vec2> controls, double u) const;
  /// Span s (0 … spans − 1) as a cubic Bézier: exact, since each span is a cubic polynomial.
  Cubic span_cubic(std::span<const Vec2> controls, int s) const;
  /// Every span as a cubic Bézier, in order.
  std::vector<Cubic> span_cubics(std::span<const Vec2> controls) const;

  /// The point at u of the spline given by its spans (span_cubic of each).
  Vec2 point_on_spans(std::span<const Cubic> spans, double u) const;
  /// Up to `steps` Newton steps from u toward the parameter of p's foot on the spline given by
  /// its spans (fewer where a step is not finite); clamped to [0, 1], or wrapped when periodic.
  double foot_parameter(std::span<const Cubic> spans, Vec2 p, double u, int steps) const;

 private:
  int spans_;
  bool periodic_;
  std::vector<double> knots_;  // clamped only
};

}  // namespace gf
