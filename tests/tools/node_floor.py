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

Inflections are left out of the first count (the faired outline has fewer than the source), so
it is a floor: a faired glyph that keeps the source's extrema, corners and lines has at least
this many nodes. A scanned font's wobbles are extrema too, which fairing rightly drops; given
--faired, the same count on the faired UFO says what its own extrema, corners and lines
require. A second count adds the outline's own inflections (inflection_points: where κ changes
sign along a smooth stretch), merged the same way: on the faired UFO, all the rule requires of
that outline as it is. Prints a line per glyph and the total ratios to the source's nodes, the
measure the bar uses.

With G2 line joins (the text bars count a curvature jump where a curve meets a line) one more
kind of place appears, the line quarter: a curve leaving a line tangentially and turning to its
first H/V extremum. Leaving the line with κ = 0 puts a cubic's second handle on the line, and
arriving along the extremum's tangent puts it on that tangent too, so it is their crossing V:
the extremum's curvature is then (2/3)(d0 − a)/d3², below (2/3)·d0/d3² (d0 = |V − P0| along the
line, d3 = |P3 − V|, a the first handle). Where the outline bends more sharply there, the
quarter takes two cubics, a node between (Comic Neue's n: a round stroke end leaves its stem
at (78, 464) and tops out at (110, 494), d0 = 30, d3 = 32, at most κ = 1/51, where the source
bends at 1/33). Such quarters are counted apart, and added to the floor in the "with G2 line
joins" totals.

usage: node_floor.py FONT [--faired FAIRED.ufo] [--glyphs a,b,...]
"""
import argparse
import math

from fontTools.ttLib import TTFont
from fontTools.ufoLib import UFOReader

from fairing_bars import CORNER_DEG, glyph_contours
from independent_checks import cross, derivative_roots, dot, join_angle, norm, point, sub


def axis_parallel_at_node(seg, at_start):
    """A curve's tangent at one of its ends is exactly horizontal or vertical."""
    if len(seg) == 2:
        return False
    a, b = (seg[0], seg[1]) if at_start else (seg[-1], seg[-2])
    dx, dy = b[0] - a[0], b[1] - a[1]
    return (dx == 0) != (dy == 0)


def inflection_points(contours):
    """Where κ changes sign along the contours' smooth stretches between corners and lines (as
    the bars count inflections): between two κ samples of opposite sign (64 a segment, |κ| under
    1e-6 left out), their midpoint; a sign change across a smooth join, its node to within a
    sample's span."""
    points = []
    for segs in contours:
        samples = []  # (point, κ) along the contour, None at each corner
        for i, seg in enumerate(segs):
            angle = join_angle(segs[i - 1], seg)
            if angle is None or angle > CORNER_DEG:
                samples.append(None)
            if len(seg) == 2:
                samples.append(None)  # a line's ends have their nodes already
                continue
            for j in range(65):
                t = j / 64
                if norm(point(hodograph(seg), t)) > 0:
                    samples.append((point(seg, t), signed_curvature(seg, t)))
        if samples and samples[0] is not None:
            # The stretch that runs through the seam: on to the first sample with a sign (a
            # faired node at an inflection has κ = 0 on both sides).
            signed = next((k for k, x in enumerate(samples) if x is None or abs(x[1]) >= 1e-6), len(samples) - 1)
            samples += samples[:signed + 1]
        last = None
        for sample in samples:
            if sample is None:
                last = None
            elif abs(sample[1]) >= 1e-6:
                if last is not None and (last[1] > 0) != (sample[1] > 0):
                    points.append(((last[0][0] + sample[0][0]) / 2, (last[0][1] + sample[0][1]) / 2))
                last = sample
    return points


def required_places(contours, inflections=False):
    """How many distinct places of the contours (closed, as glyph_contours gives them) need a node;
    with `inflections`, their inflection points too (the writeback rule puts a node at each)."""
    places = inflection_points(contours) if inflections else []
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


def hodograph(seg):
    """The derivative of a Bézier, a Bézier of one degree less."""
    n = len(seg) - 1
    return [(n * (b[0] - a[0]), n * (b[1] - a[1])) for a, b in zip(seg, seg[1:])]


def signed_curvature(seg, t):
    """κ of a quadratic or cubic at t, positive turning left."""
    d1 = hodograph(seg)
    d2 = hodograph(d1)
    v = point(d1, t)
    return cross(v, point(d2, t)) / norm(v) ** 3


def curvature(seg, t):
    """|κ| of a quadratic or cubic at t."""
    return abs(signed_curvature(seg, t))


def one_cubic_bound(p0, t0, p3, t3):
    """The most a cubic leaving p0 along unit t0 with κ = 0 can bend where it arrives at p3 along
    unit t3: (2/3)·d0/d3², its second handle at V where the two tangent lines cross (d0 = |V − p0|,
    d3 = |p3 − V|). None where V is not ahead of p0 and behind p3 (no convex turn between)."""
    det = cross(t0, t3)
    if abs(det) < 1e-12:
        return None
    d0 = cross(sub(p3, p0), t3) / det  # p0 + d0·t0 = V = p3 − d3·t3
    d3 = dot(sub(p3, p0), t3) - d0 * dot(t0, t3)
    if d0 <= 0 or d3 <= 0:
        return None
    return 2.0 / 3.0 * d0 / d3 ** 2


