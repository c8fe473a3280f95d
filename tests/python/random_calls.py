"""Calls the module with random arguments, hostile ones among them.

python3 random_calls.py SEED CALLS: makes CALLS calls (functions, methods,
properties, a second __init__, close) with arguments drawn from pools of
good values and hostile ones (NaN, infinities, huge and negative numbers,
huge integers, wrong types, names with NUL or invisible characters, long
strings), seeded so that a failure can be replayed. Each call must return
a well-formed result or raise a clean exception (ValueError, TypeError,
RuntimeError and their subclasses); anything else is printed and the
exit status is 1. A crash or hang shows as the child's death or timeout.
Prints a JSON count of the outcomes by kind.
"""
import json
import math
import pickle
import random
import sys

import numpy as np

import tabletop

CLEAN = (ValueError, TypeError, RuntimeError, OverflowError)

HOSTILE = [math.nan, math.inf, -math.inf, 1e300, -1e300, -1, -0.0, 0, 1e-320, 2 ** 62, 2 ** 64, 10 ** 400,
           None, "1", [], {}, object(), True, np.float32("nan"), np.int64(-5), 1 + 2j]
NUMBERS = [0.05, 0.3, 1.0, 45.0, -90.0, 1e6, -1e6, 100.0, 1e-9, 5e5] + HOSTILE
COUNTS = [0, 1, 2, 5, 17, 50, np.int64(3), True, -1, 2 ** 31, 2 ** 62, 2 ** 200, 10 ** 7 + 1, 1.5, math.nan,
          None, "3"]
SIDES = [1, 2, 16, 33, np.int32(20), 0, -1, 8193, 2 ** 40, 1.5, None, "16"]
NAMES = ["A", "B", "C", "", "Z", "A\x00", "table", "A\u200b", "\u202eA", "x" * 100000, None, 5, b"A"]
FACES = ["Left", "Right", "Front", "Back", "left", "Up", "", "L\x00", None, 3]
CAMERAS = ["fit", "front", "corner", "side", "top", "follow:A", "follow:Z", "1,2,3:0,0,0", "nan,0,0:0,0,0",
           "1e300,0,0:0,0,0", "0,0,0:0,0,0", "", "x" * 10000, None]
MODES = ["bullet", "compat", "rules", "BULLET", "", "fast", None]
INTEGRATORS = [None, "trapezoid", "euler", "rk4", "", 3]


def base_scene(rng):
    """Three bodies on the table, a short run, sometimes a script of its own."""
    scene = {"version": 1, "name": "random", "settings": {"duration": 2.0},
             "entities": [{"name": "A", "shape": "cube", "size": 0.1, "mass": 1.0, "position": [0.0, 0.0],
                           "on": "table"},
                          {"name": "B", "shape": "sphere", "size": 0.08, "mass": 0.5, "position": [0.3, 0.1],
                           "on": "table"},
                          {"name": "C", "shape": "cube", "size": 0.05, "mass": 0.2, "position": [0.0, 0.0],
                           "on": "A"}]}
    if rng.random() < 0.5:
        scene["script"] = [{"push": {"entity": "A", "direction": "Left", "step": 0.2}}]
    return scene


def hostile_scene(rng):
    """A scene's objects with one field replaced by a hostile value."""
    scene = base_scene(rng)
    entity = scene["entities"][rng.randrange(3)]
    key = rng.choice(["size", "mass", "position", "name", "on", "yaw", "shape"])
    entity[key] = rng.choice(HOSTILE + NAMES + [[math.nan, 0], [0] * 1000, [[[[0]]]] * 3])
    return scene


def pick(rng, pool, absent=0.3):
    """A value from `pool`, or (with probability `absent`) none: the keyword left out."""
    return rng.choice(pool) if rng.random() >= absent else ...


def keywords(**drawn):
    return {k: v for k, v in drawn.items() if v is not ...}


def build(rng):
    kw = keywords(mode=pick(rng, MODES, 0.5), script=pick(rng, [True, False, None, "yes"], 0.5),
                  timestep=pick(rng, [1 / 60, 1 / 240, 1e-3] + HOSTILE, 0.7),
                  iterations=pick(rng, [1, 10, 50] + COUNTS, 0.7), integrator=pick(rng, INTEGRATORS, 0.7))
    scene = base_scene(rng) if rng.random() < 0.85 else hostile_scene(rng)
    return tabletop.Simulation(scene, **kw)


def check_array(a, columns, n):
    assert isinstance(a, np.ndarray) and a.dtype == np.float64 and a.shape == (n, columns), a


