#!/usr/bin/python3
"""The fewest on-curve nodes the fairing issue's writeback rule leaves a font's glyphs, against
the nodes bar (handwriting: at most 0.7x the source's), measured on the source alone with
fontTools (no code shared with glyphfair).

The rule puts an on-curve node at every horizontal and vertical extremum, at every corner and
at every inflection; a line needs a node at each end. This counts, per glyph, the distinct
places (merged within one unit) of every kind but the inflections:

  extremum   a horizontal or vertical tangent inside a segment (where the coordinate's
             derivative changes sign), or at a node where a curve's tangent is exactly
             horizontal or vertical;
  corner     a join whose tangents differ by more than 3 degrees (the bars' smooth stretches
             break there);
  line end   both ends of every line.

Inflections are left out (the faired outline has fewer than the source), so the count is a
floor: a faired glyph that keeps the source's extrema, corners and lines has at least this
many nodes. A scanned font's wobbles are extrema too, which fairing rightly drops; given
--faired, the same count on the faired UFO says what its own extrema, corners and lines
require. Prints a line per glyph and the total ratios to the source's nodes, the measure the
bar uses.

usage: node_floor.py FONT [--faired FAIRED.ufo] [--glyphs a,b,...]
"""
import argparse
import math

from fontTools.ttLib import TTFont
from fontTools.ufoLib import UFOReader

from fairing_bars import CORNER_DEG, glyph_contours
from independent_checks import derivative_roots, join_angle, point


def axis_parallel_at_node(seg, at_start):
    """A curve's tangent at one of its ends is exactly horizontal or vertical."""
    if len(seg) == 2:
        return False
    a, b = (seg[0], seg[1]) if at_start else (seg[-1], seg[-2])
    dx, dy = b[0] - a[0], b[1] - a[1]
    return (dx == 0) != (dy == 0)


def required_places(contours):
    """How many distinct places of the contours (closed, as glyph_contours gives them) need a node."""
    places = []
    for segs in contours:
        for i, seg in enumerate(segs):
            before = segs[i - 1]
            angle = join_angle(before, seg)
            corner = angle is None or angle > CORNER_DEG
            if corner or len(seg) == 2 or len(before) == 2 or axis_parallel_at_node(seg, True) \
                    or axis_parallel_at_node(before, False):
                places.append(seg[0])
            if len(seg) > 2:
                for axis in (0, 1):
                    places += [point(seg, t) for t in derivative_roots(seg, axis)]
    distinct = []
    for p in places:
        if all(math.dist(p, q) > 1.0 for q in distinct):
            distinct.append(p)
    return len(distinct)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("font")
    parser.add_argument("--faired", help="the UFO glyphfair fair wrote from FONT")
    parser.add_argument("--glyphs", help="characters, comma separated (default a-z A-Z)")
    args = parser.parse_args()
    font = TTFont(args.font)
    cmap = font.getBestCmap()
    glyphset = font.getGlyphSet()
    faired = UFOReader(args.faired).getGlyphSet() if args.faired else None
    chars = args.glyphs.split(",") if args.glyphs else [chr(c) for c in list(range(97, 123)) + list(range(65, 91))]
    total_nodes = total_floor = total_faired = 0
    for ch in chars:
        name = cmap.get(ord(ch))
        if name is None or (faired is not None and name not in faired):
            continue
        contours = glyph_contours(glyphset, name, True)
        nodes = sum(len(c) for c in contours)
        floor = required_places(contours)
        total_nodes += nodes
        total_floor += floor
        line = f"{ch:2s} nodes {nodes:3d}  floor {floor:3d}  {floor / max(nodes, 1):.2f}x"
        if faired is not None:
            own = required_places(glyph_contours(faired, name, True))
            total_faired += own
            line += f"  faired floor {own:3d}  {own / max(nodes, 1):.2f}x"
        print(line)

    def verdict(ratio):
        return f"{ratio:.3f}x ({'within' if ratio <= 0.7 else 'over'} the handwriting bar of 0.7x)"

    print(f"total: the source requires {total_floor} of its {total_nodes} nodes, "
          f"{verdict(total_floor / max(total_nodes, 1))}")
    if faired is not None:
        print(f"total: the faired outline requires {total_faired}, {verdict(total_faired / max(total_nodes, 1))}")


if __name__ == "__main__":
    main()
