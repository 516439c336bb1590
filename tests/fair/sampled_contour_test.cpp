// The fairing's sampled distances (fair/sampled_contour): samples dense enough by the curve's
// turning that their chords keep to the curve, so the distance between two outlines reads as
// the brute-force Hausdorff distance does.
#include "fair/sampled_contour.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "point_set_distance.hpp"
#include "test_shapes.hpp"

namespace gf {
namespace {

// The farthest any stretch of `c` between two of its samples strays from their chord.
double largest_chord_sag(const Contour& c) {
  const ContourSamples samples = contour_samples(c);
  double worst = 0.0;
  for (std::size_t i = 0; i < c.segments.size(); ++i) {
    const auto first = std::find(samples.segment_of.begin(), samples.segment_of.end(), i);
    // The contour's closing (or end) point, listed last, is the last segment's end.
    const auto n = std::count(samples.segment_of.begin(), samples.segment_of.end(), i) - (i + 1 == c.segments.size());
    for (long k = 0; k < n; ++k) {
      const Vec2 a = samples.points[static_cast<std::size_t>(first - samples.segment_of.begin() + k)];
      const Vec2 b = point_at(c.segments[i], static_cast<double>(k + 1) / static_cast<double>(n));
      std::vector<Vec2> between;
      for (int j = 1; j < 50; ++j)
        between.push_back(point_at(c.segments[i], (static_cast<double>(k) + j / 50.0) / static_cast<double>(n)));
      worst = std::max(worst, test::directed_to_polyline(between, {a, b}));
    }
  }
  return worst;
}

TEST(SampledContour, ChordsKeepToATightCurveWithinAHundredthOfAUnit) {
  // Sampled every 3 units alone, a circle of radius 30 (a quarter 47 units long, as Comic Neue's
  // tight turns) had chords 0.034 units inside its arc.
  for (const double radius : {5.0, 10.0, 20.0, 30.0, 60.0, 100.0, 300.0, 1000.0})
    EXPECT_LE(largest_chord_sag(test::circle({0, 0}, radius)), 0.0105) << radius;
  // Unevenly parametrised cubics: their chords are unequal, and the longest sags more.
  for (const Cubic& c : {Cubic{{0, 0}, {5, 0}, {40, 30}, {40, 60}}, Cubic{{0, 0}, {30, 0}, {31, 1}, {31, 31}},
                         Cubic{{0, 0}, {2, 0}, {40, 2}, {40, 40}}}) {
    Contour piece;
    piece.closed = false;
    piece.segments = {c};
    piece.nodes.assign(1, NodeFlags{});
    EXPECT_LE(largest_chord_sag(piece), 0.02);
  }
}

TEST(SampledContour, TheDistanceBetweenTightCurvesReadsAsTheBruteForceOne) {
  // Two circles of radius 30, the second turned 0.3 radians and moved by (0.9, 0.9): sampled
  // every 3 units alone, their distance read 1.305 against 1.279.
  const Contour a = test::circle({0, 0}, 30.0), b = test::circle({0.9, 0.9}, 30.0, 0.3);
  const double truth = test::polyline_hausdorff(test::contour_points(a, 1000), test::contour_points(b, 1000));
  EXPECT_NEAR(distance_between(SampledContour(a), SampledContour(b)), truth, 0.005);
}

TEST(SampledContour, WithinADistanceAnswersAsTheDistanceDoes) {
  const SampledContour a(test::circle({0, 0}, 30.0)), b(test::circle({0.9, 0.9}, 30.0, 0.3));
  const double d = distance_between(a, b);
  for (const double limit : {0.0, 0.5 * d, std::nextafter(d, 0.0), d, 1.01 * d, 100.0}) {
    EXPECT_EQ(within_distance(a, b, limit), d <= limit) << limit;
    EXPECT_EQ(within_distance(b, a, limit), d <= limit) << limit;
  }
  const SampledContour none(Contour{});
  EXPECT_TRUE(within_distance(none, none, 0.0));
  EXPECT_FALSE(within_distance(a, none, 1e9));
}

}  // namespace
}  // namespace gf
