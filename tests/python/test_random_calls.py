"""A property test: the module called with random arguments, hostile ones among them.

random_calls.py makes the calls in a child process (a crash or a hang
fails the test, not the run); every call must return a well-formed result
or raise a clean ValueError, TypeError or RuntimeError. Seeded and bounded
(a few thousand calls, seconds each), so a failure replays.
"""
import json
import pathlib
import subprocess
import sys

import pytest

DRIVER = pathlib.Path(__file__).with_name("random_calls.py")


def calls(seed, count):
    child = subprocess.run([sys.executable, str(DRIVER), str(seed), str(count)], capture_output=True, text=True,
                           timeout=600)
    assert child.returncode == 0, f"seed {seed}: exit {child.returncode}\n{child.stderr[-4000:]}"
    return json.loads(child.stdout)


@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_random_calls_end_in_results_or_clean_exceptions(seed):
    outcomes = calls(seed, 1500)
    assert sum(outcomes.values()) == 1500
    # Both sides were exercised: calls that worked and calls refused.
    assert outcomes["ok"] > 200 and outcomes["ValueError"] > 200 and outcomes["TypeError"] > 100
    assert outcomes["RuntimeError"] > 20   # uninitialised, closed, second __init__


def test_a_seed_replays():
    assert calls(7, 300) == calls(7, 300)
