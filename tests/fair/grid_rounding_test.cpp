// Rounding to the grid: integer coordinates everywhere, and G1 exact — a smooth node's two
// handles exactly collinear with it (integer cross product zero), axis nodes axis-parallel; and
// the cubics of no extent a writeback can leave dropped before rounding.
#include "fair/grid_rounding.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "fair/contour_plan.hpp"
#include "fair/cubic_change.hpp"
#include "geom/curvature.hpp"
#include "test_shapes.hpp"

namespace gf {
namespace {

using test::node;
using test::on_grid;

TEST(GridRounding, PrimitiveStepsDivideByTheCommonDivisor) {
  // DejaVu's s spine: (63, −14) = 7·(9, −2).
  EXPECT_EQ(primitive_step({63, -14}), (Vec2{9, -2}));
  EXPECT_EQ(primitive_step({0, -5}), (Vec2{0, -1}));
  EXPECT_EQ(primitive_step({-270, -1650}), (Vec2{-9, -55}));
  EXPECT_FALSE(primitive_step({0, 0}));
  EXPECT_TRUE(is_primitive({2, 1}));
  EXPECT_TRUE(is_primitive({-1, 0}));
  EXPECT_FALSE(is_primitive({2, 2}));
  EXPECT_FALSE(is_primitive({0, 0}));
}

TEST(GridRounding, SmoothNodesStayExactlyCollinear) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    // A closed contour of 6 smooth nodes on a wobbly circle, handles along the tangent.
    std::vector<OutlineNode> nodes;
    for (int i = 0; i < 6; ++i) {
      const double t = i * std::numbers::pi / 3 + 0.2 * u(rng);
      const double r = 300 + 40 * u(rng);
      const Vec2 p{r * std::cos(t) + 0.37, r * std::sin(t) - 0.81};
      const Vec2 tangent{-std::sin(t), std::cos(t)};
      OutlineNode n;
      n.point = p;
      n.in_handle = p - tangent * (60 + 30 * u(rng));
      n.out_handle = p + tangent * (60 + 30 * u(rng));
      if (i % 3 == 0) n.grid_step = std::abs(tangent.x) > std::abs(tangent.y) ? Vec2{tangent.x > 0 ? 1.0 : -1.0, 0.0}
                                                                             : Vec2{0.0, tangent.y > 0 ? 1.0 : -1.0};
      nodes.push_back(n);
    }
    const std::vector<OutlineNode> r = round_to_grid(nodes, true);
    ASSERT_EQ(r.size(), nodes.size());
    for (const OutlineNode& n : r) {
      EXPECT_TRUE(on_grid(n.point) && on_grid(*n.in_handle) && on_grid(*n.out_handle));
      EXPECT_EQ(cross(n.point - *n.in_handle, *n.out_handle - n.point), 0.0);  // exact in integers
      EXPECT_GT(dot(n.point - *n.in_handle, *n.out_handle - n.point), 0.0);
    }
    // Nodes move to a neighbouring grid point at most; handles are placed for G1 and G2.
    for (std::size_t i = 0; i < nodes.size(); ++i) EXPECT_LE(distance(r[i].point, nodes[i].point), 1.5 * std::sqrt(2.0));
  }
}

TEST(GridRounding, CornersRoundFreelyAndLinesKeepTheirHandleOnTheLine) {
  // A line (0,0)→(200.3,0.2) meeting a curve tangentially at node 1, then a corner.
  std::vector<OutlineNode> nodes(3);
  nodes[0].point = {0.2, 0.1};
  nodes[0].smooth = false;
  nodes[0].in_handle = Vec2{30.4, 150.6};
  nodes[1].point = {200.3, 0.2};
  nodes[1].out_handle = Vec2{260.7, 0.2};
  nodes[2].point = {300.4, 100.6};
  nodes[2].smooth = false;
  nodes[2].in_handle = Vec2{300.4, 60.2};
  nodes[2].out_handle = Vec2{150.2, 180.9};
  const std::vector<OutlineNode> r = round_to_grid(nodes, true);
  const OutlineNode& join = r[1];
  EXPECT_EQ(cross(join.point - r[0].point, *join.out_handle - join.point), 0.0);
  for (const OutlineNode& n : r) EXPECT_TRUE(on_grid(n.point));
}

// EB Garamond's t, unrounded: the bar's right end rises to its y-extremum B and falls 2.9
// units to the corner C, whose handle is 0.4 units long. Its nearest grid point is C itself,
// and a handle on its node leaves the cubic no direction there: κ·UPM 15,000 at the corner.
// Rounded, the handle stays off its node, and the cubic's curvature stays within a radius of
// a unit.
TEST(GridRounding, ACornersShortHandleStaysOffItsNode) {
  const std::vector<OutlineNode> nodes{
      node(Vec2{305.9027, 48.9368}, Vec2{305.9027, 43.9488}, Vec2{305.9027, 53.3938}, true, Vec2{0, 1}),
      node(Vec2{298.7977, 60.5886}, Vec2{303.9954, 60.5886}, Vec2{297.5093, 60.5886}, true, Vec2{-1, 0}),
      node(Vec2{296, 60}, Vec2{296.3754, 60.1464}, Vec2{281.2798, 48.9598}, false),
      node(Vec2{228.3502, 40.9255}, Vec2{258.1743, 40.9255}, std::nullopt, false),
      node(Vec2{305.9027, 20}, std::nullopt, Vec2{305.9027, 30}, false),
  };
  HandleStepLimits limits;
  limits.allowance = 0.7;
  const std::vector<OutlineNode> r = round_to_grid(nodes, true, limits);
  ASSERT_EQ(r.size(), nodes.size());
  ASSERT_TRUE(r[2].in_handle);
  EXPECT_NE(*r[2].in_handle, r[2].point);
  const Cubic c = outline_cubic(r, 1);
  for (int k = 0; k <= 64; ++k)
    EXPECT_LE(std::abs(curvature(derivatives_at(c, k / 64.0)).value_or(1e9)), 1.0) << "at " << k / 64.0;
}

// Because We Build's v, unrounded: a line falling 2° to the bowl's foot, a 2.4-unit cubic to
// the horizontal extremum, the bowl rising to a corner. The line's grid directions near 2° have
// primitive steps of 17 units and more, and a handle of whole steps on the line folded the
// short cubic back on itself (a spike with an extremum off its nodes). Its join slides back
// along the line instead, so the curve leaving the line has room for a step.
TEST(GridRounding, AShortCurveBesideALineOfLongStepDoesNotFold) {
  const std::vector<OutlineNode> nodes{
      node(Vec2{133.0, 0.0}, std::nullopt, std::nullopt, false),
      node(Vec2{216.0, -3.0}, std::nullopt, Vec2{216.42, -3.02}),
      node(Vec2{218.43, -3.05}, Vec2{217.32, -3.05}, Vec2{239.83, -3.05}, true, Vec2{1.0, 0.0}),
      node(Vec2{252.56, 22.58}, Vec2{252.56, 9.07}, std::nullopt, false),
  };
  HandleStepLimits limits;
  limits.allowance = 2.0;  // what the unrounded outline leaves of a handwriting tolerance
  const std::vector<OutlineNode> r = round_to_grid(nodes, false, limits);

  ASSERT_EQ(r.size(), nodes.size());
  ASSERT_TRUE(r[1].out_handle && !r[1].in_handle);
  // G1 exact where the curve leaves the line; the extremum keeps horizontal handles.
  EXPECT_EQ(cross(r[1].point - r[0].point, *r[1].out_handle - r[1].point), 0.0);
  EXPECT_GT(dot(r[1].point - r[0].point, *r[1].out_handle - r[1].point), 0.0);
  EXPECT_EQ(r[2].in_handle->y, r[2].point.y);
  EXPECT_EQ(r[2].out_handle->y, r[2].point.y);
  for (std::size_t i = 1; i < 3; ++i) {
    const Cubic c = outline_cubic(r, i);
    for (const Vec2 p : c.p) EXPECT_TRUE(on_grid(p));
    // No fold: no H/V extremum off the nodes, no handle reaching past the chord.
    EXPECT_EQ(inner_axis_extrema(c), 0) << "cubic " << i;
    EXPECT_LE(std::max(distance(c.p[0], c.p[1]), distance(c.p[3], c.p[2])), distance(c.p[0], c.p[3])) << "cubic " << i;
  }
  // The line keeps most of its length; its far end and the extremum stay within the allowance.
  EXPECT_LE(distance(r[0].point, nodes[0].point), limits.allowance);
  EXPECT_GE(distance(r[0].point, r[1].point), 40.0);
  EXPECT_LE(distance(r[2].point, nodes[2].point), limits.allowance);
}

