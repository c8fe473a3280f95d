#!/usr/bin/env python3
"""Writes the sample outputs in the README and docs from the program itself.

A sample is a fenced block right after a line
    <!-- output of: tabletop ARGS -->
and holds what `tabletop ARGS` prints, run from the repository's root.
tests/python/test_samples.py fails when a block differs from what the
program prints (wall times aside). Usage, after building:
    docs/make-samples.py [TABLETOP]
"""
import pathlib
import re
import shlex
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
PAGES = ["README.md", "scenarios/README.md"] + sorted(str(p.relative_to(ROOT)) for p in (ROOT / "docs").glob("*.md"))
SAMPLE = re.compile(r"(<!-- output of: tabletop (?P<args>[^>]*?) -->\n```\n)(?P<body>.*?)(```\n)", re.S)
WALL = re.compile(r"\(\d+\.\d+ s wall\)")


def output(tabletop, args):
    """What `tabletop ARGS` prints; the arguments are split as a shell would, never run by one."""
    return subprocess.run([tabletop, *shlex.split(args)], cwd=ROOT, capture_output=True, text=True,
                          timeout=600).stdout


def comparable(text):
    return WALL.sub("(_ s wall)", text)


def samples(page):
    """Each sample of a page: (its arguments, the text it shows)."""
    return [(m["args"], m["body"]) for m in SAMPLE.finditer((ROOT / page).read_text())]


def rewrite(tabletop):
    for page in PAGES:
        path = ROOT / page
        text = path.read_text()
        new = SAMPLE.sub(lambda m: m[1] + output(tabletop, m["args"]) + m[4], text)
        if new != text:
            path.write_text(new)
            print(f"wrote {page}")


if __name__ == "__main__":
    rewrite(sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "build/src/app/tabletop"))
