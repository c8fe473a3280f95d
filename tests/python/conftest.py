"""Where the tests find the module, the command line and the shipped scenarios.

CTest sets TABLETOP_BIN (the built `tabletop`) and PYTHONPATH (the built
module); TABLETOP_SOURCE_DIR is the repository's root.
"""
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