// Comic Neue's i, unrounded: the stem's foot curves out of a horizontal extremum into a
// 434-unit line 0.8° off the vertical. Every grid direction within a unit of its ends steps 63
// units or more; the foot's 25-unit cubic took a handle of one such step and folded into a
// loop. A brush font's tolerance leaves room to move the line's ends a few units, so the line
// may stand upright or take a short step, and the foot keeps its shape.
TEST(GridRounding, ALineADegreeOffTheVerticalLeavesItsCurveRoom) {
  const std::vector<OutlineNode> nodes{
      node(Vec2{110.311, -5.018}, std::nullopt, Vec2{118.628, -5.018}, false),
      node(Vec2{134.930, 3.904}, Vec2{128.315, -2.711}, Vec2{142.803, 11.777}),
      node(Vec2{143.0, 26.0}, Vec2{142.950, 22.379}, std::nullopt),
      node(Vec2{149.0, 460.0}, std::nullopt, std::nullopt, false),
  };
  HandleStepLimits limits;
  limits.allowance = 9.0;  // what the unrounded outline leaves of the 12-unit tolerance
  const std::vector<OutlineNode> r = round_to_grid(nodes, false, limits);

  ASSERT_EQ(r.size(), nodes.size());
  // G1 exact where the foot meets the line.
  ASSERT_TRUE(r[2].in_handle && !r[2].out_handle);
  EXPECT_EQ(cross(r[3].point - r[2].point, r[2].point - *r[2].in_handle), 0.0);
  EXPECT_GT(dot(r[3].point - r[2].point, r[2].point - *r[2].in_handle), 0.0);
  for (std::size_t i = 0; i < 2; ++i) {
    const Cubic c = outline_cubic(r, i);
    for (const Vec2 p : c.p) EXPECT_TRUE(on_grid(p));
    // No fold: bent one way as the unrounded cubic is, no H/V extremum off the nodes, no handle
    // reaching past the chord.
    EXPECT_EQ(curvature_shape(c, 0.0).sign_changes, curvature_shape(outline_cubic(nodes, i), 0.0).sign_changes)
        << "cubic " << i;
    EXPECT_EQ(inner_axis_extrema(c), 0) << "cubic " << i;
    EXPECT_LE(overreach_length(c), 0.0) << "cubic " << i;
  }
}

// A curve leaving a (−7, 2) diagonal with κ = 0 for a smooth node 190 units on, whose
// tangent (−0.57, 0.82) rounds to a grid direction whose handle line crosses the line's
// extension between two whole steps: the curve left the line with κ·UPM 0.3 at 2048 units to
// the em. The node turned to a primitive direction a little off its tangent, whose handle
// lands on the line at a whole step, keeps κ = 0 exactly (fair/handle_steps.hpp).
TEST(GridRounding, ACurveLeavesADiagonalLineWithZeroCurvature) {
  const Vec2 a{700.0, -200.0}, join{0.0, 0.0};
  const Vec2 along = (join - a) / norm(join - a);
  const Vec2 k{-149.61, 120.11}, k_in = join + along * 90.1;  // κ = 0 at the join, unrounded
  const Vec2 tangent = (k - k_in) / norm(k - k_in);
  const Vec2 e{-230.0, 330.0};
  const std::vector<OutlineNode> nodes{
      node(a, std::nullopt, std::nullopt, false),
      node(join, std::nullopt, join + along * 50.0),
      node(k, k_in, k + tangent * 60.0),
      node(e, e - Vec2{0.0, 50.0}, std::nullopt, false),
  };
  HandleStepLimits limits;
  limits.allowance = 1.5;  // a text tolerance, most of it left
  const std::vector<OutlineNode> r = round_to_grid(nodes, false, limits);

  ASSERT_EQ(r.size(), nodes.size());
  for (std::size_t i = 1; i < 3; ++i)
    for (const Vec2 p : outline_cubic(r, i).p) EXPECT_TRUE(on_grid(p));
  // G1 exact at the join and at the node (integer cross products).
  EXPECT_EQ(cross(r[1].point - r[0].point, *r[1].out_handle - r[1].point), 0.0);
  EXPECT_EQ(cross(r[2].point - *r[2].in_handle, *r[2].out_handle - r[2].point), 0.0);
  // κ = 0 where the curve leaves the line: its far handle on the line, exactly.
  EXPECT_EQ(cross(r[1].point - r[0].point, *r[2].in_handle - r[1].point), 0.0);
  for (std::size_t i = 0; i < nodes.size(); ++i) EXPECT_LE(distance(r[i].point, nodes[i].point), 2.0) << "node " << i;
}

// Liberation Sans's W, unrounded: the right stroke of its first V, a nearly straight S-free
// run of two cubics between the corners at its foot and its top (κ·UPM under 0.3 throughout).
// Rounded, whole steps tilted the node's far handles either way, and one cubic came out
// bending the other way from its unrounded self: an inflection at the node, which the check
// counts however flat. A cubic bending wholly the other way now costs more than any choice
// that keeps the jumps within the target.
TEST(GridRounding, ANearlyStraightCubicKeepsTheWayItBends) {
  const std::vector<OutlineNode> nodes{
      node(Vec2{544.0, 168.0}, std::nullopt, Vec2{590.27, 382.55}, false),
      node(Vec2{703.13, 790.42}, Vec2{639.31, 562.22}, Vec2{721.93, 857.64}),
      node(Vec2{877.0, 1409.0}, Vec2{799.55, 1134.8}, std::nullopt, false),
  };
  HandleStepLimits limits;
  limits.flat_curvature = 0.5 / 2048.0;
  limits.allowance = 1.6;  // Liberation Sans's tolerance of 2.56 units, most of it left
  const std::vector<OutlineNode> r = round_to_grid(nodes, false, limits);

  ASSERT_EQ(r.size(), nodes.size());
  for (std::size_t i = 0; i < 2; ++i) {
    const CurvatureShape before = curvature_shape(outline_cubic(nodes, i), 0.0);
    const CurvatureShape after = curvature_shape(outline_cubic(r, i), 0.0);
    ASSERT_NE(before.bend, 0) << "cubic " << i;
    EXPECT_EQ(after.bend, before.bend) << "cubic " << i;
  }
}

