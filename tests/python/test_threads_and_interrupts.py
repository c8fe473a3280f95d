"""Long calls stop on Ctrl-C, and the module is safe from several threads.

Stepping, whole runs and rendering release the GIL; one call at a time
uses a Simulation (another thread's call waits); threads rendering for the
first time at once do not deadlock. Each case that could hang or crash
runs in a child process with a timeout.
"""
import json
import threading
import time

import pytest

import tabletop
from conftest import SCENARIOS, run_python

SCENE = {"version": 1, "name": "long",
         "settings": {"duration": 3600, "end_at_rest": False},
         "entities": [{"name": "A", "shape": "cube", "size": 0.1, "mass": 1.0, "position": [0.0, 0.0],
                       "on": "table"},
                      {"name": "B", "shape": "sphere", "size": 0.1, "mass": 1.0, "position": [0.3, 0.0],
                       "on": "table"}]}


@pytest.mark.parametrize("call", ["sim.step(10**7)", "sim.run_to_end()", "tabletop.run(scene)"])
def test_ctrl_c_stops_a_long_call_soon_and_leaves_the_object_usable(call):
    """SIGINT half a second in: KeyboardInterrupt within a second or two, not after the hour the call asks for."""
    code = f"""
import json, os, signal, threading, time
import tabletop
scene = {SCENE!r}
sim = tabletop.Simulation(scene, script=False)
threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGINT)).start()
start = time.monotonic()
try:
    {call}
except KeyboardInterrupt:
    took = time.monotonic() - start
    steps = sim.steps
    sim.step(2)
    print(json.dumps({{"took": took, "usable": sim.steps == steps + 2}}))
"""
    child = run_python(code, timeout=120)
    assert child.returncode == 0, child.stderr
    outcome = json.loads(child.stdout)
    assert 0.5 <= outcome["took"] < 3.0
    assert outcome["usable"]


def test_a_signal_handler_calling_the_busy_object_is_refused_not_deadlocked():
    code = f"""
import json, signal
import tabletop
sim = tabletop.Simulation({SCENE!r}, script=False)
signal.signal(signal.SIGALRM, lambda *_: sim.time)
signal.setitimer(signal.ITIMER_REAL, 0.2)
try:
    sim.step(10**7)
except RuntimeError as e:
    print(e)
"""
    child = run_python(code, timeout=120)
    assert child.returncode == 0, child.stderr
    assert "called while another of its calls is running in this thread" in child.stdout


def test_stepping_releases_the_gil():
    """The main thread keeps running Python while another thread steps."""
    sim = tabletop.Simulation(SCENE, script=False)
    sim.step(200)
    started = time.monotonic()
    sim.step(200)
    per_step = (time.monotonic() - started) / 200
    worker = threading.Thread(target=sim.step, args=(max(200, int(0.5 / per_step)),))
    loops = 0
    worker.start()
    while worker.is_alive():
        loops += 1
        sum(range(100))
    worker.join()
    assert loops > 1000


def test_rendering_releases_the_gil():
    sim = tabletop.Simulation(str(SCENARIOS / "example2_two_cubes.json"))
    worker = threading.Thread(target=sim.render, args=(1600, 1200))
    loops = 0
    worker.start()
    while worker.is_alive():
        loops += 1
        sum(range(100))
    worker.join()
    assert loops > 100


def test_threads_on_one_object_take_turns():
    """Two threads stepping one Simulation while a third pushes and reads: every step counted, nothing torn."""
    code = f"""
import threading
import numpy as np
import tabletop
sim = tabletop.Simulation({SCENE!r}, script=False)
errors = []
def stepper():
    try:
        for _ in range(300):
            sim.step(1)
    except Exception as e:
        errors.append(e)
def meddler():
    try:
        for k in range(300):
            if k % 50 == 0:
                sim.push("A", impulse=0.05, angle=k)
            p = sim.positions
            assert p.shape == (2, 3) and np.isfinite(p).all()
            sim.result()
    except Exception as e:
        errors.append(e)
threads = [threading.Thread(target=f) for f in (stepper, stepper, meddler)]
for t in threads:
    t.start()
for t in threads:
    t.join()
print(sim.steps, errors)
"""
    child = run_python(code, timeout=300)
    assert child.returncode == 0, child.stderr
    assert child.stdout.split() == ["600", "[]"]


