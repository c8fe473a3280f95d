#!/usr/bin/env python3
"""Measures the work count of a run (src/core/WorkCount.h) against its wall time.

Runs scenes where the cost is in different places (towers, rows, the
pyramid, the rules), each on one core, and writes to docs/limits.md their
counts, wall times and the time WorkCount's weights predict, with a
non-negative least-squares fit of the weights (relative error) that the
header's rounded constants come from.
Usage: docs/make-work.py [BUILD_DIR]   (default: build)
"""
import json
import pathlib
import re
import subprocess
import sys
import tempfile

import numpy as np

from doc_blocks import ROOT, replace_block

KEYS = ["part_bodies", "contact_points", "pairs", "swept_rows", "pivoted_rows", "rule_checks"]
CONSTANTS = ["kPartBody", "kContactPoint", "kPair", "kSweptRow", "kPivotedRow", "kRuleCheck"]


def tower(n, side, seconds, iterations=None):
    entities = [{"name": f"C{i}", "shape": "cube", "size": side, "position": [0, 0],
                 "on": "table" if i == 0 else f"C{i - 1}", "mass": 0.01} for i in range(n)]
    settings = {"timestep": 1 / 60, "duration": seconds, "end_at_rest": False}
    if iterations:
        settings["iterations"] = iterations
    return {"version": 1, "name": f"tower_{n}", "settings": settings, "entities": entities}


def row(n, side, seconds):
    entities = [{"name": f"C{i}", "shape": "cube", "size": side, "position": [-4.9 + i * side, 0],
                 "on": "table", "mass": 0.01} for i in range(n)]
    return {"version": 1, "name": f"row_{n}", "table": {"size": [10, 1]},
            "settings": {"timestep": 1 / 60, "duration": seconds, "end_at_rest": False}, "entities": entities,
            "script": [{"t": 0.0, "push": {"entity": "C0", "direction": "Left", "step": 2.0}}]}


CASES = [
    ("a tower of 50 cubes of 2 cm, 5 s", tower(50, 0.02, 5), "bullet"),
    ("a tower of 100 cubes, 100 iterations, 5 s", tower(100, 0.1, 5, 100), "bullet"),
    ("a tower of 100 cubes, 10,000 iterations, 0.2 s", tower(100, 0.1, 0.2, 10000), "bullet"),
    ("a tower of 1000 cubes of 1 mm, 0.02 s", tower(1000, 0.001, 0.02), "bullet"),
    ("a row of 300 cubes pushed, 3 s", row(300, 0.02, 3), "bullet"),
    ("a row of 1000 cubes pushed, compat, 2 s", row(1000, 0.0049, 2), "compat"),
    ("a row of 2000 cubes pushed, rules, 5 s", row(2000, 0.0049, 5), "rules"),
    ("hard/pyramid_55, 5 s", "scenarios/hard/pyramid_55.json", "bullet"),
    ("hard/tall_stack_20, 60 s", "scenarios/hard/tall_stack_20.json", "bullet"),
]


def weights_in_header():
    text = (ROOT / "src/core/WorkCount.h").read_text()
    return [float(re.search(r"%s = ([0-9.e]+);" % c, text).group(1)) for c in CONSTANTS]


def nnls(a, b):
    free = list(range(a.shape[1]))
    while True:
        x = np.zeros(a.shape[1])
        x[free] = np.linalg.lstsq(a[:, free], b, rcond=None)[0]
        if (x >= 0).all():
            return x
        free = [f for f in free if x[f] > 0]


def main():
    tabletop = ROOT / (sys.argv[1] if len(sys.argv) > 1 else "build") / "src/app/tabletop"
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for name, scene, mode in CASES:
            if isinstance(scene, dict):
                path = pathlib.Path(folder) / "scene.json"
                path.write_text(json.dumps(scene))
            else:
                path = ROOT / scene
            args = [str(tabletop), "run", str(path), "--mode", mode, "--json"]
            if "pyramid" in name:
                args += ["--duration", "5"]
            run = json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)["runs"][0]
            rows.append((name, mode, run["wall_seconds"], run["work"]))
            print(f"{name}: {run['wall_seconds']:.2f} s, {run['work']['units']:.3g} units", flush=True)
    counts = np.array([[w[k] for k in KEYS] for _, _, _, w in rows], float)
    wall = np.array([t for _, _, t, _ in rows]) * 1e9
    fitted = nnls(counts / wall[:, None], np.ones(len(rows)))
    used = weights_in_header()
    lines = ["| scene | mode | work units | wall s | predicted s | wall / predicted |", "|---|---|---|---|---|---|"]
    for (name, mode, t, w), c in zip(rows, counts):
        predicted = float(c @ used) / 1e9
        lines.append(f"| {name} | {mode} | {w['units']:.3g} | {t:.2f} | {predicted:.2f} | {t / predicted:.2f} |")
    ratios = [t / (float(c @ used) / 1e9) for (_, _, t, _), c in zip(rows, counts)]
    lines += ["", "| count | weight used, ns | fitted here, ns |", "|---|---|---|"]
    lines += [f"| {k} | {u:g} | {f:.1f} |" for k, u, f in zip(KEYS, used, fitted)]
    lines += ["", f"Wall time over predicted time: {min(ratios):.2f} to {max(ratios):.2f}.", ""]
    replace_block("docs/limits.md", "work", "\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