// Because We Build's k, unrounded: where the leg leaves the stem the pen turned back within
// three units, and the last cubic of that hook meets a line of step (−1, 2) a unit from its
// start. Choosing whole steps for κ = 0 at the line join, pass after pass, grew the handle on
// the line to eleven steps: a 25-unit spike. A handle reaching far past its cubic's chord now
// costs as an added extremum does, more the farther it reaches.
TEST(GridRounding, AHandleOnALineDoesNotGrowIntoASpike) {
  const std::vector<OutlineNode> nodes{
      node(Vec2{240.61, 145.00}, std::nullopt, Vec2{239.89, 146.30}, false),
      node(Vec2{238.97, 147.91}, Vec2{239.36, 147.23}, Vec2{238.42, 148.87}),
      node(Vec2{237.25, 150.75}, Vec2{238.36, 150.75}, Vec2{236.56, 150.75}, true, Vec2{-1.0, 0.0}),
      node(Vec2{238.08, 148.86}, Vec2{237.78, 149.48}, Vec2{238.38, 148.24}),
      node(Vec2{239.0, 147.0}, Vec2{239.31, 146.38}, std::nullopt),
      node(Vec2{221.0, 183.0}, std::nullopt, std::nullopt, false),
  };
  HandleStepLimits limits;
  limits.allowance = 6.0;  // a handwriting tolerance, most of it left
  const std::vector<OutlineNode> r = round_to_grid(nodes, false, limits);

  ASSERT_EQ(r.size(), nodes.size());
  for (std::size_t i = 0; i < 4; ++i) {
    const Cubic c = outline_cubic(r, i);
    EXPECT_LE(overreach_length(c), 0.0) << "cubic " << i;
    for (const Vec2 p : c.p) EXPECT_LE(distance(p, nodes[i].point), 6.0) << "cubic " << i;
  }
}

// Open Sans's g, unrounded: past the bottom of its lower bowl a node turns 5.9° off the
// horizontal, its in-handle 4.6 units long, the cubic before it 110 units. Directions were
// sought no longer than the shorter handle, and none within 4 units lies within the kink limit
// of 5.9°, so the node took (1, 0): the cubic, rising 5 units to end level, became an S with
// κ·UPM of 382 at the node (an inflection and a g2-jump). A longer direction, up to the longer
// handle, now keeps the node's tangent within the kink limit and both cubics bent one way.
TEST(GridRounding, AShortHandleTakesALongerDirectionThanTurnPastTheKinkLimit) {
  const std::vector<OutlineNode> nodes{
      node(Vec2{491.775, -365.021}, Vec2{364.673, -365.021}, Vec2{549.476, -365.021}, true, Vec2{1.0, 0.0}),
      node(Vec2{602.413, -359.605}, Vec2{597.848, -360.075}, Vec2{644.577, -355.262}),
      node(Vec2{730.025, -333.838}, Vec2{688.990, -347.516}, Vec2{746.116, -328.474}),
      node(Vec2{776.938, -314.598}, Vec2{761.837, -322.148}, std::nullopt, false),
  };
  HandleStepLimits limits;
  limits.allowance = 1.0;  // a text tolerance, most of it left
  const std::vector<OutlineNode> r = round_to_grid(nodes, false, limits);

  ASSERT_EQ(r.size(), nodes.size());
  const OutlineNode& n = r[1];
  const Vec2 faired = *nodes[1].out_handle - nodes[1].point;
  EXPECT_EQ(cross(n.point - *n.in_handle, *n.out_handle - n.point), 0.0);
  EXPECT_LT(std::abs(turning_angle(faired, *n.out_handle - n.point)), radians(kink_limit_deg));
  // Both cubics at the node bend left all along, as before rounding.
  for (const std::size_t i : {0u, 1u}) {
    const Cubic c = outline_cubic(r, i);
    for (int k = 0; k <= 16; ++k)
      EXPECT_GT(curvature(derivatives_at(c, k / 16.0)).value_or(0.0), 0.0) << "cubic " << i << " at " << k / 16.0;
  }
}

// dkg Bold's C, unrounded: where the top stroke ends the pen turns in two units, corner, a
// curve over a horizontal extremum, corner, a line leaving at 37°. Rounding put the extremum and
// the line's start on one grid point, and the cubic between them became a loop of a unit with
// its ends together (an extremum off any node). The two nodes become one corner: the curve
// arrives as it did, the line leaves as it did.
TEST(GridRounding, NodesRoundedOntoOnePointBecomeOne) {
  const std::vector<OutlineNode> nodes{
      node(Vec2{69.50, 601.18}, std::nullopt, Vec2{100.57, 663.34}, false),
      node(Vec2{210.25, 775.75}, Vec2{122.69, 689.79}, Vec2{210.32, 776.74}, false),
      node(Vec2{211.50, 777.33}, Vec2{210.95, 777.33}, Vec2{211.79, 777.33}, true, Vec2{1.0, 0.0}),
      node(Vec2{212.0, 777.0}, Vec2{211.98, 777.16}, std::nullopt, false),
      node(Vec2{251.0, 807.0}, std::nullopt, std::nullopt, false),
  };
  HandleStepLimits limits;
  limits.allowance = 2.0;
  const std::vector<OutlineNode> r = round_to_grid(nodes, false, limits);

  for (std::size_t i = 0; i + 1 < r.size(); ++i) {
    EXPECT_NE(r[i].point, r[i + 1].point) << "nodes " << i << " and " << i + 1;
    EXPECT_TRUE(on_grid(r[i].point));
  }
  EXPECT_LE(distance(r.front().point, nodes.front().point), std::sqrt(2.0));
  EXPECT_LE(distance(r.back().point, nodes.back().point), std::sqrt(2.0));
  for (std::size_t i = 0; i + 1 < r.size(); ++i) {
    if (!r[i].out_handle || !r[i + 1].in_handle) continue;  // a line
    EXPECT_EQ(inner_axis_extrema(outline_cubic(r, i)), 0) << "cubic " << i;
  }
}

// Whether the curvatures either side of a smooth node meet the check's G2 rule at 1000 UPM:
// within 5 % of the larger, or within 0.05/UPM of each other where both are under 0.5/UPM.
bool g2_by_the_check(double k1, double k2) {
  const double big = std::max(std::abs(k1), std::abs(k2)) * 1000.0;
  return big >= 0.5 ? std::abs(k1 - k2) * 1000.0 <= 0.05 * big : std::abs(k1 - k2) * 1000.0 <= 0.05;
}

// EB Garamond's P, unrounded at a tolerance of 1.25 (UPM 1000), where the bowl leaves the stem:
// κ·UPM 3 to 5 along cubics 10 to 40 units long, whose far handles want to lie a fifth of a
// unit off their nodes' tangents. Rounding put node 3's in-side far handle on its tangent
// (κ = 0) and left the other side at −10 (a jump, and an S in the cubic before). Such a node is
// now seated flat as an inflection is: both far handles on its tangent line.
TEST(GridRounding, ANodeRoundingLeftFlatOnOneSideIsSeatedFlatOnBoth) {
  const std::vector<OutlineNode> nodes{
      node(Vec2{258.23, 272.82}, std::nullopt, Vec2{258.23, 269.46}, false),
      node(Vec2{268.79, 260.86}, Vec2{260.96, 264.78}, Vec2{282.50, 254.01}, true, Vec2{2.0, -1.0}),
      node(Vec2{304.13, 254.00}, Vec2{302.89, 254.00}, Vec2{308.33, 254.00}, true, Vec2{1.0, 0.0}),
      node(Vec2{325.63, 254.80}, Vec2{316.36, 254.14}, Vec2{330.41, 255.14}),
      node(Vec2{347.03, 257.13}, Vec2{337.96, 255.79}, Vec2{358.68, 258.86}),
      node(Vec2{388.87, 267.01}, Vec2{373.17, 261.78}, std::nullopt, false),
  };
  HandleStepLimits limits;
  limits.flat_curvature = 0.5 / 1000.0;
  limits.allowance = 0.45;  // what the unrounded outline leaves of the tolerance
  const std::vector<OutlineNode> r = round_to_grid(nodes, false, limits);

  ASSERT_EQ(r.size(), nodes.size());
  for (std::size_t i = 1; i + 1 < r.size(); ++i) {
    const OutlineNode& n = r[i];
    EXPECT_EQ(cross(n.point - *n.in_handle, *n.out_handle - n.point), 0.0) << "node " << i;
    EXPECT_TRUE(g2_by_the_check(node_curvature(outline_cubic(r, i - 1), SegmentEnd::end),
                                node_curvature(outline_cubic(r, i), SegmentEnd::start)))
        << "node " << i;
  }
  for (std::size_t i = 0; i + 1 < r.size(); ++i)
    EXPECT_LE(curvature_shape(outline_cubic(r, i), 0.0).sign_changes,
              curvature_shape(outline_cubic(nodes, i), 0.0).sign_changes)
        << "cubic " << i;
}

