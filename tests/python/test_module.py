"""The Python module against the command line and the closed forms."""
import json
import math
import subprocess
import sys

import numpy as np
import pytest

import tabletop
from conftest import SCENARIOS, shipped_scenarios

G = 9.81


def cube_scene(friction=0.5, shape="cube", size=0.1, on="table"):
    return {
        "version": 1,
        "name": "py",
        "entities": [
            {"name": "A", "shape": shape, "size": size, "mass": 1.0, "position": [0.0, 0.0], "on": on,
             "material": {"friction": friction}},
        ],
    }


@pytest.mark.parametrize("path", shipped_scenarios(), ids=lambda p: p.stem)
def test_run_matches_the_command_line(path, tabletop_bin):
    """run() is the run in `tabletop run --json`'s document: the same entities, events and state hash."""
    cli = json.loads(subprocess.run([tabletop_bin, "run", "--json", str(path)], capture_output=True, text=True,
                                    check=False).stdout)["runs"][0]
    ours = tabletop.run(str(path))
    assert ours["state_hash"] == cli["state_hash"]
    assert ours["complete"] == cli["complete"]
    assert ours["events"] == cli["events"]


@pytest.mark.parametrize("mode", ["bullet", "compat", "rules"])
def test_every_mode_matches_the_command_line(mode, tabletop_bin):
    path = SCENARIOS / "example3_stacked_cubes.json"
    cli = json.loads(subprocess.run([tabletop_bin, "run", "--json", "--mode", mode, str(path)],
                                    capture_output=True, text=True, check=True).stdout)["runs"][0]
    assert tabletop.run(path, mode=mode)["state_hash"] == cli["state_hash"]
    stepped = tabletop.Simulation(tabletop.load(str(path)), mode=mode)
    stepped.run_to_end()
    assert stepped.result()["state_hash"] == cli["state_hash"]


def test_overrides_are_the_command_lines(tabletop_bin):
    path = str(SCENARIOS / "example1_single_cube.json")
    cli = json.loads(subprocess.run([tabletop_bin, "run", "--json", "--timestep", "0.01", "--integrator", "euler",
                                     "--iterations", "20", path], capture_output=True, text=True, check=True).stdout)["runs"][0]
    ours = tabletop.run(path, timestep=0.01, integrator="euler", iterations=20)
    assert ours["state_hash"] == cli["state_hash"]
    assert ours["settings"] == cli["settings"]


@pytest.mark.parametrize("rate", [60, 240, 1000])
@pytest.mark.parametrize("impulse", [0.6, 1.5])
def test_a_push_by_impulse_slides_the_closed_form(rate, impulse):
    """d = v0^2 / (2 mu g): within 0.2 mm at 60 Hz, 0.02 mm from 240 Hz (the bench's sweep holds the rest)."""
    mu = 0.25
    sim = tabletop.Simulation(cube_scene(friction=mu), script=False, timestep=1.0 / rate)
    start = sim.positions[0].copy()
    sim.push("A", impulse=impulse, angle=0.0)
    sim.step(int(1.5 * rate))
    assert sim.at_rest
    travelled = sim.positions[0] - start
    expected = impulse ** 2 / (2 * mu * G)
    assert travelled[0] == pytest.approx(expected, abs=2e-4 if rate < 240 else 2e-5)
    assert abs(travelled[2]) < 1e-6
    assert np.allclose(sim.velocities, 0.0, atol=1e-6)


@pytest.mark.parametrize("mode", ["bullet", "compat", "rules"])
def test_a_push_by_step_travels_it_at_any_angle(mode):
    sim = tabletop.Simulation(cube_scene(friction=0.25), mode=mode, script=False, timestep=1.0 / 240)
    start = sim.positions[0].copy()
    sim.push("A", step=0.2, angle=30.0)
    sim.step(480)
    moved = sim.positions[0] - start
    assert math.hypot(moved[0], moved[2]) == pytest.approx(0.2, rel=0.005)
    assert math.degrees(math.atan2(-moved[2], moved[0])) == pytest.approx(30.0, abs=0.05)


