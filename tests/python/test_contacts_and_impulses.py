"""Contacts and impulses from Python against closed forms, over shapes,
sizes, masses and rates: a resting body's contact impulses carry its weight
(sum of normal impulses = m g dt), an impulse J at a point r from the centre
of mass gives v = J/m and w = I^-1 (r x J), and on a frictionless table the
body then glides and turns at those rates."""
import math

import numpy as np
import pytest

import tabletop

G = 9.81
RATES = [30, 60, 240]
BOXES = [(1.0, [0.1, 0.1, 0.1]), (3.0, [0.3, 0.1, 0.2]), (0.2, [0.05, 0.2, 0.08])]


def one_box(size, mass, rate, friction, yaw=0.0):
    return {"version": 1, "name": "one box", "table": {"size": [2, 2], "material": {"friction": friction}},
            "settings": {"timestep": 1 / rate, "duration": 5},
            "entities": [{"name": "A", "shape": "box", "size": size, "mass": mass, "position": [0.1, -0.2],
                          "yaw": yaw, "material": {"friction": friction}}]}


def box_inertia(mass, size):
    a, b, c = size
    return mass / 12 * np.array([b * b + c * c, a * a + c * c, a * a + b * b])


@pytest.mark.parametrize("rate", RATES)
@pytest.mark.parametrize("mass,size", BOXES)
def test_a_resting_box_touches_the_table_at_its_corners_and_its_impulses_carry_its_weight(mass, size, rate):
    sim = tabletop.Simulation(one_box(size, mass, rate, 0.5), script=False)
    sim.step(5)
    contacts = sim.contacts
    centre = sim.positions[0]
    assert len(contacts) == 4
    for c in contacts:
        assert (c.a, c.b) == ("A", "table")
        assert c.normal == pytest.approx((0, 1, 0), abs=1e-12)
        assert abs(c.depth) < 1e-5  # m
        assert c.point[1] == pytest.approx(0.75, abs=1e-5)  # the table top, m
        # At a bottom corner: half the width and depth from the centre,
        # within the micrometres a body settles by in its first steps.
        assert abs(c.point[0] - centre[0]) == pytest.approx(size[0] / 2, abs=1e-5)
        assert abs(c.point[2] - centre[2]) == pytest.approx(size[2] / 2, abs=1e-5)
    # The weight over one step, N s, within 1e-4 relative.
    assert sum(c.impulse for c in contacts) == pytest.approx(mass * G / rate, rel=1e-4)


def test_a_stacked_cubes_contact_normal_points_from_b_to_a():
    sim = tabletop.Simulation("example3_stacked_cubes", script=False)
    sim.step(3)
    positions = dict(zip(sim.names, sim.positions))
    between = [c for c in sim.contacts if c.b in positions]
    assert between
    for c in between:
        assert np.dot(c.normal, positions[c.a] - positions[c.b]) > 0
    assert tabletop.Simulation("example3_stacked_cubes", mode="rules").contacts == []


@pytest.mark.parametrize("rate", RATES)
@pytest.mark.parametrize("mass,size", BOXES)
@pytest.mark.parametrize("arm,speed", [([0.1, 0, 0], [0, 0, 0.4]), ([0, 0, -0.03], [0.3, 0, 0.2]),
                                       ([0.02, 0, 0.01], [-0.3, 0, 0.1])])
def test_an_impulse_at_a_point_on_a_frictionless_table_glides_and_spins_as_the_closed_form(mass, size, rate, arm,
                                                                                            speed):
    sim = tabletop.Simulation(one_box(size, mass, rate, 0.0), script=False)
    start = sim.positions[0].copy()
    j, r = mass * np.array(speed), np.array(arm)  # N s: at most 0.4 m/s, so it stays on the table for 1 s
    sim.push("A", impulse=j, point=start + r)
    v, w = j / mass, np.cross(r, j) / box_inertia(mass, size)
    assert sim.velocities[0] == pytest.approx(v, abs=1e-12)
    assert sim.angular_velocities[0] == pytest.approx(w, abs=1e-12)
    sim.step(rate)  # 1 s
    t = sim.time
    assert sim.positions[0] == pytest.approx(start + v * t, abs=1e-7)  # m
    q = sim.orientations[0]
    turned = 2 * math.atan2(q[2], q[0])  # about +Y, rad
    assert math.remainder(turned - w[1] * t, 2 * math.pi) == pytest.approx(0, abs=1e-9)