// Breip's L under --continuity g3 (UPM 2048), unrounded: its stem's left side, whose vertical
// extremum (node 13) has a curve below it to a node whose line stands a unit over on the grid.
// Whole steps from there bulged the curve left past the extremum's node whatever its handles;
// the flat-node seat then turned the node 2.3° off the vertical, and the curve kept an
// x-extremum inside with no node (the check's "missing extremum").
TEST(GridRounding, AnExtremumRoundedBesideALineKeepsItsNode) {
  const std::vector<OutlineNode> nodes{
      node(Vec2{92.0, 418.0}, std::nullopt, Vec2{140.206689, 178.258545}, false),
      node(Vec2{368.5553853858288, 119.26848757209453}, Vec2{270.038327, 119.268488}, Vec2{451.732767, 119.268488}, true, Vec2{1.0, 0.0}),
      node(Vec2{565.05445306961224, 190.49067299593389}, Vec2{518.638629, 161.318530}, Vec2{593.937159, 208.643328}),
      node(Vec2{635.73388803502132, 222.3166711430826}, Vec2{615.692828, 222.316671}, Vec2{652.130451, 222.316671}, true, Vec2{1.0, 0.0}),
      node(Vec2{674.99204339574862, 195.06732094335246}, Vec2{665.813808, 213.164187}, Vec2{584.490065, 104.561411}, false),
      node(Vec2{374.69873224033074, 63.677856041435184}, Vec2{473.160788, 63.677856}, Vec2{252.955106, 63.677856}, true, Vec2{-1.0, 0.0}),
      node(Vec2{79.729667754986039, 255.17449564773943}, Vec2{144.226314, 126.181203}, Vec2{22.476546, 369.680739}, true, Vec2{-1.0, 2.0}),
      node(Vec2{17.779787264335344, 565.33350411579102}, Vec2{17.779787, 501.177625}, Vec2{17.779787, 615.708560}, true, Vec2{0.0, 1.0}),
      node(Vec2{24.605262107542909, 721.71154262290793}, Vec2{20.675506, 686.343737}, Vec2{26.947699, 742.793477}, true, Vec2{1.0, 9.0}),
      node(Vec2{36.973759527709859, 761.73184880059046}, Vec2{30.041412, 754.799501}, Vec2{41.252357, 766.010446}, true, Vec2{1.0, 1.0}),
      node(Vec2{52.170138607331758, 768.1136938398588}, Vec2{46.750548, 768.113694}, Vec2{57.648943, 768.113694}, true, Vec2{1.0, 0.0}),
      node(Vec2{67.296126677491955, 761.7227688164287}, Vec2{63.054660, 765.964236}, Vec2{75.771736, 753.247159}, true, Vec2{1.0, -1.0}),
      node(Vec2{76.738102216605711, 731.35282750812951}, Vec2{76.738102, 739.278241}, Vec2{76.738102, 723.113852}, true, Vec2{0.0, -1.0}),
      node(Vec2{75.693756439732624, 682.9509252837006}, Vec2{75.693756, 714.487413}, Vec2{75.693756, 655.385542}, true, Vec2{0.0, -1.0}),
      node(Vec2{77.484399719159299, 596.93286453030862}, Vec2{76.491651, 621.820273}, Vec2{78.930847, 560.671586}),
      node(Vec2{86.408892620028325, 479.03625556469046}, Vec2{80.965256, 538.462621}, std::nullopt),
  };
  HandleStepLimits limits;  // as glyphfair fair --profile handwriting --continuity g3 sets them
  limits.flat_curvature = 0.5 / 2048.0;
  limits.allowance = 5.58;
  limits.allowance_by_cubic = {10.91, 11.63, 11.12, 5.58, 12.81, 11.06, 8.58, 7.93,
                               6.91, 8.48, 11.55, 11.94, 11.28, 11.11, 12.97, 13.62};
  limits.polish_rounds = 3;
  limits.inflection_handles = limits.node_turns = limits.seats_beside_lines = true;
  limits.slope_jump_weight = 5.0;
  const std::vector<OutlineNode> r = round_to_grid(nodes, true, limits);

  // The last cubic, laid flat along the line after it, merges into it: the nodes before stay.
  ASSERT_GE(r.size(), nodes.size() - 1);
  for (std::size_t i = 0; i + 2 < nodes.size(); ++i) {
    if (!nodes[i].out_handle) continue;
    EXPECT_LE(inner_axis_extrema(outline_cubic(r, i)), inner_axis_extrema(outline_cubic(nodes, i))) << "cubic " << i;
  }
  EXPECT_EQ(r[13].in_handle->x, r[13].point.x);  // still vertical
  EXPECT_EQ(r[13].out_handle->x, r[13].point.x);
}

// Two more stretches of that P: the bowl's right side above the stem join, and its top. Whole
// steps leave jumps there whatever the handles, and a node's nudge, weighing only the jumps
// and the cubics' bends, took a one-step handle with its far handle a unit off the tangent:
// κ·UPM 167 and 667 against at most 10 and 3 before rounding. The nudge now weighs the
// curvature variation a cubic gains, as the choice of handles does.
TEST(GridRounding, ANudgeTakesNoCurvatureSpike) {
  const std::vector<std::vector<OutlineNode>> stretches{
      {
          node(Vec2{441.00, 457.32}, std::nullopt, Vec2{441.00, 445.13}, false),
          node(Vec2{440.33, 432.76}, Vec2{440.42, 434.45}, Vec2{439.74, 422.11}),
          node(Vec2{438.18, 408.29}, Vec2{438.86, 413.77}, Vec2{435.69, 388.05}),
          node(Vec2{427.81, 360.34}, Vec2{431.83, 372.40}, Vec2{421.84, 342.44}, true, Vec2{-1.0, -3.0}),
          node(Vec2{397.39, 308.26}, Vec2{412.50, 323.37}, std::nullopt, false),
      },
      {
          node(Vec2{397.82, 639.54}, std::nullopt, Vec2{380.23, 645.41}, false),
          node(Vec2{337.37, 653.60}, Vec2{360.11, 650.32}, Vec2{330.62, 654.58}),
          node(Vec2{299.44, 657.32}, Vec2{316.90, 656.38}, Vec2{291.33, 657.76}),
          node(Vec2{275.43, 658.00}, Vec2{282.57, 658.00}, Vec2{261.24, 658.00}, true, Vec2{-1.0, 0.0}),
          node(Vec2{228.57, 655.44}, Vec2{249.09, 657.05}, std::nullopt, false),
      },
  };
  HandleStepLimits limits;
  limits.flat_curvature = 0.5 / 1000.0;
  limits.allowance = 0.45;
  for (std::size_t s = 0; s < stretches.size(); ++s) {
    const std::vector<OutlineNode>& nodes = stretches[s];
    double largest = 0.0;
    for (std::size_t i = 0; i + 1 < nodes.size(); ++i)
      largest = std::max(largest, curvature_shape(outline_cubic(nodes, i), 0.0).largest);
    const std::vector<OutlineNode> r = round_to_grid(nodes, false, limits);
    ASSERT_EQ(r.size(), nodes.size());
    for (std::size_t i = 0; i + 1 < r.size(); ++i)
      EXPECT_LE(curvature_shape(outline_cubic(r, i), 0.0).largest, 10.0 * largest) << "stretch " << s << ", cubic " << i;
  }
}

