// glyphfair curve --alpha A --points x0,y0 x1,y1 x2,y2 [--inflection-start]
//                 | --through x,y... --curvatures K... [--slopes K'...] [--angles DEG...]
//                 [--samples N] [--format json|svg] [-o FILE]
// One log-aesthetic segment from its control triangle, or the G3 curve through points with
// their curvature (seed 004 §6), for scripting and for seeing it.
#include <iostream>
#include <numbers>

#include <nlohmann/json.hpp>

#include "aesthetic/profile_interpolation.hpp"
#include "aesthetic/segment_fit.hpp"
#include "commands.hpp"
#include "curve_svg.hpp"
#include "exit_codes.hpp"
#include "io/atomic_output.hpp"
#include "io/input_error.hpp"
#include "io/number_format.hpp"
#include "io/text_list.hpp"
#include "lac_point_json.hpp"

namespace gf {

namespace {

using json = nlohmann::ordered_json;  // fields in the documented order

Vec2 parse_point(const std::string& text, const char* option) {
  const auto parts = split_trimmed(text);
  const auto x = parts.size() == 2 ? parse_number(parts[0]) : std::nullopt;
  const auto y = parts.size() == 2 ? parse_number(parts[1]) : std::nullopt;
  if (!x || !y) throw InputError(std::string(option) + ": '" + text + "' is not x,y");
  return {*x, *y};
}

// One value per point, or none given; `auto` leaves that point's value to be chosen.
std::vector<std::optional<double>> parse_per_point(const std::vector<std::string>& texts, std::size_t points,
                                                   const char* option, bool allow_auto) {
  if (texts.empty()) return std::vector<std::optional<double>>(points);
  if (texts.size() != points)
    throw InputError(std::string(option) + ": " + std::to_string(texts.size()) + " values for " + std::to_string(points) +
                     " points");
  std::vector<std::optional<double>> out;
  for (const std::string& t : texts) {
    if (allow_auto && t == "auto") {
      out.push_back(std::nullopt);
      continue;
    }
    const auto v = parse_number(t);
    if (!v) throw InputError(std::string(option) + ": '" + t + "' is not a number" + (allow_auto ? " or auto" : ""));
    out.push_back(v);
  }
  return out;
}

json point_json(const LacPoint& p, std::optional<double> s = std::nullopt) {
  json j = lac_point_json(p);
  if (s) j["s"] = *s;
  return j;
}

std::string curve_json(const SegmentFit& fit, double alpha, int samples) {
  json j;
  if (!fit.ok()) {
    j = {{"status", "no-solution"}, {"alpha", alpha}, {"reason", fit.reason}};
    return j.dump(1) + "\n";
  }
  const LogAestheticSegment& s = *fit.segment;
  j["status"] = "ok";
  j["alpha"] = s.alpha();
  j["lambda"] = s.lambda();
  j["length"] = s.length();
  j["start"] = point_json(s.start());
  j["end"] = point_json(s.end());
  json list = json::array();
  const auto pts = s.sample(samples);
  for (std::size_t k = 0; k < pts.size(); ++k) list.push_back(point_json(pts[k], s.length() * double(k) / samples));
  j["samples"] = list;
  return j.dump(1) + "\n";
}

// Every span's n + 1 points, uniform in its arc length, each join once.
std::vector<LacPoint> spline_samples(const ProfileSpline& spline, int samples_per_span) {
  std::vector<LacPoint> out;
  for (const InterpolationSpan& s : spline.segments) {
    const auto pts = s.sample(samples_per_span);
    out.insert(out.end(), pts.begin() + (out.empty() ? 0 : 1), pts.end());
  }
  return out;
}

std::string spline_json(const ProfileSpline& spline, int samples_per_span) {
  json j;
  if (!spline.ok()) {
    j = {{"status", "no-solution"}, {"reason", spline.reason}};
    return j.dump(1) + "\n";
  }
  j["status"] = "ok";
  json spans = json::array();
  std::vector<double> span_start{0.0};  // s where each span starts, and the total last
  for (const InterpolationSpan& s : spline.segments) {
    spans.push_back({{"kind", s.kind()}, {"length", s.length()}, {"start", point_json(s.start())}, {"end", point_json(s.end())}});
    span_start.push_back(span_start.back() + s.length());
  }
  j["length"] = span_start.back();
  j["spans"] = spans;
  json list = json::array();
  const std::vector<LacPoint> pts = spline_samples(spline, samples_per_span);
  const auto n = static_cast<std::size_t>(samples_per_span);
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const std::size_t span = k == 0 ? 0 : (k - 1) / n, step = k - span * n;
    list.push_back(point_json(pts[k], span_start[span] + spline.segments[span].length() * double(step) / samples_per_span));
  }
  j["samples"] = list;
  return j.dump(1) + "\n";
}

}  // namespace

