#!/usr/bin/python3
"""glyphfair convert FONT -o OUT.json, then validate OUT.json against the documented schema
(docs/outline.schema.json) and check that every number is finite.

usage: validate_json.py GLYPHFAIR FONT SCHEMA OUT
"""
import json
import math
import subprocess
import sys

import jsonschema


def numbers(v):
    if isinstance(v, bool):
        return
    if isinstance(v, (int, float)):
        yield v
    elif isinstance(v, dict):
        for x in v.values():
            yield from numbers(x)
    elif isinstance(v, list):
        for x in v:
            yield from numbers(x)


def main():
    glyphfair, font, schema_path, out = sys.argv[1:5]
    subprocess.run([glyphfair, "convert", font, "-o", out], check=True)
    with open(schema_path) as f:
        schema = json.load(f)
    with open(out) as f:
        doc = json.load(f)
    jsonschema.validate(doc, schema)
    bad = [x for x in numbers(doc) if not math.isfinite(x)]
    if bad:
        print(f"{len(bad)} non-finite numbers")
        return 1
    print(f"{len(doc['glyphs'])} glyphs valid; 1 passed, 0 failed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