// Open Sans's w, unrounded, where its right foot leaves the baseline: a baseline line, a corner,
// a diagonal of primitive step (−201, 643) up to a curve. Its corners on the baseline went to
// grid neighbours off it, (1267, −1) and (1072, 1), for a diagonal of step (−102, 323): the
// baseline tilted. A line horizontal on the grid now stays on its y, its ends sliding along it
// only; the curve still leaves the diagonal with G1 exact.
TEST(GridRounding, ALineOnTheBaselineStaysOnIt) {
  const std::vector<OutlineNode> nodes{
      node(Vec2{1268.0, 0.0}, std::nullopt, std::nullopt, false),
      node(Vec2{1071.0, 0.0}, std::nullopt, std::nullopt, false),
      node(Vec2{870.0, 643.0}, std::nullopt, Vec2{863.43, 664.02}),
      node(Vec2{799.0, 911.0}, Vec2{848.83, 710.73}, std::nullopt, false),
      node(Vec2{791.0, 911.0}, std::nullopt, std::nullopt, false),
  };
  HandleStepLimits limits;
  limits.flat_curvature = 0.5 / 2048.0;
  limits.allowance = 1.0;
  const std::vector<OutlineNode> r = round_to_grid(nodes, false, limits);

  ASSERT_EQ(r.size(), nodes.size());
  EXPECT_EQ(r[0].point.y, 0.0);
  EXPECT_EQ(r[1].point.y, 0.0);
  EXPECT_EQ(r[3].point, nodes[3].point);
  EXPECT_EQ(r[4].point, nodes[4].point);
  EXPECT_EQ(cross(r[2].point - r[1].point, *r[2].out_handle - r[2].point), 0.0);
}

// Because We Create's s, unrounded: a brush stroke's foot, its lowest point a smooth node with
// a 1-unit handle, and from there a cubic to a corner whose rightmost point lies 0.4 units
// from the node (the check counts it there). A 3-unit handle carried it 1.5 units off, an
// extremum with no node, and no fault the rounding weighed: the cubic had one inside before.
TEST(GridRounding, AnExtremumBesideItsNodeStaysBesideIt) {
  const std::vector<OutlineNode> nodes{
      node(Vec2{147.0, 69.0}, std::nullopt, Vec2{148.926, 66.655}, false),
      node(Vec2{155.42, 60.035}, Vec2{154.372, 60.035}, Vec2{156.434, 60.035}, true, Vec2{1.0, 0.0}),
      node(Vec2{142.0, 84.0}, Vec2{153.228, 66.233}, std::nullopt, false),
  };
  for (std::size_t i = 0; i < 2; ++i) ASSERT_EQ(inner_axis_extrema_of(outline_cubic(nodes, i)).off_node, 0);
  HandleStepLimits limits;
  limits.flat_curvature = 0.5 / 1000.0;
  limits.allowance = 5.0;  // a handwriting tolerance, most of it left
  const std::vector<OutlineNode> r = round_to_grid(nodes, false, limits);

  ASSERT_EQ(r.size(), nodes.size());
  for (std::size_t i = 0; i < 2; ++i) EXPECT_EQ(inner_axis_extrema_of(outline_cubic(r, i)).off_node, 0) << "cubic " << i;
}

// Delphine's l, unrounded: a stem's line 2.3° off the vertical, the curve leaving it
// tangentially to a vertical corner 179 units up, both its handles on the line (κ = 0 at the
// join). The line took the short step (−1, 16), its end 2.6 units left; the corner's handle,
// seated on the line for κ = 0 there, left the curve turning back 3 units to the right: an
// x-extremum inside, with no node. The corner's handle on the line counts as a far handle does.
TEST(GridRounding, ACurveFromALineToACornerGainsNoExtremum) {
  const std::vector<OutlineNode> nodes{
      node(Vec2{23.0, 106.0}, std::nullopt, std::nullopt, false),
      node(Vec2{15.43, 295.95}, std::nullopt, Vec2{15.0, 306.73}),
      node(Vec2{15.0, 475.0}, Vec2{15.0, 306.73}, std::nullopt, false),
  };
  ASSERT_EQ(inner_axis_extrema_of(outline_cubic(nodes, 1)).all, 0);
  HandleStepLimits limits;
  limits.flat_curvature = 0.5 / 1000.0;
  limits.allowance = 5.0;  // a handwriting tolerance, most of it left
  const std::vector<OutlineNode> r = round_to_grid(nodes, false, limits);

  ASSERT_EQ(r.size(), nodes.size());
  EXPECT_EQ(inner_axis_extrema_of(outline_cubic(r, 1)).off_node, 0);
}

// Heros's j, unrounded: the tail's curve passes its horizontal extremum 11 units before the
// line it ends on, which leans 2.9° off the level. Rounding laid the line level and the 11-unit
// transition flat along it, a cubic of no curvature between the line and the extremum: more of
// the line, which now ends at the extremum, G1 exact there.
TEST(GridRounding, ACubicRoundedFlatAlongItsLineBecomesTheLine) {
  const std::vector<OutlineNode> nodes{
      node(Vec2{70.0, -76.0}, std::nullopt, Vec2{70.0, -85.1514}, false),
      node(Vec2{62.1387, -119.8418}, Vec2{70.0, -104.1192}, Vec2{51.4097, -141.2998}),
      node(Vec2{13.1969, -145.3575}, Vec2{31.7158, -145.3575}, Vec2{9.1497, -145.3575}, true, Vec2{-1.0, 0.0}),
      node(Vec2{2.0, -145.0}, Vec2{5.2737, -145.1637}, std::nullopt),
      node(Vec2{-18.0, -144.0}, std::nullopt, std::nullopt, false),
  };
  HandleStepLimits limits;
  limits.allowance = 1.0;
  const std::vector<OutlineNode> r = round_to_grid(nodes, false, limits);

  ASSERT_EQ(r.size(), nodes.size() - 1);
  EXPECT_EQ(r[2].point, (Vec2{13.0, -145.0}));  // the extremum, now the line's start
  EXPECT_FALSE(r[2].out_handle);
  EXPECT_EQ(r[3].point.y, r[2].point.y);  // the line level
  // G1 exact where the curve meets the line, and with a text tolerance's room κ = 0 there:
  // the far handle on the line too.
  const Vec2 line = r[3].point - r[2].point;
  EXPECT_EQ(cross(line, r[2].point - *r[2].in_handle), 0.0);
  EXPECT_EQ(cross(line, *r[1].out_handle - r[2].point), 0.0);
  for (const OutlineNode& n : r)
    for (const std::optional<Vec2>& p : {std::optional(n.point), n.in_handle, n.out_handle}) EXPECT_TRUE(!p || on_grid(*p));
}

