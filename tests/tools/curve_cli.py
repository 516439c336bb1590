#!/usr/bin/python3
"""glyphfair curve from outside: the documented JSON fields in order, values against
lac-math.md §2.4, 'no-solution' for an undrawable triangle, and the error contract.

usage: curve_cli.py GLYPHFAIR WORKDIR
"""
import json
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

    for args, code, text in [(("--alpha", "-5", "--points", "0,0", "1,0", "2,0.8", "--format", "svg"), 2, "no solution"),
                             (("--alpha", "1", "--points", "0,0", "1;0", "2,0.8"), 2, "is not x,y"),
                             (("--points", "0,0", "1,0", "2,0.8"), 2, "--alpha is required")]:
        problem = error_problem(run(*args), code, text)
        if problem:
            failures.append(f"{args}: {problem}")

    return finish(failures)


if __name__ == "__main__":
    sys.exit(main())
