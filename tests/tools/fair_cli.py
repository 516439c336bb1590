#!/usr/bin/python3
"""glyphfair fair from outside, measured with fontTools and numpy/scipy only:

  * the bundled DejaVu Sans subset (text profile) and Because We Learn subset (handwriting),
    every glyph: the UFO validates; names, unicodes and advance widths are the source's;
    contour count and each contour's direction are kept; every glyph is within the
    profile's default tolerance of the source (two-sided Hausdorff from dense samples);
    every coordinate is an integer; every smooth on-curve point is exactly collinear with
    its neighbouring handles (G1 exact on the grid); on a–z A–Z no kinks, and for handwriting
    at most 2 % of the smooth joins with a g2-jump (the fairing issue's bars, by
    independent_checks.py);
  * --no-round keeps fractional coordinates; .svg and .json outputs; --proof writes a PDF;
  * --continuity g3 --segments: the exported faired pieces are G3 at their smooth joins;
  * a point-sequence JSON (tests/data/handwriting-points.json) is fitted and faired, every
    glyph within the tolerance of its points;
  * the error contract: exit 2 with one line on stderr naming the file, nothing left behind,
    for a missing source, an unknown output format, a malformed point file, and an output
    that is the source.

usage: fair_cli.py GLYPHFAIR FONTS DATA WORKDIR
"""
import json
import os
import shutil
import subprocess
import sys

import numpy as np
from fontTools.ttLib import TTFont
from fontTools.ufoLib import UFOReader
from scipy.spatial import cKDTree

from cli_contract import error_problem, finish
from fairing_bars import area, dense, glyph_contours, segment_bars
from independent_checks import join_counts


def run(glyphfair, *args):
    return subprocess.run([glyphfair, "fair", *args], capture_output=True, text=True)


def grid_problems(glif_path, kept):
    """Fractional coordinates, and smooth on-curve points not on one line with their
    neighbours, in the contours that were faired (`kept`: indices of contours kept as the
    source had them)."""
    import xml.etree.ElementTree as ET
    bad = fractional = 0
    for index, contour in enumerate(ET.parse(glif_path).getroot().iter("contour")):
        if index in kept:
            continue
        pts = [(float(p.get("x")), float(p.get("y")), p.get("type"), p.get("smooth") == "yes") for p in contour.iter("point")]
        fractional += sum(x != round(x) or y != round(y) for x, y, _, _ in pts)
        n = len(pts)
        for i, (x, y, t, smooth) in enumerate(pts):
            if not smooth or t is None or n < 3:
                continue
            a, b = pts[i - 1], pts[(i + 1) % n]
            cross = (x - a[0]) * (b[1] - y) - (y - a[1]) * (b[0] - x)
            if cross != 0:
                bad += 1
    return fractional, bad


def kept_contours(stderr):
    """{glyph: {contour indices}} from the warnings of contours kept unfaired."""
    import re
    kept = {}
    for m in re.finditer(r"glyph '([^']+)': contour (\d+): .*\(kept unfaired\)", stderr):
        kept.setdefault(m.group(1), set()).add(int(m.group(2)))
    return kept


