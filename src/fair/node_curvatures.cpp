#include "fair/node_curvatures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gf {

namespace {

constexpr int ladder_steps = 4;       // curvatures tried either side of the path's
constexpr double ladder_reach = 0.7;  // in log κ: about a factor of two
constexpr double move_weight = 0.01;  // of a span cut, per unit of |log κ| a node moves
constexpr double cut_span = 1.0;      // a span cut into more cubics
constexpr double infeasible = std::numeric_limits<double>::infinity();

// The choice at each node and what they cost together.
struct Chosen {
  std::vector<std::size_t> at;
  double cost = infeasible;
};

// Viterbi over the nodes: the cheapest choice at each, `first` fixing node 0's (a closed chain's
// last span returns to it). None where every choice is infeasible.
template <class SpanCost, class NodeCost>
Chosen cheapest_choices(const std::vector<std::vector<double>>& choices, bool closed, std::size_t first,
                        const SpanCost& span_cost, const NodeCost& node_cost) {
  const std::size_t n = choices.size();
  std::vector<std::vector<double>> cost(n);
  std::vector<std::vector<std::size_t>> from(n);
  cost[0].assign(choices[0].size(), infeasible);
  for (std::size_t c = 0; c < choices[0].size(); ++c)
    if (!closed || c == first) cost[0][c] = node_cost(0, c);
  for (std::size_t k = 1; k < n; ++k) {
    cost[k].assign(choices[k].size(), infeasible);
    from[k].assign(choices[k].size(), 0);
    for (std::size_t b = 0; b < choices[k].size(); ++b)
      for (std::size_t a = 0; a < choices[k - 1].size(); ++a) {
        if (cost[k - 1][a] == infeasible) continue;
        const double c = cost[k - 1][a] + span_cost(k - 1, a, b) + node_cost(k, b);
        if (c < cost[k][b]) cost[k][b] = c, from[k][b] = a;
      }
  }
  std::vector<double> last = cost[n - 1];
  if (closed)
    for (std::size_t b = 0; b < last.size(); ++b)
      if (last[b] != infeasible) last[b] += span_cost(n - 1, b, first);
  const std::size_t end = static_cast<std::size_t>(std::min_element(last.begin(), last.end()) - last.begin());
  Chosen out;
  if (last[end] == infeasible) return out;
  out.cost = last[end];
  out.at.assign(n, 0);
  out.at[n - 1] = end;
  for (std::size_t k = n - 1; k > 0; --k) out.at[k - 1] = from[k][out.at[k]];
  return out;
}

}  // namespace

std::vector<double> choose_node_curvatures(std::span<const NodeCurvature> nodes, bool closed, const SpanFits& fits,
                                           const SpanSeeds& seeds) {
  const std::size_t n = nodes.size();
  std::vector<double> out(n);
  for (std::size_t k = 0; k < n; ++k) out[k] = nodes[k].path;
  if (n < 2) return out;
  const std::size_t spans = closed ? n : n - 1;
  // The spans that fit whole as the path has it; where all do, nothing to gain.
  std::vector<bool> whole(spans);
  for (std::size_t i = 0; i < spans; ++i) whole[i] = fits(i, out[i], out[(i + 1) % n]);
  if (std::all_of(whole.begin(), whole.end(), [](bool w) { return w; })) return out;
  // The path's curvature first; at a free node beside a cut span, a ladder around it and the seeds.
  std::vector<std::vector<double>> choices(n);
  for (std::size_t k = 0; k < n; ++k) choices[k] = {out[k]};
  const auto add = [&](std::size_t k, double kappa) {
    std::vector<double>& c = choices[k];
    if (!nodes[k].free || !std::isfinite(kappa) || !(kappa * c[0] > 0.0)) return;
    if (std::none_of(c.begin(), c.end(), [&](double v) { return std::abs(v - kappa) <= 1e-9 * std::abs(kappa); }))
      c.push_back(kappa);
  };
  for (std::size_t i = 0; i < spans; ++i) {
    if (whole[i]) continue;
    const std::size_t j = (i + 1) % n;
    for (const std::size_t k : {i, j})
      for (int m = -ladder_steps; m <= ladder_steps; ++m)
        if (m != 0) add(k, choices[k][0] * std::exp(ladder_reach * m / ladder_steps));
    if (const std::optional<std::array<double, 2>> seed = seeds(i)) add(i, (*seed)[0]), add(j, (*seed)[1]);
  }
  // A span with a node moved must fit whole; one as the path has it costs what it did. Each
  // pair is asked once (a closed chain's Viterbi runs once for each of its first node's choices).
  std::vector<std::vector<signed char>> fitted(spans);  // by a · |choices at the next node| + b; -1 unasked
  for (std::size_t i = 0; i < spans; ++i) fitted[i].assign(choices[i].size() * choices[(i + 1) % n].size(), -1);
  const auto span_cost = [&](std::size_t i, std::size_t a, std::size_t b) {
    const std::size_t j = (i + 1) % n;
    if (a == 0 && b == 0) return whole[i] ? 0.0 : cut_span;
    signed char& f = fitted[i][a * choices[j].size() + b];
    if (f < 0) f = fits(i, choices[i][a], choices[j][b]) ? 1 : 0;
    return f ? 0.0 : infeasible;
  };
  const auto node_cost = [&](std::size_t k, std::size_t c) {
    return c == 0 ? 0.0 : move_weight * std::abs(std::log(choices[k][c] / choices[k][0]));
  };
  Chosen best;
  for (std::size_t first = 0; first < (closed ? choices[0].size() : 1); ++first)
    if (Chosen c = cheapest_choices(choices, closed, first, span_cost, node_cost); c.cost < best.cost) best = std::move(c);
  for (std::size_t k = 0; k < best.at.size(); ++k) out[k] = choices[k][best.at[k]];
  return out;
}

}  // namespace gf
