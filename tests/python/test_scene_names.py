"""Shipped scenes by name from any folder: load, run, Simulation and shipped_scenes, as the command line."""
import json
import os
import pathlib
import subprocess

import pytest

import tabletop
from conftest import SCENARIOS, shipped_scenarios

NAMES = sorted(str(p.relative_to(SCENARIOS).with_suffix("")) for p in shipped_scenarios())


@pytest.fixture
def elsewhere(tmp_path):
    """The test runs in a folder of its own, where no scene file is."""
    before = os.getcwd()
    os.chdir(tmp_path)
    yield tmp_path
    os.chdir(before)


def test_the_list_is_every_file_under_scenarios(elsewhere, tabletop_bin):
    scenes = tabletop.shipped_scenes()
    assert [s["name"] for s in scenes] == sorted(NAMES, key=lambda n: (n.count("/"), n))
    for s in scenes:
        assert s["loads"] and s["description"], s
        assert pathlib.Path(s["file"]).resolve() == (SCENARIOS / (s["name"] + ".json")).resolve()
    cli = json.loads(subprocess.run([tabletop_bin, "list", "--json"], capture_output=True, text=True,
                                    check=True).stdout)
    assert cli["scenes"] == scenes


@pytest.mark.parametrize("name", ["example1_single_cube", "example1_single_cube.json", "analytic/free_flight",
                                  "hard/tiny_cube.json"])
def test_load_run_and_simulation_take_a_name(elsewhere, name):
    file = SCENARIOS / (name.removesuffix(".json") + ".json")
    expected = tabletop.run(str(file))
    assert pathlib.Path(tabletop.load(name).file).resolve() == file.resolve()
    assert tabletop.run(name)["state_hash"] == expected["state_hash"]
    assert tabletop.run(pathlib.Path(name))["state_hash"] == expected["state_hash"]
    with tabletop.Simulation(name) as sim:
        sim.run_to_end()
        assert sim.result()["state_hash"] == expected["state_hash"]


def test_a_file_wins_over_a_shipped_name(elsewhere):
    (elsewhere / "example2_two_cubes").write_text(json.dumps(
        {"version": 1, "name": "mine",
         "entities": [{"name": "A", "shape": "cube", "size": 0.1, "mass": 1.0, "position": [0.0, 0.0]}]}))
    assert tabletop.load("example2_two_cubes").name == "mine"
    assert tabletop.load("example2_two_cubes.json").name == "example2_two_cubes"


@pytest.mark.parametrize("call", [tabletop.load, tabletop.run, tabletop.Simulation])
def test_a_missing_name_is_one_located_line(elsewhere, call):
    with pytest.raises(tabletop.ScenarioError) as refused:
        call("hard/no_such_scene")
    assert str(refused.value) == ("hard/no_such_scene: cannot open the file for reading, and no shipped scene has "
                                  "that name (tabletop.shipped_scenes() names them)")


@pytest.mark.parametrize("name", ["../example2_two_cubes", "hard/../example2_two_cubes", "hard/..",
                                  "../../etc/passwd.json"])
def test_a_name_never_leaves_the_folder(elsewhere, name):
    with pytest.raises(tabletop.ScenarioError) as refused:
        tabletop.load(name)
    assert str(refused.value) == (f"{name}: cannot open the file for reading; as a shipped scene's name, expected no "
                                  f"'..' part, got '{name}'")


@pytest.mark.parametrize("name", ["a b", "$(touch ran)", "hard//tiny_cube", "hard/", "a" * 300])
def test_other_names_are_refused_in_one_line(elsewhere, name):
    with pytest.raises(tabletop.ScenarioError) as refused:
        tabletop.run(name)
    assert "\n" not in str(refused.value)
    assert "cannot open the file for reading; as a shipped scene's name, expected" in str(refused.value)
    assert not (elsewhere / "ran").exists()
