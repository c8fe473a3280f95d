#!/usr/bin/env python3
"""Writes docs/sweep.md's maps and measurements from `tabletop sweep` itself.

Between  <!-- NAME: begin -->  and  <!-- NAME: end -->  in docs/sweep.md:
  maps   the count of runs per first reason for each map, whose pictures it
         draws (docs/example2_angle_friction_map.png,
         docs/example4_offset_mass_map.png) from the specs in docs/sweeps/;
  speed  docs/sweeps/example2_1000_steps.json (1000 runs of example 2, rules
         and bullet) and the 10,000 random runs at 60 Hz (--random), each
         with --jobs 1 and with every core, REPEATS times each: the median
         wall and CPU times (of all the sweep's processes), with the
         machine's load average (other programs running take cores from
         the sweep), and the speed-up the CPU times give on free cores;
  dask   docs/sweeps/example2_angle_friction.json through tabletop.sweep on
         a dask LocalCluster of one worker process against tabletop.sweep
         here with one job, REPEATS times each: the cost per run of the
         cluster's path, in wall time and in CPU time (this process's and
         the worker's, which the load of other programs does not inflate).
Usage, after building (the Python module in build/python):
    docs/make-sweep.py [TABLETOP [maps|speed|dask ...]]
"""
import json
import os
import pathlib
import resource
import statistics
import subprocess
import sys
import tempfile
import time

from doc_blocks import replace_block

ROOT = pathlib.Path(__file__).resolve().parents[1]
SWEEPS = ROOT / "docs" / "sweeps"
REPEATS = 3
MAPS = ["example2_angle_friction", "example4_offset_mass"]


