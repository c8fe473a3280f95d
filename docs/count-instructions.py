#!/usr/bin/env python3
"""Instructions for each analytic case at 60 Hz, counted by callgrind: the
two tables of docs/bench.md.

    docs/count-instructions.py OLD_TABLETOP NEW_TABLETOP
    docs/count-instructions.py --baseline TABLETOP

The first form ("What the events inside a step cost") counts inside the
world's step, for an older build against this one.
OLD_TABLETOP is a tabletop built from an earlier commit (the one quoted is
cf39221, whose default solver was ten sweeps of sequential impulses);
each case runs there at that build's defaults, and here with
"solver": "sequential_impulse" (the same solver) and at the defaults.
Needs valgrind. Counts are exact and the same on every machine with the
same compiler and libraries; timings are not, which is why this counts
and `bench --baseline` times. Prints a Markdown table.

The second form ("Against Bullet's own pipeline") counts what `bench
--baseline` times, on both of its sides: tabletop's whole run of the
scene (every step and the script around it), and Bullet's own default
pipeline stepping the same scene for as long.
"""
import json
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
RATE = 60.0


def profile(command, toggle, folder):
    """Callgrind's inclusive listing of `command`, collected inside `toggle` only."""
    out = Path(folder) / "callgrind.out"
    subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", f"--toggle-collect={toggle}"] +
                   [str(part) for part in command], capture_output=True, text=True, check=True)
    result = subprocess.run(["callgrind_annotate", "--inclusive=yes", str(out)],
                            capture_output=True, text=True, check=True)
    return result.stdout


def instructions(tabletop, scene, folder):
    """Instructions inside btDiscreteDynamicsWorld::stepSimulation for one run of `scene` at RATE."""
    listing = profile([tabletop, "run", scene, "--timestep", repr(1.0 / RATE)],
                      "btDiscreteDynamicsWorld::stepSimulation*", folder)
    return inclusive(listing, "PROGRAM TOTALS")


def counted(tabletop, scene, toggle, folder):
    """Callgrind's listing of `bench --baseline` on one scene at RATE, collected inside `toggle`."""
    return profile([tabletop, "bench", "--baseline", "--rates", repr(RATE), "--repeats", "1", "--cases", scene.stem,
                    "--scenarios", scene.parent.parent], toggle, folder)


def inclusive(profile, function, required=True):
    """The inclusive count of `function` in a callgrind_annotate listing.

    A missing total means callgrind counted nothing, which is an error; a missing function may be
    one that never ran (0), which callers allow with required=False."""
    for line in profile.splitlines():
        if function in line:
            return int(line.split()[0].replace(",", ""))
    if required:
        sys.exit(f"count-instructions: callgrind's listing has no line for {function}")
    return 0


def against_bullet(tabletop, scene, folder):
    """Instructions of tabletop's runs of `scene` and of Bullet's own runs of it, in one `bench --baseline`."""
    own = counted(tabletop, scene, "tabletop::runScript*", folder)
    runs = inclusive(own, "PROGRAM TOTALS")
    steps_in_runs = inclusive(own, "btDiscreteDynamicsWorld::stepSimulation", required=False)
    both = inclusive(counted(tabletop, scene, "btDiscreteDynamicsWorld::stepSimulation*", folder), "PROGRAM TOTALS")
    return runs, both - steps_in_runs


def with_sweeps(scene, folder):
    """A copy of `scene` that asks for ten sweeps of sequential impulses."""
    text = "\n".join(line for line in scene.read_text().splitlines() if not line.lstrip().startswith("//"))
    data = json.loads(text)
    data.setdefault("settings", {})["solver"] = "sequential_impulse"
    copy = Path(folder) / scene.name
    copy.write_text(json.dumps(data))
    return copy


def millions(count):
    return f"{count / 1e6:.2f} M"


def baseline_table(tabletop):
    print("| scene | tabletop | Bullet's own | ratio |")
    print("|---|---|---|---|")
    with tempfile.TemporaryDirectory() as folder:
        for scene in sorted((ROOT / "scenarios" / "analytic").glob("*.json")):
            ours, theirs = against_bullet(tabletop, scene, folder)
            # bench --baseline makes a warm-up run and one timed run of each side.
            print(f"| `{scene.stem}` | {millions(ours / 2)} | {millions(theirs / 2)} | {ours / theirs:.2f}x |")


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "--baseline":
        baseline_table(sys.argv[2])
        return
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    old, new = sys.argv[1], sys.argv[2]
    print("| scene | before, sweeps | now, sweeps | now, defaults |")
    print("|---|---|---|---|")
    with tempfile.TemporaryDirectory() as folder:
        for scene in sorted((ROOT / "scenarios" / "analytic").glob("*.json")):
            before = instructions(old, scene, folder)
            swept = instructions(new, with_sweeps(scene, folder), folder)
            default = instructions(new, scene, folder)
            print(f"| `{scene.stem}` | {millions(before)} | {millions(swept)} ({swept / before:.2f}x) | "
                  f"{millions(default)} ({default / before:.2f}x) |")


if __name__ == "__main__":
    main()