@pytest.mark.parametrize("rate", RATES)
def test_a_vertical_impulse_throws_a_box_up_and_it_lands_where_it_left(rate):
    mass, size = 0.5, [0.1, 0.06, 0.1]
    sim = tabletop.Simulation(one_box(size, mass, rate, 0.5), script=False)
    start = sim.positions[0].copy()
    v = 1.2  # m/s up
    sim.push(0, impulse=[0, mass * v, 0])
    assert sim.velocities[0] == pytest.approx([0, v, 0], abs=1e-12)
    flight = 2 * v / G
    apex = 0.0
    while sim.time < flight - 1.5 / rate:
        sim.step()
        t = sim.time
        assert sim.positions[0][1] == pytest.approx(start[1] + v * t - G * t * t / 2, abs=1e-7)  # m
        apex = max(apex, sim.positions[0][1] - start[1])
    assert apex <= v * v / (2 * G) + 1e-9
    sim.step(2 * rate)
    assert sim.positions[0] == pytest.approx(start, abs=1e-5)


@pytest.mark.parametrize("mode", ["compat", "rules"])
def test_the_report_modes_take_only_the_reports_push(mode):
    sim = tabletop.Simulation("example2_two_cubes", mode=mode, script=False)
    for kwargs in [{"impulse": [0, 0.1, 0]}, {"impulse": [0.1, 0, 0], "point": [0, 0.8, 0]}]:
        with pytest.raises(ValueError, match="report 3.5"):
            sim.push("A", **kwargs)


def test_impulse_arguments_are_checked():
    sim = tabletop.Simulation("example2_two_cubes", script=False)
    for kwargs, error, words in [
        ({"impulse": [1, 2]}, TypeError, "expected 3 numbers"),
        ({"impulse": "abc"}, TypeError, "expected 3 numbers"),
        ({"impulse": [0, math.nan, 0]}, ValueError, r"impulse\[1\]"),
        ({"impulse": [2e6, 0, 0]}, ValueError, r"impulse\[0\]"),
        ({"impulse": [1, 0, 0], "point": [0, 1e9, 0]}, ValueError, r"point\[1\]"),
        ({"impulse": 0.1, "point": [0, 0, 0]}, ValueError, "as a vector"),
        ({"impulse": [1, 0, 0], "angle": 3}, ValueError, "no 'face' or 'angle'"),
    ]:
        with pytest.raises(error, match=words):
            sim.push("A", **kwargs)
    assert sim.velocities.any() == False  # noqa: E712 (nothing changed)


def slide(mode, rate, friction=0.3):
    return {"version": 1, "name": "slide", "table": {"size": [3, 1], "material": {"friction": friction}},
            "settings": {"timestep": 1 / rate, "duration": 30},
            "entities": [{"name": "A", "shape": "cube", "size": 0.1, "mass": 2.0, "position": [-1.2, 0.0],
                          "material": {"friction": 1.0}}]}  # combined with the table's: mu = friction


@pytest.mark.parametrize("rate", RATES)
@pytest.mark.parametrize("g", [1.62, 3.71, 9.81, 24.79])
def test_gravity_set_between_steps_sets_how_far_a_push_slides(g, rate):
    """d = v0^2 / (2 mu g), with the gravity set after the scene was built."""
    sim = tabletop.Simulation(slide("bullet", rate), script=False)
    sim.step(3)
    sim.gravity = g
    assert sim.gravity == g
    start = sim.positions[0, 0]
    v0 = 0.8
    sim.push("A", impulse=2.0 * v0)
    sim.step(int(2 * v0 / (0.3 * g) * rate) + 2 * rate)
    assert sim.positions[0, 0] - start == pytest.approx(v0 * v0 / (2 * 0.3 * g), abs=1e-4)  # m


