#include "render/glyph_painter.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geom/critical_points.hpp"
#include "geom/curvature.hpp"
#include "geom/join.hpp"
#include "render/cairo_helpers.hpp"

namespace gf {

namespace {

// A robust page maximum: the 95th percentile of |κ|, so one tight corner does not flatten
// every other comb on the page.
double robust_max_curvature(std::span<const CurvatureProfile> profiles) {
  std::vector<double> values;
  for (const CurvatureProfile& p : profiles)
    for (const SegmentProfile& s : p.segments)
      if (!s.straight)
        for (const CurvatureSample& c : s.samples)
          if (c.curvature) values.push_back(std::abs(*c.curvature));
  if (values.empty()) return 0.0;
  const std::size_t k = std::min(values.size() - 1, static_cast<std::size_t>(0.95 * double(values.size())));
  std::nth_element(values.begin(), values.begin() + static_cast<long>(k), values.end());
  return values[k];
}

void add_segment_path(cairo_t* cr, const PanelMap& map, const Segment& s) {
  const Cubic c = to_cubic(s);
  const Vec2 p1 = map(c.p[1]), p2 = map(c.p[2]), p3 = map(c.p[3]);
  if (is_line(s)) cairo_line_to(cr, p3.x, p3.y);
  else cairo_curve_to(cr, p1.x, p1.y, p2.x, p2.y, p3.x, p3.y);
}

}  // namespace

double comb_gain(std::span<const CurvatureProfile> profiles, double units_per_em) {
  const double k = robust_max_curvature(profiles);
  return k > 0.0 ? 0.12 * units_per_em / k : 0.0;
}

void paint_metrics(cairo_t* cr, const PanelMap& map, const FontInfo& font, double advance_width, const Box& panel) {
  struct Line { double y; const char* label; };
  std::vector<Line> lines{{0.0, "baseline"}, {font.ascender, "ascender"}, {font.descender, "descender"}};
  if (font.x_height) lines.push_back({*font.x_height, "x-height"});
  if (font.cap_height) lines.push_back({*font.cap_height, "cap height"});
  cairo_set_line_width(cr, 0.4);
  draw::set(cr, colour::metrics);
  for (const Line& l : lines) {
    const double y = map({0, l.y}).y;
    if (y < panel.y0 || y > panel.y1) continue;
    draw::line(cr, {panel.x0, y}, {panel.x1, y});
    cairo_stroke(cr);
    draw::text(cr, {panel.x0 + 2, y - 2}, l.label, 6.5);
  }
  const double dashes[] = {2.0, 2.0};
  cairo_set_dash(cr, dashes, 2, 0);
  for (const double x : {0.0, advance_width}) {
    const double px = map({x, 0}).x;
    draw::line(cr, {px, panel.y0}, {px, panel.y1});
    cairo_stroke(cr);
  }
  cairo_set_dash(cr, nullptr, 0, 0);
}

void paint_combs(cairo_t* cr, const PanelMap& map, std::span<const CurvatureProfile> profiles, double gain,
                 double max_tooth_units) {
  if (gain <= 0.0) return;
  cairo_set_line_width(cr, 0.35);
  for (const CurvatureProfile& p : profiles)
    for (const SegmentProfile& s : p.segments) {
      if (s.straight) continue;
      std::vector<Vec2> tips;
      for (const CurvatureSample& c : s.samples) {
        if (!c.curvature) continue;
        // Teeth stand on the outside of the bend: opposite to the left normal for left turns.
        const double length = std::clamp(gain * *c.curvature, -max_tooth_units, max_tooth_units);
        const Vec2 tip = c.point - c.normal * length;
        draw::set(cr, *c.curvature >= 0 ? colour::comb_positive : colour::comb_negative);
        draw::line(cr, map(c.point), map(tip));
        cairo_stroke(cr);
        tips.push_back(tip);
      }
      if (tips.size() < 2) continue;
      draw::set(cr, {0.15, 0.25, 0.55, 0.8});
      cairo_move_to(cr, map(tips[0]).x, map(tips[0]).y);
      for (const Vec2 t : tips) cairo_line_to(cr, map(t).x, map(t).y);
      cairo_stroke(cr);
    }
}

void paint_outline(cairo_t* cr, const PanelMap& map, const Outline& outline, colour::Rgba stroke, bool filled) {
  cairo_new_path(cr);
  for (const Contour& c : outline.contours) {
    if (c.segments.empty()) continue;
    const Vec2 s = map(c.node_point(0));
    cairo_move_to(cr, s.x, s.y);
    for (const Segment& seg : c.segments) add_segment_path(cr, map, seg);
    if (c.closed) cairo_close_path(cr);
  }
  if (filled) {
    draw::set(cr, colour::fill);
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
    cairo_fill_preserve(cr);
  }
  draw::set(cr, stroke);
  cairo_set_line_width(cr, 0.8);
  cairo_stroke(cr);
}

void paint_points(cairo_t* cr, const PanelMap& map, const Outline& outline, colour::Rgba tint, bool detailed) {
  const double r = detailed ? 1.9 : 1.4;
  for (const Contour& c : outline.contours) {
    if (c.segments.empty()) continue;
    // Handles first, so the points sit on top of them.
    cairo_set_line_width(cr, 0.45);
    draw::set(cr, detailed ? colour::handle : tint);
    for (const Segment& s : c.segments)
      std::visit([&](const auto& b) {
        constexpr int n = std::decay_t<decltype(b)>::degree;
        if constexpr (n == 2) {
          draw::line(cr, map(b.p[0]), map(b.p[1]));
          draw::line(cr, map(b.p[1]), map(b.p[2]));
        } else if constexpr (n == 3) {
          draw::line(cr, map(b.p[0]), map(b.p[1]));
          draw::line(cr, map(b.p[3]), map(b.p[2]));
        }
      }, s);
    cairo_stroke(cr);
    for (const Segment& s : c.segments)
      std::visit([&](const auto& b) {
        for (std::size_t i = 1; i + 1 < b.p.size(); ++i) draw::circle(cr, map(b.p[i]), r * 0.8);
      }, s);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_fill_preserve(cr);
    draw::set(cr, tint);
    cairo_set_line_width(cr, 0.6);
    cairo_stroke(cr);

    const std::vector<Join> joins = joins_of(c);
    for (std::size_t i = 0; i < c.node_count(); ++i) {
      const Vec2 p = map(c.node_point(i));
      const auto j = std::find_if(joins.begin(), joins.end(), [i](const Join& x) { return x.node == i; });
      const bool smooth = j != joins.end() && j->kind == JoinKind::smooth;
      if (c.nodes[i].implied) {
        draw::circle(cr, p, r * 0.6);
        draw::set(cr, tint);
        cairo_set_line_width(cr, 0.4);
        cairo_stroke(cr);
        continue;
      }
      if (smooth) draw::circle(cr, p, r);
      else draw::square(cr, p, r * 0.95);
      draw::set(cr, j != joins.end() && j->kind == JoinKind::kink ? colour::join_kink : tint);
      cairo_fill(cr);
    }
    if (detailed) {
      // The start point and the direction of travel.
      const Vec2 s = map(c.node_point(0));
      const Vec2 ahead = map(point_at(c.segments[0], 0.08));
      const Vec2 d = ahead - s;
      const double len = norm(d);
      if (len > 0) {
        const Vec2 u = d / len, n = perpendicular(u);
        const Vec2 tip = s + u * 9.0;
        draw::set(cr, colour::start_point);
        cairo_set_line_width(cr, 0.9);
        draw::circle(cr, s, r * 2.0);
        cairo_stroke(cr);
        cairo_move_to(cr, tip.x, tip.y);
        cairo_line_to(cr, tip.x - u.x * 4 + n.x * 2.5, tip.y - u.y * 4 + n.y * 2.5);
        cairo_line_to(cr, tip.x - u.x * 4 - n.x * 2.5, tip.y - u.y * 4 - n.y * 2.5);
        cairo_close_path(cr);
        cairo_fill(cr);
      }
    }
  }
}

void paint_marks(cairo_t* cr, const PanelMap& map, const Outline& outline) {
  cairo_set_line_width(cr, 0.9);
  for (const Contour& c : outline.contours)
    for (const Segment& s : c.segments) {
      if (is_line(s)) continue;
      const CriticalPoints cp = critical_points(s);
      for (const double t : cp.inflections) {
        draw::diamond(cr, map(point_at(s, t)), 3.2);
        draw::set(cr, colour::inflection);
        cairo_fill(cr);
      }
      for (const CurvatureExtremum& e : cp.curvature_extrema) {
        // A bar across the curve: long at a maximum of |κ|, short at a minimum.
        const Derivatives d = derivatives_at(s, e.t);
        const double speed = norm(d.d1);
        if (speed == 0.0) continue;
        const Vec2 n = perpendicular(d.d1) / speed;
        const Vec2 p = map(d.point);
        const Vec2 pn{n.x, -n.y};
        const double h = e.maximum ? 5.0 : 2.5;
        draw::line(cr, p - pn * h, p + pn * h);
        draw::set(cr, colour::curvature_extremum);
        cairo_stroke(cr);
      }
      for (const AxisExtremum& e : cp.axis_extrema) {
        draw::square(cr, map(point_at(s, e.t)), 2.6);
        draw::set(cr, colour::axis_extremum);
        cairo_stroke(cr);
      }
    }
}

}  // namespace gf
