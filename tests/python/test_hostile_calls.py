"""The module refuses what a scenario file may not hold, and never crashes.

An object whose __init__ never ran, a closed one, a second __init__,
arguments out of the loader's ranges, calls beyond its bounds: each is a
clean Python exception naming what is wrong, raised before anything
changes. Calls that crashed the interpreter run in a child process, so a
regression fails its test instead of ending the run.
"""
import math

import numpy as np
import pytest

import tabletop
from conftest import run_python

NAN, INF = math.nan, math.inf


def scene(script=()):
    return {"version": 1, "name": "hostile",
            "entities": [{"name": "A", "shape": "cube", "size": 0.1, "mass": 1.0, "position": [0.0, 0.0],
                          "on": "table"}],
            "script": list(script)}


def state(sim):
    """Everything a refused call must leave as it was."""
    result = sim.result()
    return (sim.steps, sim.time, sim.positions.tolist(), sim.velocities.tolist(), result["events"],
            result["state_hash"])


# Every method and property of a Simulation, called with arguments it accepts.
CALLS = """
calls = {
    "step": lambda s: s.step(1), "run_to_end": lambda s: s.run_to_end(),
    "push": lambda s: s.push("A", impulse=0.1), "rotate": lambda s: s.rotate("A", 10),
    "render": lambda s: s.render(8, 8), "result": lambda s: s.result(),
    "positions": lambda s: s.positions, "orientations": lambda s: s.orientations,
    "velocities": lambda s: s.velocities, "angular_velocities": lambda s: s.angular_velocities,
    "names": lambda s: s.names, "time": lambda s: s.time, "steps": lambda s: s.steps,
    "timestep": lambda s: s.timestep, "at_rest": lambda s: s.at_rest, "finished": lambda s: s.finished,
    "mode": lambda s: s.mode, "contacts": lambda s: s.contacts, "reset": lambda s: s.reset(),
    "get_state": lambda s: s.get_state(), "copy": lambda s: s.copy(), "__getstate__": lambda s: s.__getstate__(),
    "push at a point": lambda s: s.push(0, impulse=[0.1, 0, 0], point=[0, 0.8, 0]),
}
"""


def test_an_object_whose_init_never_ran_raises_runtime_error():
    code = CALLS + """
import copy
import tabletop
raw = tabletop.Simulation.__new__(tabletop.Simulation)
for name, call in dict(calls, close=lambda s: s.close(), closed=lambda s: s.closed).items():
    try:
        call(raw)
    except RuntimeError as e:
        assert "not initialised" in str(e), (name, e)
    else:
        raise AssertionError(name + " did not raise")
live = tabletop.Simulation({"version": 1, "name": "c", "entities": [{"name": "A", "shape": "cube", "size": 0.1,
                            "mass": 1, "position": [0, 0], "on": "table"}]})
# A copy is a scene of its own; one of an object never initialised is refused.
twin = copy.copy(live)
twin.step()
assert twin.steps == 1 and live.steps == 0
assert "not initialised" in repr(raw)
try:
    copy.copy(raw)
except RuntimeError as e:
    assert "not initialised" in str(e)
else:
    raise AssertionError("a copy of nothing was made")
# A subclass that forgets the base __init__ is told so by pybind11.
class Forgetful(tabletop.Simulation):
    def __init__(self):
        pass
try:
    Forgetful()
except TypeError as e:
    assert "__init__" in str(e)
else:
    raise AssertionError("a subclass without the base __init__ was made")
print("ok")
"""
    child = run_python(code)
    assert child.returncode == 0, child.stderr
    assert child.stdout.strip() == "ok"


def test_a_closed_object_raises_runtime_error_and_close_is_idempotent():
    code = CALLS + """
import tabletop
s = tabletop.Simulation({"version": 1, "name": "c", "entities": [{"name": "A", "shape": "cube", "size": 0.1,
                         "mass": 1, "position": [0, 0], "on": "table"}]})
assert not s.closed
s.close()
s.close()
assert s.closed
for name, call in calls.items():
    try:
        call(s)
    except RuntimeError as e:
        assert "closed" in str(e), (name, e)
    else:
        raise AssertionError(name + " did not raise")
with tabletop.Simulation("scenarios/example1_single_cube.json") as w:
    w.step(2)
assert w.closed
print("ok")
"""
    from conftest import SOURCE
    child = run_python(code, cwd=SOURCE)
    assert child.returncode == 0, child.stderr
    assert child.stdout.strip() == "ok"


