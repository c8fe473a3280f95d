"""Where the tests find the module, the command line and the shipped scenarios.

CTest sets TABLETOP_BIN (the built `tabletop`) and PYTHONPATH (the built
module); TABLETOP_SOURCE_DIR is the repository's root.
"""
import json
import os
import pathlib

import pytest

SOURCE = pathlib.Path(os.environ.get("TABLETOP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SCENARIOS = SOURCE / "scenarios"


def shipped_scenarios():
    """Every scenario file shipped: the report's examples, analytic and hard cases."""
    return sorted(p for p in SCENARIOS.rglob("*.json"))


@pytest.fixture
def tabletop_bin():
    path = os.environ.get("TABLETOP_BIN")
    if not path:
        pytest.skip("TABLETOP_BIN is not set (CTest sets it)")
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
