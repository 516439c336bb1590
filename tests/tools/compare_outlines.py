#!/usr/bin/python3
"""Independent check that a UFO (or SVG) written by glyphfair reproduces a font's outlines.

Reads the font with fontTools and the UFO with fontTools.ufoLib (validating it), splits both
into explicit line/quadratic/cubic segments (zero-length lines dropped: they have no
geometry), and requires, glyph by glyph, the same contours in the same order and direction
with every control point within TOL font units, which bounds the two-sided Hausdorff
distance by TOL (a cyclic shift of a contour's start is allowed only with
--allow-rotation). Also compares advance widths and unicodes. Exit 0 when everything
matches, 1 otherwise (a line per mismatch).

usage: compare_outlines.py FONT UFO [--tol 1e-6] [--location wght=700]
"""
import argparse
import sys

from fontTools.pens.basePen import decomposeQuadraticSegment
from fontTools.pens.recordingPen import DecomposingRecordingPen, RecordingPen
from fontTools.ttLib import TTFont
from fontTools.ufoLib import UFOReader


def segments(recording, tol=0.0):
    """RecordingPen value -> list of contours, each a list of segments (tuples of points);
    lines no longer than tol are dropped."""
    contours, current, start, pos = [], None, None, None
    for op, args in recording:
        if op == "moveTo":
            current, start, pos = [], args[0], args[0]
        elif op == "lineTo":
            current.append((pos, args[0]))
            pos = args[0]
        elif op == "qCurveTo":
            pts = list(args)
            if pts[-1] is None:  # an all-off-curve TrueType contour, drawn without moveTo
                pts = pts[:-1]
                current = []
                start = ((pts[-1][0] + pts[0][0]) / 2, (pts[-1][1] + pts[0][1]) / 2)
                pos = start
                pts.append(start)
            for c, p in decomposeQuadraticSegment(pts):
                current.append((pos, c, p))
                pos = p
        elif op == "curveTo":
            current.append((pos,) + tuple(args))
            pos = args[-1]
        elif op in ("closePath", "endPath"):
            if op == "closePath" and pos != start:
                current.append((pos, start))
            # zero-length lines carry no geometry (FreeType drops them from CFF charstrings)
            kept = [s for s in current
                    if not (len(s) == 2 and abs(s[0][0] - s[1][0]) <= tol and abs(s[0][1] - s[1][1]) <= tol)]
            contours.append(kept or current[:1])
            current = None
    return contours


def elevated(contour):
    """Quadratics as their exact cubics, so a --cubic UFO compares with a TrueType font."""
    out = []
    for s in contour:
        if len(s) == 3:
            p0, c, p2 = s
            s = (p0, (p0[0] + 2 * (c[0] - p0[0]) / 3, p0[1] + 2 * (c[1] - p0[1]) / 3),
                 (p2[0] + 2 * (c[0] - p2[0]) / 3, p2[1] + 2 * (c[1] - p2[1]) / 3), p2)
        out.append(s)
    return out


def close(a, b, tol):
    return len(a) == len(b) and all(abs(p[0] - q[0]) <= tol and abs(p[1] - q[1]) <= tol for p, q in zip(a, b))


def same_contour(a, b, tol, allow_rotation):
    if len(a) != len(b):
        return False
    shifts = range(len(a)) if allow_rotation else [0]
    return any(all(close(a[(i + k) % len(a)], b[i], tol) for i in range(len(a))) for k in shifts)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("font")
    ap.add_argument("ufo")
    ap.add_argument("--tol", type=float, default=1e-6)
    ap.add_argument("--location", default="")
    ap.add_argument("--allow-rotation", action="store_true")
    ap.add_argument("--elevate", action="store_true", help="compare quadratics as cubics")
    a = ap.parse_args()

    font = TTFont(a.font)
    location = {k: float(v) for k, v in (kv.split("=") for kv in a.location.split(",") if kv)}
    glyphset = font.getGlyphSet(location=location or None)
    cmap = {}
    for code, name in font.getBestCmap().items():
        cmap.setdefault(name, []).append(code)

    reader = UFOReader(a.ufo, validate=True)
    ufo_glyphs = reader.getGlyphSet(validateRead=True)
    failed = set()
    for name in ufo_glyphs.keys():
        if name not in glyphset:
            print(f"{name}: not in the font")
            failed.add(name)
            continue
        rf, ru = DecomposingRecordingPen(glyphset), RecordingPen()
        glyphset[name].draw(rf)
        ug = ufo_glyphs[name]
        ug.draw(ru)
        cf, cu = segments(rf.value, a.tol), segments(ru.value, a.tol)
        if a.elevate:
            cf, cu = [elevated(c) for c in cf], [elevated(c) for c in cu]
        if len(cf) != len(cu):
            print(f"{name}: {len(cu)} contours, the font has {len(cf)}")
            failed.add(name)
            continue
        for i, (x, y) in enumerate(zip(cf, cu)):
            if not same_contour(x, y, a.tol, a.allow_rotation):
                print(f"{name}: contour {i} differs")
                failed.add(name)
        # At a location HarfBuzz and FreeType round HVAR advances to whole units; fontTools does not.
        advance_tol = max(a.tol, 0.5) if location else a.tol
        if abs(getattr(ug, "width", 0) - glyphset[name].width) > advance_tol:
            print(f"{name}: advance {getattr(ug, 'width', 0)}, the font has {glyphset[name].width}")
            failed.add(name)
        unicodes = getattr(ug, "unicodes", [])
        if sorted(unicodes) != sorted(cmap.get(name, [])):
            print(f"{name}: unicodes {unicodes}, the font has {cmap.get(name, [])}")
            failed.add(name)
    n = len(ufo_glyphs.keys())
    print(f"{n - len(failed)} passed, {len(failed)} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
