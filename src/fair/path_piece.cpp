#include "fair/path_piece.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fair/cubic_change.hpp"
#include "fair/run_reference.hpp"

namespace gf {

std::vector<PathPiece> guide_pieces(const GuideStretch& g, bool whole_loop, bool at_curvature_extrema) {
  const RunReference& ref = *g.guide;
  const double length = g.s1 - g.s0;
  const int steps = std::max(8, static_cast<int>(std::ceil(length)));
  std::vector<double> kappa(static_cast<std::size_t>(steps));
  double largest = 0.0;
  for (int k = 1; k < steps; ++k)
    kappa[static_cast<std::size_t>(k)] = ref.curvature_at(g.s0 + length * k / steps),
    largest = std::max(largest, std::abs(kappa[static_cast<std::size_t>(k)]));
  // A turn of κ counts once it has swung back by a hundredth of the stretch's largest |κ|.
  const double swing = 0.01 * largest;
  // Changes of sign before |κ| first passes that hundredth, or after it last does, the first of
  // them within a twentieth of the stretch of its start (the last, of its end), are the wander
  // of an end nearly straight, not inflections (Gentium Plus's d: its bowl's guide ends at the
  // corner with κ·UPM −0.06 after +0.02; EB Garamond's Z, whose stroke's guide, cut at each,
  // wrote cubics a unit long and 23 jumps): not cut there, and that end's frame flat.
  int first_past = steps, last_past = 0;
  for (int k = 1; k < steps; ++k)
    if (std::abs(kappa[static_cast<std::size_t>(k)]) > swing) first_past = std::min(first_past, k), last_past = k;
  const auto changes_sign = [&](int k) {
    return kappa[static_cast<std::size_t>(k)] * kappa[static_cast<std::size_t>(k - 1)] < 0.0;
  };
  int lead_change = 0, tail_change = steps;  // the first change before first_past, the last after last_past
  for (int k = 2; k <= first_past && k < steps && lead_change == 0; ++k)
    if (changes_sign(k)) lead_change = k;
  for (int k = std::max(2, last_past + 1); k < steps; ++k)
    if (changes_sign(k)) tail_change = k;
  const double most_wander = 0.05 * steps;
  const bool bends = !whole_loop && last_past >= first_past;  // a whole closed guide has no ends
  const bool lead_wanders = bends && lead_change <= most_wander, tail_wanders = bends && steps - tail_change <= most_wander;
  // Sign changes count as inflections only in (cut_from, cut_to].
  const int cut_from = lead_wanders ? first_past : 1, cut_to = tail_wanders ? last_past : steps;
  std::vector<double> cuts{0.0};
  std::vector<bool> at_flip{false};
  TurnCounter counter;
  double last_sign = 0.0, theta_at_cut = ref.theta_at(g.s0);
  for (int k = 1; k < steps; ++k) {
    const double s = length * k / steps, kk = kappa[static_cast<std::size_t>(k)], theta = ref.theta_at(g.s0 + s);
    const double sign = kk > 0.0 ? 1.0 : -1.0;
    const bool flips = last_sign != 0.0 && sign != last_sign && k > cut_from && k <= cut_to;
    const bool quarter = std::abs(theta - theta_at_cut) > std::numbers::pi / 2;
    const int turns_before = counter.turns;
    counter.add(kk, swing);
    const bool turns = at_curvature_extrema && counter.turns > turns_before;
    if ((flips || quarter || turns) && s - cuts.back() > 1.0)
      cuts.push_back(s), at_flip.push_back(flips), theta_at_cut = theta;
    last_sign = sign;
  }
  cuts.push_back(length);
  LacPoint start = g.start, end = g.end;
  const auto flat_if_wandered = [swing](LacPoint& p, double kappa_past) {
    if (p.curvature * kappa_past < 0.0 && std::abs(p.curvature) <= swing) p.curvature = 0.0;
  };
  if (lead_wanders) flat_if_wandered(start, kappa[static_cast<std::size_t>(first_past)]);
  if (tail_wanders) flat_if_wandered(end, kappa[static_cast<std::size_t>(last_past)]);
  const auto frame = [&ref, &g, length, whole_loop, start, end](double s) {
    if (!whole_loop && s <= 0.0) return start;
    if (!whole_loop && s >= length) return end;
    return ref.frame_at(g.s0 + s);
  };
  std::vector<PathPiece> out;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double a = cuts[i], len = cuts[i + 1] - a;
    out.push_back({len, [frame, a](double s) { return frame(a + s); },
                   [frame, a, len](int n) {
                     std::vector<LacPoint> pts;
                     for (int k = 0; k <= n; ++k) pts.push_back(frame(a + len * k / n));
                     return pts;
                   },
                   at_flip[i]});
  }
  return out;
}

std::vector<PathPiece> chain_pieces(const FairedChain& chain) {
  if (chain.guide) return guide_pieces(*chain.guide, chain.closed, false);
  return chain.spirals.empty() ? curve_pieces(chain.segments) : curve_pieces(chain.spirals);
}

}  // namespace gf
