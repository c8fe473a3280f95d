"""Saved states: reset(), get_state()/set_state(), copy() and pickling give a
state back bit for bit (the same state_hash and identical arrays), in every
mode, and refuse what is not a state of the same scene."""
import copy
import json
import pickle

import numpy as np
import pytest

import tabletop

MODES = ["bullet", "compat", "rules"]
SCENES = ["example2_two_cubes", "example3_stacked_cubes", "example4_two_spheres"]


def arrays(sim):
    return [sim.positions, sim.orientations, sim.velocities, sim.angular_velocities]


def same(a, b):
    """Bit for bit: the hash and every array equal exactly."""
    assert a.result()["state_hash"] == b.result()["state_hash"]
    for x, y in zip(arrays(a), arrays(b)):
        assert np.array_equal(x, y)


def busy(sim, k=7):
    """Steps and pushes the report's modes all take (on bodies at rest, as they ask, when the script is off)."""
    sim.step(k)
    for _ in range(200):
        if sim.at_rest:
            break
        sim.step(10)
    sim.push(0, step=0.15, angle=30.0)
    sim.step(k)
    sim.gravity = 9.0 + k / 10
    sim.timestep = 1 / (100 + k)
    sim.step(k)
    sim.rotate(-1, 10.0)
    sim.step(k)


@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize("scene", SCENES)
def test_a_saved_state_comes_back_bit_for_bit_and_goes_on_the_same(scene, mode):
    sim = tabletop.Simulation(scene, mode=mode, script=mode == "bullet")
    busy(sim)
    saved = sim.get_state()
    twin = sim.copy()
    same(sim, twin)
    assert saved.state_hash == sim.result()["state_hash"]
    assert np.array_equal(saved.positions, sim.positions)
    assert saved.steps == sim.steps and saved.time == sim.time
    busy(sim, 11)  # away from the saved state
    assert sim.result()["state_hash"] != saved.state_hash
    sim.set_state(saved)
    same(sim, twin)
    # The restored scene and the copy go on identically, script included.
    busy(sim, 13)
    busy(twin, 13)
    same(sim, twin)


@pytest.mark.parametrize("mode", MODES)
def test_reset_is_the_scene_as_built(mode):
    fresh = tabletop.Simulation("example2_two_cubes", mode=mode)
    sim = tabletop.Simulation("example2_two_cubes", mode=mode)
    sim.step(300)
    sim.reset()
    same(sim, fresh)
    assert sim.steps == 0 and sim.time == 0.0
    sim.run_to_end()
    fresh.run_to_end()
    same(sim, fresh)


@pytest.mark.parametrize("mode", MODES)
def test_pickled_and_deep_copied_simulations_are_the_same_and_apart(mode):
    sim = tabletop.Simulation("example3_stacked_cubes", mode=mode, timestep=1 / 60, script=False)
    busy(sim)
    for other in (pickle.loads(pickle.dumps(sim)), copy.deepcopy(sim), copy.copy(sim)):
        same(sim, other)
        assert other.timestep == sim.timestep and other.gravity == sim.gravity
        other.step(20)  # a copy is its own scene
        assert other.steps == sim.steps + 20
    state = pickle.loads(pickle.dumps(sim.get_state()))
    sim.step(5)
    sim.set_state(state)
    assert sim.result()["state_hash"] == state.state_hash


def test_a_state_of_another_scene_mode_or_settings_is_refused():
    saved = tabletop.Simulation("example2_two_cubes").get_state()
    for other in (tabletop.Simulation("example3_stacked_cubes"), tabletop.Simulation("example2_two_cubes", mode="compat"),
                  tabletop.Simulation("example2_two_cubes", timestep=1 / 60),
                  tabletop.Simulation("example2_two_cubes", script=False)):
        with pytest.raises(ValueError, match="another scene"):
            other.set_state(saved)
    with pytest.raises(TypeError):
        tabletop.Simulation("example2_two_cubes").set_state("not a state")


def test_an_altered_pickle_is_refused_and_never_crashes():
    sim = tabletop.Simulation("example2_two_cubes", script=False)
    sim.push("A", impulse=0.2)
    sim.step(10)
    origin, history, digest = sim.__getstate__()
    calls = json.loads(history)

    def restore(origin=origin, history=history, digest=digest):
        blank = tabletop.Simulation.__new__(tabletop.Simulation)
        blank.__setstate__((origin, history, digest))
        return blank

    assert restore().result()["state_hash"] == digest
    with pytest.raises(RuntimeError, match="gave another one"):
        restore(history=json.dumps(calls[:-1] + [{"call": "steps", "count": 11}]))
    hostile = [
        "[" * 100000, "{}", "[1]", '[{"call": "steps", "count": -1}]', '[{"call": "steps", "count": 1e300}]',
        '[{"call": "push", "entity": "Z", "angle": 0, "impulse": 1}]',
        '[{"call": "push", "entity": "A", "angle": 0, "impulse": -1}]',
        '[{"call": "impulse", "entity": "A", "impulse": [1, "x", 0]}]',
        '[{"call": "rotate", "entity": "A", "degrees": NaN}]', '[{"call": "format c:"}]',
        '[{"call": "steps", "count": 10000000}, {"call": "steps", "count": 10000000}]',
    ]
    for text in hostile:
        with pytest.raises((ValueError, tabletop.ScenarioError)):
            restore(history=text)
    for bad in [(), ("x",) * 7, (origin[0], origin[1], "warp", *origin[3:]), ("{}", *origin[1:])]:
        with pytest.raises((ValueError, TypeError)):
            restore(origin=bad)


def test_after_a_step_that_raised_the_state_cannot_be_saved_until_reset():
    scene = {"version": 1, "name": "fling", "settings": {"duration": 100},
             "entities": [{"name": "A", "shape": "cube", "size": 0.1, "mass": 1, "position": [0, 0]}]}
    sim = tabletop.Simulation(scene, script=False)
    sim.push("A", impulse=[0.0, 1e5, 0.0])
    with pytest.raises(tabletop.DivergenceError):
        sim.step(1000)
    for call in (sim.get_state, sim.copy, lambda: pickle.dumps(sim)):
        with pytest.raises(RuntimeError, match="a step raised"):
            call()
    sim.reset()
    assert sim.get_state().steps == 0


def test_state_arrays_are_read_only():
    sim = tabletop.Simulation("example2_two_cubes")
    for a in arrays(sim) + [sim.get_state().positions]:
        with pytest.raises(ValueError, match="read-only"):
            a[0, 0] = 5.0
    assert sim.positions[0, 0] != 5.0


def test_entities_are_named_or_indexed_as_python_indexes():
    by_name = tabletop.Simulation("example2_two_cubes", script=False)
    by_index = tabletop.Simulation("example2_two_cubes", script=False)
    by_name.push("B", impulse=0.3, angle=45)
    by_index.push(-1, impulse=0.3, angle=45)
    by_name.step(30)
    by_index.step(30)
    same(by_name, by_index)
    for bad, error in [(2, ValueError), (-3, ValueError), (True, TypeError), (1.0, TypeError), (None, TypeError)]:
        with pytest.raises(error, match="push: entity"):
            by_index.push(bad, impulse=0.1)


def test_repr_says_what_the_simulation_is():
    sim = tabletop.Simulation("example2_two_cubes", mode="compat")
    sim.step(3)
    text = repr(sim)
    assert "'example2_two_cubes'" in text and "mode=compat" in text and "steps=3" in text and "entities=2" in text
    assert "steps=3" in repr(sim.get_state())
    sim.close()
    assert "closed" in repr(sim)
