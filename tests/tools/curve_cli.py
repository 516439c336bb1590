#!/usr/bin/python3
"""glyphfair curve from outside: the documented JSON fields in order, values against
lac-math.md §2.4, 'no-solution' for an undrawable triangle, the interpolation through points
(--through) against the circle it must give and its G3 joins, and the error contract.

usage: curve_cli.py GLYPHFAIR WORKDIR
"""
import json
import math
import os
import subprocess
import sys

from cli_contract import error_problem, finish


def run(*args):
    return subprocess.run([sys.argv[1], "curve", *args], capture_output=True, text=True)


def main():
    failures = []
    r = run("--alpha", "1", "--points", "0,0", "1,0", "2,0.8", "--samples", "8")
    doc = json.loads(r.stdout)
    if list(doc) != ["status", "alpha", "lambda", "length", "start", "end", "samples"]:
        failures.append(f"field order {list(doc)}")
    if list(doc["start"]) != ["point", "tangent_angle", "curvature", "dcurvature_ds"]:
        failures.append(f"end fields {list(doc['start'])}")
    checks = [(doc["lambda"], 1.139699542254), (doc["length"], 2.19425306471925),
              (doc["start"]["curvature"], 0.462898573397229), (doc["end"]["curvature"], 0.214542107220051),
              (doc["start"]["dcurvature_ds"], -0.244209221138296), (doc["end"]["dcurvature_ds"], -0.0524584504142705)]
    for got, want in checks:
        if abs(got - want) > 1e-12 * abs(want) * 10:
            failures.append(f"{got} != {want}")
    if len(doc["samples"]) != 9 or doc["samples"][-1]["s"] != doc["length"]:
        failures.append("samples")

    r = run("--alpha", "-5", "--points", "0,0", "1,0", "2,0.8")
    doc = json.loads(r.stdout)
    if r.returncode != 0 or doc["status"] != "no-solution" or not doc["reason"]:
        failures.append(f"undrawable: {r.returncode} {doc}")

    r = run("--inflection-start", "--points", "0,0", "1.8,0", "2.414,1")
    doc = json.loads(r.stdout)
    if doc["status"] != "ok" or doc["start"]["curvature"] != 0 or not doc["alpha"] < 0:
        failures.append(f"inflection start: {doc}")

    out = os.path.join(sys.argv[2], "curve.svg")
    r = run("--alpha", "2", "--points", "0,0", "100,0", "180,90", "--format", "svg", "-o", out)
    if r.returncode != 0 or "<svg" not in open(out).read():
        failures.append("svg")

    # Five points over 200° of a radius-50 circle with κ = 1/50: the circle, G3 at every join.
    r, c = 50.0, (10.0, -20.0)
    angles = [0.3 + k * math.radians(50) for k in range(5)]
    through = [f"{c[0] + r * math.cos(a)!r},{c[1] + r * math.sin(a)!r}" for a in angles]
    tangents = [str(math.degrees(a) + 90) for a in angles]
    tangents[1:4] = ["auto"] * 3
    r_ = run("--through", *through, "--curvatures", *["0.02"] * 5, "--angles", *tangents, "--samples", "4")
    doc = json.loads(r_.stdout)
    if list(doc) != ["status", "length", "spans", "samples"] or doc["status"] != "ok":
        failures.append(f"through: fields {list(doc)} {doc.get('reason')}")
    else:
        if abs(doc["length"] - r * math.radians(200)) > 1e-8:
            failures.append(f"through: length {doc['length']}")
        if len(doc["spans"]) != 4 or len(doc["samples"]) != 17 or list(doc["spans"][0]) != ["kind", "length", "start", "end"]:
            failures.append(f"through: {len(doc['spans'])} spans, {len(doc['samples'])} samples")
        for p in doc["samples"]:
            if abs(math.dist(p["point"], c) - r) > 1e-8 or abs(p["curvature"] - 0.02) > 1e-12:
                failures.append(f"through: off the circle at s = {p['s']}")
                break
        for a, b in zip(doc["spans"], doc["spans"][1:]):
            e, s = a["end"], b["start"]
            if math.dist(e["point"], s["point"]) > 1e-8 or abs(e["dcurvature_ds"] - s["dcurvature_ds"]) > 1e-12:
                failures.append("through: a join is not G3")
    out = os.path.join(sys.argv[2], "through.svg")
    r_ = run("--through", "0,0", "40,30", "80,0", "--curvatures", "0", "-0.0187", "0", "--format", "svg", "-o", out)
    if r_.returncode != 0 or "<svg" not in open(out).read():
        failures.append("through: svg")
    r_ = run("--through", "0,0", "10,0", "--curvatures", "1", "1", "--slopes", "0", "0", "--angles", "0", "0")
    doc = json.loads(r_.stdout)
    if r_.returncode != 0 or doc["status"] != "no-solution" or not doc["reason"].startswith("span 0: "):
        failures.append(f"through: no solution {doc}")

    for args, code, text in [(("--alpha", "-5", "--points", "0,0", "1,0", "2,0.8", "--format", "svg"), 2, "no solution"),
                             (("--alpha", "1", "--points", "0,0", "1;0", "2,0.8"), 2, "is not x,y"),
                             (("--points", "0,0", "1,0", "2,0.8"), 2, "--alpha is required"),
                             (("--through", "0,0", "1,0", "2,1", "--curvatures", "0", "1"), 2, "2 values for 3 points"),
                             (("--through", "0,0", "1,0", "--curvatures", "0", "auto"), 2, "'auto' is not a number"),
                             (("--through", "0,0", "1,0"), 2, "--curvatures is required"),
                             (("--through", "0,0", "1,0", "--curvatures", "0", "0", "--alpha", "1"), 2, "excludes"),
                             (("--through", "0,0", "10,0", "--curvatures", "1", "1", "--slopes", "0", "0",
                               "--angles", "0", "0", "--format", "svg"), 2, "no solution: span 0")]:
        problem = error_problem(run(*args), code, text)
        if problem:
            failures.append(f"{args}: {problem}")

    return finish(failures)


if __name__ == "__main__":
    sys.exit(main())
