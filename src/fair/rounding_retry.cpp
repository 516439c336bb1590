#include "fair/rounding_retry.hpp"

#include <algorithm>

namespace gf {

std::vector<std::size_t> cubics_about_strays(std::span<const double> by_segment, double tolerance_units,
                                             std::size_t cubics) {
  std::vector<std::size_t> out;
  const std::size_t m = by_segment.size();
  if (m != cubics) return out;
  for (std::size_t k = 0; k < m; ++k)
    if (by_segment[k] > tolerance_units)
      for (const std::size_t q : {(k + m - 1) % m, k, (k + 1) % m}) out.push_back(q);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

void halve_allowances(HandleStepLimits& limits, std::span<const std::size_t> strayed) {
  if (strayed.empty()) {
    limits.allowance *= 0.5;
    for (double& e : limits.allowance_by_cubic) e *= 0.5;
    return;
  }
  for (const std::size_t k : strayed)
    if (k < limits.allowance_by_cubic.size()) limits.allowance_by_cubic[k] *= 0.5;
}

}  // namespace gf