// Liberation Serif's D, unrounded: its bottom rises 4.6 units in a flat S from the bowl's
// extremum to the line along the baseline, the S's middle node 0.95° off level with κ = 0 on
// both sides. The nearest grid direction, (1, 0), left the far handles 3 and 2 units off the
// node's tangent line, and each cubic a curvature the other lacked (κ·UPM 1.7 against 0.1);
// with HandleStepLimits::flat_node_reach, the direction whose tangent line passes nearest both
// far handles.
TEST(GridRounding, AFlatNodeTakesTheDirectionThatKeepsItsFarHandlesOnItsTangent) {
  const std::vector<OutlineNode> nodes{
      node(Vec2{663.287, -4.559}, std::nullopt, Vec2{621.030, -4.559}, true, Vec2{-1.0, 0.0}),
      node(Vec2{518.974, -2.869}, Vec2{574.609, -3.790}, Vec2{345.647, 0.0}),
      node(Vec2{231.0, 0.0}, Vec2{345.368, 0.0}, std::nullopt),
      node(Vec2{59.0, 0.0}, std::nullopt, std::nullopt, false),
  };
  HandleStepLimits limits;
  limits.flat_curvature = 0.5 / 2048.0;
  limits.allowance = 1.0;
  const auto far_offset = [](const std::vector<OutlineNode>& r) {
    const Vec2 u = (*r[1].out_handle - r[1].point) / norm(*r[1].out_handle - r[1].point);
    return std::max(std::abs(cross(u, *r[0].out_handle - r[1].point)), std::abs(cross(u, *r[2].in_handle - r[1].point)));
  };
  const std::vector<OutlineNode> level = round_to_grid(nodes, false, limits);
  ASSERT_EQ(level.size(), nodes.size());
  EXPECT_EQ(level[1].out_handle->y, level[1].point.y);  // (1, 0)
  EXPECT_GT(far_offset(level), 2.0);

  limits.flat_node_reach = 2.5;
  const std::vector<OutlineNode> r = round_to_grid(nodes, false, limits);
  ASSERT_EQ(r.size(), nodes.size());
  EXPECT_NE(r[1].out_handle->y, r[1].point.y);
  EXPECT_EQ(cross(r[1].point - *r[1].in_handle, *r[1].out_handle - r[1].point), 0.0);  // G1 exact
  EXPECT_LT(far_offset(r), 0.5);
  // Both cubics meet the node flat, as the check compares curvature there (κ·UPM within 0.05).
  const double k_in = node_curvature(outline_cubic(r, 0), SegmentEnd::end) * 2048.0;
  const double k_out = node_curvature(outline_cubic(r, 1), SegmentEnd::start) * 2048.0;
  EXPECT_LT(std::abs(k_in - k_out), 0.05) << k_in << " " << k_out;
}

// Open Sans's s, unrounded: the spine's inflection node (κ = 0 both sides) has a 7.7-unit
// handle towards the shoulder and leaves along (8, −3) to within 0.1°; the directions no longer
// than that handle, (5, −2) nearest, leave the shoulder's far handle 7 units off its tangent
// line, and the node before it (G2 at κ·UPM 2.35) took κ·UPM 3.3 against 0.9 (the whole font's
// rounding). A flat node's direction may be a quarter longer than its shorter handle.
TEST(GridRounding, AFlatNodeWithAShortHandleMayTakeASlightlyLongerDirection) {
  const std::vector<OutlineNode> nodes{
      node(Vec2{722.963, 283.578}, std::nullopt, Vec2{722.963, 352.848}, true, Vec2{0.0, 1.0}),
      node(Vec2{587.727, 443.081}, Vec2{684.721, 394.584}, Vec2{526.179, 473.855}, true, Vec2{-2.0, 1.0}),
      node(Vec2{446.539, 503.667}, Vec2{453.718, 500.980}, Vec2{277.658, 566.885}),
      node(Vec2{106.009, 826.791}, Vec2{106.009, 631.140}, std::nullopt, true, Vec2{0.0, 1.0}),
  };
  HandleStepLimits limits;
  limits.flat_curvature = 0.5 / 2048.0;
  limits.allowance = 0.4;  // so little that no later nudge turns the node instead (at 0.5, since
  // a node's slide along the outline is measured along it, a nudge seats it too)
  // How far the shoulder's far handle lies off node 2's tangent line (κ = 0 wants it on it).
  const auto off = [](const std::vector<OutlineNode>& r) {
    const Vec2 u = (*r[2].out_handle - r[2].point) / norm(*r[2].out_handle - r[2].point);
    return std::abs(cross(u, *r[1].out_handle - r[2].point));
  };
  const std::vector<OutlineNode> short_only = round_to_grid(nodes, false, limits);
  ASSERT_EQ(short_only.size(), nodes.size());
  EXPECT_NE(cross(*short_only[2].out_handle - short_only[2].point, Vec2{-8.0, 3.0}), 0.0);

  limits.flat_node_reach = 2.5;
  const std::vector<OutlineNode> r = round_to_grid(nodes, false, limits);
  ASSERT_EQ(r.size(), nodes.size());
  EXPECT_EQ(cross(*r[2].out_handle - r[2].point, Vec2{-8.0, 3.0}), 0.0);
  EXPECT_EQ(cross(r[2].point - *r[2].in_handle, *r[2].out_handle - r[2].point), 0.0);
  EXPECT_LT(off(r), off(short_only)) << off(r) << " " << off(short_only);
}

// merge_tiny_cubics on four nodes whose middle two are under 2 units apart: the ends untouched,
// one node left between them at `kept`, its handle on the dropped node's side (`out`: after it)
// at `reached`. The merged nodes, for a test's own checks.
std::vector<OutlineNode> expect_merged(std::vector<OutlineNode> nodes, Vec2 kept, Vec2 reached, bool out) {
  const std::vector<OutlineNode> before = nodes;
  merge_tiny_cubics(nodes, false, 2.0);
  EXPECT_EQ(nodes.size(), 3u);
  if (nodes.size() != 3u) return nodes;
  EXPECT_EQ(nodes[0], before[0]);
  EXPECT_EQ(nodes[2], before[3]);
  EXPECT_EQ(nodes[1].point, kept);
  const std::optional<Vec2>& handle = out ? nodes[1].out_handle : nodes[1].in_handle;
  EXPECT_TRUE(handle);
  if (handle) {
    EXPECT_NEAR(handle->x, reached.x, 1e-12);
    EXPECT_NEAR(handle->y, reached.y, 1e-12);
  }
  return nodes;
}

TEST(OutlineNodes, CubicsUnderTwoUnitsMergeIntoOneNode) {
  // Because We Create's P: a vertical extremum 1.5 units from the next smooth node, between
  // two corners. One node stays, the extremum; it leaves along its own tangent with the
  // dropped node's out-handle length plus the chord, and arrives as it did.
  const OutlineNode first = node({58, 390}, Vec2{60, 420}, Vec2{56.79, 389.19}, false);
  const OutlineNode extremum = node({37.94, 368.05}, Vec2{37.94, 376.62}, Vec2{37.94, 367.36}, true, Vec2{0, -1});
  const OutlineNode tiny_end = node({38.16, 366.57}, Vec2{38.06, 366.88}, Vec2{39.83, 361.58});
  const OutlineNode last = node({59, 360}, Vec2{50.34, 360}, Vec2{80, 300}, false);
  const double reach = distance(*tiny_end.out_handle, tiny_end.point) + distance(extremum.point, tiny_end.point);
  const std::vector<OutlineNode> nodes =
      expect_merged({first, extremum, tiny_end, last}, extremum.point, {extremum.point.x, extremum.point.y - reach}, true);
  EXPECT_EQ(nodes[1].in_handle, extremum.in_handle);
  EXPECT_EQ(nodes[1].grid_step, extremum.grid_step);
  // Off the axes the first node stays and takes the second's way out; two units apart, none merge.
  std::vector<OutlineNode> diagonal{first, node({40, 370}, Vec2{39, 371}, Vec2{40.5, 369.5}),
                                    node({41, 369}, Vec2{40.5, 369.5}, Vec2{43, 367}), last};
  merge_tiny_cubics(diagonal, false, 2.0);
  ASSERT_EQ(diagonal.size(), 3u);
  EXPECT_EQ(diagonal[1].point, (Vec2{40, 370}));
  std::vector<OutlineNode> apart{first, node({40, 370}, Vec2{39, 371}, Vec2{41, 369}), node({42, 370}, Vec2{41, 371}, Vec2{43, 369}), last};
  const std::vector<OutlineNode> before = apart;
  merge_tiny_cubics(apart, false, 2.0);
  EXPECT_EQ(apart, before);
}

