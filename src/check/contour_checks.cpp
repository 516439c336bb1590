#include "check/contour_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "geom/arc_length.hpp"
#include "geom/critical_points.hpp"
#include "geom/curvature.hpp"
#include "geom/join.hpp"

namespace gf {

namespace {

std::string format(const char* fmt, double a, double b = 0.0) {
  char buf[160];
  std::snprintf(buf, sizeof buf, fmt, a, b);
  return buf;
}

struct GlyphChecker {
  const Glyph& glyph;
  const FontInfo& font;
  const CheckProfile& profile;
  GlyphReport report;
  std::vector<Vec2> nodes;  // every on-curve point of the glyph
  int monotone_segments = 0;

  double upm() const { return font.units_per_em; }

  Finding& add(const std::string& check, int contour, std::optional<int> node, std::optional<Vec2> point) {
    Finding f;
    f.check = check;
    f.severity = profile.severity_of(check);
    f.contour = contour;
    f.node = node;
    f.point = point;
    report.findings.push_back(std::move(f));
    return report.findings.back();
  }

  void run() {
    report.glyph = glyph.name;
    for (const Contour& c : glyph.outline.contours)
      for (std::size_t i = 0; i < c.node_count(); ++i) nodes.push_back(c.node_point(i));
    check_directions();
    for (std::size_t ci = 0; ci < glyph.outline.contours.size(); ++ci) check_contour(static_cast<int>(ci));
    report.fairness.monotone_fraction =
        report.fairness.curve_segments == 0 ? 1.0 : double(monotone_segments) / report.fairness.curve_segments;
  }

  // --- structure -------------------------------------------------------------------------

