// Where a run between two lines is cut: at its one curvature peak, unless the run is an arc
// whose curvature only wobbles about its mean (a round stroke end drawn as cubics), which is
// cut at a quarter, half and three quarters of its turning.
#include "fair/junctions.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fair/contour_plan.hpp"
#include "fair/run_reference.hpp"
#include "test_shapes.hpp"

namespace gf {
namespace {

// The runs of a closed contour that leave a line at both ends, in order.
std::vector<SmoothRun> runs_between_lines(const Contour& c) {
  std::vector<SmoothRun> runs;
  for (const auto& piece : plan_contour(c, {}, {3.0}).pieces)
    if (const auto* run = std::get_if<SmoothRun>(&piece); run && run->starts_at_line() && run->ends_at_line())
      runs.push_back(*run);
  return runs;
}

JunctionOptions text_options() { return junction_options(resolve_settings(FairOptions{}, 1000.0)); }

TEST(Junctions, ARoundStrokeEndIsCutAtQuartersOfItsTurning) {
  const Contour stem = test::round_ended_stem();
  const std::vector<SmoothRun> runs = runs_between_lines(stem);
  ASSERT_EQ(runs.size(), 2u);
  for (const SmoothRun& run : runs) {
    const RunReference ref(run);
    const std::vector<Junction> j = select_junctions(ref, true, true, text_options());
    ASSERT_EQ(j.size(), 5u);
    const double start = ref.theta_at(0.0), turning = ref.theta_at(ref.length()) - start;
    EXPECT_NEAR(std::abs(turning), std::numbers::pi, 1e-9);
    for (std::size_t k = 1; k <= 3; ++k)
      EXPECT_NEAR((ref.theta_at(j[k].s) - start) / turning, 0.25 * static_cast<double>(k), 1e-6) << k;
    EXPECT_EQ(j[2].kind, JunctionKind::extremum);
  }
}

TEST(Junctions, ATurnBetweenLinesWithAPeakIsCutThereOnly) {
  // A 150° turn between two lines drawn as one symmetric cubic whose handles nearly meet: it
  // leaves its lines gently (κ 0.0019) and peaks sharply in the middle.
  const double c = std::cos(radians(75.0)), s = std::sin(radians(75.0));
  const Vec2 p0{0, 0}, p3{60, 0}, in{c, s}, out{c, -s};
  Contour turn;
  turn.segments = {Line{{p0 - in * 100.0, p0}}, Cubic{{p0, p0 + in * 80.0, p3 - out * 80.0, p3}},
                   Line{{p3, p3 + out * 100.0}}, Line{{p3 + out * 100.0, p0 - in * 100.0}}};
  turn.nodes.assign(4, NodeFlags{});
  const std::vector<SmoothRun> runs = runs_between_lines(turn);
  ASSERT_EQ(runs.size(), 1u);
  const RunReference ref(runs[0]);
  EXPECT_NEAR(std::abs(ref.theta_at(ref.length()) - ref.theta_at(0.0)), radians(150.0), 1e-9);
  const std::vector<Junction> j = select_junctions(ref, true, true, text_options());
  ASSERT_EQ(j.size(), 3u);
  EXPECT_EQ(j[1].kind, JunctionKind::extremum);
  // At the peak of the windowed curvature: the cubic is symmetric, so half way along.
  EXPECT_NEAR(j[1].s / ref.length(), 0.5, 0.02);
}

}  // namespace
}  // namespace gf
