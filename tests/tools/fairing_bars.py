#!/usr/bin/python3
"""The fairing issue's bars, measured independently of glyphfair (fontTools, numpy, scipy; no
code shared with glyphfair) on a source font and the UFO `glyphfair fair` wrote from it.

Per glyph (a–z A–Z by default, through the font's cmap), both versions:
  total variation  ∫|dκ/ds| ds over the segments plus |Δκ| at smooth joins (≤ 3°), κ in 1/em;
  inflections      sign changes of κ along smooth stretches (within segments and across
                   smooth joins), |κ|·UPM below 1e-6 counting as 0;
  extrema          turning points of κ along smooth stretches, each rise or fall counted once
                   it exceeds 1 % of the contour's largest |κ| (so float noise on an arc is
                   not an extremum);
  nodes            on-curve points;
  kinks, g2-jumps, missing extrema   as tests/tools/independent_checks.py defines them;
  distance         two-sided Hausdorff between the outlines, from samples 0.25 unit apart;
  corners lost     (text) the source's corners, joins turning by more than 3°, with no corner
                   of the output (a join turning by more than 3°, or one without a direction
                   on a side) within 0.25 % of the em;
  contours         count and each contour's direction (sign of its area), in order.

Bars (--profile handwriting|text) as the issue states them; prints a line per glyph and a
summary; exit 1 when a bar fails.

With --continuity g3, also the G3 issue's bars on the cubics: the median over smooth joins
between cubics of |κ′− − κ′+| / max(|κ′−|, |κ′+|), and (given --g2-ufo) the nodes against
the G2 output. Given --segments (what `glyphfair fair --segments` wrote), the bar on the
faired segments: at every smooth join between pieces the same relative κ′ jump at most 1e-6
(κ′ = 0 on both sides matching), each polynomial spiral first rebuilt here from its start
frame, length, end κ, κ′ and bumps (κ(s) the cubic Hermite plus the bumps, position by
Simpson's rule) and required to reach the end point and tangent it reports.

usage: fairing_bars.py FONT FAIRED.ufo --profile handwriting|text [--glyphs a,b,...]
                       [--continuity g3 [--g2-ufo G2.ufo] [--segments SEGMENTS.json]] [--json OUT]
"""
import argparse
import json
import math
import statistics
import sys

import numpy as np
from fontTools.pens.recordingPen import DecomposingRecordingPen, RecordingPen
from fontTools.ttLib import TTFont
from fontTools.ufoLib import UFOReader
from scipy.spatial import cKDTree

from compare_outlines import segments
from independent_checks import LINE_RESIDUE, end_curvature_slope, join_angle, join_counts, joins, norm, sub

SMOOTH_DEG, CORNER_DEG = 0.05, 3.0


def bezier(seg, t):
    """Points, first and second derivatives of a Bézier at the parameters t (numpy)."""
    p = np.array(seg, dtype=float)
    n = len(p) - 1
    t = np.asarray(t)[:, None]
    if n == 1:
        d1 = np.repeat((p[1] - p[0])[None, :], len(t), axis=0)
        return p[0] + t * (p[1] - p[0]), d1, np.zeros_like(d1)
    if n == 2:
        pt = (1 - t) ** 2 * p[0] + 2 * t * (1 - t) * p[1] + t ** 2 * p[2]
        d1 = 2 * ((1 - t) * (p[1] - p[0]) + t * (p[2] - p[1]))
        d2 = np.repeat((2 * (p[2] - 2 * p[1] + p[0]))[None, :], len(t), axis=0)
        return pt, d1, d2
    pt = (1 - t) ** 3 * p[0] + 3 * t * (1 - t) ** 2 * p[1] + 3 * t ** 2 * (1 - t) * p[2] + t ** 3 * p[3]
    d1 = 3 * ((1 - t) ** 2 * (p[1] - p[0]) + 2 * t * (1 - t) * (p[2] - p[1]) + t ** 2 * (p[3] - p[2]))
    d2 = 6 * ((1 - t) * (p[2] - 2 * p[1] + p[0]) + t * (p[3] - 2 * p[2] + p[1]))
    return pt, d1, d2