  // Outer contours run the format's way, and each nested contour the other way from its
  // container (depth by point-in-polygon against the other contours, flattened).
  void check_directions() {
    const auto& contours = glyph.outline.contours;
    std::vector<std::vector<Vec2>> polygons;
    for (const Contour& c : contours) {
      std::vector<Vec2> poly;
      for (const Segment& s : c.segments)
        for (int k = 0; k < (is_line(s) ? 1 : 8); ++k) poly.push_back(point_at(s, k / (is_line(s) ? 1.0 : 8.0)));
      polygons.push_back(std::move(poly));
    }
    const auto inside = [](const std::vector<Vec2>& poly, Vec2 p) {
      bool in = false;
      for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        if ((poly[i].y > p.y) != (poly[j].y > p.y) &&
            p.x < (poly[j].x - poly[i].x) * (p.y - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x)
          in = !in;
      return in;
    };
    for (std::size_t i = 0; i < contours.size(); ++i) {
      if (!contours[i].closed || polygons[i].size() < 3) continue;
      const double area = signed_area(contours[i]);
      if (area == 0.0) continue;
      int depth = 0;
      for (std::size_t j = 0; j < contours.size(); ++j)
        if (j != i && contours[j].closed && polygons[j].size() >= 3 && inside(polygons[j], polygons[i][0])) ++depth;
      const bool clockwise = area < 0.0;
      const bool expected = (depth % 2 == 0) == font.outer_contours_clockwise;
      if (clockwise == expected) continue;
      Finding& f = add("wrong-direction", static_cast<int>(i), 0, contours[i].node_point(0));
      f.message = std::string(depth % 2 ? "an inner contour (depth " + std::to_string(depth) + ")" : "an outer contour") +
                  " runs " + (clockwise ? "clockwise" : "counter-clockwise") + "; this format wants " +
                  (expected ? "clockwise" : "counter-clockwise");
    }
  }

  void check_contour(int ci) {
    const Contour& c = glyph.outline.contours[static_cast<std::size_t>(ci)];
    if (c.segments.empty()) return;
    if (!c.closed) add("open-contour", ci, 0, c.node_point(0)).message = "the contour is not closed";
    // Each segment's analysis once, shared by the checks below.
    std::vector<double> lengths;
    std::vector<CriticalPoints> critical;
    double contour_length = 0.0;
    for (const Segment& s : c.segments) {
      lengths.push_back(arc_length_estimate(s));
      contour_length += lengths.back();
      critical.push_back(is_line(s) ? CriticalPoints{} : critical_points(s));
    }
    const std::vector<Join> joins = joins_of(c);
    for (std::size_t i = 0; i < c.segments.size(); ++i) {
      const Segment& s = c.segments[i];
      const bool previous_is_line = i > 0 ? is_line(c.segments[i - 1]) : (c.closed && is_line(c.segments.back()));
      check_segment_shape(ci, static_cast<int>(i), s, lengths[i], contour_length, previous_is_line);
      check_segment_curvature(ci, static_cast<int>(i), s, lengths[i], critical[i]);
    }
    check_joins(ci, joins);
    check_wobble(ci, c, joins, critical);
  }

  void check_segment_shape(int ci, int i, const Segment& s, double length, double contour_length, bool previous_is_line) {
    const Vec2 a = start_point(s), b = end_point(s);
    if (is_degenerate(s)) {
      add("duplicate-point", ci, i, a).message = "two consecutive points coincide (a segment of length 0)";
      return;
    }
    // fontbakery outline_short_segments: shorter than 3 units, or than 0.6% of the contour when
    // the previous segment is a line or this one is a curve.
    const double short_units = profile.short_segment_em * upm();
    const double short_fraction = profile.short_segment_contour_fraction * contour_length;
    if (length < short_units || (length < short_fraction && (previous_is_line || !is_line(s)))) {
      Finding& f = add("short-segment", ci, i, a);
      f.segment = i;
      f.value = length;
      f.threshold = length < short_units ? short_units : short_fraction;
      f.unit = "units";
      f.message = format("a segment %.3g units long", length);
    }
    if (is_line(s)) {
      const Vec2 d = b - a;
      const double from_h = degrees(std::atan2(std::abs(d.y), std::abs(d.x)));
      const double from_v = 90.0 - from_h;
      if (from_h > 0.0 && from_h <= profile.semi_hv_max_deg) {
        Finding& f = add("semi-horizontal", ci, i, a);
        f.segment = i, f.value = from_h, f.threshold = profile.semi_hv_max_deg, f.unit = "deg";
        f.message = format("a line %.3g° off horizontal", from_h);
      } else if (from_v > 0.0 && from_v <= profile.semi_hv_max_deg && font.italic_angle == 0.0) {
        Finding& f = add("semi-vertical", ci, i, a);
        f.segment = i, f.value = from_v, f.threshold = profile.semi_hv_max_deg, f.unit = "deg";
        f.message = format("a line %.3g° off vertical", from_v);
      }
      return;
    }
    std::visit([&](const auto& bz) {
      constexpr int n = std::decay_t<decltype(bz)>::degree;
      if (bz.p[1] == bz.p[0] || bz.p[n - 1] == bz.p[n]) {
        Finding& f = add("zero-handle", ci, i, bz.p[1] == bz.p[0] ? bz.p[0] : bz.p[n]);
        f.segment = i;
        f.message = "a handle is retracted onto its node (curvature is unbounded there)";
      }
      // Every control point on the chord: a straight line drawn as a curve.
      const double chord = distance(a, b);
      if (chord > 0.0) {
        double off = 0.0;
        for (const Vec2 q : bz.p) off = std::max(off, std::abs(cross(b - a, q - a)) / chord);
        if (off <= profile.collinear_handles_ratio * chord) {
          Finding& f = add("collinear-handles", ci, i, a);
          f.segment = i, f.value = off / chord, f.threshold = profile.collinear_handles_ratio, f.unit = "ratio";
          f.message = "the handles lie on the chord: a straight line drawn as a curve";
        }
      }
    }, s);
  }

  double capped(std::optional<double> k) const {
    const double cap = profile.fairness_curvature_cap_em / upm();
    return k ? std::clamp(*k, -cap, cap) : cap;
  }

  void check_segment_curvature(int ci, int i, const Segment& s, double length, const CriticalPoints& cp) {
    if (is_line(s)) return;
    FairnessFigures& fair = report.fairness;
    fair.curve_segments += 1;
    fair.inflections += static_cast<int>(cp.inflections.size());
    fair.curvature_extrema += static_cast<int>(cp.curvature_extrema.size());
    if (cp.inflections.empty() && cp.curvature_extrema.empty()) ++monotone_segments;
    // ∫|dκ/ds| ds: |Δκ| summed between the places where κ turns (exact on monotone pieces).
    std::vector<double> turns{0.0};
    for (const auto& e : cp.curvature_extrema) turns.push_back(e.t);
    for (const double t : cp.cusps) turns.push_back(t);
    turns.push_back(1.0);
    std::sort(turns.begin(), turns.end());
    const EndCurvature k0 = end_curvature(s, SegmentEnd::start), k1 = end_curvature(s, SegmentEnd::end);
    double previous = capped(k0.curvature);
    for (std::size_t k = 1; k < turns.size(); ++k) {
      const double value = k + 1 == turns.size() ? capped(k1.curvature) : capped(curvature(derivatives_at(s, turns[k])));
      fair.total_variation += std::abs(value - previous) * upm();
      previous = value;
    }
    for (const double t : cp.inflections) {
      Finding& f = add("inflection-in-segment", ci, i, point_at(s, t));
      f.segment = i, f.t = t;
      f.message = format("an inflection inside the segment at t = %.3f", t);
    }
    for (const AxisExtremum& e : cp.axis_extrema) {
      const double before = arc_length_estimate(s, 0.0, e.t);
      const double fraction = profile.extremum_end_fraction * length;
      if (before <= fraction || length - before <= fraction) continue;
      const Vec2 p = point_at(s, e.t);
      double nearest = INFINITY;
      for (const Vec2 n : nodes) nearest = std::min(nearest, distance(n, p));
      if (nearest <= profile.extremum_node_distance_em * upm()) continue;
      Finding& f = add("missing-extremum", ci, i, p);
      f.segment = i, f.t = e.t, f.value = nearest, f.threshold = profile.extremum_node_distance_em * upm();
      f.unit = "units";
      f.message = format(e.tangent == Axis::horizontal ? "a horizontal extremum at t = %.3f, %.3g units from the nearest node"
                                                       : "a vertical extremum at t = %.3f, %.3g units from the nearest node",
                         e.t, nearest);
    }
  }

  void check_joins(int ci, const std::vector<Join>& joins) {
    for (const Join& j : joins) {
      const double angle = std::abs(j.angle_deg);
      const int node = static_cast<int>(j.node);
      if (j.kind == JoinKind::degenerate) continue;
      if (angle > profile.kink_min_deg && angle < profile.kink_max_deg) {
        Finding& f = add("kink", ci, node, j.point);
        f.value = angle, f.threshold = profile.kink_min_deg, f.unit = "deg";
        f.message = format("the tangents differ by %.3g° (smooth below %.2g°)", angle, profile.kink_min_deg);
        continue;
      }
      if (angle > profile.kink_min_deg) continue;  // a corner
      // At a smooth join, line–curve joins included: κ should not jump.
      const std::optional<double> ki = j.curvature_in, ko = j.curvature_out;
      const double upm_ = upm();
      report.fairness.total_variation += std::abs(capped(ki) - capped(ko)) * upm_;
      const std::optional<CurvatureJump> jump = curvature_jump(j, upm_, profile.g2);
      if (!jump) {
        Finding& f = add("g2-jump", ci, node, j.point);
        f.unit = "ratio";
        f.message = "curvature is unbounded on one side (a retracted handle)";
        continue;
      }
      if (!jump->exceeds()) continue;
      Finding& f = add("g2-jump", ci, node, j.point);
      f.value = jump->value, f.threshold = jump->limit, f.unit = jump->relative ? "ratio" : "1/em";
      f.message = jump->relative ? format("curvature jumps by %.0f%% of the larger side (%.3g/em)", 100 * jump->value,
                                          std::max(std::abs(*ki), std::abs(*ko)) * upm_)
                                 : format("curvature jumps by %.3g/em", jump->value);
    }
  }

  // The sign of κ just beside a node, on the side `side` (−1 before it, +1 after): κ's own, or
  // where κ is zero to rounding there (an inflection on the node itself, as on a spline's knot
  // at the middle of a symmetric S), the sign dκ/ds gives it a little way in. The residue's
  // own sign (±1e-15) depends on the machine's last bits.
  double side_sign(std::optional<double> k, std::optional<double> dk, double side) const {
    if (!k) return 0.0;
    if (std::abs(*k) * upm() > 1e-9 || !dk) return *k > 0.0 ? 1.0 : *k < 0.0 ? -1.0 : 0.0;
    const double ahead = side * *dk;
    return ahead > 0.0 ? 1.0 : ahead < 0.0 ? -1.0 : 0.0;
  }

  // More than one curvature extremum between two consecutive inflections of a smooth run.
  void check_wobble(int ci, const Contour& c, const std::vector<Join>& joins, const std::vector<CriticalPoints>& critical) {
    struct Event {
      enum Kind { brk, inflection, extremum, none } kind;
      int segment;
      double t;
    };
    std::vector<Event> events;
    // A run breaks at corners, kinks and straight lines; curvature changing sign across a
    // smooth join is an inflection there.
    std::vector<Event::Kind> at_node(c.segments.size(), Event::brk);
    for (const Join& j : joins) {
      const bool smooth = std::abs(j.angle_deg) <= profile.kink_min_deg && j.kind != JoinKind::degenerate;
      if (!smooth) continue;
      const bool flips = side_sign(j.curvature_in, j.curvature_derivative_in, -1.0) *
                             side_sign(j.curvature_out, j.curvature_derivative_out, 1.0) <
                         0.0;
      // dκ/ds changing sign at the node: κ has its extremum there (B-splines put it on a knot).
      const bool turns = j.curvature_derivative_in && j.curvature_derivative_out &&
                         *j.curvature_derivative_in * *j.curvature_derivative_out < 0.0;
      at_node[j.node] = flips ? Event::inflection : turns ? Event::extremum : Event::none;
      if (!flips && turns) ++report.fairness.curvature_extrema;
    }
    for (std::size_t i = 0; i < c.segments.size(); ++i) {
      if (is_line(c.segments[i])) at_node[i] = Event::brk;
      if (at_node[i] != Event::none) events.push_back({at_node[i], static_cast<int>(i), 0.0});
      const CriticalPoints& cp = critical[i];
      std::vector<Event> inside;
      for (const double t : cp.inflections) inside.push_back({Event::inflection, static_cast<int>(i), t});
      for (const auto& e : cp.curvature_extrema) inside.push_back({Event::extremum, static_cast<int>(i), e.t});
      for (const double t : cp.cusps) inside.push_back({Event::brk, static_cast<int>(i), t});
      std::sort(inside.begin(), inside.end(), [](const Event& a, const Event& b) { return a.t < b.t; });
      events.insert(events.end(), inside.begin(), inside.end());
    }
    if (events.empty()) return;
    // A closed contour starts at a break when it has one; a closed contour without any is a
    // cycle, walked twice so the interval that wraps round is seen, reporting only intervals
    // that open on the first lap.
    const std::size_t n = events.size();
    const auto first_break =
        std::find_if(events.begin(), events.end(), [](const Event& e) { return e.kind == Event::brk; });
    std::rotate(events.begin(), first_break == events.end() ? events.begin() : first_break, events.end());
    const std::size_t laps = c.closed && first_break == events.end() ? 2 : 1;
    constexpr std::size_t none = static_cast<std::size_t>(-1);
    std::size_t opened = none;  // index of the inflection that opened the interval
    int extrema = 0;
    Event second{};
    for (std::size_t k = 0; k < laps * n; ++k) {
      if (k >= n && (opened == none || opened >= n)) break;
      const Event& e = events[k % n];
      if (e.kind == Event::brk) {
        opened = none;
      } else if (e.kind == Event::extremum) {
        if (opened != none && ++extrema == 2) second = e;
      } else {
        if (opened != none && extrema > 1) {
          const Segment& s = c.segments[static_cast<std::size_t>(second.segment)];
          Finding& f = add("wobble", ci, second.segment, point_at(s, second.t));
          f.segment = second.segment, f.value = extrema, f.threshold = 1, f.unit = "extrema";
          if (second.t > 0.0) f.t = second.t;  // else the extremum is at the node itself
          f.message = std::to_string(extrema) + " curvature extrema between two inflections (one is fair)";
        }
        opened = k;
        extrema = 0;
      }
    }
  }
};

}  // namespace

GlyphReport check_glyph(const Glyph& glyph, const FontInfo& font, const CheckProfile& profile) {
  GlyphChecker checker{glyph, font, profile, {}, {}, 0};
  checker.run();
  return std::move(checker.report);
}

}  // namespace gf
