#include "fair/g3_local.hpp"

#include <algorithm>
#include <cmath>

namespace gf {

namespace {

constexpr int shape_samples = 32;
constexpr double noise_share = 1e-3;  // of a run's largest |κ|: turning back by less is noise

// κ′ of `piece` at s, on the side ahead of s or behind it.
std::optional<double> slope_at(const PathPiece& piece, double s, bool ahead) {
  const LacPoint here = piece.at(s);
  if (here.curvature_derivative) return here.curvature_derivative;
  const double other = std::clamp(s + (ahead ? 1.0 : -1.0) * piece.length / 64.0, 0.0, piece.length);
  if (other == s) return std::nullopt;
  return (piece.at(other).curvature - here.curvature) / (other - s);
}

// How κ runs over `curvatures` (in order): how far it turns back (Σ|Δκ| − |κ(end) − κ(start)|)
// and how often it changes sign, |κ| under `zero` having no sign.
SegmentShape shape_of(const std::vector<double>& curvatures, double zero) {
  SegmentShape out;
  double walked = 0.0, last_sign = 0.0;
  for (std::size_t k = 0; k < curvatures.size(); ++k) {
    const double c = curvatures[k];
    if (k > 0) walked += std::abs(c - curvatures[k - 1]);
    if (std::abs(c) < zero) continue;
    const double sign = c > 0.0 ? 1.0 : -1.0;
    out.sign_changes += last_sign != 0.0 && sign != last_sign;
    last_sign = sign;
  }
  out.turn_back = walked - std::abs(curvatures.back() - curvatures.front());
  return out;
}

}  // namespace

LocalTargets local_targets(const RunPieces& pieces, std::span<const std::vector<double>> cuts, bool closed) {
  LocalTargets out;
  const std::size_t m = pieces.pieces.size();
  for (std::size_t i = 0; i < m; ++i) {
    const PathPiece& piece = pieces.pieces[i];
    for (std::size_t k = 0; k + 1 < cuts[i].size(); ++k) {
      NodeSlopes s;
      s.after = slope_at(piece, cuts[i][k], true);
      if (k > 0) s.before = slope_at(piece, cuts[i][k], false);
      else if (i > 0 || closed) {
        const PathPiece& before = pieces.pieces[(i + m - 1) % m];
        s.before = slope_at(before, before.length, false);
      }
      out.slopes.push_back(s);
      std::vector<double> kappa;
      for (int q = 0; q <= shape_samples; ++q)
        kappa.push_back(piece.at(cuts[i][k] + (cuts[i][k + 1] - cuts[i][k]) * q / shape_samples).curvature);
      out.curvatures.push_back(std::move(kappa));
    }
  }
  if (!closed) out.slopes.push_back({slope_at(pieces.pieces.back(), pieces.pieces.back().length, false), std::nullopt});
  return out;
}

double shared_slope(G3NodeKind kind, NodeSlopes slopes) {
  if (kind == G3NodeKind::line || kind == G3NodeKind::line_g2) return 0.0;
  if (!slopes.before || !slopes.after) return slopes.before.value_or(slopes.after.value_or(0.0));
  const double a = *slopes.before, b = *slopes.after;
  return a * b > 0.0 ? 2.0 * a * b / (a + b) : 0.0;
}

bool LocalG3::ok() const {
  return !spirals.empty() && std::all_of(spirals.begin(), spirals.end(), [](const auto& s) { return s.has_value(); });
}

std::vector<PolynomialSpiral> LocalG3::found() const {
  std::vector<PolynomialSpiral> out;
  for (const std::optional<PolynomialSpiral>& s : spirals) out.push_back(*s);
  return out;
}

LocalG3 fit_g3_locally(const G3Problem& problem, const LocalTargets& targets, double zero) {
  LocalG3 out;
  for (std::size_t j = 0; j < problem.nodes.size(); ++j) {
    const G3Node& n = problem.nodes[j];
    const bool at_zero = n.kind == G3NodeKind::inflection || n.kind == G3NodeKind::line || n.kind == G3NodeKind::line_g2;
    out.ends.push_back({n.point, n.tangent_angle, at_zero ? 0.0 : n.curvature, shared_slope(n.kind, targets.slopes[j])});
  }
  double largest = 0.0;  // the run's largest |κ| at its nodes: what float noise is measured against
  for (const CurvatureEnd& e : out.ends) largest = std::max(largest, std::abs(e.curvature));
  const double noise = noise_share * largest;
  const std::size_t m = problem.lengths.size();
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t k = problem.closed ? (i + 1) % m : i + 1;
    const SegmentShape g2 = shape_of(targets.curvatures[i], std::max(zero, noise));
    // The spiral from a to b, if it keeps the G2 curve's shape there.
    const auto fit = [&](const CurvatureEnd& a, CurvatureEnd b) -> std::optional<PolynomialSpiral> {
      // A closed run's last segment ends where its first starts, a whole turn on.
      b.tangent_angle = a.tangent_angle + wrapped_angle(b.tangent_angle - a.tangent_angle);
      SpiralFit f = fit_polynomial_spiral(a, b);
      if (!f.ok()) return std::nullopt;
      std::vector<double> kappa;
      for (const LacPoint& q : f.spiral->sample(shape_samples)) kappa.push_back(q.curvature);
      const SegmentShape shape = shape_of(kappa, std::max(zero, noise));
      if (shape.turn_back > g2.turn_back + noise || shape.sign_changes > g2.sign_changes) return std::nullopt;
      return f.spiral;
    };
    std::optional<PolynomialSpiral> spiral = fit(out.ends[i], out.ends[k]);
    // A line end may slide along its line (into it by its room at most, or out of it by an
    // eighth of the segment), as the whole-run solve's does: a curve leaving its line with κ = 0
    // and κ′ = 0 turns more slowly at first than the G2 curve, with κ′ > 0 there.
    for (const bool at_start : {true, false}) {
      const std::size_t j = at_start ? i : k;
      const G3Node& n = problem.nodes[j];
      if (spiral || (n.kind != G3NodeKind::line && n.kind != G3NodeKind::line_g2)) continue;
      const Vec2 into = direction_of(n.tangent_angle) * (at_start ? -1.0 : 1.0);
      for (const double share : {1.0 / 32, -1.0 / 32, 1.0 / 16, -1.0 / 16, 1.0 / 8, -1.0 / 8, 1.0 / 4, 1.0 / 2}) {
        const double slide = share * problem.lengths[i];
        if (slide > n.slide_room) continue;
        CurvatureEnd moved = out.ends[j];
        moved.point = n.point + into * slide;
        spiral = at_start ? fit(moved, out.ends[k]) : fit(out.ends[i], moved);
        if (spiral) {
          out.ends[j] = moved;
          break;
        }
      }
    }
    out.spirals.push_back(std::move(spiral));
  }
  return out;
}

}  // namespace gf