@pytest.mark.parametrize("first,second", [(30, 240), (240, 60), (60, 1000)])
def test_a_timestep_set_mid_flight_goes_on_along_the_same_parabola(first, second):
    """A ball thrown across the room: x = x0 + v t, y = y0 + u t - g t^2 / 2 at
    every step, across the change of rate; the clock counts the new steps."""
    scene = {"version": 1, "name": "throw", "settings": {"timestep": 1 / first, "duration": 5},
             "entities": [{"name": "A", "shape": "sphere", "size": 0.05, "mass": 1.0, "position": [0, 3, 0],
                           "velocity": [0.5, 2.0, 0]}]}
    sim = tabletop.Simulation(scene, script=False)
    sim.step(first // 10)
    t1 = sim.time
    sim.timestep = 1 / second
    for n in range(1, second // 5):
        sim.step()
        assert sim.time == t1 + n * (1 / second)
        t = sim.time
        assert sim.positions[0] == pytest.approx([0.5 * t, 3 + 2 * t - G * t * t / 2, 0], abs=1e-9)  # m


def test_settings_set_between_steps_are_refused_out_of_range_and_kept_by_states():
    sim = tabletop.Simulation(slide("bullet", 60), script=False)
    for name, value, error in [("timestep", 0.0, ValueError), ("timestep", 1.0, ValueError),
                               ("gravity", -1.0, ValueError), ("gravity", math.nan, ValueError),
                               ("gravity", "9.81", TypeError)]:
        with pytest.raises(error):
            setattr(sim, name, value)
    assert (sim.timestep, sim.gravity) == (1 / 60, 9.81)
    sim.gravity = 3.71
    sim.timestep = 1 / 120
    sim.push(0, impulse=1.0)
    sim.step(10)
    saved = sim.get_state()
    sim.step(10)
    sim.gravity = 9.81
    sim.set_state(saved)
    assert (sim.timestep, sim.gravity) == (1 / 120, 3.71)
    assert sim.result()["state_hash"] == saved.state_hash
    sim.reset()
    assert (sim.timestep, sim.gravity, sim.steps) == (1 / 60, 9.81, 0)


def struck(size, mass, rate, yaw, push):
    scene = one_box(size, mass, rate, 0.0, yaw)
    scene["script"] = [{"t": 0, "push": push}]
    return scene


def turn(yaw_degrees):
    """Body to world about +Y by the yaw (x' = x cos + z sin, z' = -x sin + z cos)."""
    c, s = math.cos(math.radians(yaw_degrees)), math.sin(math.radians(yaw_degrees))
    return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])


@pytest.mark.parametrize("rate", RATES)
@pytest.mark.parametrize("mass,size", BOXES)
@pytest.mark.parametrize("yaw", [0.0, 30.0, -75.0])
@pytest.mark.parametrize("push", [{"direction": "Left", "impulse": 0.3, "at": [-0.5, 0.0, 0.4]},
                                  {"angle": 120.0, "impulse": 0.2, "at": [0.2, 0.3, -0.4]},
                                  {"direction": "Front", "impulse": 0.25, "at": [0.45, -0.2, 0.5]}])
def test_a_scripted_push_at_a_point_sets_the_body_spinning_as_the_closed_form(mass, size, rate, yaw, push):
    """A push with "at" (a point in the body's frame, here given as shares of the half sizes) on a frictionless
    table: v = J/m along the arrow, w = I_world^-1 (r x J) with r turned by the yaw."""
    half = np.array(size) / 2
    push = dict(push, entity="A", at=list(np.array(push["at"]) * half))
    sim = tabletop.Simulation(struck(size, mass, rate, yaw, push))
    angle = math.radians(push["angle"] if "angle" in push else {"Left": 0, "Front": 90}[push["direction"]] + yaw)
    j = push["impulse"] * np.array([math.cos(angle), 0.0, -math.sin(angle)])
    rotation = turn(yaw)
    r = rotation @ np.array(push["at"])
    inertia_world = rotation @ np.diag(box_inertia(mass, size)) @ rotation.T
    assert sim.velocities[0] == pytest.approx(j / mass, abs=1e-12)
    assert sim.angular_velocities[0] == pytest.approx(np.linalg.solve(inertia_world, np.cross(r, j)), abs=1e-12)


@pytest.mark.parametrize("mode", ["compat", "rules"])
def test_the_report_modes_refuse_a_scripted_push_at_a_point_where_it_stands(mode):
    scene = struck([0.1, 0.1, 0.1], 1.0, 60, 0.0, {"entity": "A", "direction": "Left", "impulse": 0.2,
                                                     "at": [0, 0, 0.03]})
    with pytest.raises(tabletop.ScenarioError, match=r"/script/0.*report 3\.5"):
        tabletop.Simulation(scene, mode=mode).step(1)


def test_a_push_at_a_point_takes_an_impulse_not_a_step():
    scene = struck([0.1, 0.1, 0.1], 1.0, 60, 0.0, {"entity": "A", "direction": "Left", "step": 0.2,
                                                     "at": [0, 0, 0.03]})
    with pytest.raises(tabletop.ScenarioError, match=r"at /script/0/push/at: expected 'impulse' with 'at'"):
        tabletop.scene(scene)
