#!/usr/bin/python3
"""An independent implementation of three of glyphfair check's definitions, written from the
issue's text with fontTools and plain Python (no code shared with glyphfair):

  kink              a join whose tangents differ by more than 0.05° and less than 3°;
  g2-jump           at a smooth join (≤ 0.05°), |κ− − κ+| / max(|κ−|, |κ+|) > 0.05 when
                    max|κ|·UPM ≥ 0.5, else |κ− − κ+|·UPM > 0.05 (line–curve joins count;
                    an unbounded side counts);
  missing-extremum  a horizontal or vertical tangent inside a segment, farther than 1% of its
                    arc length from both ends, with no on-curve point within 0.5 units
                    (at 1000 UPM, scaled with UPM).

Compares its counts with glyphfair's JSON report; exit 1 when any differs by more than 5%.

usage: independent_checks.py GLYPHFAIR FONT [WORKDIR]
"""
import json
import math
import os
import subprocess
import sys
import tempfile

from fontTools.pens.recordingPen import DecomposingRecordingPen
from fontTools.ttLib import TTFont

from compare_outlines import segments  # the same reading of fontTools' drawing as the UFO check

# Lines this short are residue of CFF's 16.16 arithmetic (Linux Libertine's Y closes with a
# 1.5e-5-unit line), not geometry: FreeType, and so glyphfair, never see them.
LINE_RESIDUE = 1e-3


def contours_of(glyphset, name):
    """Explicit segments per contour (fonts' contours are all closed), zero-length ones dropped."""
    pen = DecomposingRecordingPen(glyphset)
    glyphset[name].draw(pen)
    return [([s for s in c if any(p != s[0] for p in s)], True) for c in segments(pen.value, LINE_RESIDUE)]


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1]


def norm(a):
    return math.hypot(a[0], a[1])


def tangent(seg, at_end):
    pts = list(reversed(seg)) if at_end else list(seg)
    for q in pts[1:]:
        d = sub(q, pts[0])
        if d != (0, 0):
            return (-d[0], -d[1]) if at_end else d
    return None


def end_curvature(seg, at_end):
    """κ at an end of a Bézier of degree n: (n−1)/n · (Δ0 × Δ1) / |Δ0|³ (signed, along travel)."""
    n = len(seg) - 1
    if n == 1:
        return 0.0
    p = list(reversed(seg)) if at_end else list(seg)
    d0, d1 = sub(p[1], p[0]), sub(p[2], p[1])
    if norm(d0) == 0:
        return math.inf
    k = (n - 1) / n * cross(d0, d1) / norm(d0) ** 3
    return -k if at_end else k  # walking the reversed points flips the turn


def end_curvature_slope(seg, at_end):
    """dκ/ds at an end of a cubic (None for lines and quadratics), signed along travel:
    (|B′|²(B′ × B‴) − 3(B′ × B″)(B′ · B″)) / |B′|⁶ at t = 0 of the points walked from that
    end. Walking backwards flips both κ and s, so the far end needs no sign change."""
    if len(seg) != 4:
        return None
    p = list(reversed(seg)) if at_end else list(seg)
    d1 = tuple(3 * (p[1][i] - p[0][i]) for i in range(2))
    d2 = tuple(6 * (p[2][i] - 2 * p[1][i] + p[0][i]) for i in range(2))
    d3 = tuple(6 * (p[3][i] - 3 * p[2][i] + 3 * p[1][i] - p[0][i]) for i in range(2))
    v2 = dot(d1, d1)
    if v2 == 0:
        return None
    slope = (v2 * cross(d1, d3) - 3 * cross(d1, d2) * dot(d1, d2)) / v2 ** 3
    return slope  # reversed walk: κ → −κ and s → −s, so dκ/ds is unchanged


def point(seg, t):
    pts = list(seg)
    while len(pts) > 1:
        pts = [((1 - t) * a[0] + t * b[0], (1 - t) * a[1] + t * b[1]) for a, b in zip(pts, pts[1:])]
    return pts[0]


def speed(seg, t):
    n = len(seg) - 1
    h = [(n * (b[0] - a[0]), n * (b[1] - a[1])) for a, b in zip(seg, seg[1:])]
    return norm(point(h, t)) if len(h) > 1 else norm(h[0])


def length(seg, t0, t1, n=64):
    h = (t1 - t0) / n
    total = speed(seg, t0) + speed(seg, t1)
    for i in range(1, n):
        total += (4 if i % 2 else 2) * speed(seg, t0 + i * h)
    return total * h / 3


