"""Every sample output in the README and docs is what the program prints (docs/make-samples.py writes them)."""
import importlib.util

import pytest

from conftest import SOURCE

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


spec_analytic = importlib.util.spec_from_file_location("make_analytic", SOURCE / "docs" / "make-analytic.py")
make_analytic = importlib.util.module_from_spec(spec_analytic)
spec_analytic.loader.exec_module(make_analytic)


def test_the_analytic_tables_are_what_bench_measures(tabletop_bin):
    block = make_analytic.table(make_analytic.measure(tabletop_bin))
    for page in make_analytic.PAGES:
        text = (SOURCE / page).read_text()
        assert make_analytic.written(text, block) == text, \
            f"{page}: the analytic cases' table is stale; run docs/make-analytic.py"
