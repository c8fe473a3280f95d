#!/usr/bin/env python3
"""Measures how long the Python module's render() takes per frame in a loop.

Steps a shipped scene one step between frames, as a learning loop or a
video does, and times each frame at the sizes below: RGB alone, and with
the depth and segmentation images. The first frame of each size is left
out (it makes the OpenGL context and finds the fitted camera's run).
Writes the medians to docs/library.md, with the goals of the issue that
asked for them.
Usage: docs/make-render-times.py [BUILD_DIR]   (default: build)
"""
import os
import pathlib
import statistics
import sys
import time

from doc_blocks import ROOT, replace_block

SIZES = [(84, 84, 3.0), (640, 480, 15.0)]  # width, height, goal in ms
FRAMES = 40
SCENE = "example2_two_cubes"


def median_ms(sim, width, height, **images):
    sim.render(width, height, **images)  # the context, the fitted run
    times = []
    for _ in range(FRAMES):
        sim.step()
        start = time.perf_counter()
        sim.render(width, height, **images)
        times.append(time.perf_counter() - start)
    return 1e3 * statistics.median(times)


def main():
    build = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ROOT / "build")
    sys.path.insert(0, str(build / "python"))
    import tabletop
    rows = ["| frame | RGB, ms | RGB + depth + segmentation, ms | goal (RGB), ms |", "|---|---|---|---|"]
    for width, height, goal in SIZES:
        sim = tabletop.Simulation(SCENE)
        rgb = median_ms(sim, width, height)
        sim = tabletop.Simulation(SCENE)
        all_three = median_ms(sim, width, height, depth=True, segmentation=True)
        rows.append(f"| {width} x {height} | {rgb:.1f} | {all_three:.1f} | {goal:g} |")
        print(rows[-1], flush=True)
    load = os.getloadavg()[0]
    rows += ["", f"Medians of {FRAMES} frames of `{SCENE}`, one step between frames, on {os.cpu_count()} cores "
             f"(load average {load:.1f} when measured), by `docs/make-render-times.py`.", ""]
    replace_block("docs/library.md", "render-times", "\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
