#!/usr/bin/env python3
"""Instructions inside the world's step for each analytic case at 60 Hz,
counted by callgrind, for an older build against this one: the table of
docs/bench.md, "What the events inside a step cost".

    docs/count-instructions.py OLD_TABLETOP NEW_TABLETOP

OLD_TABLETOP is a tabletop built from an earlier commit (the one quoted is
cf39221, whose default solver was ten sweeps of sequential impulses);
each case runs there at that build's defaults, and here with
"solver": "sequential_impulse" (the same solver) and at the defaults.
Needs valgrind. Counts are exact and the same on every machine with the
same compiler and libraries; timings are not, which is why this counts
and `bench --baseline` times. Prints a Markdown table.
"""
import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
RATE = 60.0


def instructions(tabletop, scene):
    """Instructions callgrind counts inside btDiscreteDynamicsWorld::stepSimulation for one run."""
    result = subprocess.run(
        ["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null",
         "--toggle-collect=btDiscreteDynamicsWorld::stepSimulation*",
         str(tabletop), "run", str(scene), "--timestep", repr(1.0 / RATE)],
        capture_output=True, text=True, check=True)
    found = re.search(r"Collected : (\d+)", result.stderr)
    if not found:
        sys.exit(f"no count from callgrind for {scene}:\n{result.stderr}")
    return int(found.group(1))


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


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    old, new = sys.argv[1], sys.argv[2]
    print("| scene | before, sweeps | now, sweeps | now, defaults |")
    print("|---|---|---|---|")
    with tempfile.TemporaryDirectory() as folder:
        for scene in sorted((ROOT / "scenarios" / "analytic").glob("*.json")):
            before = instructions(old, scene)
            swept = instructions(new, with_sweeps(scene, folder))
            default = instructions(new, scene)
            print(f"| `{scene.stem}` | {millions(before)} | {millions(swept)} ({swept / before:.2f}x) | "
                  f"{millions(default)} ({default / before:.2f}x) |")


if __name__ == "__main__":
    main()
