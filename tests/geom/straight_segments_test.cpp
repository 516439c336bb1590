#include "geom/straight_segments.hpp"

#include <gtest/gtest.h>

#include "point_set_distance.hpp"

namespace gf {
namespace {

// A closed contour of `segments`, every node smooth unless listed in `corners`.
Contour closed_contour(std::vector<Segment> segments, std::vector<std::size_t> corners) {
  Contour c;
  c.segments = std::move(segments);
  c.nodes.assign(c.segments.size(), NodeFlags{false, true});
  for (const std::size_t k : corners) c.nodes[k].smooth = false;
  return c;
}

// Its points, closed: the polyline through them draws the whole contour.
std::vector<Vec2> outline_points(const Contour& c) {
  std::vector<Vec2> pts = test::contour_points(c, 64);
  pts.push_back(pts.front());
  return pts;
}

// A D: a flat base from (0, 0) to (100, 0) drawn as a straight cubic to (40, 0) and then
// `rest` of the base, and a bowl back to the start.
Contour d_shape(Segment rest, bool smooth_at_40 = true) {
  const Cubic base{{{0, 0}, {10, 0}, {30, 0}, {40, 0}}};
  const Cubic bowl_out{{{100, 0}, {160, 0}, {160, 100}, {100, 100}}};
  const Line top{{{100, 100}, {0, 100}}};
  const Line stem{{{0, 100}, {0, 0}}};
  Contour c = closed_contour({base, rest, bowl_out, top, stem}, {0, 3, 4});
  c.nodes[1].smooth = smooth_at_40;
  return c;
}

// Where the cubic is along its chord at `t`, as a share of the chord.
double along_chord(const Cubic& c, double t) {
  const Vec2 d = c.p[3] - c.p[0];
  return dot(d, c.point_at(t) - c.p[0]) / dot(d, d);
}

TEST(StraightCubic, IsALineWhereverItsHandlesLieOnTheChordsLineAsLongAsItNeverRunsBack) {
  // Handles from 0.4 chords behind its start to 0.4 past its end, in twentieths: straight
  // exactly when, sampled finely, it never runs back along the chord.
  int straight = 0, bent = 0;
  for (int i = -8; i <= 28; ++i)
    for (int j = -8; j <= 28; ++j) {
      const Cubic c{{{0, 0}, {0.05 * i, 0}, {0.05 * j, 0}, {1, 0}}};
      bool monotone = true;
      for (int k = 1; k <= 4000 && monotone; ++k)
        monotone = along_chord(c, k / 4000.0) >= along_chord(c, (k - 1) / 4000.0) - 1e-15;
      EXPECT_EQ(is_straight(c), monotone) << "handles at " << 0.05 * i << ", " << 0.05 * j;
      ++(monotone ? straight : bent);
    }
  EXPECT_GT(straight, 0);
  EXPECT_GT(bent, 0);
  // Rounding's short stem piece: handles past each other and past the end, never running back.
  EXPECT_TRUE(is_straight(Cubic{{{424, 73}, {424, 44}, {424, 47}, {424, 45}}}));
  // A handle a hair off the line, or the chord a point.
  EXPECT_FALSE(is_straight(Cubic{{{0, 0}, {10, 0.01}, {30, 0}, {40, 0}}}));
  EXPECT_FALSE(is_straight(Cubic{{{0, 0}, {10, 0}, {-10, 0}, {0, 0}}}));
}

TEST(StraightRunsJoined, TwoStraightCubicsOnOneLineBecomeOneWithTheOuterHandles) {
  const Contour c = d_shape(Cubic{{{40, 0}, {55, 0}, {85, 0}, {100, 0}}});
  const Contour joined = with_straight_runs_joined(c);
  ASSERT_EQ(joined.segments.size(), c.segments.size() - 1);
  ASSERT_EQ(joined.nodes.size(), joined.segments.size());
  const Cubic* base = std::get_if<Cubic>(&joined.segments[0]);
  ASSERT_NE(base, nullptr);
  EXPECT_EQ(*base, (Cubic{{{0, 0}, {10, 0}, {85, 0}, {100, 0}}}));
  // The rest as it was, each node with its flags.
  for (std::size_t k = 1; k < joined.segments.size(); ++k) {
    EXPECT_EQ(joined.segments[k], c.segments[k + 1]);
    EXPECT_EQ(joined.nodes[k], c.nodes[k + 1]);
  }
  EXPECT_EQ(joined.nodes[0], c.nodes[0]);
  // The same outline: every point of each on the other.
  EXPECT_LT(test::polyline_hausdorff(outline_points(c), outline_points(joined)), 1e-9);
}

TEST(StraightRunsJoined, AStraightCubicAndALineBecomeALine) {
  const Contour c = d_shape(Line{{{40, 0}, {100, 0}}});
  const Contour joined = with_straight_runs_joined(c);
  ASSERT_EQ(joined.segments.size(), c.segments.size() - 1);
  EXPECT_EQ(joined.segments[0], Segment{(Line{{{0, 0}, {100, 0}}})});
  EXPECT_LT(test::polyline_hausdorff(outline_points(c), outline_points(joined)), 1e-9);
}

TEST(StraightRunsJoined, StraightCubicsWhoseHandlesReachPastTheirEndsBecomeOne) {
  // Rounding's pieces of a stem, each handle past the next's: one cubic, the outer handles kept.
  const Contour stem = d_shape(Cubic{{{40, 0}, {70, 0}, {38, 0}, {100, 0}}});
  const Contour joined = with_straight_runs_joined(stem);
  ASSERT_EQ(joined.segments.size(), stem.segments.size() - 1);
  EXPECT_EQ(joined.segments[0], Segment{(Cubic{{{0, 0}, {10, 0}, {38, 0}, {100, 0}}})});
  EXPECT_LT(test::polyline_hausdorff(outline_points(stem), outline_points(joined)), 1e-9);
  // A long first handle and a short second cubic whose handle reaches back: the outer handles
  // (0, 130, 99.7, 101) would run back, so they become a line.
  Contour far_reach = d_shape(Cubic{{{100, 0}, {100.3, 0}, {99.7, 0}, {101, 0}}});
  far_reach.segments[0] = Cubic{{{0, 0}, {130, 0}, {65, 0}, {100, 0}}};
  far_reach.segments[2] = Cubic{{{101, 0}, {160, 0}, {160, 100}, {100, 100}}};
  ASSERT_TRUE(is_straight(std::get<Cubic>(far_reach.segments[0])));
  ASSERT_TRUE(is_straight(std::get<Cubic>(far_reach.segments[1])));
  const Contour as_line = with_straight_runs_joined(far_reach);
  ASSERT_EQ(as_line.segments.size(), far_reach.segments.size() - 1);
  EXPECT_EQ(as_line.segments[0], Segment{(Line{{{0, 0}, {101, 0}}})});
}

TEST(StraightRunsJoined, ANodeThatTurnsBendsOrIsACornerStays) {
  // A corner between the two, though they run on along one line.
  const Contour corner = d_shape(Cubic{{{40, 0}, {55, 0}, {85, 0}, {100, 0}}}, false);
  EXPECT_EQ(with_straight_runs_joined(corner), corner);
  // The second a hair off the first's line: a turn, however slight.
  const Contour turning = d_shape(Cubic{{{40, 0}, {55, 0}, {85, 0.01}, {100, 0.01}}});
  EXPECT_EQ(with_straight_runs_joined(turning), turning);
  // The second curved, though it leaves along the line.
  const Contour bending = d_shape(Cubic{{{40, 0}, {55, 0}, {85, 0}, {100, 1}}});
  EXPECT_EQ(with_straight_runs_joined(bending), bending);
}

TEST(StraightRunsJoined, ASpurThatDoublesBackStays) {
  // Out along the line and back: joined, the two would be a point.
  Contour c = closed_contour({Line{{{0, 0}, {50, 0}}}, Line{{{50, 0}, {20, 0}}}, Line{{{20, 0}, {20, 40}}},
                              Line{{{20, 40}, {0, 0}}}},
                             {0, 2, 3});
  EXPECT_EQ(with_straight_runs_joined(c), c);
}

TEST(StraightRunsJoined, AClosedContourKeepsItsFirstNodeAndAnOpenOneItsEnds) {
  // The join at node 0 runs on along the base line: the contour still starts there.
  Contour closed = closed_contour({Line{{{0, 0}, {60, 0}}}, Line{{{60, 0}, {60, 40}}}, Line{{{60, 40}, {-30, 0}}},
                                   Line{{{-30, 0}, {0, 0}}}},
                                  {1, 2});
  EXPECT_EQ(with_straight_runs_joined(closed), closed);
  // Open: three lines on one line are one, from the first end to the last.
  Contour open;
  open.closed = false;
  open.segments = {Line{{{0, 0}, {10, 10}}}, Line{{{10, 10}, {20, 20}}}, Line{{{20, 20}, {35, 35}}}};
  open.nodes.assign(4, NodeFlags{false, true});
  const Contour joined = with_straight_runs_joined(open);
  ASSERT_EQ(joined.segments.size(), 1u);
  EXPECT_EQ(joined.segments[0], Segment{(Line{{{0, 0}, {35, 35}}})});
  EXPECT_EQ(joined.nodes.size(), 2u);
}

}  // namespace
}  // namespace gf
