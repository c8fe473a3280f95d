#!/usr/bin/env python3
"""Writes the analytic cases' error table from `tabletop bench` itself.

The table sits between
    <!-- analytic: begin -->  and  <!-- analytic: end -->
in each page that has the markers (scenarios/README.md, docs/bench.md):
for every scene of scenarios/analytic/, its error against the closed form
(computed in src/measure/AnalyticCase.cpp) at 60, 240 and 1000 Hz with
the trapezoid rule (the default) and with Bullet's Euler, 10 iterations,
in full physics. Errors are deterministic, so tests/python/test_samples.py
fails when a page's table differs from what the program measures.
Usage, after building:
    docs/make-analytic.py [TABLETOP]
"""
import json
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
PAGES = ["scenarios/README.md", "docs/bench.md"]
BEGIN, END = "<!-- analytic: begin -->\n", "<!-- analytic: end -->\n"
RATES = [60, 240, 1000]
INTEGRATORS = ["trapezoid", "euler"]


def measure(tabletop):
    """bench's rows for every analytic case, at RATES with both integrators."""
    scenes = sorted(str(p.relative_to(ROOT)) for p in (ROOT / "scenarios" / "analytic").glob("*.json"))
    args = [tabletop, "bench", *scenes, "--json", "--repeats", "1", "--rates", ",".join(map(str, RATES)),
            "--iterations", "10", "--integrators", ",".join(INTEGRATORS), "--modes", "bullet"]
    out = subprocess.run(args, cwd=ROOT, capture_output=True, text=True, timeout=600, check=True).stdout
    return json.loads(out)["sweep"]


def millimetres(error_m):
    """An error in mm to two significant figures; 0 below a nanometre."""
    mm = error_m * 1e3
    if mm < 1e-6:
        return "0"
    return f"{mm:.2g}" if mm < 10 else f"{mm:.1f}"


def table(rows):
    errors = {(r["scene"], r["integrator"], round(r["rate_hz"])): r["error_m"] for r in rows}
    lines = ["| file | trapezoid (default), 60 / 240 / 1000 Hz | Bullet's Euler |", "|---|---|---|"]
    for scene in sorted({r["scene"] for r in rows}):
        cells = [" / ".join(millimetres(errors[(scene, i, rate)]) for rate in RATES) + " mm" for i in INTEGRATORS]
        lines.append(f"| `{scene}.json` | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def written(page_text, block):
    head, rest = page_text.split(BEGIN)
    _, tail = rest.split(END)
    return head + BEGIN + block + END + tail


def main():
    tabletop = sys.argv[1] if len(sys.argv) > 1 else "build/src/app/tabletop"
    block = table(measure(str(pathlib.Path(tabletop).resolve())))
    for page in PAGES:
        path = ROOT / page
        path.write_text(written(path.read_text(), block))


if __name__ == "__main__":
    main()