def derivative_roots(seg, axis):
    """t in (0, 1) where the derivative of coordinate `axis` is 0 and changes sign."""
    c = [p[axis] for p in seg]
    if len(c) == 3:
        a, b = c[0] - 2 * c[1] + c[2], c[1] - c[0]  # x'(t)/2 = b + a t
        return [-b / a] if a != 0 and 0 < -b / a < 1 else []
    if len(c) == 4:
        A = -c[0] + 3 * c[1] - 3 * c[2] + c[3]
        B = 2 * (c[0] - 2 * c[1] + c[2])
        C = c[1] - c[0]  # x'(t)/3 = A t² + B t + C
        if abs(A) < 1e-12 * (abs(B) + abs(C) + 1e-300):
            return [-C / B] if B != 0 and 0 < -C / B < 1 else []
        disc = B * B - 4 * A * C
        if disc <= 0:
            return []
        r = math.sqrt(disc)
        return [t for t in ((-B - r) / (2 * A), (-B + r) / (2 * A)) if 0 < t < 1]
    return []


def join_angle(a, b):
    """|Turning| in degrees from segment a's end to segment b's start; None where either has
    no direction there."""
    tin, tout = tangent(a, True), tangent(b, False)
    if tin is None or tout is None:
        return None
    return abs(math.degrees(math.atan2(cross(tin, tout), dot(tin, tout))))


def joins(segs):
    """(incoming, outgoing, |turning| in degrees) at every join of a closed contour whose two
    segments both have a direction there."""
    for i in range(len(segs)):
        angle = join_angle(segs[i - 1], segs[i])
        if angle is not None:
            yield segs[i - 1], segs[i], angle


def join_counts(contours, upm):
    """Kinks, g2-jumps and missing extrema of one glyph's contours (closed, segments without
    zero-length ones), and how many smooth joins there were."""
    kinks = jumps = smooth = missing = 0
    nodes = [s[0] for c in contours for s in c] + [s[-1] for c in contours for s in c]
    for segs in contours:
        for a, b, angle in joins(segs):
            if 0.05 < angle < 3:
                kinks += 1
            elif angle <= 0.05:
                smooth += 1
                k1, k2 = end_curvature(a, True), end_curvature(b, False)
                if math.isinf(k1) or math.isinf(k2):
                    jumps += 1
                    continue
                big = max(abs(k1), abs(k2))
                if big * upm >= 0.5:
                    jumps += abs(k1 - k2) / big > 0.05
                else:
                    jumps += abs(k1 - k2) * upm > 0.05
        for s in segs:
            if len(s) == 2:
                continue
            total = length(s, 0, 1)
            for axis in (0, 1):
                for t in derivative_roots(s, axis):
                    before = length(s, 0, t)
                    if before <= 0.01 * total or total - before <= 0.01 * total:
                        continue
                    p = point(s, t)
                    if min(norm(sub(p, q)) for q in nodes) > 0.5 * upm / 1000:
                        missing += 1
    return kinks, jumps, smooth, missing


def count(font_path):
    font = TTFont(font_path)
    upm = font["head"].unitsPerEm
    gs = font.getGlyphSet()
    kinks = jumps = missing = 0
    for name in font.getGlyphOrder():
        k, j, _, m = join_counts([c for c, _ in contours_of(gs, name)], upm)
        kinks, jumps, missing = kinks + k, jumps + j, missing + m
    return {"kink": kinks, "g2-jump": jumps, "missing-extremum": missing}


def main():
    glyphfair, font = sys.argv[1:3]
    work = sys.argv[3] if len(sys.argv) > 3 else tempfile.mkdtemp()
    os.makedirs(work, exist_ok=True)
    report = os.path.join(work, os.path.basename(font) + ".check.json")
    subprocess.run([glyphfair, "check", font, "--format", "json", "--fail-on", "never", "-o", report], check=True)
    with open(report) as f:
        ours = json.load(f)["summary"]["by_check"]
    theirs = count(font)
    bad = 0
    for check, n in theirs.items():
        m = ours.get(check, 0)
        ok = abs(m - n) <= 0.05 * max(m, n) or abs(m - n) <= 1
        bad += not ok
        print(f"{check:17s} glyphfair {m:6d}  independent {n:6d}  {'ok' if ok else 'DIFFERS'}")
    print(f"{3 - bad} passed, {bad} failed")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
