// --continuity g3 on whole glyphs of a real font (the S and the a stalled until a stall was
// cut): every smooth run comes out G3, and the faired pieces the fairing reports (what `fair
// --segments` exports) are checked from their own data:
// each spiral rebuilt from its start frame, length, end κ, κ′ and bumps reaches the end it reports
// and keeps κ monotone, and at every smooth join the two sides agree in point, tangent, κ and
// κ′ (a line's κ′ being 0), line joins included.
#include "fair/glyph_fairing.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "aesthetic/polynomial_spiral.hpp"
#include "fair/outline_nodes.hpp"
#include "io/source.hpp"
#include "test_fonts.hpp"

namespace gf {
namespace {

GlyphFairing fair_g3(const std::string& glyph, FairSettings& settings, const std::string& font = test::dejavu,
                     Rounding rounding = Rounding::none, FairProfile profile = FairProfile::text) {
  SourceOptions options;
  options.selection.names.push_back(glyph);
  const GlyphSource source = GlyphSource::open(font, options);
  FairOptions fo;
  fo.continuity = Continuity::g3;
  fo.rounding = rounding;
  fo.profile = profile;
  settings = resolve_settings(fo, source.font().units_per_em);
  return fair_glyph(*source.load(0), settings);
}

double relative(double a, double b, double floor) {
  const double big = std::max({std::abs(a), std::abs(b), floor});
  return std::abs(a - b) / big;
}

// Every run of `r` G3, checked on the pieces it reports (the file comment).
void expect_g3(const std::string& name, const GlyphFairing& r, const FairSettings& settings) {
  ASSERT_TRUE(r.kept.empty()) << name << ": " << r.kept.front();
  EXPECT_TRUE(r.g3_shortfalls.empty()) << name << ": " << r.g3_shortfalls.front();
  EXPECT_GT(r.g3_runs, 0) << name;
  EXPECT_LE(r.deviation, settings.tolerance_units) << name;
  int joins = 0, spirals = 0, g2_line_joins = 0;
  for (const FairedPieces& pieces : r.pieces) {
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const FairedPiece& p = pieces[i];
      EXPECT_NE(p.kind, FairedPieceKind::log_aesthetic) << name << ": a run left G2";
      EXPECT_NE(p.kind, FairedPieceKind::guide) << name << ": a run left on its smoothing guide";
      if (p.kind == FairedPieceKind::polynomial_spiral) {
        ++spirals;
        const CurvatureEnd start{p.start.point, angle_of(p.start.tangent), p.start.curvature, *p.start.curvature_derivative};
        const auto [c1, c2] = p.bumps.value_or(std::pair{0.0, 0.0});
        const PolynomialSpiral rebuilt(start, p.length, p.end.curvature, *p.end.curvature_derivative, c1, c2);
        EXPECT_LE(distance(rebuilt.end().point, p.end.point), 1e-6) << name << " piece " << i;
        EXPECT_NEAR(cross(rebuilt.end().tangent, p.end.tangent), 0.0, 1e-9) << name << " piece " << i;
        EXPECT_TRUE(rebuilt.curvature_monotone()) << name << " piece " << i;
      }
      if (!p.smooth_start || (i == 0 && pieces.size() == 1)) continue;
      const FairedPiece& q = pieces[(i + pieces.size() - 1) % pieces.size()];
      ++joins;
      EXPECT_LE(distance(q.end.point, p.start.point), 1e-6) << name << " join " << i;
      EXPECT_NEAR(cross(q.end.tangent, p.start.tangent), 0.0, 1e-9) << name << " join " << i;
      const double scale = 1.0 / settings.tolerance_units;  // flatter than this, compare absolutely
      EXPECT_LE(relative(q.end.curvature, p.start.curvature, 1e-6 * scale), 1e-9) << name << " join " << i;
      ASSERT_TRUE(q.end.curvature_derivative && p.start.curvature_derivative) << name << " join " << i;
      const double jump = relative(*q.end.curvature_derivative, *p.start.curvature_derivative, 1e-12);
      const bool line_join = p.kind == FairedPieceKind::line || q.kind == FairedPieceKind::line;
      if (line_join && jump > 1e-6) ++g2_line_joins;  // reported: too little line to slide along
      else EXPECT_LE(jump, 1e-6) << name << " join " << i << ": κ′ " << *q.end.curvature_derivative << " against "
                                 << *p.start.curvature_derivative;
    }
  }
  EXPECT_EQ(g2_line_joins, r.g2_line_joins) << name;
  // Where holding the line joins to G2 solved a run first, the segments at them are cut and
  // tried at G3 again (the S, a, e and s each had one or two line joins G2 only before).
  EXPECT_EQ(g2_line_joins, 0) << name;
  EXPECT_GT(spirals, 0) << name;
  EXPECT_GT(joins, 0) << name;
}

TEST(G3Fairing, EverySmoothJoinOfTheFairedPiecesIsG3) {
  for (const char* name : {"o", "e", "n", "c", "O", "D", "G", "U", "S", "a", "s"}) {
    FairSettings settings;
    expect_g3(name, fair_g3(name, settings), settings);
  }
}

TEST(G3Fairing, ARunAlongTheSmoothingGuideComesOutG3) {
  // Inter's m and s: a stretch of each has no G2 log-aesthetic chain within the budget and
  // follows the smoothing guide, a C2 spline; its pieces are re-expressed as spirals too.
  for (const char* name : {"uni006D", "uni0073"}) {
    FairSettings settings;
    expect_g3(name, fair_g3(name, settings, test::inter_variable), settings);
  }
}

TEST(G3Fairing, ARunStrayingALittlePastItsBudgetThroughEveryRoundComesOutG3) {
  // Cantarell's S, rounded after (half a unit of the budget kept for it): its G3 curve strayed
  // 0.308 units of a budget of 0.30 through all six rounds, and the run stayed G2. The round
  // that strayed least is kept when within a fifth past the budget; the contour is still held
  // to the tolerance.
  FairSettings settings;
  expect_g3("S", fair_g3("S", settings, test::cantarell, Rounding::integers), settings);
}

TEST(G3Fairing, OnAThousandUnitEmTheCubicsKeepRoomForG3BeforeRounding) {
  // Cantarell's S, 1000 units to the em, tolerance 1.25: with 0.75 units kept for rounding and
  // the faired outline past half a unit from its source, the cubics had nothing left to carry
  // G3 and none of its runs was G3 before rounding (TeX Gyre Heros a–z A–Z: 23 of 77, and a
  // median dκ/ds jump of 0.100 after). At most 40 % of the tolerance is kept now.
  FairSettings settings;
  const GlyphFairing r = fair_g3("S", settings, test::cantarell, Rounding::integers);
  ASSERT_TRUE(r.kept.empty());
  EXPECT_GT(r.g3_cubics.runs_g3, 0);
  EXPECT_LE(r.deviation, settings.tolerance_units);
}

TEST(G3Fairing, NodesTheSolveCarriesAcrossZeroAreHeldAndTheRunComesOutG3) {
  // Because We Learn's R, rounded after: the G3 solve of its outer run carried nearly flat
  // nodes of the stem (|κ| under 1e-3 per unit) across zero, a wiggle the G2 curve has not,
  // through its rounds of cuts, and the run stayed G2. Held at their G2 κ, the run is G3.
  FairSettings settings;
  expect_g3("R", fair_g3("R", settings, test::because_we_learn, Rounding::integers, FairProfile::handwriting), settings);
}

TEST(G3Fairing, ARunWhoseGuideBendsAtItsLineComesOutG3OnAStraightEndedGuide) {
  // Kristi's N: the smoothing guide of its right stroke holds the line's tangent where the run
  // leaves the stem but bends at once (κ·UPM 1.9), so the G2 curve jumps to κ = 0 at the line.
  // No spiral leaving the line with κ = κ′ = 0 follows it without turning κ back, and every G3
  // attempt fell short (3 smooth joins of the segments off G3). Faired again on a guide held
  // straight at its lines, the run is G3.
  FairSettings settings;
  expect_g3("N", fair_g3("N", settings, test::kristi, Rounding::none, FairProfile::handwriting), settings);
}

TEST(G3Fairing, ARunWhoseChainsMeetItsGuideOffItsOwnFramesComesOutG3OnTheGuideAlone) {
  // dkg's T, rounded after: the run along the bar's top, corner to corner, is log-aesthetic chains
  // with two stretches of the guide between them. Where a stretch meets a chain at an inflection
  // it takes the chain's frame (the guide's mean point and tangent over the feature window),
  // 0.0055 rad off the guide's own tangent there, whose κ changes sign a unit or two before the
  // join: every G3 attempt fell short (κ changed sign 9 times against the G2 curve's 5, and piece
  // by piece the last units of each stretch would not bend so), 10 smooth joins off G3. The run
  // re-expressed from its guide alone, one stretch with its own frames throughout, is G3.
  FairSettings settings;
  const GlyphFairing r = fair_g3("T", settings, test::handwriting_probe, Rounding::integers, FairProfile::handwriting);
  expect_g3("T", r, settings);
}

TEST(G3Fairing, ARunStallingThroughFourCutsComesOutG3AfterSix) {
  // Inter's a: one of its runs stalled 0.003 from meeting its junctions after four rounds of
  // cutting every segment in two, and stayed G2; the fifth and sixth rounds solve it.
  FairSettings settings;
  expect_g3("a", fair_g3("uni0061", settings, test::inter_variable), settings);
}

TEST(G3Fairing, ARunG3AtItsLinesOnlyWhenCutEvenlyComesOutG3) {
  // Because We Learn's L, rounded after: its solve stalls. Cut at equal lengths through six
  // rounds (the first attempt, 352 spirals) it is G3 at its two line joins too; cut where κ
  // changes fast as well as by length, by either mean of the secants, it solved only with those
  // joins held to G2. So the attempt that cuts evenly comes first.
  FairSettings settings;
  expect_g3("L", fair_g3("L", settings, test::because_we_learn, Rounding::integers, FairProfile::handwriting), settings);
}

// The jumps of dκ/ds, relative to the larger side (the G3 issue's measure), at every join
// between two cubics of `contours` whose tangents agree to 0.05°.
std::vector<double> cubic_slope_jumps(const std::vector<Contour>& contours) {
  std::vector<double> out;
  for (const Contour& c : contours)
    for (std::size_t i = c.closed ? 0 : 1; i < c.segments.size(); ++i) {
      const Segment& into = c.segments[(i + c.segments.size() - 1) % c.segments.size()];
      const Segment& out_of = c.segments[i];
      if (!std::holds_alternative<Cubic>(into) || !std::holds_alternative<Cubic>(out_of)) continue;
      const std::optional<Vec2> a = end_tangent(into, SegmentEnd::end), b = end_tangent(out_of, SegmentEnd::start);
      if (!a || !b || std::abs(turning_angle(*a, *b)) > 0.05 * std::numbers::pi / 180.0) continue;
      const double d1 = end_curvature(into, SegmentEnd::end).curvature_derivative.value_or(0.0);
      const double d2 = end_curvature(out_of, SegmentEnd::start).curvature_derivative.value_or(0.0);
      const double big = std::max(std::abs(d1), std::abs(d2));
      out.push_back(big > 0.0 ? std::abs(d1 - d2) / big : 0.0);
    }
  return out;
}

std::size_t node_count(const std::vector<Contour>& contours) {
  std::size_t n = 0;
  for (const Contour& c : contours) n += c.node_count();
  return n;
}

TEST(G3Fairing, TheWrittenCubicsCarryG3WithinTheNodeBudget) {
  // The G3 issue's bar on the cubics (median dκ/ds jump at smooth joins under 0.05, at most
  // 20 % more nodes than the G2 output), on the float outline: the G2 Hermite cubics of the
  // writeback alone left a median near 1.
  std::vector<double> jumps;
  std::size_t g3_nodes = 0, g2_nodes = 0;
  G3CubicReport report;
  for (const char* name : {"o", "e", "n", "c", "O", "D", "G", "U", "S", "a", "s"}) {
    FairSettings settings;
    const GlyphFairing g3 = fair_g3(name, settings);
    ASSERT_TRUE(g3.kept.empty()) << name;
    EXPECT_LE(g3.deviation, settings.tolerance_units) << name;
    report += g3.g3_cubics;
    const std::vector<double> j = cubic_slope_jumps(g3.glyph.outline.contours);
    jumps.insert(jumps.end(), j.begin(), j.end());
    g3_nodes += node_count(g3.glyph.outline.contours);
    settings.continuity = Continuity::g2;
    SourceOptions options;
    options.selection.names.push_back(name);
    const GlyphSource source = GlyphSource::open(test::dejavu, options);
    g2_nodes += node_count(fair_glyph(*source.load(0), settings).glyph.outline.contours);
  }
  ASSERT_GT(jumps.size(), 50u);
  std::nth_element(jumps.begin(), jumps.begin() + static_cast<std::ptrdiff_t>(jumps.size() / 2), jumps.end());
  EXPECT_LT(jumps[jumps.size() / 2], 0.05);
  EXPECT_LE(double(g3_nodes), 1.2 * double(g2_nodes));
  EXPECT_GT(2 * report.runs_g3, report.runs);
  EXPECT_GT(report.nodes_added, 0);
}

TEST(G3Fairing, RoundedTheCubicsStayG2AndKeepPartOfG3) {
  // On the integer grid dκ/ds at a cubic's end moves by tens of per cent a unit; rounding
  // weighs its jumps under the curvature's, and polishes the nodes where it jumps. Every smooth
  // join stays within the fairing bar's 5 % of κ; the median dκ/ds jump comes to about 0.15
  // on these glyphs (near 1 for the G2 Hermite cubics, and for rounding that ignores it).
  std::vector<double> jumps;
  for (const char* name : {"o", "e", "n", "c", "O", "D", "G", "U", "S", "a", "s"}) {
    FairSettings settings;
    const GlyphFairing g3 = fair_g3(name, settings, test::dejavu, Rounding::as_source);
    ASSERT_TRUE(g3.kept.empty()) << name;
    for (const Contour& c : g3.glyph.outline.contours)
      for (std::size_t i = 0; i < c.segments.size(); ++i) {
        const Segment& into = c.segments[(i + c.segments.size() - 1) % c.segments.size()];
        const Segment& out_of = c.segments[i];
        for (const Vec2 p : {start_point(into), end_point(into)}) EXPECT_EQ(p, nearest_grid_point(p)) << name;
        const std::optional<Vec2> a = end_tangent(into, SegmentEnd::end), b = end_tangent(out_of, SegmentEnd::start);
        if (!a || !b || std::abs(turning_angle(*a, *b)) > 0.05 * std::numbers::pi / 180.0) continue;
        const double k1 = end_curvature(into, SegmentEnd::end).curvature.value_or(0.0);
        const double k2 = end_curvature(out_of, SegmentEnd::start).curvature.value_or(0.0);
        const double flat = settings.flat_curvature();  // half a unit per em: compared by difference
        EXPECT_LE(std::abs(k1 - k2) / std::max({std::abs(k1), std::abs(k2), flat}), 0.05) << name << " join " << i;
      }
    const std::vector<double> j = cubic_slope_jumps(g3.glyph.outline.contours);
    jumps.insert(jumps.end(), j.begin(), j.end());
  }
  ASSERT_GT(jumps.size(), 50u);
  std::nth_element(jumps.begin(), jumps.begin() + static_cast<std::ptrdiff_t>(jumps.size() / 2), jumps.end());
  EXPECT_LT(jumps[jumps.size() / 2], 0.3);
}

TEST(G3Fairing, HandwritingRoundedKeepsTheCubicsG3) {
  // A handwriting font's runs often end at corners between two curves: each run's last tangent
  // is the one it arrives by (taking the next run's, the first cubic solve of these glyphs
  // reached G3 on 13 of 24 runs; 21 now). Rounded, a dκ/ds jump weighs five times what it does
  // on text (its G2 bar is a share of the joins): the G3 issue's bar, median under 0.05.
  std::vector<double> jumps;
  G3CubicReport report;
  for (const char* name : {"a", "e", "g", "o", "s", "n", "B", "S", "R", "C"}) {
    FairSettings settings;
    const GlyphFairing g3 = fair_g3(name, settings, test::because_we_learn, Rounding::as_source, FairProfile::handwriting);
    ASSERT_TRUE(g3.kept.empty()) << name;
    EXPECT_LE(g3.deviation, settings.tolerance_units) << name;
    report += g3.g3_cubics;
    const std::vector<double> j = cubic_slope_jumps(g3.glyph.outline.contours);
    jumps.insert(jumps.end(), j.begin(), j.end());
  }
  ASSERT_GT(jumps.size(), 100u);
  std::nth_element(jumps.begin(), jumps.begin() + static_cast<std::ptrdiff_t>(jumps.size() / 2), jumps.end());
  EXPECT_LT(jumps[jumps.size() / 2], 0.05);
  EXPECT_GE(4 * report.runs_g3, 3 * report.runs);
}

}  // namespace
}  // namespace gf