void CurveCommand::add_to(CLI::App& app) {
  command_ = app.add_subcommand(
      "curve", "Construct one log-aesthetic segment from three control points, or the G3 curve through points");
  auto* alpha = command_->add_option("--alpha", alpha_, "LCG slope α (solved, and not needed, with --inflection-start)");
  auto* points = command_->add_option("--points", points_, "P0 P1 P2 as x,y (P1: where the end tangents meet)")->expected(3);
  auto* inflection = command_->add_flag("--inflection-start", inflection_start_, "κ = 0 at P0; α is solved");
  auto* through = command_->add_option("--through", through_, "The points to pass through, as x,y (two or more)")
                      ->expected(2, 1 << 20);
  command_->add_option("--curvatures", curvatures_, "κ at each --through point (1/unit, left turns positive)")
      ->expected(2, 1 << 20)
      ->needs(through);
  command_->add_option("--slopes", slopes_, "dκ/ds at each --through point, or auto (default: chosen)")
      ->expected(2, 1 << 20)
      ->needs(through);
  command_->add_option("--angles", angles_, "The tangent's direction at each --through point in degrees, or auto")
      ->expected(2, 1 << 20)
      ->needs(through);
  through->excludes(alpha)->excludes(points)->excludes(inflection);
  command_->add_option("--samples", samples_, "Points along the segment (along each span with --through), uniform in arc length")
      ->check(CLI::Range(1, 1000000));
  command_->add_option("--format", format_, "json or svg")->check(CLI::IsMember({"json", "svg"}));
  command_->add_option("-o,--output", output_, "Write here instead of standard output");
}

std::string CurveCommand::interpolation() const {
  if (curvatures_.empty()) throw InputError("--curvatures is required with --through");
  std::vector<Vec2> through;
  for (const std::string& t : through_) through.push_back(parse_point(t, "--through"));
  const auto curvatures = parse_per_point(curvatures_, through.size(), "--curvatures", false);
  const auto slopes = parse_per_point(slopes_, through.size(), "--slopes", true);
  const auto angles = parse_per_point(angles_, through.size(), "--angles", true);
  std::vector<InterpolationPoint> points;
  for (std::size_t i = 0; i < through.size(); ++i) {
    std::optional<double> angle;
    if (angles[i]) angle = *angles[i] * std::numbers::pi / 180.0;
    points.push_back({through[i], *curvatures[i], slopes[i], angle});
  }
  const ProfileSpline spline = interpolate_curvature_profiles(points);
  if (format_ == "json") return spline_json(spline, samples_);
  if (!spline.ok()) throw InputError("no solution: " + spline.reason);
  return curve_svg(spline_samples(spline, samples_), through);
}

int CurveCommand::run() const {
  const std::string text = through_.empty() ? segment() : interpolation();
  if (output_.empty()) std::cout << text;
  else write_file_atomically(output_, text);
  return exit_code::ok;
}

std::string CurveCommand::segment() const {
  if (points_.empty()) throw InputError("--points is required (or --through)");
  if (!inflection_start_ && !alpha_) throw InputError("--alpha is required (or --inflection-start)");
  Vec2 control[3];
  for (int i = 0; i < 3; ++i) control[i] = parse_point(points_[static_cast<std::size_t>(i)], "--points");
  const SegmentFit fit = inflection_start_ ? fit_inflection_start(control[0], control[1], control[2])
                                           : fit_three_point(control[0], control[1], control[2], *alpha_);
  if (format_ == "json") return curve_json(fit, alpha_.value_or(std::nan("")), samples_);
  if (!fit.ok()) throw InputError("no solution: " + fit.reason);
  return curve_svg(fit.segment->sample(samples_), control);
}

}  // namespace gf