def test_arrays_have_a_row_per_entity_in_scenario_order():
    sim = tabletop.Simulation(str(SCENARIOS / "example3_stacked_cubes.json"))
    n = len(sim.names)
    assert sim.names == tabletop.load(str(SCENARIOS / "example3_stacked_cubes.json")).entities
    assert sim.positions.shape == (n, 3) and sim.velocities.shape == (n, 3)
    assert sim.angular_velocities.shape == (n, 3) and sim.orientations.shape == (n, 4)
    assert np.allclose(np.linalg.norm(sim.orientations, axis=1), 1.0, atol=1e-12)
    before = sim.time
    sim.step(3)
    assert sim.time == pytest.approx(before + 3 * sim.timestep) and sim.steps == 3


def test_rotate_turns_an_entity_about_its_vertical_axis():
    sim = tabletop.Simulation(cube_scene(), script=False)
    sim.rotate("A", 90.0)
    w, x, y, z = sim.orientations[0]
    assert 2 * math.degrees(math.atan2(y, w)) == pytest.approx(90.0, abs=1e-9)


def test_without_numpy_the_import_says_what_to_install():
    """NumPy hidden (None in sys.modules makes its import fail): the module's ImportError names the package."""
    code = "import sys; sys.modules['numpy'] = None\ntry:\n    import tabletop\nexcept ImportError as e:\n    print(e)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert "tabletop needs NumPy" in out and "apt-get install python3-numpy" in out, out


def test_render_gives_an_rgb_image_of_the_scene():
    sim = tabletop.Simulation(str(SCENARIOS / "example2_two_cubes.json"))
    image = sim.render(160, 120, camera="corner")
    assert image.shape == (120, 160, 3) and image.dtype == np.uint8
    assert image.std() > 10  # a scene, not a blank frame
    with pytest.raises(ValueError, match="camera"):
        sim.render(160, 120, camera="nowhere")


def test_frames_of_one_size_in_a_loop_are_each_the_scene_as_it_is(tmp_path):
    """The kept context draws each frame anew: the same state gives the same pixels as a fresh object's
    frame, a changed state a different frame, and a frame of another size in between changes nothing."""
    first = tabletop.Simulation(str(SCENARIOS / "example2_two_cubes.json"))
    frames = [first.render(96, 72, camera="corner")]
    first.render(50, 40, camera="corner")
    for _ in range(3):
        first.step(30)
        frames.append(first.render(96, 72, camera="corner"))
    second = tabletop.Simulation(str(SCENARIOS / "example2_two_cubes.json"))
    second.step(90)
    assert np.array_equal(second.render(96, 72, camera="corner"), frames[-1])
    assert not np.array_equal(frames[0], frames[-1])  # cube A moved


@pytest.mark.parametrize("scene", ["example2_two_cubes", "example4_two_spheres"])
def test_a_fitted_camera_frames_the_whole_run_so_a_loop_of_frames_keeps_still(scene):
    """fit frames all the run reaches from its first frame on, as render does: between the first frame and the
    last no more pixels change than under a fixed preset camera (only the bodies'). fit:now frames the scene as
    it is, so it zooms as bodies leave."""
    def changed(camera):
        sim = tabletop.Simulation(scene)
        first = sim.render(160, 120, camera=camera).astype(int)
        sim.run_to_end()
        last = sim.render(160, 120, camera=camera).astype(int)
        return np.mean(np.any(first != last, axis=2))  # the share of pixels that changed
    still, fixed, moving = changed("fit"), changed("corner"), changed("fit:now")
    assert still <= 1.5 * fixed + 0.01
    assert moving > 2 * still


