// The band around a source, piece by piece: a replacement that holds keeps the whole contour
// within the bound both ways (brute force over the contour with the piece replaced), and two
// concentric arcs hold exactly while their gap is within the bound.
#include "geom/tolerance_band.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "point_set_distance.hpp"

namespace gf {
namespace {

// Points along a circle of radius r from angle a0 to a1, n + 1 of them.
std::vector<Vec2> arc(double r, double a0, double a1, int n) {
  std::vector<Vec2> out;
  for (int k = 0; k <= n; ++k) {
    const double a = a0 + (a1 - a0) * k / n;
    out.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return out;
}

// A closed contour as one polyline of `pieces` arcs of `per_piece` chords each, and the piece
// each point's stretch belongs to.
struct Pieces {
  std::vector<Vec2> points;
  std::vector<std::size_t> piece_of;
};
Pieces circle_in_pieces(double r, int pieces, int per_piece) {
  Pieces out;
  const double step = 2.0 * std::numbers::pi / pieces;
  for (int p = 0; p < pieces; ++p) {
    const std::vector<Vec2> a = arc(r, p * step, (p + 1) * step, per_piece);
    for (int k = 0; k < per_piece; ++k) out.points.push_back(a[k]), out.piece_of.push_back(p);
  }
  out.points.push_back(out.points.front()), out.piece_of.push_back(pieces - 1);
  return out;
}

TEST(ToleranceBand, ConcentricArcsHoldWhileTheirGapIsWithinTheBound) {
  const Pieces source = circle_in_pieces(100.0, 4, 400), faired = circle_in_pieces(100.0, 4, 100);
  const PolylineGrid faired_grid(faired.points, 8.0);
  const ToleranceBand band(source.points, nearest_pieces(faired_grid, faired.piece_of, source.points), 2.0);
  EXPECT_EQ(band.bound(), 2.0);
  const double quarter = 0.5 * std::numbers::pi;
  // The source's chords lie 100 (1 − cos(π/1600)) ≈ 2e-4 inside the circle.
  EXPECT_TRUE(band.holds(0, arc(101.99, 0.0, quarter, 200)));
  EXPECT_FALSE(band.holds(0, arc(102.01, 0.0, quarter, 200)));
  EXPECT_TRUE(band.holds(1, arc(98.01, quarter, 2 * quarter, 200)));
  EXPECT_FALSE(band.holds(1, arc(97.99, quarter, 2 * quarter, 200)));
  // The last quarter ends where the polyline closes on itself: its stretch of source runs
  // across the seam.
  EXPECT_TRUE(band.holds(3, arc(101.99, 3 * quarter, 4 * quarter, 200)));
  EXPECT_FALSE(band.holds(3, arc(102.01, 3 * quarter, 4 * quarter, 200)));
  EXPECT_TRUE(band.holds(0, arc(101.99, -0.1, quarter, 200)));  // reaching back across the seam
  // Within the band everywhere it reaches, but leaving the source points of its quarter's end
  // 5° of arc (8.7 units) from anything: the source's side of the distance refuses it.
  EXPECT_FALSE(band.holds(2, arc(100.0, 2 * quarter, 3 * quarter - 0.0873, 200)));
}

TEST(ToleranceBand, ANeighbourMayCoverWhatAShortenedPieceLeaves) {
  // A node slid 5° of arc along the circle: the shortened quarter leaves its end's source
  // points to the next quarter, spliced on as it was.
  const Pieces source = circle_in_pieces(100.0, 4, 400), faired = circle_in_pieces(100.0, 4, 100);
  const PolylineGrid faired_grid(faired.points, 8.0);
  const ToleranceBand band(source.points, nearest_pieces(faired_grid, faired.piece_of, source.points), 2.0);
  const double quarter = 0.5 * std::numbers::pi, slid = 0.0873;
  const std::vector<Vec2> shortened = arc(100.0, 2 * quarter, 3 * quarter - slid, 200);
  std::vector<Vec2> along = shortened;
  for (const Vec2 p : arc(100.0, 3 * quarter, 4 * quarter, 100)) along.push_back(p);
  EXPECT_FALSE(band.holds(2, shortened));
  EXPECT_TRUE(band.holds_along(2, shortened, along));
  // The piece's own points still answer to the band: 2.01 units out is out, neighbour or not.
  const std::vector<Vec2> out = arc(102.01, 2 * quarter, 3 * quarter - slid, 200);
  std::vector<Vec2> out_along = out;
  for (const Vec2 p : arc(100.0, 3 * quarter, 4 * quarter, 100)) out_along.push_back(p);
  EXPECT_FALSE(band.holds_along(2, out, out_along));
  // Without the neighbour, nothing covers the quarter's end.
  EXPECT_FALSE(band.holds_along(2, shortened, shortened));
}

// A wobbly closed source, the faired contour a copy within half a unit of it in pieces of ten
// chords; each piece replaced by itself shifted and bent at random.
TEST(ToleranceBand, AReplacementThatHoldsKeepsTheWholeContourWithinTheBound) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.35, 0.35), shift(-3.0, 3.0), bend(-3.0, 3.0);
  const Pieces source = circle_in_pieces(120.0, 1, 600);
  std::vector<Vec2> wobbly = source.points;
  for (std::size_t k = 0; k < wobbly.size(); ++k) {
    const double a = 2.0 * std::numbers::pi * k / (wobbly.size() - 1);
    wobbly[k] = wobbly[k] * (1.0 + 0.03 * std::sin(7.0 * a));
  }
  wobbly.back() = wobbly.front();
  std::vector<Vec2> faired;
  std::vector<std::size_t> piece_of;
  for (std::size_t k = 0; k + 1 < wobbly.size(); k += 6) {
    faired.push_back(wobbly[k] + Vec2{jitter(rng), jitter(rng)});
    piece_of.push_back(faired.size() / 10);
  }
  faired.push_back(faired.front()), piece_of.push_back(piece_of.back());
  const PolylineGrid faired_grid(faired, 8.0);
  const double bound = 2.0;
  const ToleranceBand band(wobbly, nearest_pieces(faired_grid, piece_of, wobbly), bound);
  int held = 0, refused = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t piece = trial % (piece_of.back() + 1);
    std::vector<std::size_t> at;  // the points whose stretch belongs to the piece, and the next
    for (std::size_t k = 0; k + 1 < faired.size(); ++k)
      if (piece_of[k] == piece) at.push_back(k);
    at.push_back(at.back() + 1);
    const Vec2 by{shift(rng), shift(rng)};
    const double b = bend(rng);
    std::vector<Vec2> replacement;
    for (std::size_t m = 0; m < at.size(); ++m) {
      const double u = double(m) / double(at.size() - 1);
      replacement.push_back(faired[at[m]] + by + Vec2{0.0, b * 4.0 * u * (1.0 - u)});
    }
    // The other pieces as they were: the polyline from the piece's end round to its start.
    std::vector<Vec2> others;
    for (std::size_t k = at.back(); k != at.front(); k = (k + 1) % (faired.size() - 1)) others.push_back(faired[k]);
    others.push_back(faired[at.front()]);
    auto from_contour = [&](Vec2 p) {
      const std::vector<Vec2> one{p};
      return std::min(test::directed_to_polyline(one, replacement), test::directed_to_polyline(one, others));
    };
    if (band.holds(piece, replacement)) {
      ++held;
      EXPECT_LE(test::directed_to_polyline(replacement, wobbly), bound + 1e-12);
      for (const Vec2 p : wobbly) EXPECT_LE(from_contour(p), bound + 1e-12) << "piece " << piece;
    } else {
      ++refused;
      EXPECT_TRUE(test::directed_to_polyline(replacement, wobbly) > bound ||
                  test::directed_to_polyline(wobbly, replacement) > bound);
    }
  }
  EXPECT_GT(held, 30);
  EXPECT_GT(refused, 30);
}

}  // namespace
}  // namespace gf