def test_threads_initialising_one_object_at_once_leave_one_scene():
    code = f"""
import threading
import tabletop
raw = tabletop.Simulation.__new__(tabletop.Simulation)
start = threading.Barrier(8)
outcomes = []
def init():
    start.wait()
    try:
        raw.__init__({SCENE!r}, script=False)
        outcomes.append("made")
    except RuntimeError as e:
        outcomes.append("refused" if "already initialised" in str(e) else repr(e))
threads = [threading.Thread(target=init) for _ in range(8)]
for t in threads:
    t.start()
for t in threads:
    t.join()
raw.step(3)
print(sorted(outcomes), raw.steps, raw.names)
"""
    child = run_python(code, timeout=120)
    assert child.returncode == 0, child.stderr
    assert child.stdout.strip() == str(["made"] + ["refused"] * 7) + " 3 ['A', 'B']"


def test_two_threads_rendering_first_do_not_deadlock():
    """Neither thread made an array before: NumPy's C API must already be looked up.

    Looked up lazily, this deadlocked the whole interpreter (the child then
    never answers: the timeout fails the test)."""
    code = """
import threading
import tabletop
sims = [tabletop.Simulation("scenarios/example2_two_cubes.json") for _ in range(2)]
start = threading.Barrier(2)
shapes = []
def render(sim):
    start.wait()
    shapes.append(sim.render(64, 48).shape)
threads = [threading.Thread(target=render, args=(s,), daemon=True) for s in sims]
for t in threads:
    t.start()
for t in threads:
    t.join(30)
print("hung" if any(t.is_alive() for t in threads) else shapes)
"""
    from conftest import SOURCE
    for _ in range(3):
        child = run_python(code, timeout=60, cwd=SOURCE)
        assert child.returncode == 0, child.stderr
        assert child.stdout.strip() == "[(48, 64, 3), (48, 64, 3)]"


def test_threads_on_separate_objects_give_the_sequential_results():
    paths = [SCENARIOS / "example2_two_cubes.json", SCENARIOS / "example3_stacked_cubes.json"]
    modes = ["bullet", "compat", "rules"]
    alone = {(p, m): tabletop.run(str(p), mode=m)["state_hash"] for p in paths for m in modes}
    together = {}

    def run(p, m):
        sim = tabletop.Simulation(str(p), mode=m)
        sim.run_to_end()
        together[(p, m)] = sim.result()["state_hash"]

    threads = [threading.Thread(target=run, args=key) for key in alone]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert together == alone


# Two layers of cubes and balls dropped onto the table, the upper one
# between the lower one's bodies, so that they land on one another in many
# islands.
HEAP = {"version": 1, "name": "heap",
        "settings": {"timestep": 1 / 60, "duration": 1.0, "end_at_rest": False},
        "entities": [{"name": f"E{i}", "shape": ["cube", "sphere"][i % 2], "size": 0.05, "mass": 0.2,
                      "position": [-0.45 + 0.1 * (i % 10) + 0.04 * (i // 30), 0.85 + 0.1 * (i // 30),
                                   -0.1 + 0.1 * ((i // 10) % 3) + 0.03 * (i // 30)]}
                     for i in range(60)]}


def test_threads_share_out_the_islands_and_change_no_bit():
    """Like --threads: any count gives the run one thread gives, to the bit; so does the default."""
    one = tabletop.run(HEAP, threads=1)
    for threads in (2, 3, None):
        assert tabletop.run(HEAP, threads=threads)["state_hash"] == one["state_hash"], threads
    with tabletop.Simulation(HEAP, threads=2) as sim:
        sim.run_to_end()
        two = sim.result()["state_hash"]
    assert two == one["state_hash"]


@pytest.mark.parametrize("threads", [0, 257, -1])
def test_a_thread_count_out_of_range_is_refused(threads):
    with pytest.raises(ValueError, match="threads"):
        tabletop.run(HEAP, threads=threads)
    with pytest.raises(ValueError, match="threads"):
        tabletop.Simulation(HEAP, threads=threads)


@pytest.mark.parametrize("value", ["0", "two", "2 ", "1e3", ""])
def test_a_bad_tabletop_threads_is_refused_by_name(value):
    code = f"""
import tabletop
try:
    tabletop.run({HEAP!r})
except ValueError as e:
    print(e)
"""
    import os
    child = run_python(code, env={**os.environ, "TABLETOP_THREADS": value})
    assert child.returncode == 0, child.stderr
    assert "TABLETOP_THREADS: expected a whole number from 1 to 256" in child.stdout
