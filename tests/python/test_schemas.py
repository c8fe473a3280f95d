"""The JSON Schemas of the scenario format and of run --json's output, against every shipped file and output."""
import json
import subprocess

import jsonschema
import pytest

from conftest import SCENARIOS, schema, shipped_scenarios, without_comments

SCENARIO = schema("scenario.schema.json")
OUTPUT = schema("run-output.schema.json")


def test_the_schemas_are_valid_schemas():
    jsonschema.Draft202012Validator.check_schema(SCENARIO)
    jsonschema.Draft202012Validator.check_schema(OUTPUT)


@pytest.mark.parametrize("path", shipped_scenarios(), ids=lambda p: p.stem)
def test_every_shipped_scenario_meets_the_scenario_schema(path):
    jsonschema.validate(json.loads(without_comments(path.read_text())), SCENARIO)


@pytest.mark.parametrize("change, where", [
    (lambda s: s.update(colour=[1, 2, 3]), "additional"),
    (lambda s: s["entities"][0].update(shape="cone"), "cone"),
    (lambda s: s["entities"][0].update(size=[0.1, 0.1]), "size"),
    (lambda s: s["entities"][0].update(on="table", position=[0, 0.8, 0]), "position"),
    (lambda s: s["script"][0]["push"].update(direction="Left"), "push"),
    (lambda s: s["settings"].update(timestep=1.0), "timestep"),
    (lambda s: s["entities"][0].update(name="A\u200b"), "name"),
    (lambda s: s.update(name="s\u2028"), "name"),
])
def test_the_scenario_schema_refuses_what_the_loader_refuses(change, where, tmp_path, tabletop_bin):
    scene = {"version": 1, "name": "s", "settings": {},
             "entities": [{"name": "A", "shape": "cube", "size": 0.1, "mass": 1, "position": [0, 0]}],
             "script": [{"push": {"entity": "A", "angle": 0, "step": 0.1}}]}
    jsonschema.validate(scene, SCENARIO)
    change(scene)
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(scene, SCENARIO)
    path = tmp_path / "s.json"
    path.write_text(json.dumps(scene))
    assert subprocess.run([tabletop_bin, "run", str(path)], capture_output=True).returncode == 2


@pytest.mark.parametrize("mode", ["bullet", "compat", "rules"])
def test_run_output_meets_its_schema_for_one_file_and_several(mode, tabletop_bin):
    examples = sorted(str(p) for p in SCENARIOS.glob("example?_*.json"))
    for files in (examples[:1], examples):
        out = subprocess.run([tabletop_bin, "run", "--json", "--mode", mode, *files], capture_output=True, text=True,
                             check=True).stdout
        document = json.loads(out)
        jsonschema.validate(document, OUTPUT)
        assert [r["file"] for r in document["runs"]] == files


def test_an_incomplete_run_meets_the_schema(tmp_path, tabletop_bin):
    # A 0.1 g cube struck by 1e6 N s leaves the world in the first step: the run stops, marked incomplete.
    scene = {"version": 1, "name": "absurd", "settings": {"timestep": 0.1, "duration": 5},
             "entities": [{"name": "A", "shape": "cube", "size": 0.01, "position": [0, 0], "mass": 0.0001}],
             "script": [{"push": {"entity": "A", "direction": "Left", "impulse": 1e6}}]}
    path = tmp_path / "absurd.json"
    path.write_text(json.dumps(scene))
    result = subprocess.run([tabletop_bin, "run", "--json", str(path)], capture_output=True, text=True)
    assert result.returncode == 3
    document = json.loads(result.stdout)
    jsonschema.validate(document, OUTPUT)
    assert not document["runs"][0]["complete"] and "entity 'A'" in document["runs"][0]["failure"]
