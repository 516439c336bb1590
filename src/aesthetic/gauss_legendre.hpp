// Gauss–Legendre rules (lac-math.md §8.2) for the aesthetic curves' integrals: 12 points for
// panels as long as their distance to a singularity, 6 and 4 for short panels far from one.
#pragma once

#include <array>
#include <complex>
#include <cstddef>

namespace gf {

/// The positive nodes of the N-point rule on [−1, 1] and their weights; the rule is symmetric.
template <std::size_t N>
struct GaussLegendreRule;

template <>
struct GaussLegendreRule<4> {
  static constexpr std::array<double, 2> nodes{0.33998104358485626, 0.86113631159405258};
  static constexpr std::array<double, 2> weights{0.65214515486254614, 0.34785484513745386};
};

template <>
struct GaussLegendreRule<6> {
  static constexpr std::array<double, 3> nodes{0.23861918608319691, 0.66120938646626451, 0.93246951420315203};
  static constexpr std::array<double, 3> weights{0.46791393457269105, 0.36076157304813861, 0.17132449237917035};
};

template <>
struct GaussLegendreRule<12> {
  static constexpr std::array<double, 6> nodes{0.12523340851146891, 0.36783149899818018, 0.58731795428661748,
                                               0.76990267419430469, 0.9041172563704748,  0.98156063424671924};
  static constexpr std::array<double, 6> weights{0.24914704581340269, 0.23349253653835464, 0.20316742672306565,
                                                 0.16007832854334611, 0.10693932599531888, 0.047175336386512022};
};

/// ∫_a^b f with N nodes; f may return any type that adds and scales (double, complex).
template <std::size_t N = 12, typename F>
auto gauss_legendre(F&& f, double a, double b) {
  using Rule = GaussLegendreRule<N>;
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  decltype(f(a)) sum{};
  for (std::size_t k = 0; k < Rule::nodes.size(); ++k)
    sum += Rule::weights[k] * (f(mid - half * Rule::nodes[k]) + f(mid + half * Rule::nodes[k]));
  return half * sum;
}

/// ∫_a^b e^{i(φ + σt)} g(t) dt with N nodes, σ = ±1, g real. The phase at the node pair
/// mid ± h·x is e^{i(φ+σ·mid)} e^{±iσh·x}: one cosine and sine per pair and one for the
/// panel, where the plain rule takes one per node (the LAC quadrature's largest cost).
template <std::size_t N = 12, typename G>
std::complex<double> gauss_legendre_phased(G&& g, double phase, double sigma, double a, double b) {
  using Rule = GaussLegendreRule<N>;
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  double even = 0.0, odd = 0.0;  // Σ w cos(hx)(g₊ + g₋) and Σ w sin(hx)(g₊ − g₋)
  for (std::size_t k = 0; k < Rule::nodes.size(); ++k) {
    const double offset = half * Rule::nodes[k];
    const double plus = g(mid + offset), minus = g(mid - offset);
    even += Rule::weights[k] * std::cos(offset) * (plus + minus);
    odd += Rule::weights[k] * std::sin(offset) * (plus - minus);
  }
  return half * std::polar(1.0, phase + sigma * mid) * std::complex<double>(even, sigma * odd);
}

}  // namespace gf