def cpu_of_children():
    """User and system time of every process this one has waited for (and theirs), s."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def sweep(tabletop, what, out, *args):
    """Runs a sweep (WHAT: a spec, or a list of arguments) into OUT.csv/.jsonl afresh: its wall time
    and CPU time in seconds, and its rows."""
    for suffix in (".csv", ".jsonl"):
        pathlib.Path(out + suffix).unlink(missing_ok=True)
    start, cpu = time.monotonic(), cpu_of_children()
    what = what if isinstance(what, list) else [str(what)]
    subprocess.run([tabletop, "sweep", *what, "--out", out, *args], cwd=ROOT, check=True,
                   stdout=subprocess.DEVNULL, timeout=3600)
    wall, cpu = time.monotonic() - start, cpu_of_children() - cpu
    return wall, cpu, [json.loads(line) for line in open(out + ".jsonl")]


def maps(tabletop, tmp):
    lines = ["| map | runs | bullet agrees with the rules | first reason where it does not |", "|---|---|---|---|"]
    for name in MAPS:
        picture = ROOT / "docs" / f"{name}_map.png"
        _, _, rows = sweep(tabletop, SWEEPS / f"{name}.json", f"{tmp}/{name}", "--plot", str(picture))
        reasons = {}
        for row in rows:
            if not row["bullet.agrees"]:
                reasons[row["bullet.reason"]] = reasons.get(row["bullet.reason"], 0) + 1
        agree = sum(1 for row in rows if row["bullet.agrees"])
        listed = ", ".join(f"{r} {n}" for r, n in sorted(reasons.items(), key=lambda kv: -kv[1]))
        lines.append(f"| `docs/sweeps/{name}.json` | {len(rows)} | {agree} | {listed} |")
    return "\n".join(lines) + "\n"


SPEED = [("1000 runs of example 2, rules and bullet", SWEEPS / "example2_1000_steps.json"),
         ("10,000 random runs at 60 Hz", ["--random", "10000", "--rate", "60"])]


def speed(tabletop, tmp):
    cores = os.cpu_count()
    lines = ["| sweep | --jobs | wall [s] | CPU, all processes [s] | speed-up, measured | on free cores |",
             "|---|---|---|---|---|---|"]
    loads = []
    for label, what in SPEED:
        walls, cpus, tables = {1: [], cores: []}, {1: [], cores: []}, {}
        for _ in range(REPEATS):
            for jobs in (1, cores):
                loads.append(os.getloadavg()[0])
                wall, cpu, rows = sweep(tabletop, what, f"{tmp}/speed{jobs}", "--jobs", str(jobs))
                walls[jobs].append(wall)
                cpus[jobs].append(cpu)
                tables[jobs] = [{k: v for k, v in r.items() if not k.endswith(".wall_s")} for r in rows]
        assert tables[1] == tables[cores], "the tables differ with the number of jobs"
        one, many = statistics.median(walls[1]), statistics.median(walls[cores])
        cpu_one, cpu_many = statistics.median(cpus[1]), statistics.median(cpus[cores])
        # With the cores free, the workers' CPU time is split evenly among them
        # (many short runs, handed out one at a time, share out evenly).
        free = cpu_one / (cpu_many / cores)
        lines.append(f"| {label} | 1 | {one:.1f} | {cpu_one:.1f} | | |")
        lines.append(f"| | {cores} | {many:.1f} | {cpu_many:.1f} | {one / many:.2f}x | {free:.2f}x |")
    return ("\n".join(lines) + "\n\n"
            f"Medians of {REPEATS}; the load average (1 min) was {min(loads):.1f} to {max(loads):.1f} "
            f"before each sweep on these {cores} cores. The same tables, row for row, with either count "
            f"of jobs.\n")


def cpu_of_this_process():
    """User and system time of this process, all its threads, s."""
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def dask():
    # The cluster's worker processes find the module as this one does.
    module = str(ROOT / "build" / "python")
    sys.path.insert(0, module)
    os.environ["PYTHONPATH"] = os.pathsep.join(p for p in (module, os.environ.get("PYTHONPATH")) if p)
    # Dask's statistical profiler samples a busy worker every 10 ms; off, as docs/sweep.md advises.
    os.environ["DASK_DISTRIBUTED__WORKER__PROFILE__ENABLED"] = "False"
    import distributed  # pylint: disable=import-outside-toplevel
    import tabletop  # pylint: disable=import-outside-toplevel
    spec = str(SWEEPS / "example2_angle_friction.json")
    walls, cpus = {"here": [], "there": []}, {"here": [], "there": []}
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        def workers_cpu():
            return sum(client.run(cpu_of_this_process).values())
        for _ in range(REPEATS):
            start, cpu = time.monotonic(), cpu_of_this_process()
            local = tabletop.sweep(spec)
            walls["here"].append(time.monotonic() - start)
            cpus["here"].append(cpu_of_this_process() - cpu)
            start, cpu, worker = time.monotonic(), cpu_of_this_process(), workers_cpu()
            remote = tabletop.sweep(spec, client)
            walls["there"].append(time.monotonic() - start)
            cpus["there"].append(cpu_of_this_process() - cpu + workers_cpu() - worker)
        # What the idle cluster costs (its event loops, heartbeats) per second.
        start, cpu, worker = time.monotonic(), cpu_of_this_process(), workers_cpu()
        time.sleep(10)
        idle = (cpu_of_this_process() - cpu + workers_cpu() - worker) / (time.monotonic() - start)
    same = [c for c in local.columns if not c.endswith(".wall_s")]
    assert local[same].equals(remote[same]), "the cluster's rows differ"
    runs = len(local)
    wall = {k: statistics.median(v) for k, v in walls.items()}
    cpu = {k: statistics.median(v) for k, v in cpus.items()}
    return (f"| runs | | here, one job | a LocalCluster of one worker | cost per run of the cluster's path |\n"
            f"|---|---|---|---|---|\n"
            f"| {runs} | wall [s] | {wall['here']:.1f} | {wall['there']:.1f} | "
            f"{1000 * (wall['there'] - wall['here']) / runs:.1f} ms |\n"
            f"| | CPU [s] | {cpu['here']:.1f} | {cpu['there']:.1f} | "
            f"{1000 * (cpu['there'] - cpu['here']) / runs:.1f} ms |\n"
            f"| | CPU less the idle cluster's [s] | {cpu['here']:.1f} | {cpu['there'] - idle * wall['there']:.1f} | "
            f"{1000 * (cpu['there'] - idle * wall['there'] - cpu['here']) / runs:.1f} ms |\n\n"
            f"Medians of {REPEATS}. CPU is this process's (the client and the LocalCluster's scheduler) and the "
            f"worker process's; idle, they take {idle:.3f} s of CPU a second, which the cluster's wall time, "
            f"stretched by the other programs running (load average {os.getloadavg()[0]:.1f} at the end), "
            f"multiplies.\n")


def main():
    tabletop = sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "build" / "src" / "app" / "tabletop")
    parts = sys.argv[2:] or ["maps", "speed", "dask"]  # any of them, to redo one
    with tempfile.TemporaryDirectory() as tmp:
        if "maps" in parts:
            replace_block("docs/sweep.md", "maps", maps(tabletop, tmp))
        if "speed" in parts:
            replace_block("docs/sweep.md", "speed", speed(tabletop, tmp))
    if "dask" in parts:
        replace_block("docs/sweep.md", "dask", dask())


if __name__ == "__main__":
    main()
