#!/usr/bin/env python3
"""Writes the measured tables of the docs from `tabletop bench` itself.

Each table sits between  <!-- NAME: begin -->  and  <!-- NAME: end -->  in
the pages that hold it:
  analytic  scenarios/README.md, docs/bench.md: each scene of
            scenarios/analytic/ against its closed form (computed in
            src/measure/AnalyticCase.cpp) at 60, 240 and 1000 Hz, with the
            trapezoid rule (the default) and Bullet's Euler, 10 iterations;
  hard      docs/hard-cases.md: `bench --hard`, each hard case at its own
            settings, with 10 sweeps, and in Bullet's own pipeline;
  switches  docs/bench.md: `bench --switches`, each model switch on every
            analytic case and report example;
  scale     docs/bench.md: `bench --scale`, the cube field of 10 to 1000;
  piles     docs/bench.md: `bench --piles`, the piles of PILES bodies
            against Bullet's own pipeline.
Everything but wall times is deterministic, so tests/python/test_samples.py
fails when a page differs from what the program measures in any cell that
is not a cost (comparable() blanks those).
Usage, after building (NAME...: only those tables):
    docs/make-tables.py [TABLETOP [NAME...]]
"""
import json
import pathlib
import re
import statistics
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
RATES = [60, 240, 1000]
INTEGRATORS = ["trapezoid", "euler"]
SCALE = [10, 100, 1000]
PILES = [100, 300, 1000]
PILE_BUDGET = 600  # s: more than the largest of PILES takes, so no run is cut
PILE_THREADS = 2  # the piles' second run: the same on any machine with 2 cores or more
REPEATS = 3


def bench(tabletop, *args):
    """bench's JSON for ARGS, run from the project's root."""
    out = subprocess.run([tabletop, "bench", *args, "--json"], cwd=ROOT, capture_output=True, text=True,
                         timeout=1800, check=True).stdout
    return json.loads(out)


def millimetres(error_m):
    """A length in mm to two significant figures; 0 below a nanometre."""
    mm = error_m * 1e3
    if mm < 1e-6:
        return "0"
    return f"{mm:.2g}" if mm < 10 else f"{mm:.1f}"


def cost(ms):
    """A wall time per simulated second (or per step), ms."""
    return f"{ms:.2g}" if ms < 10 else f"{ms:.0f}"


def share(fraction):
    """A fraction as a percentage to two significant figures; 0 below 1e-6 %."""
    return "0%" if abs(fraction) < 1e-8 else f"{100.0 * fraction:.2g}%"


def ratio(value, reference):
    """A cost against the defaults' as a signed percentage."""
    return f"{100.0 * (value / reference - 1.0):+.0f}%"


def analytic(tabletop):
    scenes = sorted(str(p.relative_to(ROOT)) for p in (ROOT / "scenarios" / "analytic").glob("*.json"))
    rows = bench(tabletop, *scenes, "--repeats", "1", "--rates", ",".join(map(str, RATES)), "--iterations", "10",
                 "--integrators", ",".join(INTEGRATORS), "--modes", "bullet")["sweep"]
    errors = {(r["scene"], r["integrator"], round(r["rate_hz"])): r["error_m"] for r in rows}
    lines = ["| file | trapezoid (default), 60 / 240 / 1000 Hz | Bullet's Euler |", "|---|---|---|"]
    for scene in sorted({r["scene"] for r in rows}):
        cells = [" / ".join(millimetres(errors[(scene, i, rate)]) for rate in RATES) + " mm" for i in INTEGRATORS]
        lines.append(f"| `{scene}.json` | " + " | ".join(cells) + " |")
    return lines


def peer(row):
    """The lowest rate holding a peer's drift, its cost and drift; dashes for a case that does not rest."""
    if row["peer_drift_rate_hz"] is None:
        return "- | - | - |"
    return (f"{row['peer_drift_rate_hz']:.0f} | {cost(row['peer_drift_cost_ms_per_s'])} | "
            f"{millimetres(row['peer_drift_worst_drift_m'])} |")


