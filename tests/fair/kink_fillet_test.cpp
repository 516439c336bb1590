// Kinks between lines filleted G2: the fillet leaves each line along it with κ = 0 (both its
// handles on the vertex), its ends on the grid, within the allowance of the lines; a kink
// whose fillet would bend against its neighbours stays.
#include "fair/kink_fillet.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geom/curvature.hpp"
#include "geom/join.hpp"
#include "point_set_distance.hpp"
#include "test_shapes.hpp"

namespace gf {
namespace {

using test::polygon;

double degrees(Vec2 a, Vec2 b) { return std::abs(turning_angle(a, b)) * 180.0 / std::numbers::pi; }

std::vector<Vec2> dense(const Contour& c) { return test::contour_points(c, 200); }

// The fillets of a filleted polygon, each checked: every point on the grid, every join smooth
// (0°) or a corner (3° or more), each fillet leaving its lines with κ = 0 exactly.
std::vector<std::size_t> fillets_checked(const Contour& out) {
  EXPECT_EQ(out.segments.size(), out.nodes.size());
  std::vector<std::size_t> fillets;
  for (std::size_t i = 0; i < out.segments.size(); ++i) {
    const Segment& s = out.segments[i];
    for_each_point(s, [](Vec2 p) { EXPECT_TRUE(test::on_grid(p)); });
    const Segment& next = out.segments[(i + 1) % out.segments.size()];
    const double turn = degrees(*end_tangent(s, SegmentEnd::end), *end_tangent(next, SegmentEnd::start));
    EXPECT_TRUE(turn == 0.0 || turn >= 3.0) << "join " << i << " turns " << turn << "°";
    if (is_line(s)) continue;
    fillets.push_back(i);
    EXPECT_EQ(*end_curvature(s, SegmentEnd::start).curvature, 0.0);
    EXPECT_EQ(*end_curvature(s, SegmentEnd::end).curvature, 0.0);
  }
  return fillets;
}

TEST(KinkFillet, AKinkBetweenTwoLinesBecomesG2OnTheGrid) {
  // A stroke's side bending by 1.07° at (280, 0) between corners (Cantarell's y).
  const Contour source = polygon({{115, -217}, {200, -217}, {280, 0}, {468, 482}, {388, 482}});
  const double allowance = 1.0;
  const Contour out = fillet_line_kinks(source, allowance, true);
  EXPECT_EQ(fillets_checked(out).size(), 1u);
  EXPECT_LE(test::directed_to_polyline(dense(out), dense(source)), allowance);
}

TEST(KinkFillet, AKinkAgainstItsNeighboursStays) {
  // A side bending left at one kink and right at the next: a fillet at each would be an S
  // (an inflection the polygon has not got), so neither is filleted.
  const Contour source = polygon({{0, 0}, {1000, 0}, {1000, 100}, {600, 104}, {300, 100}, {0, 104}});
  const Contour out = fillet_line_kinks(source, 2.0, true);
  EXPECT_EQ(out.segments.size(), source.segments.size());
}

TEST(KinkFillet, AKinkBetweenBendsEachWayIsFilleted) {
  // A stroke from a curve bending left, through a 0.92° kink left, into a curve bending right
  // (a split italic stroke, Gentium Plus Italic's V): the contour already turns from one bend
  // to the other along the lines, and the fillet, bending left with the first curve, adds no
  // inflection. Mirrored, the kink turns right with the first curve.
  for (const double m : {1.0, -1.0}) {
    const auto at = [m](double x, double y) { return Vec2{m * x, y}; };
    Contour source = test::closed({Cubic{{at(-200, 60), at(-120, 10), at(-60, 0), at(0, 0)}}, Line{{at(0, 0), at(500, 0)}},
                                   Line{{at(500, 0), at(1000, 8)}},
                                   Cubic{{at(1000, 8), at(1125, 10), at(1175, 0), at(1200, -40)}},
                                   Line{{at(1200, -40), at(1200, -300)}}, Line{{at(1200, -300), at(-200, -300)}},
                                   Line{{at(-200, -300), at(-200, 60)}}});
    const Contour out = fillet_line_kinks(source, 1.0, true);
    const auto fillet = std::find_if(out.segments.begin(), out.segments.end(), [&](const Segment& s) {
      const Cubic* c = std::get_if<Cubic>(&s);
      return c && c->p[1] == at(500, 0) && c->p[2] == at(500, 0);
    });
    ASSERT_NE(fillet, out.segments.end()) << "mirror " << m;
    EXPECT_EQ(*end_curvature(*fillet, SegmentEnd::start).curvature, 0.0);
    EXPECT_EQ(*end_curvature(*fillet, SegmentEnd::end).curvature, 0.0);
    for (const Join& j : joins_of(out)) EXPECT_NE(j.kind, JoinKind::kink) << "node " << j.node;
    EXPECT_LE(test::directed_to_polyline(dense(out), dense(source)), 1.0);
  }
}

TEST(KinkFillet, TheLongerLegIsAtMostFourTimesTheShorterOrAStep) {
  // An 8-unit line from a corner, bent 0.82° into a 700-unit line of step (70, 1) (a stroke split
  // near its end): the fillet's leg on the long line is one step, not the whole line, which
  // would be drawn as a curve for nothing gentler.
  const Contour source = polygon({{0, 0}, {8, 0}, {708, 10}, {708, -200}, {0, -200}});
  const Contour out = fillet_line_kinks(source, 2.0, true);
  const std::vector<std::size_t> fillets = fillets_checked(out);
  ASSERT_EQ(fillets.size(), 1u);
  const Cubic& fillet = std::get<Cubic>(out.segments[fillets.front()]);
  EXPECT_EQ(fillet.p[1], (Vec2{8, 0}));
  EXPECT_EQ(fillet.p[0], (Vec2{0, 0}));  // the short line whole
  EXPECT_EQ(fillet.p[3], (Vec2{78, 1}));  // one step of the long one
  EXPECT_LE(test::directed_to_polyline(dense(out), dense(source)), 2.0);
}

// Liberation Sans's N: its left stem tapers, (5, −97) then (5, −167), kinks of 1.2° and 1.7°
// with no whole step of either line short enough for a leg. And its w: 1.9° between (31, 139)
// and (205, 794), each line a single step. Each is filleted at a vertex moved on the grid (for
// the N where its outer lines meet, the middle line taken), the outer lines redrawn to it from
// their corners, which turn by a fraction of a degree.
TEST(KinkFillet, KinksWithoutWholeLegsAreFilletedAtAMovedVertex) {
  const std::vector<std::vector<Vec2>> shapes = {{{168, 0}, {168, 1409}, {328, 1200}, {333, 1103}, {338, 936}, {338, 0}},
                                                 {{1000, 0}, {1072, 149}, {1103, 288}, {1308, 1082}, {1200, 1082}}};
  const double allowance = 2.3;
  for (const std::vector<Vec2>& shape : shapes) {
    const Contour source = polygon(shape);
    EXPECT_EQ(fillet_line_kinks(source, 0.2, true).segments.size(), source.segments.size()) << "no fillet within 0.2";
    const Contour out = fillet_kinks_at_moved_vertices(source, allowance);
    const std::vector<std::size_t> fillets = fillets_checked(out);
    ASSERT_EQ(fillets.size(), 1u);
    // Each leg at most half its line: the lines stay lines beside the fillet.
    const std::size_t i = fillets.front(), n = out.segments.size();
    const Segment &before = out.segments[(i + n - 1) % n], &fillet = out.segments[i], &after = out.segments[(i + 1) % n];
    const Vec2 vertex = std::get<Cubic>(fillet).p[1];
    EXPECT_GE(norm(end_point(before) - start_point(before)), distance(start_point(fillet), vertex));
    EXPECT_GE(norm(end_point(after) - start_point(after)), distance(end_point(fillet), vertex));
    EXPECT_LE(test::directed_to_polyline(dense(out), dense(source)), allowance);
    EXPECT_LE(test::directed_to_polyline(dense(source), dense(out)), allowance);
  }
}

// Liberation Sans's M (OFL): its inner stroke tapers in three lines, 2.79° apart at (420, 960)
// and 1.53° at (364, 1130), between corners. The first kink's legs would lie on a line of step
// (−123, 320), none within the 0.29 units the contour leaves; the second has whole legs, and
// filleted first it took half the line between them, leaving the first between lines whose
// far ends are no longer both corners: a kink no moved vertex could take. The kinks without
// whole legs go first, with their same-way neighbour, to a moved vertex.
TEST(KinkFillet, AKinkWithoutWholeLegsTakesItsNeighbourToAMovedVertex) {
  const Contour source = polygon({{923, 0}, {789, 0}, {420, 960}, {364, 1130}, {331, 1240}, {338, 0}});
  const double left = 0.29, most = 2.3;
  // Whole legs first: the neighbour alone, and the kink stays.
  const Contour neighbour_first = fillet_kinks_at_moved_vertices(fillet_line_kinks(source, left, true), most);
  bool kinked = false;
  for (std::size_t i = 0; i < neighbour_first.segments.size(); ++i) {
    const double turn = degrees(*end_tangent(neighbour_first.segments[i], SegmentEnd::end),
                                *end_tangent(neighbour_first.segments[(i + 1) % neighbour_first.segments.size()], SegmentEnd::start));
    kinked = kinked || (turn > 0.0 && turn < 3.0);
  }
  EXPECT_TRUE(kinked);
  // The kink without whole legs first: one fillet for both, every join smooth or a corner.
  Contour out = source;
  for (const double allowance : {left, most}) out = fillet_legless_kinks_at_moved_vertices(out, left, allowance);
  EXPECT_EQ(fillets_checked(out).size(), 1u);
  EXPECT_LE(test::directed_to_polyline(dense(out), dense(source)), most);
  EXPECT_LE(test::directed_to_polyline(dense(source), dense(out)), most);
}

TEST(MergeLineKinks, LinesMeetingAtAKinkBecomeOneAcrossTheSeamToo) {
  // A square whose base bends 1.1° at its middle, where the contour starts: the base is one
  // line again, and the contour starts where its last line did.
  const Contour bent = polygon({{50, 0.5}, {100, 0}, {100, 100}, {0, 100}, {0, 0}});
  const Contour merged = merge_line_kinks(bent, 1.0);
  EXPECT_EQ(merged.segments, polygon({{0, 0}, {100, 0}, {100, 100}, {0, 100}}).segments);
  EXPECT_EQ(merged.nodes.size(), merged.segments.size());
}

TEST(MergeLineKinks, ASliverFoldedOntoItselfComesBackAsItWas) {
  // One kink, but merged there the triangle would be one line there and back.
  const Contour sliver = polygon({{0, 0}, {100, 1}, {200, 0}});
  EXPECT_EQ(merge_line_kinks(sliver, 1.0), sliver);
  // Nor is a line merged into a curve.
  Contour with_curve = polygon({{0, 0}, {100, 1}, {200, 0}, {100, 100}});
  with_curve.segments[1] = Cubic{{{100, 1}, {133, 0.7}, {166, 0.3}, {200, 0}}};
  EXPECT_EQ(merge_line_kinks(with_curve, 1.0), with_curve);
}

TEST(MergeLineKinks, AChainMergesOnlyWhereItsOneLineStaysWithinTheAllowance) {
  // A base bending 1.83° at (100, 4), 1.07 units from the line (0, 0)–(150, 4.4), then 0.23°
  // at (150, 4.4), a tenth of a unit from the line (100, 4)–(200, 4.6): the second bend goes,
  // the first stays (Liberation Sans Narrow's V, all or nothing before, kept all five).
  const Contour bent = polygon({{0, 0}, {100, 4}, {150, 4.4}, {200, 4.6}, {200, 100}, {0, 100}});
  EXPECT_EQ(merge_line_kinks(bent, 1.0).segments, polygon({{0, 0}, {100, 4}, {200, 4.6}, {200, 100}, {0, 100}}).segments);
  // With room for the first as well, the base is one line.
  EXPECT_EQ(merge_line_kinks(bent, 2.0).segments, polygon({{0, 0}, {200, 4.6}, {200, 100}, {0, 100}}).segments);
}

TEST(MergeLineKinks, NoMergedLineTurnsACurvesJoinIntoAKink) {
  // Lines bending 1.15° at (100, 0), within a unit of their chord, the second leaving into a
  // curve along its own direction: one line would meet the curve 0.57° off, a kink the fillets
  // between lines cannot take. The lines stay.
  Contour lines = polygon({{0, 0}, {100, 0}, {200, 2}, {300, 100}, {0, 100}});
  lines.segments[2] = Cubic{{{200, 2}, {250, 3}, {300, 50}, {300, 100}}};
  EXPECT_EQ(merge_line_kinks(lines, 2.0), lines);
  // Leaving along the chord instead, the curve keeps its join smooth and the lines merge.
  lines.segments[2] = Cubic{{{200, 2}, {250, 2.5}, {300, 50}, {300, 100}}};
  EXPECT_EQ(merge_line_kinks(lines, 2.0).segments.size(), 4u);
}

TEST(MergeLineKinks, OnlyAgainstTheirNeighboursMergesTheKinksNoFilletMayTake) {
  // URW P052's Z, its top: bent 1.1° and 0.63° one way, then 0.28° back, which a fillet would
  // turn into an inflection (AKinkAgainstItsNeighboursStays): only that bend merges.
  const Contour top = polygon({{633, 692}, {477, 689}, {427, 689}, {245, 691}, {80, 692}, {80, 530}, {637, 530}});
  EXPECT_EQ(merge_line_kinks(top, 1.25, true).segments,
            polygon({{633, 692}, {477, 689}, {427, 689}, {80, 692}, {80, 530}, {637, 530}}).segments);
  // Every bend merges where the allowance lets it: the second is 2.6 units off the line from
  // (633, 692) past it.
  EXPECT_EQ(merge_line_kinks(top, 1.25).segments,
            polygon({{633, 692}, {427, 689}, {80, 692}, {80, 530}, {637, 530}}).segments);
}

TEST(KinkFillet, WithoutAKinkTheContourComesBackAsItWas) {
  const Contour square = polygon({{0, 0}, {100, 0}, {100, 100}, {0, 100}});
  EXPECT_EQ(fillet_line_kinks(square, 1.0, true).segments.size(), 4u);
}

}  // namespace
}  // namespace gf
