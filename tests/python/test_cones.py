"""Cones: a cylinder with a radius of 0 at one end. Checked against closed
forms over sizes and rates: a cone standing on its base rests with its
centroid h/4 above the table top, one lying on its side rests on its slant
line (its centroid 3h/4 sin(a) up, a its half angle), one dropped onto its
base lands there upright,
its image narrows to its point, and a cone of no radius at all is refused
where it stands."""
import math

import numpy as np
import pytest

import tabletop

TOP = 0.75  # the table top, m
RATES = [30, 60, 240]
CONES = [(0.03, 0.08), (0.05, 0.05), (0.1, 0.3)]  # base radius, height, m


def cone(radius, height, rate, y=None):
    entity = {"name": "K", "shape": "cylinder", "size": [radius, 0, height], "mass": 0.4, "position": [0.1, -0.2]}
    if y is not None:
        entity["position"] = [0.1, y, -0.2]
    return {"version": 1, "name": "cone", "settings": {"timestep": 1 / rate, "duration": 5}, "entities": [entity]}


@pytest.mark.parametrize("rate", RATES)
@pytest.mark.parametrize("radius,height", CONES)
def test_a_cone_on_its_base_rests_with_its_centroid_a_quarter_up(radius, height, rate):
    sim = tabletop.Simulation(cone(radius, height, rate), script=False)
    assert sim.positions[0, 1] == pytest.approx(TOP + height / 4, abs=1e-8)  # placed (seated 1 nm in), m
    sim.step(rate)  # 1 s
    assert sim.positions[0] == pytest.approx([0.1, TOP + height / 4, -0.2], abs=1e-5)  # m
    assert np.abs(sim.velocities[0]).max() < 1e-5  # m/s
    assert sim.orientations[0] == pytest.approx([1, 0, 0, 0], abs=1e-6)


@pytest.mark.parametrize("rate", RATES)
@pytest.mark.parametrize("radius,height", CONES)
def test_a_cone_lying_on_its_side_rests_on_its_slant_line(radius, height, rate):
    """Turned by 90 deg + a about z, its slant line lies level: the point and
    its rim's lowest point touch the table, the centroid 3h/4 sin(a) up."""
    a = math.atan(radius / height)
    scene = cone(radius, height, rate)
    scene["entities"][0]["orientation"] = {"axis": [0, 0, 1], "angle": 90 + math.degrees(a)}
    sim = tabletop.Simulation(scene, script=False)
    up = TOP + 0.75 * height * math.sin(a)
    assert sim.positions[0, 1] == pytest.approx(up, abs=1e-8)  # placed, m
    start = sim.orientations[0].copy()
    sim.step(rate)  # 1 s
    assert sim.positions[0] == pytest.approx([0.1, up, -0.2], abs=1e-5)  # m
    assert np.abs(sim.velocities[0]).max() < 1e-5  # m/s
    turn = 2 * math.acos(min(1.0, abs(float(np.dot(sim.orientations[0], start)))))
    assert turn * max(radius, height) < 1e-5  # its farthest point moved under 0.01 mm


@pytest.mark.parametrize("rate", RATES)
@pytest.mark.parametrize("radius,height", CONES)
def test_a_cone_dropped_on_its_base_lands_upright_a_quarter_up(radius, height, rate):
    sim = tabletop.Simulation(cone(radius, height, rate, TOP + height / 4 + 0.05), script=False)
    sim.step(2 * rate)
    assert sim.positions[0] == pytest.approx([0.1, TOP + height / 4, -0.2], abs=1e-4)  # m
    assert sim.orientations[0] == pytest.approx([1, 0, 0, 0], abs=1e-4)


def test_a_cone_narrows_to_its_point_in_the_image():
    radius, height = 0.1, 0.3
    sim = tabletop.Simulation(cone(radius, height, 60), script=False)
    y = TOP + height / 2
    _, labels = sim.render(120, 160, camera=f"0.1,{y},0.6:0.1,{y},-0.2", segmentation=True)
    rows = [np.count_nonzero(row == 0) for row in labels if np.any(row == 0)]
    assert len(rows) > 40
    assert rows[0] <= 3 and max(rows) > 20  # the point at the top, the base below
    # The slant widens all the way down (the last rows are the base's near rim, seen from above it).
    slant = rows[: int(0.8 * len(rows))]
    assert all(b >= a for a, b in zip(slant, slant[1:]))


@pytest.mark.parametrize("size,where,words", [
    ([0, 0, 0.1], "/entities/0/size", "expected a radius above 0 at one end"),
    ([0.0005, 0, 0.1], "/entities/0/size/0", "expected 0 \\(a cone's point\\) or"),
    ([0.05, 0, 0], "/entities/0/size/2", "expected a number from"),
    ([0.05, -0.01, 0.1], "/entities/0/size/1", "expected"),
])
def test_a_cylinder_without_a_radius_is_refused_where_it_stands(size, where, words):
    scene = cone(0.05, 0.1, 60)
    scene["entities"][0]["size"] = size
    with pytest.raises(tabletop.ScenarioError, match=f"at {where}: {words}"):
        tabletop.scene(scene)