def smooth_join(before, after):
    angle = join_angle(before, after)
    return angle is not None and angle <= CORNER_DEG


def first_extremum(segs, i):
    """From the curve segs[i] on, the first H/V extremum a unit or more past its start, before a
    corner, a line or an inflection: (point, unit tangent, |κ|), else None."""
    start = segs[i][0]
    side = 0.0
    for k in range(len(segs)):
        seg = segs[(i + k) % len(segs)]
        if len(seg) == 2 or (k > 0 and not smooth_join(segs[(i + k - 1) % len(segs)], seg)):
            return None
        extrema = set(derivative_roots(seg, 0) + derivative_roots(seg, 1))
        for t in sorted(extrema | {j / 16 for j in range(17)}):
            d = point(hodograph(seg), t)
            if norm(d) == 0:
                continue
            bend = signed_curvature(seg, t)
            if side * bend < 0:
                return None  # an inflection before any extremum
            side = side or bend
            on_axis = t in extrema or (t in (0.0, 1.0) and (d[0] == 0) != (d[1] == 0))
            if on_axis and math.dist(point(seg, t), start) > 1.0:
                return point(seg, t), (d[0] / norm(d), d[1] / norm(d)), abs(bend)
    return None


def line_quarters(contours):
    """How many curves leaving or reaching a line tangentially bend at their first H/V extremum
    more sharply than one cubic from the line with κ = 0 can (one_cubic_bound)."""
    count = 0
    for segs in contours:
        for walk in (segs, [list(reversed(s)) for s in reversed(segs)]):
            for i, seg in enumerate(walk):
                before = walk[i - 1]
                if len(seg) == 2 or len(before) != 2 or not smooth_join(before, seg):
                    continue
                t0 = sub(before[1], before[0])
                t0 = (t0[0] / norm(t0), t0[1] / norm(t0))
                found = first_extremum(walk, i)
                if not found:
                    continue
                p3, t3, k3 = found
                bound = one_cubic_bound(seg[0], t0, p3, t3)
                count += bound is not None and k3 > bound
    return count


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
    totals = {"nodes": 0, "floor": 0, "quarters": 0, "inflected": 0,
              "faired": 0, "faired quarters": 0, "faired inflected": 0}
    for ch in chars:
        name = cmap.get(ord(ch))
        if name is None or (faired is not None and name not in faired):
            continue
        contours = glyph_contours(glyphset, name, True)
        nodes = sum(len(c) for c in contours)
        floor, quarters = required_places(contours), line_quarters(contours)
        inflected = required_places(contours, inflections=True)
        totals["nodes"] += nodes
        totals["floor"] += floor
        totals["quarters"] += quarters
        totals["inflected"] += inflected
        line = (f"{ch:2s} nodes {nodes:3d}  floor {floor:3d}  {floor / max(nodes, 1):.2f}x  line quarters {quarters:2d}"
                f"  with inflections {inflected:3d}")
        if faired is not None:
            own_contours = glyph_contours(faired, name, True)
            own, own_quarters = required_places(own_contours), line_quarters(own_contours)
            own_inflected = required_places(own_contours, inflections=True)
            totals["faired"] += own
            totals["faired quarters"] += own_quarters
            totals["faired inflected"] += own_inflected
            line += (f"  faired floor {own:3d}  {own / max(nodes, 1):.2f}x  line quarters {own_quarters:2d}"
                     f"  with inflections {own_inflected:3d}")
        print(line)
    total_nodes = max(totals["nodes"], 1)

    def verdict(ratio):
        return f"{ratio:.3f}x ({'within' if ratio <= 0.7 else 'over'} the handwriting bar of 0.7x)"

    def text_bar(places):
        return f"{places / total_nodes:.3f}x ({'within' if places / total_nodes <= 1.3 else 'over'} the text bar of 1.3x)"

    def with_quarters(places, quarters, inflected):
        return (f"with G2 line joins {places + quarters} ({quarters} line quarters), {text_bar(places + quarters)}; "
                f"with the inflections' nodes too {inflected + quarters}, {text_bar(inflected + quarters)}")

    print(f"total: the source requires {totals['floor']} of its {totals['nodes']} nodes, "
          f"{verdict(totals['floor'] / total_nodes)}; "
          f"{with_quarters(totals['floor'], totals['quarters'], totals['inflected'])}")
    if faired is not None:
        print(f"total: the faired outline requires {totals['faired']}, {verdict(totals['faired'] / total_nodes)}; "
              f"{with_quarters(totals['faired'], totals['faired quarters'], totals['faired inflected'])}")


if __name__ == "__main__":
    main()
