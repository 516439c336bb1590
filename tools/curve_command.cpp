// glyphfair curve --alpha A --points x0,y0 x1,y1 x2,y2 [--inflection-start] [--samples N]
//                 [--format json|svg] [-o FILE]: one log-aesthetic segment, for scripting and
// for seeing it.
#include <cmath>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "aesthetic/segment_fit.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "io/atomic_output.hpp"
#include "io/input_error.hpp"
#include "io/number_format.hpp"
#include "io/text_list.hpp"
#include "lac_point_json.hpp"

namespace gf {

namespace {

using json = nlohmann::ordered_json;  // fields in the documented order

Vec2 parse_point(const std::string& text) {
  const auto parts = split_trimmed(text);
  if (parts.size() != 2) throw InputError("--points: '" + text + "' is not x,y");
  Vec2 p;
  double* out[] = {&p.x, &p.y};
  for (std::size_t i = 0; i < 2; ++i) {
    const std::string s(parts[i]);
    char* end = nullptr;
    *out[i] = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0' || !std::isfinite(*out[i])) throw InputError("--points: '" + text + "' is not x,y");
  }
  return p;
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

// The segment with its control triangle and curvature comb, y up, fitted to a 600-unit box.
std::string curve_svg(const LogAestheticSegment& s, const Vec2 control[3], int samples) {
  const auto pts = s.sample(samples);
  double max_k = 0.0;
  for (const auto& p : pts) max_k = std::max(max_k, std::abs(p.curvature));
  double lo_x = 1e300, lo_y = 1e300, hi_x = -1e300, hi_y = -1e300;
  const auto grow = [&](Vec2 v) {
    lo_x = std::min(lo_x, v.x), lo_y = std::min(lo_y, v.y), hi_x = std::max(hi_x, v.x), hi_y = std::max(hi_y, v.y);
  };
  for (int i = 0; i < 3; ++i) grow(control[i]);
  const double size = std::max(hi_x - lo_x, hi_y - lo_y);
  const double gain = max_k > 0.0 ? 0.15 * size / max_k : 0.0;
  std::vector<Vec2> tips;
  for (const auto& p : pts) {
    tips.push_back(p.point - perpendicular(p.tangent) * (gain * p.curvature));
    grow(tips.back());
  }
  const double margin = 0.05 * size;
  std::ostringstream o;
  const auto xy = [&](Vec2 v) { return shortest_decimal(v.x) + "," + shortest_decimal(v.y); };
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << shortest_decimal(lo_x - margin) << " "
    << shortest_decimal(-hi_y - margin) << " " << shortest_decimal(hi_x - lo_x + 2 * margin) << " "
    << shortest_decimal(hi_y - lo_y + 2 * margin) << "\" width=\"600\" height=\""
    << static_cast<int>(600 * (hi_y - lo_y + 2 * margin) / (hi_x - lo_x + 2 * margin)) << "\">\n"
    << "<g transform=\"scale(1 -1)\" fill=\"none\" stroke-width=\"" << shortest_decimal(size / 400) << "\">\n";
  o << "<polyline stroke=\"#999\" stroke-dasharray=\"" << shortest_decimal(size / 100) << "\" points=\""
    << xy(control[0]) << " " << xy(control[1]) << " " << xy(control[2]) << "\"/>\n";
  for (std::size_t k = 0; k < pts.size(); ++k)
    o << "<line stroke=\"#2a6bd1\" stroke-opacity=\"0.6\" x1=\"" << shortest_decimal(pts[k].point.x) << "\" y1=\""
      << shortest_decimal(pts[k].point.y) << "\" x2=\"" << shortest_decimal(tips[k].x) << "\" y2=\""
      << shortest_decimal(tips[k].y) << "\"/>\n";
  o << "<polyline stroke=\"#2a6bd1\" points=\"";
  for (const Vec2 t : tips) o << xy(t) << " ";
  o << "\"/>\n<polyline stroke=\"#111\" stroke-width=\"" << shortest_decimal(size / 200) << "\" points=\"";
  for (const auto& p : pts) o << xy(p.point) << " ";
  o << "\"/>\n</g>\n</svg>\n";
  return o.str();
}

}  // namespace

void CurveCommand::add_to(CLI::App& app) {
  command_ = app.add_subcommand("curve", "Construct one log-aesthetic segment from three control points");
  command_->add_option("--alpha", alpha_, "LCG slope α (solved, and not needed, with --inflection-start)");
  command_->add_option("--points", points_, "P0 P1 P2 as x,y (P1: where the end tangents meet)")->required()->expected(3);
  command_->add_flag("--inflection-start", inflection_start_, "κ = 0 at P0; α is solved");
  command_->add_option("--samples", samples_, "Points along the segment, uniform in arc length")
      ->check(CLI::Range(1, 1000000));
  command_->add_option("--format", format_, "json or svg")->check(CLI::IsMember({"json", "svg"}));
  command_->add_option("-o,--output", output_, "Write here instead of standard output");
}

int CurveCommand::run() const {
  if (!inflection_start_ && !alpha_) throw InputError("--alpha is required (or --inflection-start)");
  Vec2 control[3];
  for (int i = 0; i < 3; ++i) control[i] = parse_point(points_[static_cast<std::size_t>(i)]);
  const SegmentFit fit = inflection_start_ ? fit_inflection_start(control[0], control[1], control[2])
                                           : fit_three_point(control[0], control[1], control[2], *alpha_);
  std::string text;
  if (format_ == "json") {
    text = curve_json(fit, alpha_.value_or(std::nan("")), samples_);
  } else {
    if (!fit.ok()) throw InputError("no solution: " + fit.reason);
    text = curve_svg(*fit.segment, control, samples_);
  }
  if (output_.empty()) std::cout << text;
  else write_file_atomically(output_, text);
  return exit_code::ok;
}

}  // namespace gf