def hard(tabletop):
    rows = bench(tabletop, "--hard")["hard"]
    lines = ["| scene | rate [Hz] | islands exact (by the guess) / swept / long / fell back | cost [ms/s] | drift [mm] | "
             "penetration [mm] | rest [mm/s] | energy gain | 10 sweeps: cost [ms/s] | drift [mm] | "
             "Bullet's pipeline: cost [ms/s] | drift [mm] | "
             f"lowest rate holding {1e3 * rows[0]['peer_drift_m']:.2g} mm [Hz] | its cost [ms/s] | "
             "drift [mm] |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        swept_drift = millimetres(r["sweeps_worst_drift_m"]) if r["sweeps_complete"] else "diverged"
        gain = r["energy_gain_j"] / r["energy_scale_j"] if r["energy_scale_j"] > 0 else 0.0
        lines.append(
            f"| `{r['scene']}` | {1.0 / r['timestep_s']:.0f} | "
            f"{r['islands_direct']} ({r['islands_guessed']}) / {r['islands_swept']} / {r['islands_long_swept']} / "
            f"{r['islands_fallen_back']} | "
            f"{cost(r['cost_ms_per_s'])} | {millimetres(r['worst_drift_m'])} | "
            f"{millimetres(r['worst_penetration_m'])} | {millimetres(r['rest_speed_m_per_s'])} | {share(gain)} | "
            f"{cost(r['sweeps_cost_ms_per_s'])} | {swept_drift} | "
            f"{cost(r['bullet_cost_ms_per_s'])} | {millimetres(r['bullet_worst_drift_m'])} | " + peer(r))
    return lines


SWITCH_NAMES = {
    "floor-pairs=all": "the floor paired with every body (`floor_pairs_near_floor` off)",
    "legs=always": "the legs in the world from the start (`legs_when_reachable` off)",
    "sleeping=on": "sleeping (`sleeping` on)",
    "broadphase=sap": "sweep and prune (`broadphase: sap`)",
    "broadphase=simple": "every pair compared (`broadphase: simple`)",
}


def switches(tabletop):
    rows = bench(tabletop, "--switches", "--repeats", str(REPEATS))["switches"]
    base = {r["scene"]: r for r in rows if r["switch"] == "defaults"}
    lines = [f"| switch | cost against the defaults, {len(base)} scenes: median (range) | outcome |", "|---|---|---|"]
    for switch, name in SWITCH_NAMES.items():
        mine = [r for r in rows if r["switch"] == switch]
        ratios = [r["cost_ms_per_s"] / base[r["scene"]]["cost_ms_per_s"] for r in mine]
        differing = [r for r in mine if not r["same_state"]]
        # The report's examples tumble off the table, and their error (against
        # a 4000 Hz run) is a different tumble's; the analytic cases' is not.
        analytic = [r for r in differing if not r["scene"].startswith("example")]
        if not differing:
            outcome = "bit-identical on every scene"
        else:
            outcome = f"differs in {len(differing)} of {len(mine)} scenes"
        if analytic:
            worst = max(analytic, key=lambda r: abs(r["error_m"] - base[r["scene"]]["error_m"]))
            outcome += (f"; of the analytic cases most in `{worst['scene']}`: error "
                        f"{millimetres(worst['error_m'])} mm against {millimetres(base[worst['scene']]['error_m'])}")
        spread = f"{ratio(statistics.median(ratios), 1)} ({ratio(min(ratios), 1)} to {ratio(max(ratios), 1)})"
        lines.append(f"| {name} | {spread} | {outcome} |")
    return lines


def scale(tabletop):
    rows = bench(tabletop, "--scale", ",".join(map(str, SCALE)), "--repeats", str(REPEATS))["scale"]
    base = {r["cubes"]: r for r in rows if r["switch"] == "defaults"}
    head = "| cubes | defaults: ms per step | us per cube | " + " | ".join(SWITCH_NAMES) + " |"
    lines = [head, "|---" * (3 + len(SWITCH_NAMES)) + "|"]
    for cubes in SCALE:
        cells = [f"{base[cubes]['ms_per_step']:.2g}", f"{1e3 * base[cubes]['ms_per_step'] / cubes:.2g}"]
        for switch in SWITCH_NAMES:
            r = next(r for r in rows if r["cubes"] == cubes and r["switch"] == switch)
            same = "same" if r["same_state"] else f"{millimetres(r['difference_m'])} mm apart"
            cells.append(f"{ratio(r['ms_per_step'], base[cubes]['ms_per_step'])}, {same}")
        lines.append(f"| {cubes} | " + " | ".join(cells) + " |")
    return lines


def piles(tabletop):
    out = bench(tabletop, "--piles", ",".join(map(str, PILES)), "--pile-budget", str(PILE_BUDGET),
                "--threads", str(PILE_THREADS))
    rows, k = out["piles"], out["pile_exponents"]
    lines = [f"| bodies | tabletop ms per s | Bullet ms per s | cost ratio | on {PILE_THREADS} threads, ms per s "
             "| cost ratio on threads | drift over 1 s, mm (Bullet) | deepest, mm (Bullet) "
             "| energy gained, J (Bullet) | parts per step | largest island |", "|---" * 11 + "|"]
    for r in rows:
        threaded = (f"{cost(r['threaded_ms_per_s'])} | {r['threaded_ratio']:.2g}"
                    if r["threaded_ms_per_s"] is not None else "- | -")
        lines.append(f"| {r['bodies']} | {cost(r['tabletop_ms_per_s'])} | {cost(r['bullet_ms_per_s'])} "
                     f"| {r['ratio']:.2g} | {threaded} "
                     f"| {millimetres(r['tabletop_drift_m'])} ({millimetres(r['bullet_drift_m'])}) "
                     f"| {millimetres(r['tabletop_penetration_m'])} ({millimetres(r['bullet_penetration_m'])}) "
                     f"| {r['tabletop_energy_gain_j']:.2g} ({r['bullet_energy_gain_j']:.2g}) "
                     f"| {r['parts_per_step']:.2f} | {r['largest_island']} |")
    lines.append(f"| cost exponent = | {k['tabletop']:.2f} | {k['bullet']:.2f} | | | | | | | | |")
    return lines


TABLES = {
    "analytic": (analytic, ["scenarios/README.md", "docs/bench.md"]),
    "hard": (hard, ["docs/hard-cases.md"]),
    "switches": (switches, ["docs/bench.md"]),
    "scale": (scale, ["docs/bench.md"]),
    "piles": (piles, ["docs/bench.md"]),
}


def markers(name):
    return f"<!-- {name}: begin -->\n", f"<!-- {name}: end -->\n"


def written(page_text, name, block):
    """The page with table NAME's block replaced by BLOCK."""
    begin, end = markers(name)
    head, rest = page_text.split(begin)
    _, tail = rest.split(end)
    return head + begin + block + end + tail


def shown(page_text, name):
    """Table NAME's block as the page shows it."""
    begin, end = markers(name)
    return page_text.split(begin)[1].split(end)[0]


def comparable(block):
    """BLOCK with every wall time and cost ratio blanked, the cells that differ from run to run."""
    lines = block.splitlines()
    if not lines:
        return lines
    header = [c.strip() for c in lines[0].strip("|").split("|")]
    timed = {i for i, c in enumerate(header) if re.search(r"cost|ms per|us per|=", c)}
    out = []
    for line in lines:
        cells = [c.strip() for c in line.strip("|").split("|")]
        out.append([re.sub(r"^[+-]?[0-9.e+-]+%?( \([^)]*\))?", "~", c) if i in timed else c for i, c in enumerate(cells)])
    return out


def block(name, tabletop):
    return "\n".join(TABLES[name][0](tabletop)) + "\n"


def main():
    tabletop = str(pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "build/src/app/tabletop").resolve())
    names = sys.argv[2:] or list(TABLES)
    for name, (_, pages) in TABLES.items():
        if name not in names:
            continue
        text = block(name, tabletop)
        for page in pages:
            path = ROOT / page
            path.write_text(written(path.read_text(), name, text))


if __name__ == "__main__":
    main()
