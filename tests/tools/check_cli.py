#!/usr/bin/python3
"""glyphfair check from outside: the JSON report validates against docs/check.schema.json
for every bundled font in both profiles; several fonts in one call; Markdown and text;
--fail-on exit codes; and the error contract (one line, exit 2, no report left behind).

usage: check_cli.py GLYPHFAIR FONTS SCHEMA WORKDIR
"""
import json
import os
import subprocess
import sys

import jsonschema

from cli_contract import error_problem, finish


def main():
    glyphfair, fonts, schema_path, work = sys.argv[1:5]
    os.makedirs(work, exist_ok=True)
    with open(schema_path) as f:
        schema = json.load(f)
    dejavu = os.path.join(fonts, "DejaVuSans/DejaVuSans-subset.ttf")
    bwl = os.path.join(fonts, "BecauseWeLearn/BecauseWeLearn-Regular-subset.otf")
    inter = os.path.join(fonts, "Inter/Inter-subset.var.ttf")
    failures = []

    def run(*args):
        return subprocess.run([glyphfair, "check", *args], capture_output=True, text=True)

    for profile in ("text", "handwriting"):
        out = os.path.join(work, f"report-{profile}.json")
        r = run(dejavu, bwl, inter, "--profile", profile, "--format", "json", "--fail-on", "never", "-o", out)
        if r.returncode != 0:
            failures.append(f"{profile}: exit {r.returncode} {r.stderr}")
            continue
        with open(out) as f:
            doc = json.load(f)
        try:
            jsonschema.validate(doc, schema)
        except jsonschema.ValidationError as e:
            failures.append(f"{profile}: schema: {e.message}")
        if len(doc["sources"]) != 3:
            failures.append("three sources expected")
        total = sum(s["summary"]["glyphs"] for s in doc["sources"])
        if doc["summary"]["glyphs"] != total:
            failures.append("the summary does not add up")
        if profile == "handwriting" and not doc["relaxed"]:
            failures.append("the handwriting profile does not say what it relaxed")

    md = run(bwl, "--format", "markdown", "--fail-on", "never")
    if "| glyph | severity | check | where | what |" not in md.stdout or "**Summary:**" not in md.stdout:
        failures.append("markdown")
    text = run(bwl, "--glyphs", "a,g", "--fail-on", "never")
    if "summary: 2 glyphs checked" not in text.stdout:
        failures.append(f"text: {text.stdout[-300:]}")

    # BWL (handwriting traced) has kinks: errors in the text profile, info in the handwriting one.
    if run(bwl, "-o", os.path.join(work, "r.txt")).returncode != 4:
        failures.append("--fail-on error should fail on BWL's kinks")
    if run(bwl, "--profile", "handwriting", "--fail-on", "error", "-o", os.path.join(work, "r.txt")).returncode != 0:
        failures.append("the handwriting profile should not fail on errors there")
    if run(bwl, "--profile", "handwriting", "--fail-on", "warning", "-o", os.path.join(work, "r.txt")).returncode != 4:
        failures.append("--fail-on warning")

    for args, text_ in [(("missing.ttf",), "no such file"), ((dejavu, "--glyphs", "nosuch"), "no glyph of that name"),
                        ((dejavu, "--profile", "poster"), "poster")]:
        target = os.path.join(work, "bad.json")
        if os.path.exists(target):
            os.remove(target)
        problem = error_problem(run(*args, "-o", target), 2, text_)
        if problem or os.path.exists(target):
            failures.append(f"{args}: {problem or 'left the report behind'}")

    return finish(failures)


if __name__ == "__main__":
    sys.exit(main())
