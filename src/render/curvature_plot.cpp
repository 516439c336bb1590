#include "render/curvature_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/cairo_helpers.hpp"

namespace gf {

namespace {

// 1, 2 or 5 times a power of ten, at least `raw`.
double nice_step(double raw) {
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}

std::string label(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

void paint_curvature_plot(cairo_t* cr, const Box& panel, std::span<const PlotSeries> series, double upm) {
  const double gap_units = 0.04 * upm;
  // Horizontal layout: contour k of every series starts at the same s offset.
  std::size_t contours = 0;
  for (const PlotSeries& s : series) contours = std::max(contours, s.contours.size());
  std::vector<double> offset(contours + 1, 0.0);
  for (std::size_t k = 0; k < contours; ++k) {
    double longest = 0.0;
    for (const PlotSeries& s : series)
      if (k < s.contours.size()) longest = std::max(longest, s.contours[k].length);
    offset[k + 1] = offset[k] + longest + gap_units;
  }
  const double total = std::max(offset[contours] - gap_units, 1e-9);

  // Vertical scale: the 98th percentile of |κ|·UPM, so spikes clip instead of flattening the rest.
  std::vector<double> values;
  for (const PlotSeries& s : series)
    for (const CurvatureProfile& p : s.contours)
      for (const SegmentProfile& seg : p.segments)
        for (const CurvatureSample& c : seg.samples)
          if (c.curvature) values.push_back(std::abs(*c.curvature) * upm);
  double y_max = 1.0;
  if (!values.empty()) {
    const std::size_t k = std::min(values.size() - 1, static_cast<std::size_t>(0.98 * double(values.size())));
    std::nth_element(values.begin(), values.begin() + static_cast<long>(k), values.end());
    y_max = std::max(values[k] * 1.15, 0.5);
  }
  const Box plot{panel.x0 + 34, panel.y0 + 14, panel.x1 - 6, panel.y1 - 18};
  const auto px = [&](double s) { return plot.x0 + s / total * plot.width(); };
  const auto py = [&](double k) {
    const double v = std::clamp(k * upm, -y_max, y_max);
    return 0.5 * (plot.y0 + plot.y1) - v / y_max * 0.5 * plot.height();
  };

  // Frame, grid and labels.
  draw::set(cr, colour::ink);
  draw::text(cr, {panel.x0, panel.y0 + 8}, "curvature \u03BA \u00B7 UPM against arc length s (font units)", 8, true);
  cairo_set_line_width(cr, 0.3);
  draw::set(cr, colour::metrics);
  const double y_step = nice_step(y_max / 3.0);
  for (double v = -std::floor(y_max / y_step) * y_step; v <= y_max + 1e-9; v += y_step) {
    const double y = py(v / upm);
    draw::line(cr, {plot.x0, y}, {plot.x1, y});
    cairo_stroke(cr);
    draw::text(cr, {panel.x0, y + 2.5}, label(v), 6.5);
  }
  const double x_step = nice_step(total / 8.0);
  for (double s = 0; s <= total + 1e-9; s += x_step) draw::text(cr, {px(s) - 4, plot.y1 + 10}, label(s), 6.5);
  cairo_set_line_width(cr, 0.8);
  draw::set(cr, colour::ink);
  draw::line(cr, {plot.x0, py(0)}, {plot.x1, py(0)});
  cairo_stroke(cr);
  cairo_set_line_width(cr, 0.5);
  cairo_rectangle(cr, plot.x0, plot.y0, plot.width(), plot.height());
  cairo_stroke(cr);

  for (std::size_t k = 0; k < contours; ++k) {
    draw::set(cr, colour::metrics);
    draw::text(cr, {px(offset[k]) + 2, plot.y0 + 8}, "contour " + std::to_string(k + 1), 6.5);
  }

  for (std::size_t si = 0; si < series.size(); ++si) {
    const PlotSeries& s = series[si];
    for (std::size_t k = 0; k < s.contours.size(); ++k) {
      const CurvatureProfile& p = s.contours[k];
      // Joins: smooth ones dotted, kinks orange, corners dashed.
      if (si == 0)
        for (const ProfileJoin& j : p.joins) {
          const double x = px(offset[k] + j.s);
          const double dots[] = {1.0, 2.0}, dashes[] = {4.0, 2.0};
          const bool smooth = j.join.kind == JoinKind::smooth;
          cairo_set_dash(cr, smooth ? dots : dashes, 2, 0);
          draw::set(cr, j.join.kind == JoinKind::kink ? colour::join_kink
                        : smooth                       ? colour::metrics
                                                       : colour::join_corner);
          cairo_set_line_width(cr, smooth ? 0.4 : 0.6);
          draw::line(cr, {x, plot.y0}, {x, plot.y1});
          cairo_stroke(cr);
          cairo_set_dash(cr, nullptr, 0, 0);
        }
      // One polyline per segment: a jump at a join shows as a break.
      draw::set(cr, s.colour);
      cairo_set_line_width(cr, 1.0);
      for (const SegmentProfile& seg : p.segments) {
        bool drawing = false;
        for (const CurvatureSample& c : seg.samples) {
          if (!c.curvature) { drawing = false; continue; }
          const double x = px(offset[k] + c.s), y = py(*c.curvature);
          if (drawing) cairo_line_to(cr, x, y);
          else cairo_move_to(cr, x, y);
          drawing = true;
        }
        cairo_stroke(cr);
      }
    }
  }
}

}  // namespace gf
