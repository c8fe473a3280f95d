#!/usr/bin/env python3
"""Writes docs/tests.md's test times from a clean run of `.ci/run`.

Between  <!-- times: begin -->  and  <!-- times: end -->  in docs/tests.md:
for each build `.ci/run` tests (build: Release; build-asan: the sanitizers),
the entries, the sum of their times and its share per label, from CTest's
own record of the run (Testing/Temporary/CTestCostData.txt, the last time
of each entry); and the wall time of the whole of `.ci/run`.
Usage:
    docs/make-test-times.py --run-ci   # clones HEAD, times .ci/run in it (about 40 minutes)
    docs/make-test-times.py CLONE      # the entries of a clone .ci/run has run in, without the wall time
On a failure of .ci/run its log is kept and its failing lines printed.
"""
import os
import pathlib
import re
import subprocess
import sys
import tempfile
import time

from doc_blocks import replace_block

ROOT = pathlib.Path(__file__).resolve().parents[1]
BUILDS = [("build", "Release"), ("build-asan", "AddressSanitizer and UBSan")]


def costs(build):
    """Each entry's time in the last run, s, from CTest's cost data."""
    out = {}
    for line in (build / "Testing" / "Temporary" / "CTestCostData.txt").read_text().splitlines():
        if line.startswith("---"):
            break
        parts = line.rsplit(" ", 2)
        if len(parts) == 3:
            out[parts[0]] = float(parts[2])
    return out


def labelled(build, label):
    """The names of the entries that carry `label`."""
    listed = subprocess.run(["ctest", "--test-dir", str(build), "-N", "-L", f"^{label}$"], capture_output=True,
                            text=True, check=True).stdout
    return set(re.findall(r"Test +#\d+: (\S+)", listed))


def table(clone, seconds=None):
    lines = ["| build | entries | their times added [min] | by label [min] |", "|---|---|---|---|"]
    for name, what in BUILDS:
        build = clone / name
        cost = costs(build)
        labels = subprocess.run(["ctest", "--test-dir", str(build), "--print-labels"], capture_output=True,
                                text=True, check=True).stdout
        labels = [l.strip() for l in labels.splitlines()[labels.splitlines().index("All Labels:") + 1:] if l.strip()]
        shares = []
        for label in labels:
            total = sum(cost.get(t, 0.0) for t in labelled(build, label))
            shares.append(f"{label} {total / 60:.1f}")
        lines.append(f"| {what} | {len(cost)} | {sum(cost.values()) / 60:.1f} | {', '.join(shares)} |")
    text = "\n".join(lines) + "\n"
    if seconds is not None:
        text += (f"\nThe whole of `.ci/run` (both builds made from nothing, both suites at `-j2`, the fuzzer's "
                 f"build and its minute) took {seconds / 60:.1f} min of wall time on a machine of "
                 f"{os.cpu_count()} cores.\n")
    return text


def main():
    if sys.argv[1:] == ["--run-ci"]:
        with tempfile.TemporaryDirectory() as tmp:
            clone = pathlib.Path(tmp) / "clone"
            subprocess.run(["git", "clone", "-q", str(ROOT), str(clone)], check=True)
            start = time.monotonic()
            log = pathlib.Path(tempfile.gettempdir()) / "tabletop-ci-run.log"
            with open(log, "w") as out:
                run = subprocess.run(["bash", ".ci/run"], cwd=clone, stdout=out, stderr=subprocess.STDOUT)
            if run.returncode != 0:
                failed = [l for l in log.read_text(errors="replace").splitlines() if "***" in l or "FAILED" in l]
                sys.exit("\n".join(failed[-20:]) + f"\n.ci/run failed (status {run.returncode}); its log: {log}")
            replace_block("docs/tests.md", "times", table(clone, time.monotonic() - start))
    elif len(sys.argv) == 2:
        replace_block("docs/tests.md", "times", table(pathlib.Path(sys.argv[1])))
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
