"""Depth and segmentation images beside RGB (render(depth=True,
segmentation=True)), against the scene's geometry: a face seen square on
lies at its distance along the view axis, each pixel names the body it
shows, and the three images are of one frame."""
import numpy as np
import pytest

import tabletop

TOP = 0.75  # the table top, m


def scene(size):
    return {"version": 1, "name": "look", "table": {"size": [2, 2]},
            "entities": [{"name": "A", "shape": "box", "size": size, "mass": 1, "position": [0.1, -0.1]},
                         {"name": "B", "shape": "sphere", "size": 0.05, "mass": 1, "position": [-0.5, 0.4]}]}


@pytest.mark.parametrize("size", [[0.4, 0.1, 0.4], [0.3, 0.25, 0.2]])
@pytest.mark.parametrize("distance", [0.3, 1.0, 2.0, 4.0])
@pytest.mark.parametrize("pixels", [(64, 48), (84, 84), (160, 120)])
def test_a_face_seen_square_on_lies_at_its_distance_and_names_its_body(size, distance, pixels):
    sim = tabletop.Simulation(scene(size), script=False)
    x, y, z = 0.1 - size[0] / 2, TOP + size[1] / 2, -0.1  # the centre of A's face towards -X, m
    camera = f"{x - distance},{y},{z}:{x},{y},{z}"  # level, square on to it
    w, h = pixels
    rgb, depth, labels = sim.render(w, h, camera=camera, arrow=False, depth=True, segmentation=True)
    assert rgb.shape == (h, w, 3) and depth.shape == labels.shape == (h, w)
    assert depth.dtype == np.float32 and labels.dtype == np.int32
    assert labels[h // 2, w // 2] == 0  # entity A, the first
    # Every pixel showing A's face is at its distance along the view axis,
    # within the depth buffer's resolution (2e-4 of the distance).
    on_face = (labels == 0) & (np.abs(depth - distance) < 0.5 * size[0])
    assert on_face[h // 2, w // 2]
    assert np.allclose(depth[on_face], distance, rtol=2e-4)


def test_each_body_is_labelled_and_nothing_is_infinitely_far():
    sim = tabletop.Simulation(scene([0.2, 0.1, 0.16]), script=False)
    rgb, depth, labels = sim.render(160, 120, camera="0,1.2,4:0,0.9,-10", depth=True, segmentation=True)
    assert set(np.unique(labels)) == {-3, -2, -1, 0, 1}  # ground, table, sky, A, B
    assert np.all(np.isinf(depth[labels == -1])) and np.all(np.isfinite(depth[labels != -1]))
    # The sky is above the horizon, the ground below it.
    assert labels[0, 80] == -1 and labels[-1, 80] == -3
    # Only the RGB frame without the flags, and the same frame with them.
    plain = sim.render(160, 120, camera="0,1.2,4:0,0.9,-10")
    assert np.array_equal(plain, rgb)
    only_labels = sim.render(160, 120, camera="0,1.2,4:0,0.9,-10", segmentation=True)
    assert len(only_labels) == 2 and np.array_equal(only_labels[1], labels)


def test_labels_follow_the_bodies_as_they_move():
    sim = tabletop.Simulation(scene([0.2, 0.1, 0.16]), script=False)
    camera = "0.1,3,-0.0999:0.1,0.85,-0.1"
    _, before = sim.render(96, 96, camera=camera, segmentation=True)
    sim.push("A", impulse=0.8, angle=0)
    sim.step(240)
    _, after = sim.render(96, 96, camera=camera, segmentation=True)
    moved = sim.positions[0, 0] - 0.1
    assert moved > 0.02
    columns = lambda labels: np.nonzero((labels == 0).any(axis=0))[0]  # noqa: E731
    # A's pixels moved towards +X, which this camera shows to the right.
    assert columns(after).mean() > columns(before).mean()