def test_a_second_init_is_refused_and_keeps_the_scene():
    sim = tabletop.Simulation(scene(), script=False)
    sim.push("A", impulse=0.5)
    sim.step(5)
    before = state(sim)
    other = scene()
    other["entities"][0]["name"] = "B"
    with pytest.raises(RuntimeError, match="already initialised"):
        sim.__init__(other)
    assert state(sim) == before and sim.names == ["A"]


@pytest.mark.parametrize("call, message", [
    (lambda s: s.push("A", impulse=NAN), "push: impulse: expected a positive number up to 1e+06, got nan"),
    (lambda s: s.push("A", impulse=INF), "push: impulse: expected a positive number up to 1e+06, got inf"),
    (lambda s: s.push("A", impulse=1e300), "push: impulse: expected a positive number up to 1e+06, got 1e+300"),
    (lambda s: s.push("A", impulse=-1), "push: impulse: expected a positive number, got -1"),
    (lambda s: s.push("A", impulse=0), "push: impulse: expected a positive number, got 0"),
    (lambda s: s.push("A", impulse=1, angle=NAN), "push: angle: expected a number from -1e+06 to 1e+06, got nan"),
    (lambda s: s.push("A", impulse=1, angle=1e300), "push: angle: expected a number from -1e+06 to 1e+06, got 1e+300"),
    (lambda s: s.push("A", step=NAN), "push: step: expected a positive number up to 100, got nan"),
    (lambda s: s.push("A", step=1e300), "push: step: expected a positive number up to 100, got 1e+300"),
    (lambda s: s.push("A", step=-INF), "push: step: expected a positive number, got -inf"),
    (lambda s: s.push("A", impulse=1, face="Up"), 'push: face: expected one of Left, Right, Front, Back, got "Up"'),
    (lambda s: s.push("A", impulse=1, face="Left", angle=0), "push: expected at most one of 'face', 'angle'"),
    (lambda s: s.push("A", impulse=1, step=1), "push: expected exactly one of 'step', 'impulse'"),
    (lambda s: s.push("Z\x00", impulse=1), 'push: entity: expected the name of an entity, got "Z\\x00"'),
    (lambda s: s.rotate("A", NAN), "rotate: degrees: expected a number from -1e+06 to 1e+06, got nan"),
    (lambda s: s.rotate("A", INF), "rotate: degrees: expected a number from -1e+06 to 1e+06, got inf"),
    (lambda s: s.rotate("A", 1e300), "rotate: degrees: expected a number from -1e+06 to 1e+06, got 1e+300"),
    (lambda s: s.rotate("B", 1), 'rotate: entity: expected the name of an entity, got "B"'),
    (lambda s: s.step(-1), "step: n: expected an integer from 0 to 10000000, got -1"),
    (lambda s: s.step(2 ** 62), "step: n: expected an integer from 0 to 10000000, got 4611686018427387904"),
    (lambda s: s.step(2 ** 200), "step: n: expected an integer from 0 to 10000000, got 16069380442589902755419620923"),
    (lambda s: s.render(0, 10), "render: width: expected an integer from 1 to 8192, got 0"),
    (lambda s: s.render(10, 8193), "render: height: expected an integer from 1 to 8192, got 8193"),
    (lambda s: s.render(10, 10, camera="nowhere"), "render: camera: "),
])
def test_a_bad_argument_is_a_value_error_naming_it_before_anything_changes(call, message):
    sim = tabletop.Simulation(scene(), script=False)
    sim.push("A", impulse=0.3)
    sim.step(3)
    before = state(sim)
    with pytest.raises(ValueError) as raised:
        call(sim)
    assert str(raised.value).startswith(message)
    assert state(sim) == before


@pytest.mark.parametrize("call", [
    lambda s: s.step(1.5), lambda s: s.step("1"), lambda s: s.step(None), lambda s: s.render(10.0, 10),
    lambda s: s.push("A", impulse="1"), lambda s: s.rotate("A", None), lambda s: s.push(None, impulse=1),
])
def test_a_value_of_the_wrong_type_is_a_type_error(call):
    sim = tabletop.Simulation(scene(), script=False)
    before = state(sim)
    with pytest.raises(TypeError):
        call(sim)
    assert state(sim) == before