def check_font(glyphfair, font_path, profile, tolerance_fraction, work, failures):
    out = os.path.join(work, f"{profile}.ufo")
    r = run(glyphfair, font_path, "--profile", profile, "-o", out)
    if r.returncode != 0:
        failures.append(f"{profile}: exit {r.returncode}: {r.stderr.strip()}")
        return
    kept = kept_contours(r.stderr)
    print(f"{profile}: {sum(len(v) for v in kept.values())} contours kept unfaired (warned on stderr)")
    font = TTFont(font_path)
    upm = font["head"].unitsPerEm
    tolerance = tolerance_fraction * upm
    reader = UFOReader(out, validate=True)
    ufo = reader.getGlyphSet()
    src = font.getGlyphSet()
    cmap = {}
    for code, name in font.getBestCmap().items():
        cmap.setdefault(name, set()).add(code)
    contents = reader.getGlyphSet().contents
    letters = {name for name, codes in cmap.items() if any(chr(c).isascii() and chr(c).isalpha() for c in codes)}
    kinks = jumps = smooth = 0
    for name in font.getGlyphOrder():
        a = glyph_contours(src, name, True)
        if not a:
            continue
        if name not in ufo:
            failures.append(f"{profile}: {name} missing from the UFO")
            continue
        g = type("Glyph", (), {})()
        ufo.readGlyph(name, g)
        if set(getattr(g, "unicodes", []))  != cmap.get(name, set()):
            failures.append(f"{profile}: {name} unicodes {g.unicodes}")
        if getattr(g, "width", 0) != font["hmtx"][name][0]:
            failures.append(f"{profile}: {name} advance {getattr(g, 'width', 0)} != {font['hmtx'][name][0]}")
        b = glyph_contours(ufo, name, True)
        if len(a) != len(b):
            failures.append(f"{profile}: {name} has {len(b)} contours, the source {len(a)}")
            continue
        for k, (x, y) in enumerate(zip(a, b)):
            if (area(x) > 0) != (area(y) > 0):
                failures.append(f"{profile}: {name} contour {k} changed direction")
        if name in letters:
            k, j, n, _ = join_counts(b, upm)
            kinks, jumps, smooth = kinks + k, jumps + j, smooth + n
        pa, pb = dense(a), dense(b)
        d = max(cKDTree(pb).query(pa)[0].max(), cKDTree(pa).query(pb)[0].max())
        if d > tolerance * 1.01:
            failures.append(f"{profile}: {name} is {d:.3f} units from the source (tolerance {tolerance})")
        fractional, bad = grid_problems(os.path.join(out, "glyphs", contents[name]), kept.get(name, set()))
        if fractional:
            failures.append(f"{profile}: {name} has {fractional} fractional coordinates")
        if bad:
            failures.append(f"{profile}: {name} has {bad} smooth points not collinear with their handles")
    # The fairing issue's bars on a–z A–Z: no kinks; no smooth join with a curvature jump over
    # 5 % (independent_checks' rule) for text, at most 2 % of them for handwriting.
    print(f"{profile}: a–z A–Z {kinks} kinks, {jumps} of {smooth} smooth joins with a g2-jump")
    if kinks:
        failures.append(f"{profile}: {kinks} kinks on a–z A–Z")
    if profile == "text" and jumps:
        failures.append(f"{profile}: {jumps} of {smooth} smooth joins on a–z A–Z jump in curvature (bar 0)")
    if profile == "handwriting" and jumps > 0.02 * smooth:
        failures.append(f"{profile}: {jumps} of {smooth} smooth joins on a–z A–Z jump in curvature (bar 2 %)")


