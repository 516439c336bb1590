#!/usr/bin/python3
"""node_floor.py against glyphs whose places are known by construction (DejaVu Sans subset):
o and O, two closed bowls of four extrema each: 8; l and I, rectangles: 4 corners; D, a stem
with two corners and two line-to-bowl joins and one extremum, outside and inside: 10; none of
them has an inflection. An S-shaped cubic inflects once, at its middle by symmetry, and so do its
halves split there (de Casteljau), at the node between them. And its
line quarters against the closed form: a cubic leaving a line with κ = 0 for an extremum has
its second handle where the two tangents cross, so it bends there by (2/3)(d0 − a)/d3²,
never past one_cubic_bound; Comic Neue's n's round stroke end, whose quarters bend more
sharply, counts two, a flat turn from a line none.

usage: node_floor_test.py DEJAVU_SUBSET.ttf"""
import math
import sys

from fontTools.ttLib import TTFont

from fairing_bars import glyph_contours
from node_floor import curvature, inflection_points, line_quarters, one_cubic_bound, required_places

font = TTFont(sys.argv[1])
cmap, glyphset = font.getBestCmap(), font.getGlyphSet()
expected = {"o": 8, "O": 8, "l": 4, "I": 4, "D": 10}
bad = 0
for ch, want in expected.items():
    got = required_places(glyph_contours(glyphset, cmap[ord(ch)], True))
    print(f"{ch}: {got} places (expected {want})")
    bad += got != want
    inflected = required_places(glyph_contours(glyphset, cmap[ord(ch)], True), inflections=True)
    print(f"{ch}: {inflected} places with inflections (expected {want})")
    bad += inflected != want

# An S from (0, 0) to (100, 0), symmetric about (50, 0), closed by a line; then its halves.
s_curve = ((0, 0), (50, 100), (50, -100), (100, 0))
halves = [((0, 0), (25, 50), (37.5, 25), (50, 0)), ((50, 0), (62.5, -25), (75, -50), (100, 0))]
closing = ((100, 0), (0, 0))
# Started at the inflection node, the stretch runs through the seam: one inflection still.
seamed = [halves[1], closing, halves[0]]
for name, contour in (("S cubic", [s_curve, closing]), ("S split at its inflection", halves + [closing]),
                      ("S split, started at its inflection", seamed)):
    got = inflection_points([contour])
    print(f"{name}: inflections at {got} (expected one at (50, 0))")
    bad += len(got) != 1 or math.dist(got[0], (50, 0)) > 0.5

# The closed form: from (0, 100) up a line, to (100, 200) along the level; V = (0, 200).
bound = one_cubic_bound((0, 100), (0, 1), (100, 200), (1, 0))
print(f"one-cubic bound {bound} (expected {2 / 3 * 100 / 100 ** 2})")
bad += abs(bound - 2 / 3 * 100 / 100 ** 2) > 1e-15
for a in (1, 25, 50, 99):
    k = curvature(((0, 100), (0, 100 + a), (0, 200), (100, 200)), 1.0)
    want = 2 / 3 * (100 - a) / 100 ** 2
    print(f"first handle {a}: the extremum bends at {k:.6f} (expected {want:.6f}, at most {bound:.6f})")
    bad += abs(k - want) > 1e-12 or k > bound
bad += one_cubic_bound((0, 100), (0, 1), (-100, 50), (1, 0)) is not None  # no convex turn between

# Comic Neue's n (1,000 units per em): its stem's round top between two lines, two quarters each
# bending at κ 0.030 where the bound is 1/48 and 1/51; then a flat turn from a line into a corner.
round_end = [((141, 306), (141, 464)), ((141, 464), (141, 481), (127, 494), (110, 494)),
             ((110, 494), (93, 494), (78, 481), (78, 464)), ((78, 464), (78, 306)), ((78, 306), (141, 306))]
flat_turn = [((0, 0), (0, 100)), ((0, 100), (0, 190), (10, 200), (100, 200)), ((100, 200), (100, 0)),
             ((100, 0), (0, 0))]
for name, contour, want in (("round stroke end", round_end, 2), ("flat turn", flat_turn, 0)):
    got = line_quarters([contour])
    print(f"{name}: {got} line quarters (expected {want})")
    bad += got != want
sys.exit(1 if bad else 0)
