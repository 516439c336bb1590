#!/usr/bin/python3
"""node_floor.py against glyphs whose places are known by construction (DejaVu Sans subset):
o and O, two closed bowls of four extrema each: 8; l and I, rectangles: 4 corners; D, a stem
with two corners and two line-to-bowl joins and one extremum, outside and inside: 10.

usage: node_floor_test.py DEJAVU_SUBSET.ttf"""
import sys

from fontTools.ttLib import TTFont

from fairing_bars import glyph_contours
from node_floor import required_places

font = TTFont(sys.argv[1])
cmap, glyphset = font.getBestCmap(), font.getGlyphSet()
expected = {"o": 8, "O": 8, "l": 4, "I": 4, "D": 10}
bad = 0
for ch, want in expected.items():
    got = required_places(glyph_contours(glyphset, cmap[ord(ch)], True))
    print(f"{ch}: {got} places (expected {want})")
    bad += got != want
sys.exit(1 if bad else 0)
