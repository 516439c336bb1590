#!/usr/bin/python3
"""Two runs of scripts/text_sweep.sh compared: per font, the text bars that differ (old → new)
and whether it passes; per glyph (with --glyphs), the nodes, inflections, g2-jumps and kinks
that changed; then the totals of nodes, jumps and kinks over the fonts both runs measured, and
the fonts only one of them did (text_sweep.sh's ERROR lines).

usage: scripts/sweep_diff.py OLD_DIR NEW_DIR [--glyphs]
"""
import argparse
import json
import pathlib


def load(path):
    doc = json.loads(path.read_text())
    return {b["bar"]: b for b in doc["bars"]}, {g["glyph"]: g for g in doc["glyphs"]}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("old", type=pathlib.Path)
    ap.add_argument("new", type=pathlib.Path)
    ap.add_argument("--glyphs", action="store_true", help="also the glyphs whose counts changed")
    args = ap.parse_args()
    totals = {"nodes": [0, 0], "g2_jumps": [0, 0], "kinks": [0, 0]}
    passing = [0, 0]
    fonts = sorted(p.name for p in args.old.glob("*.json") if (args.new / p.name).exists())
    for name in fonts:
        (bars_a, glyphs_a), (bars_b, glyphs_b) = load(args.old / name), load(args.new / name)
        ok_a, ok_b = all(b["pass"] for b in bars_a.values()), all(b["pass"] for b in bars_b.values())
        passing[0] += ok_a
        passing[1] += ok_b
        for key in totals:
            for i, glyphs in enumerate((glyphs_a, glyphs_b)):
                totals[key][i] += sum(g[key][1] if key == "nodes" else g[key] for g in glyphs.values())
        moved = [f"{bar} {bars_a[bar]['value']:.4g} → {b['value']:.4g}" for bar, b in bars_b.items()
                 if bar in bars_a and abs(b["value"] - bars_a[bar]["value"]) > 1e-9]
        if moved or ok_a != ok_b:
            verdict = ("PASS" if ok_a else "FAIL") + " → " + ("PASS" if ok_b else "FAIL")
            print(f"{name[:-5]:32s} {verdict}  " + "; ".join(moved))
        if args.glyphs:
            for glyph, b in glyphs_b.items():
                a = glyphs_a.get(glyph)
                if a is None:
                    continue
                changes = [f"{k} {a[k][1]} → {b[k][1]}" for k in ("nodes", "inflections") if a[k][1] != b[k][1]]
                changes += [f"{k} {a[k]} → {b[k]}" for k in ("g2_jumps", "kinks") if a[k] != b[k]]
                if changes:
                    print(f"    {glyph:10s} " + ", ".join(changes))
    one_only = sorted({p.name for d in (args.old, args.new) for p in d.glob("*.json")} - set(fonts))
    if one_only:
        print("measured by one run only: " + ", ".join(n[:-5] for n in one_only))
    print(f"{len(fonts)} fonts: passing {passing[0]} → {passing[1]}; " +
          "; ".join(f"{k} {a} → {b}" for k, (a, b) in totals.items()))


if __name__ == "__main__":
    main()
