// The outline model: contours of segments between on-curve nodes, glyphs and font metrics.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "geom/segment.hpp"

namespace gf {

/// What the source said about an on-curve node, kept so writers reproduce it.
struct NodeFlags {
  /// A TrueType on-curve point implied between two off-curve points (not stored in the source).
  bool implied = false;
  /// The source's smooth flag (UFO `smooth="yes"`); nullopt when the source has none.
  std::optional<bool> smooth;
  bool operator==(const NodeFlags&) const = default;
};

/// A closed or open sequence of segments. Segment i starts at node i. A closed contour has as
/// many nodes as segments (the last segment ends at node 0); an open one has one node more.
struct Contour {
  std::vector<Segment> segments;
  std::vector<NodeFlags> nodes;
  bool closed = true;

  std::size_t node_count() const { return nodes.size(); }
  Vec2 node_point(std::size_t i) const {
    return i < segments.size() ? start_point(segments[i]) : end_point(segments.back());
  }
  bool operator==(const Contour&) const = default;
};

/// The signed area enclosed by a closed contour (exact for Bézier segments);
/// positive for counter-clockwise contours.
double signed_area(const Contour& c);

/// How thick a closed contour is: 2·|area| / perimeter, a stroke's width for a long thin one,
/// the radius of a round one; 0 for a contour with no length.
double thickness(const Contour& c);

/// The same contour with every quadratic written as its exact cubic (degree elevation: the
/// curve is unchanged, its new control points are the thirds); implied nodes become explicit.
Contour with_cubics(const Contour& c);

/// Every point the source stores on a whole unit (a TrueType on-curve point implied halfway
/// between two off-curve points is not stored, and may fall on a half).
bool on_integer_grid(const Contour& c);

struct Outline {
  std::vector<Contour> contours;
};

struct Glyph {
  std::string name;
  std::vector<char32_t> unicodes;
  double advance_width = 0.0;
  Outline outline;
};

/// Font-wide facts the writers and proofs need.
struct FontInfo {
  std::string source_path;
  std::string family_name;
  std::string style_name;
  double units_per_em = 1000.0;
  double ascender = 800.0;
  double descender = -200.0;
  std::optional<double> x_height;
  std::optional<double> cap_height;
  double italic_angle = 0.0;  ///< degrees, counter-clockwise from vertical (post table)
  /// The format's convention for outer contours: clockwise for TrueType (glyf), counter-
  /// clockwise for PostScript outlines (CFF, CFF2) and UFO.
  bool outer_contours_clockwise = false;
};

struct GlyphSet {
  FontInfo font;
  std::vector<Glyph> glyphs;
};

}  // namespace gf