def test_integers_are_taken_as_python_takes_them():
    """NumPy's integers and bools are integers (they have __index__); floats are not."""
    sim = tabletop.Simulation(scene(), script=False)
    sim.step(np.int64(3))
    sim.step(True)
    assert sim.steps == 4
    assert sim.render(np.int32(12), np.uint16(9)).shape == (9, 12, 3)


def loader_expectation(action):
    """What the scenario loader says it expected of `action` in a script."""
    with pytest.raises(tabletop.ScenarioError) as raised:
        tabletop.scene(scene([action]))
    return expectation(str(raised.value))


def expectation(message):
    """What a message says was expected (the value it shows is written as each side writes numbers)."""
    return message.split(": expected ", 1)[1].rsplit(", got ", 1)[0]


@pytest.mark.parametrize("value", [-1, 0, 1e300, 2e6, -5e6])
def test_the_refusals_use_the_loaders_ranges_and_words(value):
    """A value a scenario file's script may not hold is refused from Python with the same words."""
    sim = tabletop.Simulation(scene(), script=False)
    cases = [
        ({"push": {"entity": "A", "angle": 0, "impulse": value}}, lambda: sim.push("A", impulse=value)),
        ({"push": {"entity": "A", "angle": 0, "step": value}}, lambda: sim.push("A", step=value)),
        ({"push": {"entity": "A", "angle": value, "step": 0.1}}, lambda: sim.push("A", step=0.1, angle=value)),
        ({"rotate": {"entity": "A", "angle": value}}, lambda: sim.rotate("A", value)),
    ]
    refused = 0
    for action, call in cases:
        try:
            tabletop.scene(scene([action]))
            call()                       # the file takes it: so does Python
        except tabletop.ScenarioError:
            with pytest.raises(ValueError) as raised:
                call()
            assert expectation(str(raised.value)) == loader_expectation(action)
            refused += 1
    assert refused >= 1


@pytest.mark.parametrize("settings, message", [
    (dict(timestep=NAN), "timestep: expected a number from 1e-05 to 0.1, got nan"),
    (dict(timestep=0.5), "timestep: expected a number from 1e-05 to 0.1, got 0.5"),
    (dict(iterations=0), "iterations: expected an integer from 1 to 10000, got 0"),
    (dict(iterations=2 ** 64), "iterations: expected an integer from 1 to 10000, got 18446744073709551616"),
    (dict(integrator="rk4"), "integrator: expected trapezoid or euler, got 'rk4'"),
    (dict(mode="fast"), "mode: expected bullet, compat or rules, got 'fast'"),
])
def test_overrides_are_checked_as_the_command_lines(settings, message):
    with pytest.raises(ValueError, match="^" + message.replace("(", r"\(").replace(")", r"\)")):
        tabletop.Simulation(scene(), **settings)
    with pytest.raises(ValueError, match="^" + message.replace("(", r"\(").replace(")", r"\)")):
        tabletop.run(scene(), **settings)


def test_run_durations_are_the_loaders():
    with pytest.raises(ValueError, match="^duration: expected a positive number, got -1"):
        tabletop.run(scene(), duration=-1)
    with pytest.raises(ValueError, match="^duration: expected a positive number up to 3600, got inf"):
        tabletop.run(scene(), duration=INF)
    with pytest.raises(tabletop.ScenarioError, match="at most 1e\\+07 steps"):
        tabletop.run(scene(), duration=3600, timestep=1e-4)


def test_step_is_bounded_by_the_loaders_solver_work():
    """n x max_substeps x iterations x entities at most 1e11, as a file's run: refused up front."""
    sim = tabletop.Simulation(scene(), script=False, iterations=10000)
    before = state(sim)
    most = int(1e11 / (64 * 10000 * 1))
    with pytest.raises(ValueError, match=r"^step: n: expected at most 1e\+11 solver work"):
        sim.step(most + 1)
    assert state(sim) == before


def test_a_path_holding_nul_is_refused_not_shortened():
    from conftest import SCENARIOS
    path = str(SCENARIOS / "example1_single_cube.json")
    with pytest.raises(ValueError, match="^path: .*NUL"):
        tabletop.load(path + "\x00.bak")
    with pytest.raises(ValueError, match="^path: .*NUL"):
        tabletop.Simulation(path + "\x00")