TEST(OutlineNodes, ExtremaOnBothAxesUnderTwoUnitsApartBecomeACorner) {
  // Because We Create's s: a brush hook's level foot and its upright side 0.9 units apart, the
  // curve turning a right angle between. Merged into the foot's smooth node, the side's
  // x-extremum fell 0.9 units into the next cubic, with no node. A corner where their tangents
  // cross keeps both: each handle where it was, each cubic meeting its axis at the corner.
  const OutlineNode first = node({147, 69}, Vec2{146, 68.7}, Vec2{151, 64.13}, false);
  const OutlineNode foot = node({152.03, 63.78}, Vec2{151.69, 63.78}, Vec2{152.17, 63.78}, true, Vec2{1, 0});
  const OutlineNode side = node({152.39, 64.60}, Vec2{152.39, 63.84}, Vec2{152.39, 67.30}, true, Vec2{0, 1});
  const OutlineNode last = node({142, 84}, Vec2{149.72, 71.78}, Vec2{143, 85}, false);
  std::vector<OutlineNode> nodes{first, foot, side, last};
  merge_tiny_cubics(nodes, false, 2.0);
  ASSERT_EQ(nodes.size(), 3u);
  EXPECT_FALSE(nodes[1].smooth);
  EXPECT_NEAR(nodes[1].point.x, 152.39, 1e-12);
  EXPECT_NEAR(nodes[1].point.y, 63.78, 1e-12);
  EXPECT_EQ(nodes[1].in_handle, foot.in_handle);
  EXPECT_EQ(nodes[1].out_handle, side.out_handle);
  EXPECT_EQ(inner_axis_extrema(outline_cubic(nodes, 0)), 0);
  EXPECT_EQ(inner_axis_extrema(outline_cubic(nodes, 1)), 0);
}

TEST(OutlineNodes, ACubicOfTwoUnitsMergesBeforeTheGridFoldsIt) {
  // Vollkorn's z, the foot of its baseline stroke: a level extremum 2.005 units before the
  // inflection where the stroke starts to rise, then the stroke's level top and its corner.
  // Rounded as they were, the cubic between the first two became (424, −2) → (423, −2) with its
  // handles crossed (423, then 424): a zigzag with κ·UPM −13.8 at one end and 0 at the other.
  const std::vector<OutlineNode> faired{
      node({456, 17}, std::nullopt, Vec2{449.96606874, 4.26170068}, false),
      node({423.60562086, -1.97580384}, Vec2{441.23844493, -1.97580384}, Vec2{422.76319811, -1.97580384}, true, Vec2{-1, 0}),
      node({421.60084709, -1.95321596}, Vec2{422.03056050, -1.96156655}, Vec2{367.98249488, -0.91125476}),
      node({244.48554988, -0.00013569}, Vec2{321.09715692, -0.00013569}, Vec2{194.28883756, -0.00013569}, true, Vec2{-1, 0}),
      node({67, -2}, Vec2{124.91393547, -0.39127957}, std::nullopt, false)};
  ASSERT_GT(distance(faired[1].point, faired[2].point), 2.0);
  std::vector<OutlineNode> nodes = faired;
  merge_tiny_cubics(nodes, false, tiny_cubic_chord);
  ASSERT_EQ(nodes.size(), 4u);
  EXPECT_EQ(nodes[1].point, faired[1].point);  // the extremum stays
  const std::vector<OutlineNode> r = round_to_grid(nodes, false);
  ASSERT_EQ(r.size(), nodes.size());
  // The stroke runs leftward: no control point of a cubic turns back to the right.
  for (std::size_t i = 0; i + 1 < r.size(); ++i) {
    const Cubic c = outline_cubic(r, i);
    for (std::size_t k = 1; k < c.p.size(); ++k) EXPECT_LE(c.p[k].x, c.p[k - 1].x) << "cubic " << i << " point " << k;
  }
}

TEST(OutlineNodes, ACubicTooShortForTheGridToBendMergesBeforeRounding) {
  // Spartan's e (UPM 2,000): its right side from the crossbar's corner up to the top's level
  // extremum, unrounded. A 5.4-unit cubic leaves the x-extremum at (862, 435.5) with κ·UPM 7.0
  // and 3.4 at its ends; whole steps bend a cubic that short at least κ·UPM 2/(3·5.4³)·2000 =
  // 8.5, so rounded it was straight against the 3.4 of the cubic after it. Merged, the
  // extremum stays and its out-handle reaches on up its tangent, as far as the dropped node's
  // did plus the chord.
  const std::vector<OutlineNode> faired{
      node({859, 379}, std::nullopt, Vec2{860.83888785, 397.38887846}, false),
      node({861.99133983, 435.53910679}, Vec2{861.99133983, 420.85783001}, Vec2{861.99133983, 435.79837837}, true,
           Vec2{0, 1}),
      node({861.95567092, 440.92993849}, Vec2{861.99098041, 437.87102987}, Vec2{861.88890415, 446.71403454}),
      node({861.51067969, 458.00033283}, Vec2{861.73896472, 452.40403693}, Vec2{861.19968996, 465.62409396}),
      node({860.14770006, 480.42521425}, Vec2{860.74228650, 473.09890624}, Vec2{858.89448757, 495.86690626}),
      node({854.60760924, 525.00373677}, Vec2{857.02552560, 510.72681894}, Vec2{851.07423886, 545.86700542}),
      node({837.81848905, 592.80402112}, Vec2{845.79418470, 568.87693418}, Vec2{817.20567880, 654.64245189}),
      node({750.13358559, 737.57202875}, Vec2{785.33207884, 702.37353550}, Vec2{683.86587471, 803.83973963}),
      node({465.28480332, 844.98998617}, Vec2{586.50867238, 844.98998617}, std::nullopt, false)};
  const Cubic short_one = outline_cubic(faired, 1);
  const double chord = distance(short_one.p[0], short_one.p[3]);
  ASSERT_GT(chord, tiny_cubic_chord);
  ASSERT_LT(chord, flat_cubic_chord);
  const double least = 2.0 / (3.0 * chord * chord * chord);
  ASSERT_LT(std::abs(node_curvature(short_one, SegmentEnd::start)), least);
  ASSERT_LT(std::abs(node_curvature(short_one, SegmentEnd::end)), least);
  std::vector<OutlineNode> nodes = faired;
  merge_tiny_cubics(nodes, false, tiny_cubic_chord);
  ASSERT_EQ(nodes.size(), faired.size() - 1);
  EXPECT_EQ(nodes[1].point, faired[1].point);  // the extremum stays
  const double reach = distance(faired[2].point, *faired[2].out_handle) + chord;
  EXPECT_NEAR(nodes[1].out_handle->x, faired[1].point.x, 1e-9);
  EXPECT_NEAR(nodes[1].out_handle->y, faired[1].point.y + reach, 1e-9);
  EXPECT_EQ(nodes[2].point, faired[3].point);
}