def curvature_samples(seg, n=64):
    t = np.linspace(0, 1, n + 1)
    pt, d1, d2 = bezier(seg, t)
    speed = np.hypot(d1[:, 0], d1[:, 1])
    with np.errstate(divide="ignore", invalid="ignore"):
        k = (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / speed ** 3
    ok = np.isfinite(k)
    return pt, k[ok], ok


def stretches(segs):
    """The contour's κ samples cut into smooth stretches (cut at joins over 3°), with the
    |Δκ| at the smooth joins."""
    n = len(segs)
    angles = [join_angle(segs[i - 1], segs[i]) for i in range(n)]
    breaks = [i for i in range(n) if angles[i] is None or angles[i] > CORNER_DEG]  # 0.0° is smooth
    order = list(range(n))
    if breaks:
        order = order[breaks[0]:] + order[:breaks[0]]
    out, current, jumps = [], [], 0.0
    for i in order:
        if i in breaks and current:
            out.append(current)
            current = []
        _, k, _ = curvature_samples(segs[i])
        if current and len(k):
            jumps += abs(k[0] - current[-1])
        current.extend(k.tolist())
    if current:
        if not breaks and current:  # a closed smooth contour: the seam joins too
            jumps += abs(current[0] - current[-1])
            current = current + current[:1]
        out.append(current)
    return out, jumps


def measures(contours, upm):
    tv = infl = ext = 0
    tv = 0.0
    for segs in contours:
        if not segs:
            continue
        runs, jumps = stretches(segs)
        tv += jumps * upm
        kmax = max((abs(x) for r in runs for x in r), default=0.0)
        for r in runs:
            k = np.array(r) * upm
            tv += float(np.sum(np.abs(np.diff(k))))
            signs = np.sign(np.where(np.abs(k) < 1e-6, 0, k))
            signs = signs[signs != 0]
            infl += int(np.sum(signs[1:] != signs[:-1]))
            # extrema with hysteresis
            step = 0.01 * kmax * upm
            direction, anchor = 0, k[0] if len(k) else 0
            for x in k[1:]:
                if direction >= 0 and x < anchor - step:
                    ext += direction > 0
                    direction, anchor = -1, x
                elif direction <= 0 and x > anchor + step:
                    ext += direction < 0
                    direction, anchor = 1, x
                elif (direction > 0 and x > anchor) or (direction < 0 and x < anchor) or direction == 0:
                    anchor = x if direction != 0 else anchor
    return tv, infl, ext


def corners_lost(source, faired, upm):
    """The source's corners (joins turning by more than CORNER_DEG) that have no output corner
    (the same, or a join without a direction on one side) within 0.25 % of the em."""
    def corners(contours, undirected):
        out = []
        for segs in contours:
            for i in range(len(segs)):
                a = join_angle(segs[i - 1], segs[i])
                if (a is None and undirected) or (a is not None and a > CORNER_DEG):
                    out.append(segs[i][0])
        return out
    kept = corners(faired, True)
    reach = 0.0025 * upm
    return sum(not any(math.dist(p, q) <= reach for q in kept) for p in corners(source, False))


def g3_jumps(contours):
    """At every smooth join (≤ 0.05°) between two cubics, |κ′− − κ′+| / max(|κ′−|, |κ′+|)
    (0 where both are 0): the G3 bar's measure."""
    out = []
    for segs in contours:
        for a, b, angle in joins(segs):
            if angle > SMOOTH_DEG:
                continue
            d1, d2 = end_curvature_slope(a, True), end_curvature_slope(b, False)
            if d1 is None or d2 is None:
                continue
            big = max(abs(d1), abs(d2))
            out.append(abs(d1 - d2) / big if big > 0 else 0.0)
    return out


def dense(contours, spacing=0.25):
    pts = []
    for segs in contours:
        for s in segs:
            approx = sum(norm(sub(b, a)) for a, b in zip(s, s[1:]))
            n = max(2, int(approx / spacing))
            pt, _, _ = bezier(s, np.linspace(0, 1, n + 1))
            pts.append(pt)
    return np.vstack(pts) if pts else np.zeros((0, 2))


def hausdorff(a, b):
    pa, pb = dense(a), dense(b)
    if len(pa) == 0 or len(pb) == 0:
        return 0.0 if len(pa) == len(pb) else math.inf
    return max(cKDTree(pb).query(pa)[0].max(), cKDTree(pa).query(pb)[0].max())


def area(segs):
    pts = dense([segs], 2.0)
    x, y = pts[:, 0], pts[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def glyph_contours(glyphset, name, decompose):
    pen = DecomposingRecordingPen(glyphset) if decompose else RecordingPen()
    glyphset[name].draw(pen)
    return [[s for s in c if any(p != s[0] for p in s)] for c in segments(pen.value, LINE_RESIDUE)]


def spiral_end(piece, steps=400):
    """The far end of a polynomial spiral piece, from its start frame, length, end κ, κ′ and
    bumps (c1·16u²(1−u)² + c2·20u²(1−u)²(2u−1) added to κ; 0 where not given)."""
    a, b = piece["start"], piece["end"]
    L = piece["length"]
    k0, d0, k1, d1 = a["curvature"], L * a["dcurvature_ds"], b["curvature"], L * b["dcurvature_ds"]
    c1, c2 = piece.get("symmetric_bump", 0.0), piece.get("odd_bump", 0.0)

    def theta(u):  # θ0 + L ∫ (Hermite(κ0, κ0′, κ1, κ1′) + bumps)
        h00 = u - u**3 + u**4 / 2
        h10 = u**2 / 2 - 2 * u**3 / 3 + u**4 / 4
        h01 = u**3 - u**4 / 2
        h11 = u**4 / 4 - u**3 / 3
        b1 = 16 * (u**3 / 3 - u**4 / 2 + u**5 / 5)
        b2 = 20 * (-(u**3) / 3 + u**4 - u**5 + u**6 / 3)
        return a["tangent_angle"] + L * (k0 * h00 + d0 * h10 + k1 * h01 + d1 * h11 + c1 * b1 + c2 * b2)

    us = np.linspace(0.0, 1.0, steps + 1)
    w = np.ones(steps + 1)
    w[1:-1:2], w[2:-1:2] = 4, 2
    th = theta(us)
    x = a["point"][0] + L / (3 * steps) * np.sum(w * np.cos(th))
    y = a["point"][1] + L / (3 * steps) * np.sum(w * np.sin(th))
    return (x, y), theta(1.0)


def segment_bars(path, glyph_names):
    """Smooth joins between faired pieces whose κ′ jump exceeds 1e-6, spirals that miss their
    reported ends, and the number of smooth joins, over the given glyphs."""
    doc = json.load(open(path))
    over = misses = count = 0
    for g in doc["glyphs"]:
        if g["name"] not in glyph_names:
            continue
        for c in g["contours"]:
            pieces = c["pieces"]
            for i, p in enumerate(pieces):
                if p["kind"] == "polynomial-spiral":
                    (x, y), th = spiral_end(p)
                    ex, ey = p["end"]["point"]
                    turn = math.remainder(th - p["end"]["tangent_angle"], 2 * math.pi)
                    if math.hypot(x - ex, y - ey) > 1e-6 * max(p["length"], 1.0) or abs(turn) > 1e-8:
                        misses += 1
                if not p["smooth_start"] or (i == 0 and not c["closed"]) or len(pieces) == 1:
                    continue
                q = pieces[i - 1]
                a, b = q["end"]["dcurvature_ds"], p["start"]["dcurvature_ds"]
                count += 1
                if a is None or b is None:
                    over += 1
                    continue
                big = max(abs(a), abs(b))
                if big > 0 and abs(a - b) > 1e-6 * big:
                    over += 1
    return over, misses, count


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("font")
    ap.add_argument("ufo")
    ap.add_argument("--profile", choices=["handwriting", "text"], required=True)
    ap.add_argument("--glyphs", default="abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ")
    ap.add_argument("--continuity", choices=["g2", "g3"], default="g2",
                    help="g3: also the G3 bars (median κ′ jump; nodes against --g2-ufo)")
    ap.add_argument("--g2-ufo", help="the G2 output of the same glyphs, for the G3 node bar")
    ap.add_argument("--segments", help="glyphfair fair --segments output, for the G3 bar on the faired segments")
    ap.add_argument("--json")
    args = ap.parse_args()
    font = TTFont(args.font)
    upm = font["head"].unitsPerEm
    cmap = font.getBestCmap()
    src_gs = font.getGlyphSet()
    ufo_gs = UFOReader(args.ufo, validate=True).getGlyphSet()
    g2_gs = UFOReader(args.g2_ufo, validate=True).getGlyphSet() if args.g2_ufo else None
    rows = []
    slope_jumps = []
    g2_nodes = 0
    for ch in args.glyphs:
        name = cmap.get(ord(ch))
        if name is None or name not in ufo_gs:
            continue
        a = glyph_contours(src_gs, name, True)
        b = glyph_contours(ufo_gs, name, True)
        tv_a, infl_a, ext_a = measures(a, upm)
        tv_b, infl_b, ext_b = measures(b, upm)
        kinks, jumps, smooth, missing = join_counts(b, upm)
        slope_jumps += g3_jumps(b)
        if g2_gs is not None:
            g2_nodes += sum(len(c) for c in glyph_contours(g2_gs, name, True))
        row = {
            "glyph": name, "tv": [tv_a, tv_b], "inflections": [infl_a, infl_b], "extrema": [ext_a, ext_b],
            "nodes": [sum(len(c) for c in a), sum(len(c) for c in b)],
            "kinks": kinks, "g2_jumps": jumps, "smooth_joins": smooth, "missing_extrema": missing,
            "distance": hausdorff(a, b), "corners_lost": corners_lost(a, b, upm),
            "contours_kept": len(a) == len(b) and all((area(x) > 0) == (area(y) > 0) for x, y in zip(a, b)),
        }
        rows.append(row)
        print(f"{name:12s} tv {tv_a:9.2f} -> {tv_b:8.2f}  infl {infl_a:3d} -> {infl_b:3d}  ext {ext_a:3d} -> {ext_b:3d}  "
              f"nodes {row['nodes'][0]:3d} -> {row['nodes'][1]:3d}  kinks {kinks}  g2 {jumps}/{smooth}  "
              f"missing {missing}  dist {row['distance']:.2f}  corners lost {row['corners_lost']}"
              f"{'' if row['contours_kept'] else '  CONTOURS CHANGED'}")

    def ratio(key, f=statistics.median):
        # NaN (the bar not met) where no glyph's source has any: Humor Sans draws only lines.
        values = [r[key][1] / r[key][0] for r in rows if r[key][0] > 0]
        return f(values) if values else math.nan

    def total_ratio(key):
        a, b = sum(r[key][0] for r in rows), sum(r[key][1] for r in rows)
        return b / a if a else (math.inf if b else 0.0)

    jumps = sum(r["g2_jumps"] for r in rows)
    smooth = sum(r["smooth_joins"] for r in rows)
    worst = max(r["distance"] for r in rows) / upm
    bars = []
    if args.profile == "handwriting":
        bars = [
            ("median TV ratio <= 0.25", ratio("tv"), ratio("tv") <= 0.25),
            ("inflections <= 0.4x", total_ratio("inflections"), total_ratio("inflections") <= 0.4),
            ("curvature extrema <= 0.5x", total_ratio("extrema"), total_ratio("extrema") <= 0.5),
            ("no missing extrema", sum(r["missing_extrema"] for r in rows), sum(r["missing_extrema"] for r in rows) == 0),
            ("no kinks", sum(r["kinks"] for r in rows), sum(r["kinks"] for r in rows) == 0),
            ("g2-jumps <= 2% of smooth joins", jumps / max(smooth, 1), jumps <= 0.02 * smooth),
            ("every glyph within 1.5% UPM", worst, worst <= 0.015),
            ("nodes <= 0.7x", total_ratio("nodes"), total_ratio("nodes") <= 0.7),
            ("contour count and direction kept", sum(not r["contours_kept"] for r in rows), all(r["contours_kept"] for r in rows)),
        ]
    else:
        bars = [
            ("every glyph within 0.15% UPM", worst, worst <= 0.0015),
            ("corners kept", sum(r["corners_lost"] for r in rows), sum(r["corners_lost"] for r in rows) == 0),
            ("no g2-jump at smooth joins", jumps, jumps == 0),
            ("no kinks", sum(r["kinks"] for r in rows), sum(r["kinks"] for r in rows) == 0),
            ("TV <= 0.95x (median)", ratio("tv"), ratio("tv") <= 0.95),
            ("inflections not increased", total_ratio("inflections"), total_ratio("inflections") <= 1.0),
            ("nodes <= 1.3x", total_ratio("nodes"), total_ratio("nodes") <= 1.3),
            ("contour count and direction kept", sum(not r["contours_kept"] for r in rows), all(r["contours_kept"] for r in rows)),
        ]
    if args.continuity == "g3":
        # No smooth join between two cubics (a TrueType source): nothing measured, no pass.
        median_jump = statistics.median(slope_jumps) if slope_jumps else math.nan
        bars.append(("dk/ds jump at smooth joins, median < 0.05", median_jump, median_jump < 0.05))
        if g2_gs is not None:
            growth = sum(r["nodes"][1] for r in rows) / max(g2_nodes, 1)
            bars.append(("nodes <= 1.2x the G2 output", growth, growth <= 1.2))
        if args.segments:
            over, misses, count = segment_bars(args.segments, {r["glyph"] for r in rows})
            print(f"segments: {count} smooth joins, {over} with a dk/ds jump over 1e-6, "
                  f"{misses} spirals missing their reported ends")
            bars.append(("segments: smooth joins with dk/ds jump > 1e-6", over, over == 0 and count > 0))
            bars.append(("segments: spirals rebuilt reach their ends", misses, misses == 0))
    failed = 0
    for name, value, ok in bars:
        failed += not ok
        print(f"{'PASS' if ok else 'FAIL'}  {name:36s} {value:.4g}")
    if args.json:
        with open(args.json, "w") as f:
            # numpy's scalars (bool_, float64) are not JSON: plain Python values out.
            json.dump({"glyphs": rows, "bars": [{"bar": n, "value": float(v), "pass": bool(ok)} for n, v, ok in bars]},
                      f, indent=1, default=lambda x: x.item() if hasattr(x, "item") else str(x))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
