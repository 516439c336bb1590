// Rounding again after a stray: only the cubics about where the rounded contour strayed lose
// half their allowance.
#include "fair/rounding_retry.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace gf {
namespace {

TEST(RoundingRetry, TheCubicsAtAndBesideEachStrayAreNamedOnce) {
  // Segments 2 and 3 stray (2.6 and 3.0 against 2.5): cubics 1–4, each once.
  const std::vector<double> d{1.0, 2.0, 2.6, 3.0, 0.5, 2.5, 1.2};
  EXPECT_EQ(cubics_about_strays(d, 2.5, d.size()), (std::vector<std::size_t>{1, 2, 3, 4}));
  // At the seam of a closed contour the neighbours wrap: the last segment and the first.
  const std::vector<double> seam{2.7, 0.1, 0.1, 0.1, 0.1};
  EXPECT_EQ(cubics_about_strays(seam, 2.5, seam.size()), (std::vector<std::size_t>{0, 1, 4}));
  // Exactly at the tolerance is within it.
  EXPECT_TRUE(cubics_about_strays(std::vector<double>{2.5, 2.5}, 2.5, 2).empty());
  // Rounding merged two nodes: the segments no longer match the cubics, so none is named.
  EXPECT_TRUE(cubics_about_strays(d, 2.5, d.size() + 1).empty());
}

TEST(RoundingRetry, OnlyTheNamedCubicsLoseHalfTheirAllowance) {
  HandleStepLimits limits;
  limits.allowance = 1.0;
  limits.allowance_by_cubic = {0.8, 0.6, 0.4, 0.2};
  halve_allowances(limits, std::vector<std::size_t>{1, 3});
  EXPECT_EQ(limits.allowance_by_cubic, (std::vector<double>{0.8, 0.3, 0.4, 0.1}));
  EXPECT_EQ(limits.allowance, 1.0);
  // None named (where the stray is not known): every cubic's, and the default.
  halve_allowances(limits, {});
  EXPECT_EQ(limits.allowance_by_cubic, (std::vector<double>{0.4, 0.15, 0.2, 0.05}));
  EXPECT_EQ(limits.allowance, 0.5);
}

}  // namespace
}  // namespace gf
