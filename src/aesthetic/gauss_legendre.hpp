// The 12-point Gauss–Legendre rule (lac-math.md §8.2) for the aesthetic curves' integrals.
#pragma once

#include <array>
#include <cstddef>

namespace gf {

/// ∫_a^b f with 12 nodes; f may return any type that adds and scales (double, complex).
template <typename F>
auto gauss_legendre_12(F&& f, double a, double b) {
  static constexpr std::array<double, 6> nodes{0.12523340851146891, 0.36783149899818018, 0.58731795428661748,
                                               0.76990267419430469, 0.9041172563704748,  0.98156063424671924};
  static constexpr std::array<double, 6> weights{0.24914704581340269, 0.23349253653835464, 0.20316742672306565,
                                                 0.16007832854334611, 0.10693932599531888, 0.047175336386512022};
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  decltype(f(a)) sum{};
  for (std::size_t k = 0; k < nodes.size(); ++k)
    sum += weights[k] * (f(mid - half * nodes[k]) + f(mid + half * nodes[k]));
  return half * sum;
}

}  // namespace gf