TEST(OutlineNodes, AShortCubicThatBendsAsTheGridCanDrawStays) {
  // A serif's round end: a quarter circle of radius 4 (chord 5.7, κ = 0.25) between two level
  // and upright stretches. The grid draws a cubic that bends so, and it is not merged.
  const double h = 4.0 * 0.5523;
  const std::vector<OutlineNode> faired{
      node({0, 0}, std::nullopt, Vec2{20, 0}, false),
      node({40, 0}, Vec2{30, 0}, Vec2{40 + h, 0}, true, Vec2{1, 0}),
      node({44, 4}, Vec2{44, 4 - h}, Vec2{44, 14}, true, Vec2{0, 1}),
      node({44, 40}, Vec2{44, 30}, std::nullopt, false)};
  std::vector<OutlineNode> nodes = faired;
  merge_tiny_cubics(nodes, false, tiny_cubic_chord);
  EXPECT_EQ(nodes.size(), faired.size());
}

TEST(OutlineNodes, ATinyCubicAfterALineMergesIntoTheLinesEnd) {
  // Comic Neue's i dot: a line stood upright to x = 86 ends at (86, 603), and the curve leaving
  // it passes the vertical 0.8 units on, where a node sat; rounded, that cubic folded on its
  // unit. The line's end stays, with the line's tangent, and reaches on to where the dropped
  // node's out-handle did (its length plus the chord); the line's other end is untouched.
  // An extremum goes only where the line runs along its axis.
  const OutlineNode top = node({86, 644}, Vec2{87, 660}, std::nullopt, false);
  const OutlineNode line_end = node({86, 603}, std::nullopt, Vec2{86, 602.9});
  const OutlineNode extremum = node({85.99, 602.2}, Vec2{85.99, 602.5}, Vec2{85.99, 587}, true, Vec2{0, -1});
  const OutlineNode bottom = node({117, 572}, Vec2{101, 572}, Vec2{133, 572}, true, Vec2{1, 0});
  const double reach = distance(*extremum.out_handle, extremum.point) + distance(line_end.point, extremum.point);
  const Vec2 reached{86.0, 603.0 - reach};
  EXPECT_FALSE(expect_merged({top, line_end, extremum, bottom}, line_end.point, reached, true)[1].in_handle);
  // Mirrored: the tiny cubic before a line merges into the line's start the same way.
  std::vector<OutlineNode> reversed{bottom, extremum, line_end, top};
  for (OutlineNode& n : reversed) std::swap(n.in_handle, n.out_handle);
  EXPECT_FALSE(expect_merged(reversed, line_end.point, reached, false)[1].out_handle);
  // Past a slanted line the extremum stays: merged, the curve would turn through the vertical
  // inside the cubic (DejaVu Sans's ☃).
  std::vector<OutlineNode> slanted{node({80, 644}, Vec2{81, 660}, std::nullopt, false), line_end, extremum, bottom};
  const std::vector<OutlineNode> kept = slanted;
  merge_tiny_cubics(slanted, false, 2.0);
  EXPECT_EQ(slanted, kept);
}

TEST(OutlineNodes, ANodeBreakingG1ByLessThanTheKinkLimitIsMadeG1WithinItsMove) {
  // A node whose handles, 30 and 40 units long, leave 1° above and below the level: a 2° kink.
  const double deg = std::numbers::pi / 180.0, limit = 3.0 * deg;
  const Vec2 p{100.0, 50.0};
  const OutlineNode kinked = node(p, p - direction_of(1.0 * deg) * 30.0, p + direction_of(-1.0 * deg) * 40.0, false);
  OutlineNode joined = kinked;
  ASSERT_TRUE(join_nearly_smooth_node(joined, limit, 1.0));
  EXPECT_TRUE(joined.smooth);
  // Both along their bisector (the level), each as long as it was: G1, each handle turned by
  // 1°, its tip moved by the chord 2L·sin(½°), the cubic by at most 4/9 of that.
  EXPECT_NEAR(joined.in_handle->x, p.x - 30.0, 1e-9);
  EXPECT_NEAR(joined.in_handle->y, p.y, 1e-9);
  EXPECT_NEAR(joined.out_handle->x, p.x + 40.0, 1e-9);
  EXPECT_NEAR(joined.out_handle->y, p.y, 1e-9);
  EXPECT_NEAR(distance(*joined.out_handle, *kinked.out_handle), 80.0 * std::sin(0.5 * deg), 1e-9);
  // Not where the move it takes is over the bound, nor where the break is the kink limit or
  // more (a corner): the node as it was.
  OutlineNode far = kinked;
  EXPECT_FALSE(join_nearly_smooth_node(far, limit, 0.2));
  EXPECT_EQ(far, kinked);
  OutlineNode corner = node(p, p - direction_of(2.0 * deg) * 30.0, p + direction_of(-2.0 * deg) * 40.0, false);
  const OutlineNode corner_was = corner;
  EXPECT_FALSE(join_nearly_smooth_node(corner, limit, 10.0));
  EXPECT_EQ(corner, corner_was);
  // Exactly G1 already: smooth, its handles as they were.
  OutlineNode straight = node(p, p - Vec2{30.0, 0.0}, p + Vec2{40.0, 0.0}, false);
  EXPECT_TRUE(join_nearly_smooth_node(straight, limit, 0.0));
  EXPECT_TRUE(straight.smooth);
  EXPECT_EQ(*straight.out_handle, (p + Vec2{40.0, 0.0}));
}

TEST(OutlineNodes, CubicsOfNoExtentAreDropped) {
  // An open chain ending with two cubics of length 0 at its end point (all their points on
  // it), and a closed square with one at its first node: the outlines without them.
  const Vec2 end{620.0, 33.0};
  const std::vector<OutlineNode> open{
      node(Vec2{500.0, 500.0}, std::nullopt, Vec2{600.0, 400.0}, false),
      node(end, Vec2{620.0, 100.0}, end, true, Vec2{0.0, -1.0}),
      node(end, end, end, true),
      node(end, end, std::nullopt, false),
  };
  std::vector<OutlineNode> dropped = open;
  drop_empty_cubics(dropped, false);
  ASSERT_EQ(dropped.size(), 2u);
  EXPECT_EQ(dropped[0], open[0]);
  EXPECT_EQ(dropped[1].point, end);
  EXPECT_EQ(dropped[1].in_handle, open[1].in_handle);  // arrives as it did
  EXPECT_EQ(dropped[1].out_handle, std::nullopt);      // and leaves as the last node did
  EXPECT_FALSE(dropped[1].smooth);
  EXPECT_EQ(dropped[1].grid_step, open[1].grid_step);

  const Vec2 a{0, 0}, b{100, 0}, c{100, 100}, d{0, 100};
  const std::vector<OutlineNode> square{node(a, Vec2{0, 30}, Vec2{30, 0}, false), node(b, Vec2{70, 0}, Vec2{100, 30}, false),
                                        node(c, Vec2{100, 70}, Vec2{70, 100}, false), node(d, Vec2{30, 100}, Vec2{0, 70}, false)};
  // The square closing through a second node at a, joined to the first by a cubic of no extent.
  const std::vector<OutlineNode> with_empty{node(a, a, Vec2{30, 0}, false), square[1], square[2], square[3],
                                            node(a, Vec2{0, 30}, a, false)};
  std::vector<OutlineNode> closed = with_empty;
  drop_empty_cubics(closed, true);
  EXPECT_EQ(closed, square);

  // Nothing to drop: unchanged.
  std::vector<OutlineNode> same = square;
  drop_empty_cubics(same, true);
  EXPECT_EQ(same, square);
}

}  // namespace
}  // namespace gf
