// The runs a contour's fairings share (RunFairings) and each fairing's own view of them
// (FairedRuns): the oracle is fair_run itself, asked directly.
#include "fair/plan_fairing.hpp"

#include <gtest/gtest.h>

#include "../test_shapes.hpp"

namespace gf {
namespace {

// The round cap on top of a stem: a smooth run between two lines.
SmoothRun stem_cap() {
  const ContourPlan plan = plan_contour(test::round_ended_stem(), {}, {3.0});
  for (const auto& piece : plan.pieces)
    if (const SmoothRun* run = std::get_if<SmoothRun>(&piece); run && run->cubics.front().p[0].y > 400.0) return *run;
  ADD_FAILURE() << "no cap in the plan";
  return {};
}

FairSettings text_settings() { return resolve_settings(FairOptions{}, 1000.0); }

void expect_same_fairing(const FairedRun& got, const FairedRun& want) {
  ASSERT_EQ(got.ok, want.ok);
  EXPECT_EQ(got.deviation, want.deviation);
  ASSERT_EQ(got.chains.size(), want.chains.size());
  for (std::size_t k = 0; k < got.chains.size(); ++k) {
    EXPECT_EQ(got.chains[k].start_frame().point, want.chains[k].start_frame().point);
    EXPECT_EQ(got.chains[k].end_frame().curvature, want.chains[k].end_frame().curvature);
  }
}

TEST(RunFairings, ARunIsFairedOnceForSettingsThatDifferOnlyInWhatTheWritebackAndRoundingRead) {
  const SmoothRun run = stem_cap();
  const FairSettings s = text_settings();
  FairSettings writeback = s;
  writeback.free_node_curvatures = !s.free_node_curvatures;
  writeback.rounding_reserve_units = 1.0;
  writeback.shortest_rounded_span_units = 16.0;
  RunFairings memo;
  const RunFairings::Entry& first = memo.fair(run, s, 0.5, RunBasis::own);
  EXPECT_EQ(&memo.fair(run, writeback, 0.5, RunBasis::own), &first);
  expect_same_fairing(first.faired, fair_run(run, writeback, 0.5, RunBasis::own));
  // What the run fairing reads (the tolerance sets the junctions' wobble limit), a budget or a
  // basis of its own: faired again.
  FairSettings tighter = s;
  tighter.tolerance_units = 0.5 * s.tolerance_units;
  EXPECT_NE(&memo.fair(run, tighter, 0.5, RunBasis::own), &first);
  EXPECT_NE(&memo.fair(run, s, 0.25, RunBasis::own), &first);
  EXPECT_NE(&memo.fair(run, s, 0.5, RunBasis::guide), &first);
  EXPECT_EQ(&memo.fair(run, s, 0.5, RunBasis::own), &first);
}

TEST(FairedRuns, ARunFairedWithinALargerBudgetStandsOnlyForTheFairingThatFairedIt) {
  const SmoothRun run = stem_cap();
  const FairSettings s = text_settings();
  RunFairings memo;
  FairedRuns one(memo), other(memo);
  const FairedRun& wide = one.get(run, s, 1.0, false, RunBasis::own);
  ASSERT_TRUE(wide.ok);
  // Its own halved budget after a run failed: the larger one's run stands.
  EXPECT_EQ(&one.get(run, s, 0.5, true, RunBasis::own), &wide);
  // Another fairing never asked for the larger budget: it gets the run as fair_run gives it
  // within its own, as it would without the memo.
  const FairedRun& narrow = other.get(run, s, 0.5, true, RunBasis::own);
  EXPECT_NE(&narrow, &wide);
  expect_same_fairing(narrow, fair_run(run, s, 0.5, RunBasis::own));
  // The same budget asked by both: one fairing of it.
  EXPECT_EQ(&other.get(run, s, 1.0, false, RunBasis::own), &wide);
}

}  // namespace
}  // namespace gf
