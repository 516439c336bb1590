// The last pass over a rounded text contour (fair/join_mending): each join the check counts as
// a curvature jump searched for on the grid, judged by the check's own rule (CurvatureJumpRule),
// G1 exact on whole units, and the two-sided distance from the source.
#include "fair/join_mending.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "fair/outline_faults.hpp"
#include "geom/join.hpp"
#include "io/source.hpp"
#include "test_fonts.hpp"
#include "test_shapes.hpp"

namespace gf {
namespace {

constexpr double upm = 1000.0;

using test::closed;

Cubic cubic(Vec2 a, Vec2 b, Vec2 c, Vec2 d) { return Cubic{a, b, c, d}; }
Line line(Vec2 a, Vec2 b) { return Line{a, b}; }

// Noto Serif's W (1,000 units to the em) as the fairing rounded it at stop 93: its left leg, a
// line of step (−8, 27), meets the curve to the cap serif with κ·UPM 0.149 on the curve's side.
Contour noto_serif_w() {
  return closed({cubic({133, 486}, {125, 513}, {94, 617}, {86, 637}), cubic({86, 637}, {82, 647}, {75, 658}, {61, 665}),
                 cubic({61, 665}, {47, 672}, {32, 672}, {22, 672}), line({22, 672}, {9, 672}), line({9, 672}, {9, 714}),
                 line({9, 714}, {284, 714}), line({284, 714}, {284, 672}), line({284, 672}, {261, 672}),
                 cubic({261, 672}, {247, 672}, {219, 672}, {206, 646}), cubic({206, 646}, {203, 640}, {201, 633}, {201, 626}),
                 cubic({201, 626}, {201, 616}, {205, 602}, {209, 588}), line({209, 588}, {301, 266}),
                 cubic({301, 266}, {309, 238}, {325, 182}, {344, 98}), cubic({344, 98}, {371, 223}, {371, 223}, {386, 278}),
                 line({386, 278}, {503, 707}), line({503, 707}, {577, 707}), line({577, 707}, {693, 301}),
                 cubic({693, 301}, {711, 238}, {727, 182}, {744, 98}), cubic({744, 98}, {756, 156}, {768, 201}, {772, 216}),
                 cubic({772, 216}, {788, 276}, {788, 276}, {802, 325}), line({802, 325}, {878, 591}),
                 cubic({878, 591}, {880, 598}, {884, 612}, {884, 624}), cubic({884, 624}, {884, 644}, {873, 657}, {859, 664}),
                 cubic({859, 664}, {843, 672}, {823, 672}, {817, 672}), line({817, 672}, {794, 672}),
                 line({794, 672}, {794, 714}), line({794, 714}, {1038, 714}), line({1038, 714}, {1038, 672}),
                 line({1038, 672}, {1019, 672}), cubic({1019, 672}, {1003, 672}, {988, 672}, {971, 655}),
                 cubic({971, 655}, {956, 640}, {951, 623}, {929, 546}), line({929, 546}, {773, 0}), line({773, 0}, {684, 0}),
                 line({684, 0}, {521, 560}), line({521, 560}, {368, 0}), line({368, 0}, {277, 0}),
                 line({277, 0}, {133, 486})});
}

// A circle of radius 200 about the origin as four cubics, each handle `handle` long but the
// first cubic's first, `first`: equal handles give every node the same curvature.
Contour circle(double first, double handle = 110.0) {
  return closed({cubic({200, 0}, {200, first}, {handle, 200}, {0, 200}), cubic({0, 200}, {-handle, 200}, {-200, handle}, {-200, 0}),
                 cubic({-200, 0}, {-200, -handle}, {-handle, -200}, {0, -200}),
                 cubic({0, -200}, {handle, -200}, {200, -handle}, {200, 0})});
}

// TeX Gyre Pagella's W (1,000 units to the em) about its right arm's top: a (2, 7) leg, a turn
// of 68° in 45 units, a (10, 1) line to the serif's corner. `rounded`: two cubics as the
// fairing rounded them at stop 101, κ·UPM 9.9 where they leave the leg; else the source's one.
Contour pagella_w_arm(bool rounded) {
  std::vector<Segment> segments;
  if (rounded)
    segments = {line({771, 128}, {913, 625}), cubic({913, 625}, {917, 639}, {922, 645}, {925, 648}),
                cubic({925, 648}, {934, 657}, {944, 658}, {954, 659}), line({954, 659}, {984, 662})};
  else
    segments = {line({771, 128}, {914, 630}), cubic({914, 630}, {919, 647}, {930, 657}, {952, 659}),
                line({952, 659}, {984, 662})};
  for (const Line& l : {line({984, 662}, {984, 692}), line({984, 692}, {771, 692}), line({771, 692}, {771, 128})})
    segments.push_back(l);
  return closed(segments);
}

bool all_on_grid(const Contour& c) {
  bool on = true;
  for (const Segment& s : c.segments) for_each_point(s, [&](Vec2 p) { on = on && test::on_grid(p); });
  return on;
}

// No jump or kink at a smooth join, no inflection beyond the source's, no corner lost.
void expect_no_faults(const OutlineFaults& f) {
  EXPECT_EQ(f.jumps, 0);
  EXPECT_EQ(f.kinks, 0);
  EXPECT_EQ(f.inflections, 0);
  EXPECT_EQ(f.corners_lost, 0);
}

JoinMendingLimits limits_for(double tolerance) { return {.tolerance_units = tolerance, .units_per_em = upm}; }

// `rounded`, with one jump against `source` as the check counts it, mended in one join: no
// fault left, on the grid, within 1.25 units of the source.
void expect_the_jump_mended(const Contour& source, Contour& rounded) {
  const FaultCounter counter(source, upm);
  ASSERT_EQ(counter.count(rounded).jumps, 1);
  EXPECT_EQ(mend_jumping_joins(rounded, SampledContour(source), limits_for(1.25)), 1);
  expect_no_faults(counter.count(rounded));
  EXPECT_TRUE(all_on_grid(rounded));
  EXPECT_LE(distance_between(SampledContour(rounded), SampledContour(source)), 1.25);
}

TEST(JoinMending, ACurveLeavingASlantedLegWithAJumpIsMendedOnTheGridWithinTheTolerance) {
  const Contour source = noto_serif_w();
  const FaultCounter counter(source, upm);
  ASSERT_EQ(counter.count(source).jumps, 1);
  Contour mended = source;
  EXPECT_EQ(mend_jumping_joins(mended, SampledContour(source), limits_for(1.25)), 1);
  expect_no_faults(counter.count(mended));
  // The join stays where the leg ends, the curve's handle exactly on the leg's line.
  const Cubic& curve = std::get<Cubic>(mended.segments[0]);
  const Line& leg = std::get<Line>(mended.segments.back());
  EXPECT_EQ(cross(leg.p[1] - leg.p[0], curve.p[1] - curve.p[0]), 0.0);
  EXPECT_GT(dot(leg.p[1] - leg.p[0], curve.p[1] - curve.p[0]), 0.0);
  EXPECT_TRUE(all_on_grid(mended));
  EXPECT_EQ(mended.segments.size(), source.segments.size());
  EXPECT_LE(distance_between(SampledContour(mended), SampledContour(source)), 1.25);
}

TEST(JoinMending, AJumpBetweenTwoCubicsIsMended) {
  const Contour source = circle(110.0);
  const FaultCounter counter(source, upm);
  ASSERT_EQ(counter.count(source).jumps, 0);
  // One handle ten units short: κ·UPM 6.0 against 5.0 at (200, 0), and the cubic's far end
  // bends differently from the next cubic too.
  Contour mended = circle(100.0);
  ASSERT_EQ(counter.count(mended).jumps, 2);
  EXPECT_GE(mend_jumping_joins(mended, SampledContour(source), limits_for(1.25)), 1);
  EXPECT_EQ(counter.count(mended).jumps, 0);
  EXPECT_EQ(counter.count(mended).kinks, 0);
  EXPECT_TRUE(all_on_grid(mended));
  EXPECT_LE(distance_between(SampledContour(mended), SampledContour(source)), 1.25);
}

TEST(JoinMending, AJoinEveryMendOfWhichStraysPastTheToleranceIsLeftAsItWas) {
  const Contour source = noto_serif_w();
  Contour mended = source;
  // The nearest mend slides the leg's end a step (8, −27) down the leg, the curve's near handle
  // kept: the curve leaves the leg sooner and as straight, 0.036 units from where it was.
  EXPECT_EQ(mend_jumping_joins(mended, SampledContour(source), limits_for(0.02)), 0);
  EXPECT_EQ(mended, source);
  EXPECT_EQ(mend_jumping_joins(mended, SampledContour(source), limits_for(0.05)), 1);
  EXPECT_EQ(std::get<Line>(mended.segments.back()).p[1], (Vec2{141, 459}));
  EXPECT_EQ(FaultCounter(source, upm).count(mended).jumps, 0);
}

TEST(JoinMending, ATightCurveBetweenTwoLinesIsRedrawnSeatedOnBoth) {
  // Two or three units from its node, no grid point gives the curve's handle a place on the
  // leg: the node goes 18 units up the curve, where its tangent line crosses both lines on the
  // grid, and the line to the corner goes, the second cubic reaching the corner along it.
  Contour mended = pagella_w_arm(true);
  expect_the_jump_mended(pagella_w_arm(false), mended);
  ASSERT_EQ(mended.segments.size(), 6u);
  ASSERT_EQ(mended.nodes.size(), 6u);
  const Line& leg = std::get<Line>(mended.segments[0]);
  const Cubic& leaving = std::get<Cubic>(mended.segments[1]);
  const Cubic& arriving = std::get<Cubic>(mended.segments[2]);
  // κ = 0 exactly where the curve leaves the leg and where it meets the corner's line: each
  // cubic's handles on its line.
  const Vec2 along_leg = leg.p[1] - leg.p[0], along_top = Vec2{10, 1};
  EXPECT_EQ(leaving.p[0], leg.p[1]);
  EXPECT_EQ(cross(leaving.p[1] - leg.p[0], along_leg), 0.0);
  EXPECT_EQ(cross(leaving.p[2] - leg.p[0], along_leg), 0.0);
  EXPECT_EQ(arriving.p[3], (Vec2{984, 662}));
  EXPECT_EQ(cross(arriving.p[1] - arriving.p[3], along_top), 0.0);
  EXPECT_EQ(cross(arriving.p[2] - arriving.p[3], along_top), 0.0);
}

// Quicksand's x (The Quicksand Project Authors, OFL; UPM 1000) as the fairing rounded it at
// stop 104: its lower left leg, a line of step (−10, −13), runs into the foot's curve at
// (92, 13), and the curve reaches the baseline extremum (65, −3) in one cubic, leaving the leg
// with κ·UPM 13 against 0. The leg, carried on, crosses y = −3 off the grid.
Contour quicksand_x_rounded() {
  return closed({cubic({450, 27}, {450, 13}, {434, -5}, {420, -5}), cubic({420, -5}, {406, -5}, {392, 13}, {362, 52}),
                 line({362, 52}, {242, 208}), line({242, 208}, {92, 13}), cubic({92, 13}, {82, 0}, {73, -3}, {65, -3}),
                 cubic({65, -3}, {51, -3}, {36, 6}, {36, 24}), cubic({36, 24}, {36, 32}, {39, 39}, {43, 43}),
                 line({43, 43}, {208, 253}), line({208, 253}, {47, 460}), cubic({47, 460}, {40, 469}, {33, 478}, {33, 487}),
                 cubic({33, 487}, {33, 500}, {47, 516}, {65, 516}), cubic({65, 516}, {75, 516}, {83, 511}, {88, 503}),
                 line({88, 503}, {245, 303}), line({245, 303}, {395, 503}),
                 cubic({395, 503}, {398, 507}, {404, 515}, {420, 515}), cubic({420, 515}, {436, 515}, {448, 507}, {448, 490}),
                 cubic({448, 490}, {448, 483}, {446, 476}, {441, 471}), line({441, 471}, {279, 258}),
                 line({279, 258}, {443, 45}), cubic({443, 45}, {448, 37}, {450, 32}, {450, 27})});
}

TEST(JoinMending, ACurveFromALegIntoAnExtremumIsRedrawnAsTwoCubics) {
  SourceOptions options;
  options.selection.names.push_back("x");
  Contour mended = quicksand_x_rounded();
  expect_the_jump_mended(GlyphSource::open(test::quicksand, options).load(0)->outline.contours.at(0), mended);
  // A node more: the leg, a cubic leaving it with its first three points on the leg's line
  // (κ = 0 there exactly), a cubic on to the extremum, which stays where it was, level.
  ASSERT_EQ(mended.segments.size(), 21u);
  const Line& leg = std::get<Line>(mended.segments[3]);
  const Cubic& leaving = std::get<Cubic>(mended.segments[4]);
  const Cubic& arriving = std::get<Cubic>(mended.segments[5]);
  const Vec2 along_leg{-10, -13};
  EXPECT_EQ(leg.p[0], (Vec2{242, 208}));
  EXPECT_EQ(leaving.p[0], leg.p[1]);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(cross(leaving.p[i] - leg.p[0], along_leg), 0.0) << i;
  EXPECT_EQ(arriving.p[3], (Vec2{65, -3}));
  EXPECT_EQ(arriving.p[2].y, -3.0);
}

// The same x begun at the foot's curve, so the join that jumps is the contour's first node:
// the mend splits the curve after it and finds the leg as the contour's last segment (its
// index taken before the split had been another segment's).
TEST(JoinMending, AJumpAtTheContoursFirstNodeIsMendedAsAnyOther) {
  SourceOptions options;
  options.selection.names.push_back("x");
  Contour mended = quicksand_x_rounded();
  std::rotate(mended.segments.begin(), mended.segments.begin() + 4, mended.segments.end());
  expect_the_jump_mended(GlyphSource::open(test::quicksand, options).load(0)->outline.contours.at(0), mended);
  ASSERT_EQ(mended.segments.size(), 21u);
  const Line& leg = std::get<Line>(mended.segments.back());
  const Cubic& leaving = std::get<Cubic>(mended.segments[0]);
  EXPECT_EQ(leg.p[0], (Vec2{242, 208}));
  EXPECT_EQ(leaving.p[0], leg.p[1]);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(cross(leaving.p[i] - leg.p[0], Vec2{-10, -13}), 0.0) << i;
}

// The same x with the leg's last stretch, from (132, 65), a straight cubic, as rounding leaves
// a stem (Comic Neue's d: (385, 47) to (385, 27) before its round end), and the node between it
// and the rest of the leg smooth. The mends from a line read the two as one line: the curve
// leaving the leg takes four of its steps, more than the straight cubic has.
TEST(JoinMending, AStraightCubicBesideTheJumpIsALineToTheMends) {
  SourceOptions options;
  options.selection.names.push_back("x");
  Contour mended = quicksand_x_rounded();
  mended.segments[3] = line({242, 208}, {132, 65});
  mended.segments.insert(mended.segments.begin() + 4, cubic({132, 65}, {122, 52}, {112, 39}, {92, 13}));
  mended.nodes.insert(mended.nodes.begin() + 4, NodeFlags{false, true});
  expect_the_jump_mended(GlyphSource::open(test::quicksand, options).load(0)->outline.contours.at(0), mended);
  // As the x with its leg one line is mended: the leg, a cubic leaving it with its first three
  // points on the leg's line (κ = 0 there exactly), a cubic on to the extremum.
  ASSERT_EQ(mended.segments.size(), 21u);
  const Line& leg = std::get<Line>(mended.segments[3]);
  const Cubic& leaving = std::get<Cubic>(mended.segments[4]);
  EXPECT_EQ(leg.p[0], (Vec2{242, 208}));
  EXPECT_EQ(leaving.p[0], leg.p[1]);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(cross(leaving.p[i] - leg.p[0], Vec2{-10, -13}), 0.0) << i;
  EXPECT_EQ(std::get<Cubic>(mended.segments[5]).p[3], (Vec2{65, -3}));
}

}  // namespace
}  // namespace gf