def test_write_png_saves_a_frame_whole_and_refuses_what_is_not_one(tmp_path, tabletop_bin):
    sim = tabletop.Simulation(str(SCENARIOS / "example2_two_cubes.json"))
    image = sim.render(64, 48, camera="corner")
    path = tmp_path / "frame.png"
    tabletop.write_png(image, str(path))
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["frame.png"]  # no temporary left
    with pytest.raises(TypeError, match="uint8"):
        tabletop.write_png(image.astype(np.float32), str(path))
    with pytest.raises(ValueError, match="shape"):
        tabletop.write_png(image[:, :, 0], str(path))
    with pytest.raises(OSError, match="write_png"):
        tabletop.write_png(image, str(tmp_path / "no-such-folder" / "f.png"))
    with pytest.raises(OSError, match="printable"):
        tabletop.write_png(image, str(tmp_path / "a\nb.png"))
    tabletop.write_png(np.ascontiguousarray(image[::-1]), str(path))  # any layout NumPy gives


def test_errors_carry_the_command_lines_located_message(tmp_path, tabletop_bin):
    bad = tmp_path / "bad.json"
    bad.write_text('{"version": 1, "name": "bad",\n "entities": [{"name": "A", "shape": "cube", "size": -1,'
                   ' "mass": 1, "position": [0, 0], "on": "table"}]}')
    cli = subprocess.run([tabletop_bin, "run", str(bad)], capture_output=True, text=True)
    assert cli.returncode == 2
    with pytest.raises(tabletop.ScenarioError) as raised:
        tabletop.load(str(bad))
    assert str(raised.value).strip() == cli.stderr.strip()
    assert ":2:" in str(raised.value) and "at /entities/0/size" in str(raised.value)
    with pytest.raises(tabletop.ScenarioError, match=r"^<scene>:\d+:\d+: at /entities/0/size"):
        tabletop.scene(cube_scene(size=-1))
    with pytest.raises(ValueError, match="mode: expected bullet, compat or rules, got 'nope'"):
        tabletop.run(cube_scene(), mode="nope")
    with pytest.raises(ValueError, match="exactly one of .step., .impulse."):
        tabletop.Simulation(cube_scene(), script=False).push("A")


def test_a_scene_built_from_objects_runs_like_its_file(tmp_path):
    scene = cube_scene()
    scene["script"] = [{"push": {"entity": "A", "angle": 0, "impulse": 1.0}}]
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(scene))
    assert tabletop.run(scene)["state_hash"] == tabletop.run(str(path))["state_hash"]


def test_every_function_has_a_docstring():
    for name in ["load", "scene", "run", "shipped_scenes", "Simulation", "Scenario", "ScenarioError",
                 "DivergenceError"]:
        assert getattr(tabletop, name).__doc__, name
    for name in ["step", "run_to_end", "push", "rotate", "render", "result", "positions", "orientations",
                 "velocities", "angular_velocities", "names", "time", "steps", "at_rest", "finished"]:
        assert getattr(tabletop.Simulation, name).__doc__, name


def test_the_library_pages_session_runs_as_shown(monkeypatch, tmp_path):
    """docs/library.md's Python session is a doctest: its outputs are what the module prints, from any folder."""
    import doctest
    import re

    from conftest import SOURCE
    page = (SOURCE / "docs" / "library.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", page, re.S)
    assert blocks, "docs/library.md shows no Python session"
    monkeypatch.chdir(tmp_path)
    parser = doctest.DocTestParser()
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    session = {}  # the page's blocks are one session
    for text in blocks:
        test = parser.get_doctest(text, session, "library", "docs/library.md", 0)
        runner.run(test, clear_globs=False)
        session = test.globs
    assert runner.summarize(verbose=False).failed == 0


def test_the_readmes_scene_runs():
    """The README's smallest scene is a scene the loader takes, and its push travels its step."""
    import json
    import re

    from conftest import SOURCE
    blocks = re.findall(r"```json\n(.*?)```", (SOURCE / "README.md").read_text(), re.S)
    assert blocks, "the README shows no scene"
    for text in blocks:
        sim = tabletop.Simulation(json.loads(text))
        start = sim.positions[0].copy()
        sim.run_to_end()
        assert abs(sim.positions[0, 0] - start[0] - 0.2) < 0.2 * 0.005   # the step, within 0.5%
