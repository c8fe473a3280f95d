"""tabletop.sweep: the command line's table as a DataFrame, here and on a Dask cluster."""
import json
import re
import os
import subprocess
import sys

import pytest

import tabletop
from conftest import SOURCE, schema, without_comments

# Example 2 with B's mass and the push's step varied: 12 runs in two modes.
SPEC = {
    "version": 1, "name": "py_sweep", "scene": "example2_two_cubes",
    "parameters": [
        {"name": "mass", "pointer": "/entities/1/mass", "values": [0.25, 0.5, 1.0]},
        {"name": "step", "pointer": "/script/0/push/step", "range": {"from": 0.5, "to": 1.1, "count": 4}},
    ],
    "modes": ["rules", "bullet"],
}


def comparable(frame):
    """The table without its wall times, which differ from one running to the next."""
    return frame[[c for c in frame.columns if not c.endswith(".wall_s")]]


@pytest.fixture(scope="module")
def local():
    return tabletop.sweep(SPEC)


def test_the_dataframe_is_the_command_lines_table(local, tabletop_bin, tmp_path):
    spec = tmp_path / "spec.json"
    spec.write_text(json.dumps(SPEC))
    out = subprocess.run([tabletop_bin, "sweep", str(spec), "--jobs", "2"], capture_output=True, text=True,
                         check=True, env={"TABLETOP_DATA_DIR": str(SOURCE)}).stdout
    rows = [json.loads(line) for line in out.splitlines()]
    assert len(rows) == len(local) == 12
    assert list(rows[0].keys()) == list(local.columns)
    for row, (_, ours) in zip(rows, comparable(local).iterrows()):
        for column, value in ours.items():
            assert row[column] == value, column
    # Real runs: every bullet run ends in another state.
    assert local["bullet.state_hash"].nunique() == 12


def test_a_bad_spec_raises_the_located_error():
    bad = dict(SPEC, parameters=[{"pointer": "/entities/9/mass", "values": [1]}])
    with pytest.raises(tabletop.ScenarioError, match=r"<spec>:1:\d+: at /parameters/0/pointer: expected a place"):
        tabletop.sweep(bad)


def test_a_dask_cluster_of_two_worker_processes_gives_the_same_rows(local, tabletop_bin, tmp_path):
    import distributed  # pylint: disable=import-outside-toplevel
    spec = tmp_path / "spec.json"
    spec.write_text(json.dumps(SPEC))
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        remote = tabletop.sweep(SPEC, client)
        # The runs went to a cluster of two worker processes.
        assert len(client.scheduler_info()["workers"]) == 2
        # The command line, through the same scheduler, into a table.
        out = tmp_path / "cluster"
        subprocess.run([tabletop_bin, "sweep", str(spec), "--scheduler", cluster.scheduler_address, "--out", str(out)],
                       check=True, capture_output=True, timeout=300,
                       env=dict(os.environ, TABLETOP_PYTHON=sys.executable, TABLETOP_DATA_DIR=str(SOURCE)))
    assert comparable(remote).equals(comparable(local))
    assert list(remote["bullet.state_hash"]) == list(local["bullet.state_hash"])
    rows = [json.loads(line) for line in (tmp_path / "cluster.jsonl").read_text().splitlines()]
    assert [r["bullet.state_hash"] for r in rows] == list(local["bullet.state_hash"])
    for row, (_, ours) in zip(rows, comparable(local).iterrows()):
        assert all(row[column] == value for column, value in ours.items())


@pytest.mark.parametrize("path", sorted((SOURCE / "docs" / "sweeps").glob("*.json")), ids=lambda p: p.stem)
def test_every_shipped_spec_meets_the_schema(path):
    import jsonschema  # pylint: disable=import-outside-toplevel
    jsonschema.Draft202012Validator.check_schema(schema("sweep.schema.json"))
    jsonschema.validate(json.loads(without_comments(path.read_text())), schema("sweep.schema.json"))


def test_the_schema_refuses_what_the_loader_refuses():
    import jsonschema  # pylint: disable=import-outside-toplevel
    bad = dict(SPEC, parameters=[{"pointer": "/entities/1/mass", "range": {"from": 1, "to": 2, "count": 0}}])
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(bad, schema("sweep.schema.json"))
    with pytest.raises(tabletop.ScenarioError, match="at /parameters/0/range/count: expected a whole number from 1"):
        tabletop.sweep(bad)


RANDOM = {"version": 1, "name": "py_random", "seed": 30, "random": {"runs": 4, "rate": 60}}


def test_the_random_runs_go_from_python_and_meet_the_schema(tabletop_bin):
    import jsonschema  # pylint: disable=import-outside-toplevel
    jsonschema.validate(RANDOM, schema("sweep.schema.json"))
    for bad in (dict(RANDOM, scene="example2_two_cubes"), dict(RANDOM, modes=["rules"]),
                dict(RANDOM, random={"runs": 0})):
        with pytest.raises(jsonschema.ValidationError):
            jsonschema.validate(bad, schema("sweep.schema.json"))
        with pytest.raises(tabletop.ScenarioError):
            tabletop.sweep(bad)
    table = tabletop.sweep(RANDOM, jobs=2)
    assert list(table["seed"]) == [30, 31, 32, 33]
    assert table["bullet.stable"].all()
    out = subprocess.run([tabletop_bin, "sweep", "--random", "4", "--seed", "30", "--rate", "60"],
                         capture_output=True, text=True, check=True, env={"TABLETOP_DATA_DIR": str(SOURCE)}).stdout
    rows = [json.loads(line) for line in out.splitlines()]
    assert [r["bullet.state_hash"] for r in rows] == list(table["bullet.state_hash"])


def test_the_maps_table_in_the_docs_is_what_the_sweeps_give():
    """docs/sweep.md's maps table (docs/make-sweep.py writes it) against the sweeps run now."""
    page = (SOURCE / "docs" / "sweep.md").read_text()
    block = re.search(r"<!-- maps: begin -->\n(.*?)<!-- maps: end -->", page, re.S).group(1)
    rows = [line for line in block.splitlines() if line.startswith("| `")]
    assert len(rows) == 2
    for line in rows:
        spec, runs, agree, reasons = [cell.strip() for cell in line.strip().strip("|").split("|")]
        table = tabletop.sweep(str(SOURCE / spec.strip("`")), jobs=2)
        assert len(table) == int(runs), spec
        assert int(table["bullet.agrees"].sum()) == int(agree), spec
        counts = table.loc[~table["bullet.agrees"], "bullet.reason"].value_counts()
        listed = dict((r.rsplit(" ", 1)[0], int(r.rsplit(" ", 1)[1])) for r in reasons.split(", ") if r)
        assert listed == {k: int(v) for k, v in counts.items()}, spec
