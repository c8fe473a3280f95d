"""Where the tests find the module, the command line and the shipped scenarios.

CTest sets TABLETOP_BIN (the built `tabletop`) and PYTHONPATH (the built
module); TABLETOP_SOURCE_DIR is the repository's root. Without them the
run fails at its start, saying what to set: a test that needs the command
line would otherwise skip, and a run of nothing would pass. Setting
TABLETOP_PYTEST_WITHOUT_CTEST=1 runs what can run without them.
"""
import importlib.util
import json
import os
import pathlib

import pytest

OPT_OUT = "TABLETOP_PYTEST_WITHOUT_CTEST"

# The tests that take longest, by their cost under CTest (pytest
# --durations), marked slow: tests/CMakeLists.txt runs them as entries of
# their own, labelled slow. `bench --hard`'s table of docs/hard-cases.md,
# the pyramid of 55 cubes for 60 s (run by the command line and by the
# module) and `bench --scale`'s table of docs/bench.md.
SLOW = {
    "test_samples.py::test_a_measured_table_is_what_bench_measures[hard]",
    "test_module.py::test_run_matches_the_command_line[pyramid_55]",
    "test_samples.py::test_a_measured_table_is_what_bench_measures[scale]",
}


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(config, items):
    """Marks the SLOW tests, before -m selects by marks."""
    for item in items:
        if f"{item.path.name}::{item.name}" in SLOW:
            item.add_marker(pytest.mark.slow)


def pytest_configure(config):
    """Registers the marks; fails the run when CTest's environment is missing, unless OPT_OUT is set."""
    config.addinivalue_line("markers", "docs: checks a page of the docs against what the program prints or measures")
    config.addinivalue_line("markers", "slow: among the costliest tests (SLOW), run by CTest as entries of their own")
    if os.environ.get(OPT_OUT):
        return
    missing = [f"{name} ({what})" for name, what in [
        ("TABLETOP_BIN", "BUILD/src/app/tabletop"), ("TABLETOP_SOURCE_DIR", "the repository's root")]
        if not os.environ.get(name)]
    if importlib.util.find_spec("tabletop") is None:
        missing.append("PYTHONPATH (BUILD/python, where the built module is)")
    if missing:
        raise pytest.UsageError(
            "tests/python runs under CTest (ctest --test-dir BUILD -L python), which sets its environment; "
            "to run pytest directly, set " + ", ".join(missing) + f" (or {OPT_OUT}=1 to skip what needs them)")
    if not os.access(os.environ["TABLETOP_BIN"], os.X_OK):
        raise pytest.UsageError(f"TABLETOP_BIN={os.environ['TABLETOP_BIN']} is not an executable: build first")

SOURCE = pathlib.Path(os.environ.get("TABLETOP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SCENARIOS = SOURCE / "scenarios"


def shipped_scenarios():
    """Every scenario file shipped: the report's examples, analytic and hard cases."""
    return sorted(p for p in SCENARIOS.rglob("*.json"))


@pytest.fixture
def tabletop_bin():
    path = os.environ.get("TABLETOP_BIN")
    if not path:
        pytest.skip(f"TABLETOP_BIN is not set ({OPT_OUT} is)")
    return path


def without_comments(text):
    """A scenario file's text with its // and /* */ comments blanked (strings kept), as the loader reads it."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if c == '"':
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            out.append(text[i:j + 1])
            i = j + 1
        elif text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            i = n if j < 0 else j + 2
        else:
            out.append(c)
            i += 1
    return "".join(out)


def schema(name):
    return json.loads((SOURCE / "data" / "schema" / name).read_text())


def run_python(code, timeout=120, **kwargs):
    """`code` run by this interpreter in a child process (with this process's
    environment, so the same module), for calls that could crash or hang it:
    a regression then fails one test instead of ending the run."""
    import subprocess
    import sys
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=timeout, **kwargs)