def one_call(rng, sim):
    """One random call on `sim` (or the module); returns the Simulation to go on with."""
    what = rng.randrange(26)
    if what < 5:
        sim.step(rng.choice(COUNTS))
    elif what < 9:
        sim.push(rng.choice(NAMES), **keywords(impulse=pick(rng, NUMBERS), step=pick(rng, NUMBERS),
                                              angle=pick(rng, NUMBERS), face=pick(rng, FACES, 0.7)))
    elif what < 11:
        sim.rotate(rng.choice(NAMES), rng.choice(NUMBERS))
    elif what == 11:
        image = sim.render(rng.choice(SIDES), rng.choice(SIDES), **keywords(camera=pick(rng, CAMERAS),
                                                                            arrow=pick(rng, [True, False, None])))
        assert image.dtype == np.uint8 and image.ndim == 3 and image.shape[2] == 3
    elif what == 12:
        n = len(sim.names)
        check_array(sim.positions, 3, n)
        check_array(sim.orientations, 4, n)
        check_array(sim.velocities, 3, n)
        check_array(sim.angular_velocities, 3, n)
        assert isinstance(sim.time, float) and isinstance(sim.steps, int) and sim.mode in ("bullet", "compat", "rules")
    elif what == 13:
        result = sim.result()
        assert len(result["state_hash"]) == 16 and len(result["entities"]) == len(sim.names)
    elif what == 14:
        if rng.random() < 0.2:
            sim.run_to_end()
        else:
            sim.step(rng.randrange(30))
    elif what == 15:
        if rng.random() < 0.3:
            sim.close()
        else:
            sim.__init__(base_scene(rng))
    elif what == 16:
        return build(rng)
    elif what == 17:
        kw = keywords(mode=pick(rng, MODES, 0.5), timestep=pick(rng, [1 / 60] + HOSTILE, 0.7),
                      iterations=pick(rng, [1, 10] + COUNTS, 0.7), integrator=pick(rng, INTEGRATORS, 0.7),
                      duration=pick(rng, [0.1, 0.5] + HOSTILE, 0.5))
        result = tabletop.run(base_scene(rng) if rng.random() < 0.7 else hostile_scene(rng), **kw)
        assert isinstance(result["complete"], bool)
    elif what == 18:
        tabletop.scene(hostile_scene(rng))
    elif what == 20:
        saved = sim.get_state()
        sim.step(rng.randrange(20))
        sim.set_state(saved)
        assert sim.result()["state_hash"] == saved.state_hash, "a state did not come back"
    elif what == 21:
        twin = pickle.loads(pickle.dumps(sim)) if rng.random() < 0.5 else sim.copy()
        assert twin.result()["state_hash"] == sim.result()["state_hash"], "a copy is not the same"
    elif what == 22:
        vector = lambda: [rng.choice(NUMBERS) for _ in range(rng.choice([3, 3, 3, 2]))]  # noqa: E731
        sim.push(rng.choice(NAMES + [0, -1, 7]), impulse=vector(), **keywords(point=pick(rng, [vector()], 0.5)))
    elif what == 23:
        vector = [rng.choice(NUMBERS) for _ in range(3)]
        if rng.random() < 0.5:
            sim.apply_force(rng.choice(NAMES + [0, -1]), vector, **keywords(point=pick(rng, [vector], 0.5)))
        else:
            sim.apply_torque(rng.choice(NAMES + [0, -1]), vector)
    elif what == 24:
        setattr(sim, rng.choice(["timestep", "gravity"]), rng.choice(NUMBERS + [1 / 60, 9.81, 1.62]))
    elif what == 25:
        assert all(len(c.point) == 3 and c.b in ("table", "ground", *sim.names) for c in sim.contacts)
        if rng.random() < 0.3:
            sim.reset()
            assert sim.steps == 0
    else:
        uninitialised = tabletop.Simulation.__new__(tabletop.Simulation)
        rng.choice([lambda: uninitialised.step(1), lambda: uninitialised.positions,
                    lambda: uninitialised.render(4, 4), lambda: uninitialised.close()])()
    return sim


def main(seed, calls):
    rng = random.Random(seed)
    sim = build_until_made(rng)
    outcomes = {}
    for k in range(calls):
        try:
            sim = one_call(rng, sim)
            kind = "ok"
        except CLEAN as e:
            kind = type(e).__name__
        except Exception as e:  # anything else is a failure of the module
            print(f"seed {seed}, call {k}: unclean {type(e).__name__}: {e}", file=sys.stderr)
            return 1
        outcomes[kind] = outcomes.get(kind, 0) + 1
        if sim_is_closed(sim):
            sim = build_until_made(rng)
    print(json.dumps(outcomes, sort_keys=True))
    return 0


def build_until_made(rng):
    while True:
        try:
            return build(rng)
        except CLEAN:
            continue


def sim_is_closed(sim):
    try:
        return sim.closed
    except RuntimeError:
        return True


if __name__ == "__main__":
    sys.exit(main(int(sys.argv[1]), int(sys.argv[2])))