def main():
    glyphfair, fonts, data, work = sys.argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    failures = []
    dejavu = os.path.join(fonts, "DejaVuSans/DejaVuSans-subset.ttf")
    bwl = os.path.join(fonts, "BecauseWeLearn/BecauseWeLearn-Regular-subset.otf")
    check_font(glyphfair, dejavu, "text", 0.00125, work, failures)
    check_font(glyphfair, bwl, "handwriting", 0.014, work, failures)

    # Other outputs, unrounded, with a proof.
    for ext in ("svg", "json"):
        out = os.path.join(work, f"o.{ext}")
        r = run(glyphfair, dejavu, "--glyphs", "o,S", "--no-round", "-o", out, "--proof", os.path.join(work, f"o-{ext}.pdf"))
        if r.returncode != 0 or not os.path.exists(out) or not os.path.exists(os.path.join(work, f"o-{ext}.pdf")):
            failures.append(f"--no-round .{ext}: exit {r.returncode}: {r.stderr.strip()}")
    with open(os.path.join(work, "o.json")) as f:
        doc = json.load(f)
    coords = json.dumps(doc)
    if "." not in coords:
        failures.append("--no-round wrote no fractional coordinate at all")

    # A font drawn off the integer grid (Inconsolata: CFF in 1/1024 units) keeps fractions by
    # default, and --round puts it on the grid. (Its S is no example: at the text tolerance of
    # 1.25 units it is kept unfaired under --round, its source fractions and all.)
    inconsolata = os.path.join(fonts, "Inconsolata/Inconsolata-subset.otf")
    for flags, fractions in (((), True), (("--round",), False)):
        out = os.path.join(work, f"inconsolata{''.join(flags)}.ufo")
        r = run(glyphfair, inconsolata, "--glyphs", "e", *flags, "-o", out)
        if r.returncode != 0:
            failures.append(f"Inconsolata e {' '.join(flags)}: exit {r.returncode}: {r.stderr.strip()}")
            continue
        fractional, _ = grid_problems(os.path.join(out, "glyphs", "e.glif"), set())
        if (fractional > 0) != fractions:
            failures.append(f"Inconsolata e {' '.join(flags) or '(default)'}: fractions {'lost' if fractions else 'left'}")
    r = run(glyphfair, inconsolata, "--glyphs", "e", "--round", "--no-round", "-o", os.path.join(work, "both.ufo"))
    if r.returncode == 0:
        failures.append("--round with --no-round was accepted")

    # G3 with the faired segments exported: every smooth join between pieces, line joins
    # included, has κ′ matched to 1e-6 (the summary reports no line join G2 only), and every
    # spiral rebuilt here from its own data reaches the end it reports (fairing_bars.segment_bars).
    segments_path = os.path.join(work, "g3-segments.json")
    names = ["o", "e", "c", "O", "D", "G"]
    r = run(glyphfair, dejavu, "--glyphs", ",".join(names), "--continuity", "g3", "-o", os.path.join(work, "g3.ufo"),
            "--segments", segments_path)
    if r.returncode != 0:
        failures.append(f"--continuity g3: exit {r.returncode}: {r.stderr.strip()}")
    else:
        over, misses, count = segment_bars(segments_path, set(names))
        summary = r.stderr.strip().splitlines()[-1]
        line_joins = int(summary.split("smooth runs (")[1].split()[0])
        if count == 0 or over > 0 or line_joins > 0 or misses:
            failures.append(f"--continuity g3: {over} of {count} smooth joins off G3 ({line_joins} line joins reported), "
                            f"{misses} spirals missing their ends")
        ufo = UFOReader(os.path.join(work, "g3.ufo"), validate=True).getGlyphSet()
        src = TTFont(dejavu).getGlyphSet()
        for name in names:
            a, b = dense(glyph_contours(src, name, False)), dense(glyph_contours(ufo, name, False))
            d = max(cKDTree(b).query(a)[0].max(), cKDTree(a).query(b)[0].max())
            if d > 0.00125 * 2048 * 1.01:
                failures.append(f"--continuity g3: {name} is {d:.2f} units from the source")
    problem = error_problem(run(glyphfair, dejavu, "--glyphs", "o", "-o", os.path.join(work, "e4.ufo"), "--segments",
                                os.path.join(work, "e4.txt")), 2, "e4.txt")
    if problem:
        failures.append(f"--segments to a .txt: {problem}")

    # Point sequences: every glyph within the tolerance of its points.
    points_path = os.path.join(data, "handwriting-points.json")
    out = os.path.join(work, "points.ufo")
    r = run(glyphfair, points_path, "--profile", "handwriting", "-o", out)
    if r.returncode != 0:
        failures.append(f"points: exit {r.returncode}: {r.stderr.strip()}")
    else:
        with open(points_path) as f:
            pts = json.load(f)
        ufo = UFOReader(out, validate=True).getGlyphSet()
        tolerance = 0.014 * pts["unitsPerEm"] + pts["fitTolerance"]
        for g in pts["glyphs"]:
            b = glyph_contours(ufo, g["name"], False)
            if len(b) != len(g["strokes"]):
                failures.append(f"points: {g['name']} has {len(b)} contours for {len(g['strokes'])} strokes")
                continue
            curve = dense(b)
            for stroke in g["strokes"]:
                d = cKDTree(curve).query(np.array(stroke["points"]))[0].max()
                if d > tolerance:
                    failures.append(f"points: {g['name']}: a point is {d:.2f} units from the faired curve")

    # Errors: exit 2, one line naming the file, no output left.
    bad_points = os.path.join(work, "bad-points.json")
    with open(bad_points, "w") as f:
        json.dump({"glyphs": [{"name": "x", "strokes": [{"points": [[0, 0], [1]]}]}]}, f)
    for args, needle in (([os.path.join(work, "missing.ttf"), "-o", os.path.join(work, "e1.ufo")], "missing.ttf"),
                         ([dejavu, "-o", os.path.join(work, "e2.txt")], "e2.txt"),
                         ([bad_points, "-o", os.path.join(work, "e3.ufo")], "glyph 'x'"),
                         ([dejavu, "-o", dejavu], "DejaVuSans-subset.ttf")):
        problem = error_problem(run(glyphfair, *args), 2, needle)
        target = args[-1]
        if problem:
            failures.append(f"error {args}: {problem}")
        if target != dejavu and os.path.exists(target):
            failures.append(f"error {args}: left {target} behind")
    if not os.path.exists(dejavu):
        failures.append("the source was overwritten")

    return finish(failures)


if __name__ == "__main__":
    sys.exit(main())
