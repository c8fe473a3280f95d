"""Every sample output in the README and docs is what the program prints (docs/make-samples.py writes them)."""
import importlib.util
import re

import pytest

from conftest import SOURCE

pytestmark = pytest.mark.docs

spec = importlib.util.spec_from_file_location("make_samples", SOURCE / "docs" / "make-samples.py")
make_samples = importlib.util.module_from_spec(spec)
spec.loader.exec_module(make_samples)

CASES = [(page, args, shown) for page in make_samples.PAGES for args, shown in make_samples.samples(page)]


def test_the_readme_has_samples():
    assert any(page == "README.md" for page, _, _ in CASES)


@pytest.mark.parametrize("page, args, shown", CASES, ids=[f"{p}: {a}" for p, a, _ in CASES])
def test_a_sample_is_what_the_program_prints(page, args, shown, tabletop_bin):
    printed = make_samples.output(tabletop_bin, args)
    assert make_samples.comparable(shown) == make_samples.comparable(printed), \
        f"{page}: the sample of `tabletop {args}` is stale; run docs/make-samples.py"


spec_tables = importlib.util.spec_from_file_location("make_tables", SOURCE / "docs" / "make-tables.py")
make_tables = importlib.util.module_from_spec(spec_tables)
spec_tables.loader.exec_module(make_tables)


@pytest.mark.parametrize("name", list(make_tables.TABLES))
def test_a_measured_table_is_what_bench_measures(name, tabletop_bin):
    """Every cell but the costs (wall times, which vary from run to run)."""
    block = make_tables.block(name, tabletop_bin)
    for page in make_tables.TABLES[name][1]:
        shown = make_tables.shown((SOURCE / page).read_text(), name)
        assert make_tables.comparable(shown) == make_tables.comparable(block), \
            f"{page}: the {name} table is stale; run docs/make-tables.py"


def test_the_work_weights_in_limits_md_are_the_headers():
    """docs/limits.md's table of weights names those src/core/WorkCount.h weighs a run's work by."""
    spec = importlib.util.spec_from_file_location("make_work", SOURCE / "docs" / "make-work.py")
    make_work = importlib.util.module_from_spec(spec)
    import sys
    sys.path.insert(0, str(SOURCE / "docs"))
    spec.loader.exec_module(make_work)
    page = (SOURCE / "docs" / "limits.md").read_text()
    for key, weight in zip(make_work.KEYS, make_work.weights_in_header()):
        assert f"| {key} | {weight:g} |" in page, key


def test_the_render_times_in_library_md_are_the_scripts():
    """docs/library.md's frame times are docs/make-render-times.py's table: a row for each size it measures, with
    the goal it names, and its own closing line."""
    import sys
    sys.path.insert(0, str(SOURCE / "docs"))
    spec = importlib.util.spec_from_file_location("make_render_times", SOURCE / "docs" / "make-render-times.py")
    script = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(script)
    page = (SOURCE / "docs" / "library.md").read_text()
    block = page.split("<!-- render-times: begin -->")[1].split("<!-- render-times: end -->")[0]
    for width, height, goal in script.SIZES:
        assert re.search(rf"\| {width} x {height} \| [0-9.]+ \| [0-9.]+ \| {goal:g} \|", block), (width, height)
    assert "by `docs/make-render-times.py`" in block
