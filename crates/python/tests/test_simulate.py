"""kreisel.simulate bit for bit against `kreisel simulate` (the CSV), and the
World object API against closed forms and against the same scene run by
the CLI's pipeline; every error path."""

import csv
import io
import math
import os

import numpy as np
import pytest

import kreisel
import kreisel_cli_runner as cli

REPO = cli.REPO
SCENES = sorted((REPO / "examples" / "scenes").glob("*.toml"))
ALL_COLUMNS = "t,body,qw,qx,qy,qz,wx,wy,wz,energy,lx,ly,lz,x,y,z,vx,vy,vz".split(",")


def cli_csv(*args):
    """The columns `kreisel simulate ARGS` writes, as lists of str."""
    done = cli.run("simulate", *args)
    assert done.returncode == 0, done.stderr
    rows = list(csv.reader(io.StringIO(done.stdout)))
    header, rows = rows[0], rows[1:]
    return {name: [r[k] for r in rows] for k, name in enumerate(header)}


def assert_same_as_csv(columns, result):
    assert list(result) == ALL_COLUMNS
    assert set(columns) <= set(result)
    n = len(columns["t"])
    for name, text in columns.items():
        value = result[name]
        assert value.shape == (n,), name
        if name == "body":
            assert value.tolist() == text
        else:
            # The CSV's shortest round-trip digits parse back to the same bits.
            expected = np.array([float(x) for x in text])
            assert value.dtype == np.float64
            assert np.array_equal(value, expected), name


@pytest.mark.parametrize("scene", SCENES, ids=lambda p: p.name)
def test_example_scenes_bit_for_bit(scene):
    done = cli.run("simulate", scene, "--columns", ",".join(ALL_COLUMNS))
    if done.returncode != 0:
        # A scene that stops at a contact event (the tippe top's stem ball
        # touching down): Python raises the CLI's one line.
        with pytest.raises(kreisel.KreiselError) as e:
            kreisel.simulate(scene)
        assert str(e.value) == cli.error_line("simulate", scene)
        assert "touches down at t = " in str(e.value)
        return
    columns = cli_csv(scene, "--columns", ",".join(ALL_COLUMNS))
    assert_same_as_csv(columns, kreisel.simulate(scene))
    assert_same_as_csv(columns, kreisel.simulate(str(scene), threads=1))


def test_default_csv_columns_are_the_first_thirteen():
    columns = cli_csv(SCENES[0])
    assert list(columns) == ALL_COLUMNS[:13]
    assert_same_as_csv(columns, kreisel.simulate(SCENES[0]))


SCENE = """\
[simulation]
duration = 0.5
dt = 0.01
output_interval = 0.05
gravity = [0.0, 0.0, -9.81]

[[body]]
name = "handle"
mass = 1.0
inertia = [1.0, 2.0, 3.0]
angular_velocity = [0.01, 1.0, 0.0]
position = [1.0, 2.0, 3.0]
velocity = [0.5, 0.0, 4.0]

[[body]]
name = "tensor"
mass = 2.0
inertia_tensor = [[2.0, 0.1, 0.0], [0.1, 3.0, 0.2], [0.0, 0.2, 4.0]]
euler = { sequence = "ZXZ", angles = [0.1, 0.2, 0.3] }
angular_velocity = [1.0, -2.0, 0.5]

[[body]]
name = "top"
mass = 0.5
inertia = [0.02, 0.02, 0.01]
orientation = [0.99, 0.14, 0.0, 0.0]
angular_velocity = [0.0, 0.0, 50.0]
pivot = [0.0, 0.0, -0.05]

[[body]]
name = "driven"
mass = 3.0
inertia = [0.3, 0.4, 0.5]
angular_velocity = [0.2, 0.1, 3.0]
torque = [0.0, 0.1, 0.0]
torque_body = [0.01, 0.0, 0.0]
force = [1.0, 0.0, 0.0]
angular_damping = 0.02
"""


@pytest.mark.parametrize("method", [None, "strang", "splitting4"])
def test_scene_text_and_method_override(tmp_path, method):
    path = tmp_path / "scene.toml"
    path.write_text(SCENE)
    args = ["--columns", ",".join(ALL_COLUMNS)] + (["--method", method] if method else [])
    columns = cli_csv(path, *args)
    assert_same_as_csv(columns, kreisel.simulate(SCENE, method=method))
    assert_same_as_csv(columns, kreisel.simulate(path, method=method))
    assert set(columns["body"]) == {"handle", "tensor", "top", "driven"}


def test_free_fall_is_exact():
    # x(t) = x0 + v0 t + g t^2 / 2 at every row (independent closed form).
    r = kreisel.simulate(SCENE)
    sel = r["body"] == "handle"
    t = r["t"][sel]
    z = 3.0 + 4.0 * t - 0.5 * 9.81 * t**2
    assert np.allclose(r["z"][sel], z, rtol=0, atol=1e-14)
    assert np.allclose(r["x"][sel], 1.0 + 0.5 * t, rtol=0, atol=1e-15)
    # Torque-free: |L| and the rotational energy are constant.
    # (to the rounding of turning L into world axes at each row: a few ulp)
    l = np.hypot(np.hypot(r["lx"][sel], r["ly"][sel]), r["lz"][sel])
    assert np.ptp(l) <= 1e-14 * l[0]


# --- errors: the CLI's one line


def test_missing_scene_file(tmp_path):
    missing = tmp_path / "nope.toml"
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.simulate(missing)
    assert str(e.value) == cli.error_line("simulate", missing)


@pytest.mark.parametrize(
    "edit",
    [
        ("dt = 0.01", "dt = -0.01"),
        ("dt = 0.01", "dt = \"fast\""),
        ("mass = 1.0", "mass = 1.0\nmass = 2.0"),
        ("inertia = [1.0, 2.0, 3.0]", "inertia = [1.0, 2.0, 30.0]"),
        ("name = \"top\"", "name = \"handle\""),
        ("name = \"top\"", "name = \"a,b\""),
        ("[[body]]\nname = \"handle\"", "[[body]]\nname = \"handle\"\nspin = 3"),
        ("output_interval = 0.05", "output_interval = 0.015"),
        ("duration = 0.5", "duration = 1e300"),
        ("angular_velocity = [0.0, 0.0, 50.0]", "angular_velocity = [0.0, 0.0, 1e300]"),
        ("inertia = [0.3, 0.4, 0.5]", "mesh = \"missing.stl\"\ndensity = 1.0"),
        ("[simulation]", "[simulation]\nmethod = \"euler\""),
        ("[simulation]", "[simulation]\nmethod = \"dmv\""),
        ("[simulation]", "[simulation]\ntolerance = -1"),
        (SCENE, "[simulation]\nduration = 1\ndt = 0.1\n"),
        (SCENE, "not toml ["),
        (SCENE, "\n"),
    ],
)
def test_bad_scenes_have_the_cli_message(tmp_path, edit):
    old, new = edit
    assert old in SCENE
    text = SCENE.replace(old, new, 1)
    path = tmp_path / "bad.toml"
    path.write_text(text)
    expected = cli.error_line("simulate", path)
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.simulate(path)
    assert str(e.value) == expected
    if "\n" in text:
        with pytest.raises(kreisel.KreiselError) as e:
            kreisel.simulate(text)
        assert str(e.value) == expected.replace(str(path), "<string>")


def method_line(*args):
    """The CLI's error line, but naming the `method` argument where the CLI
    names its option `--method`."""
    line = cli.error_line(*args)
    return "method: " + line[len("--method: ") :] if line.startswith("--method: ") else line


def test_unknown_method_and_divergence(tmp_path):
    path = tmp_path / "scene.toml"
    path.write_text(SCENE)
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.simulate(path, method="euler")
    assert str(e.value) == method_line("simulate", path, "--method", "euler")
    # rk4 cannot move the driven body; dmv has no heavy-top version.
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.simulate(SCENE, method="rk4")
    assert str(e.value) == method_line("simulate", path, "--method", "rk4").replace(str(path), "<string>")
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.simulate(path, method="dmv")
    assert str(e.value) == method_line("simulate", path, "--method", "dmv")
    fast = tmp_path / "fast.toml"
    fast.write_text(
        "[simulation]\nduration = 1\ndt = 0.1\n[[body]]\nmass = 1\n"
        "inertia = [1, 2, 3]\nangular_velocity = [1e4, 1e2, 0]\n"
    )
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.simulate(fast, method="rk4")
    assert "diverged" in str(e.value)
    assert str(e.value) == cli.error_line("simulate", fast, "--method", "rk4", "--output", tmp_path / "o.csv")


def test_garbage_arguments():
    for bad in [3, None, b"[simulation]\n", ["a"]]:
        with pytest.raises((kreisel.KreiselError, TypeError)):
            kreisel.simulate(bad)
    with pytest.raises(kreisel.KreiselError, match="^threads: 0 is out of range"):
        kreisel.simulate(SCENE, threads=0)
    with pytest.raises(kreisel.KreiselError, match="^threads: -1 is out of range"):
        kreisel.simulate(SCENE, threads=-1)
    with pytest.raises(kreisel.KreiselError):
        kreisel.simulate("\x00\n")


# --- the World object API


def rotation_quat(axis, angle):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    return np.concatenate([[math.cos(angle / 2)], math.sin(angle / 2) * axis])


def quat_mul(a, b):
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    return np.array([
        w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
        w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
        w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
        w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
    ])  # fmt: skip


def quat_rotate(q, v):
    return quat_mul(quat_mul(q, np.concatenate([[0.0], v])), q * [1, -1, -1, -1])[1:]


def test_free_symmetric_body_closed_form():
    # I1 = I2: R(t) = Rot(L, |L| t / I1) R0 Rot(e3, w3 (I1 - I3) / I1 t).
    i1, i3 = 1.0, 2.0
    omega = np.array([0.3, -0.2, 1.0])
    q0 = rotation_quat([1.0, 2.0, 3.0], 0.7)
    world = kreisel.World(dt=0.01)
    b = world.add_body(5.0, moments=(i1, i1, i3), attitude=q0, omega_body=omega)
    l_world = quat_rotate(q0, np.array([i1, i1, i3]) * omega)
    assert np.allclose(world.state(b)["l_world"], l_world, rtol=0, atol=1e-15)
    for t in [0.1, 1.0, 12.5, 100.0]:
        world.advance_to(t)
        s = world.state(b)
        assert s["time"] == t
        q = quat_mul(
            quat_mul(rotation_quat(l_world, np.linalg.norm(l_world) * t / i1), q0),
            rotation_quat([0, 0, 1], omega[2] * (i1 - i3) / i1 * t),
        )
        q = q if np.dot(q, s["attitude"]) > 0 else -q
        assert np.abs(s["attitude"] - q).max() < 1e-13 * max(1.0, t), t
        assert np.allclose(s["l_world"], l_world, rtol=0, atol=1e-14)
        assert math.isclose(s["energy"], 0.5 * np.dot([i1, i1, i3], omega**2), rel_tol=1e-15)


def test_world_matches_the_scene_run_bit_for_bit():
    # The scene's bodies built through the object API and moved along the
    # CLI's schedule give the very numbers kreisel.simulate gives.
    euler = 'euler = { sequence = "ZXZ", angles = [0.1, 0.2, 0.3] }'
    rows = kreisel.simulate(SCENE.replace(euler, "orientation = [0.9, 0.1, 0.2, 0.3]"))
    world = kreisel.World(dt=0.01, gravity=(0.0, 0.0, -9.81))
    world.add_body(1.0, moments=(1.0, 2.0, 3.0), omega_body=(0.01, 1.0, 0.0),
                   position=(1.0, 2.0, 3.0), velocity=(0.5, 0.0, 4.0))  # fmt: skip
    world.add_body(2.0, inertia=[[2.0, 0.1, 0.0], [0.1, 3.0, 0.2], [0.0, 0.2, 4.0]],
                   attitude=(0.9, 0.1, 0.2, 0.3), omega_body=(1.0, -2.0, 0.5))  # fmt: skip
    world.add_body(0.5, moments=(0.02, 0.02, 0.01), attitude=(0.99, 0.14, 0.0, 0.0),
                   omega_body=(0.0, 0.0, 50.0), pivot=(0.0, 0.0, -0.05))  # fmt: skip
    world.add_body(3.0, moments=(0.3, 0.4, 0.5), omega_body=(0.2, 0.1, 3.0),
                   torque=(0.0, 0.1, 0.0), torque_body=(0.01, 0.0, 0.0),
                   force=(1.0, 0.0, 0.0), angular_damping=0.02)  # fmt: skip
    assert len(world) == 4
    names = ["attitude", "omega_body", "energy", "l_world", "position", "velocity"]
    columns = [("qw", "qx", "qy", "qz"), ("wx", "wy", "wz"), ("energy",), ("lx", "ly", "lz"),
               ("x", "y", "z"), ("vx", "vy", "vz")]  # fmt: skip
    n = 4
    for k, t in enumerate(rows["t"][::n]):
        if k > 0:
            if k < 10:
                world.advance_steps(5)  # output_interval = 5 dt
            else:
                world.advance_steps(4)
                world.advance_to(0.5)
        s = world.states()
        assert s["time"] == t
        for name, cols in zip(names, columns):
            expected = np.array([rows[c][k * n : k * n + n] for c in cols]).T
            assert np.array_equal(s[name].reshape(n, -1), expected.reshape(n, -1)), (t, name)


def test_torque_on_a_sphere_closed_form():
    # L(t) = L0 + tau t for a sphere with a world torque (exact kicks):
    # with a dyadic dt every kick is exact, so L is exactly L0 + tau t.
    world = kreisel.World(dt=1.0 / 64.0)
    b = world.add_body(1.0, moments=(2.0, 2.0, 2.0), omega_body=(0.0, 0.0, 1.0))
    assert world.plan(b).startswith("free sphere: exact, one uniform rotation")
    world.set_inputs(b, torque=(0.0, 0.0, 0.5))
    world.advance_to(2.0)
    assert np.array_equal(world.state(b)["l_world"], [0.0, 0.0, 2.0 + 1.0])
    # The same torque given when the body is added.
    other = kreisel.World(dt=1.0 / 64.0)
    c = other.add_body(1.0, moments=(2.0, 2.0, 2.0), omega_body=(0.0, 0.0, 1.0), torque=(0.0, 0.0, 0.5))
    other.advance_to(2.0)
    assert np.array_equal(other.state(c)["l_world"], [0.0, 0.0, 3.0])
    world.set_inputs(b)  # off again
    world.step(0.5)
    s = world.state(b)
    assert math.isclose(s["time"], 2.5) and np.allclose(s["l_world"], [0, 0, 3.0], atol=1e-12)
    assert world.plan(b).startswith("free sphere: exact, one uniform rotation")
    world.set_rotation(b, (1.0, 0.0, 0.0, 0.0), (1.0, 0.0, 0.0))
    assert np.array_equal(world.state(b)["l_world"], [2.0, 0.0, 0.0])


def test_heavy_top_energy_and_pivot():
    world = kreisel.World(dt=1e-3, gravity=(0.0, 0.0, -9.81), method="rk4")
    b = world.add_body(0.5, moments=(0.02, 0.02, 0.01), attitude=(0.99, 0.14, 0.0, 0.0),
                       omega_body=(0.0, 0.0, 50.0), pivot=(0.0, 0.0, -0.05), position=(0, 0, 1))  # fmt: skip
    e0 = world.state(b)["energy"]
    world.advance_to(1.0)
    s = world.state(b)
    assert abs(s["energy"] - e0) < 1e-9 * abs(e0)
    # The centre of mass stays 5 cm from the pivot at (0, 0, 1).
    assert math.isclose(np.linalg.norm(s["position"] - [0, 0, 1]), 0.05, rel_tol=1e-12)


@pytest.mark.parametrize(
    "make,fragment",
    [
        (lambda: kreisel.World(dt=0.0), "step size must be positive"),
        (lambda: kreisel.World(dt=float("nan")), "dt: nan is not a finite number"),
        (lambda: kreisel.World(dt=0.1, method="euler"), "euler"),
        (lambda: kreisel.World(dt=0.1, gravity=(0, 0, float("inf"))), "gravity"),
        (lambda: kreisel.World(dt=0.1).add_body(1.0, moments=(1, 1, 3)), "inequality"),
        (lambda: kreisel.World(dt=0.1).add_body(-1.0, moments=(1, 1, 1)), "mass"),
        (lambda: kreisel.World(dt=0.1).add_body(1.0), "give exactly one of"),
        (lambda: kreisel.World(dt=0.1).add_body(1.0, moments=(1, 1, 1), inertia=np.eye(3)), "exactly one"),
        (lambda: kreisel.World(dt=0.1).add_body(1.0, inertia=-np.eye(3)), "inertia"),
        (lambda: kreisel.World(dt=0.1).add_body(1.0, moments=(1, 1, 1), attitude=(0, 0, 0, 0)), "quaternion"),
        (lambda: kreisel.World(dt=0.1).add_body(1.0, moments=(1, 1, 1), omega_body=(np.nan, 0, 0)), "finite"),
        (lambda: kreisel.World(dt=0.1).add_body(1.0, moments=(1, 1, 1), pivot=(0, 0, 1), velocity=(1, 0, 0)), "pivot is fixed"),
        (lambda: kreisel.World(dt=0.1).add_body(1.0, moments=(1, 1, 1), angular_damping=-1.0), "damping"),
        (lambda: kreisel.World(dt=0.1, method="dmv").add_body(1.0, moments=(1, 2, 3), torque=(1, 0, 0)), "dmv"),
        (lambda: kreisel.World(dt=0.1).state(0), "no body 0"),
        (lambda: kreisel.World(dt=0.1).set_inputs(3, torque=(1, 0, 0)), "no body 3"),
        (lambda: kreisel.World(dt=0.1).step(-1.0), "step"),
        (lambda: kreisel.World(dt=0.1).advance_to(float("nan")), "t: nan is not a finite number"),
        (lambda: kreisel.World(dt=0.1).advance_to(-1.0), "t: cannot advance the world"),
    ],
)
def test_world_errors(make, fragment):
    with pytest.raises(kreisel.KreiselError) as e:
        world = make()
        # Some are refused only when the world moves.
        if isinstance(world, int):
            raise AssertionError("accepted")
    assert fragment.lower() in str(e.value).lower(), str(e.value)
    assert "\n" not in str(e.value)


def test_world_refuses_to_go_back_and_keeps_its_state():
    world = kreisel.World(dt=0.1)
    b = world.add_body(1.0, moments=(1.0, 2.0, 3.0), omega_body=(0.1, 1.0, 0.0))
    world.advance_to(1.0)
    before = world.state(b)
    with pytest.raises(kreisel.KreiselError):
        world.advance_to(0.5)
    after = world.state(b)
    assert after["time"] == 1.0 and np.array_equal(before["attitude"], after["attitude"])
    for bad in [lambda: world.add_body(1.0, moments="abc"), lambda: world.step("x"), lambda: world.state(-1)]:
        with pytest.raises((TypeError, ValueError, OverflowError)):
            bad()
    assert "bodies=1" in repr(world)
    assert np.array_equal(world.gravity, [0.0, 0.0, 0.0]) and world.dt == 0.1


def test_mutated_scenes_never_panic():
    # Numbers of the scene replaced by extreme ones, lines dropped: a result
    # or a KreiselError, never a panic caught by the guard.
    import re

    rng = np.random.default_rng(17)
    numbers = list(re.finditer(r"-?\d+\.\d+(e-?\d+)?", SCENE))
    lines = SCENE.splitlines()
    extremes = ["0.0", "-1.0", "1e300", "-1e300", "1e-300", "nan", "inf", "5e-324", "1e9", "3"]
    for k in range(150):
        if k % 2:
            m = numbers[int(rng.integers(len(numbers)))]
            text = SCENE[: m.start()] + str(rng.choice(extremes)) + SCENE[m.end():]
        else:
            keep = rng.random(len(lines)) > 0.1
            text = "\n".join(l for l, kept in zip(lines, keep) if kept) + "\n"
        text = text.replace("duration = 0.5", "duration = 0.05")
        for method in [None, "rk4", "strang"]:
            try:
                kreisel.simulate(text, method=method)
            except kreisel.KreiselError as e:
                assert "internal error" not in str(e) and "\n" not in str(e), (text, str(e))


def test_mesh_bodies_relative_to_the_scene_or_the_working_directory(tmp_path, monkeypatch):
    # A scene file finds its mesh relative to its folder (as the CLI); a
    # scene given as text, relative to the working directory.
    mesh = REPO / "assets" / "t_handle.obj"
    body = ('[simulation]\nduration = 0.2\ndt = 0.01\n[[body]]\nname = "handle"\n'
            'mesh = "{}"\ndensity = 2700.0\nangular_velocity = [0.1, 3.0, 0.2]\n')  # fmt: skip
    (tmp_path / "assets").mkdir()
    (tmp_path / "assets" / "t_handle.obj").write_bytes(mesh.read_bytes())
    path = tmp_path / "scene.toml"
    path.write_text(body.format("assets/t_handle.obj"))
    columns = cli_csv(path, "--columns", ",".join(ALL_COLUMNS))
    assert_same_as_csv(columns, kreisel.simulate(path))
    monkeypatch.chdir(REPO)
    assert_same_as_csv(columns, kreisel.simulate(body.format("assets/t_handle.obj")))
    monkeypatch.chdir(tmp_path / "assets")
    with pytest.raises(kreisel.KreiselError, match="t_handle.obj"):
        kreisel.simulate(body.format("assets/t_handle.obj"))


def test_the_world_moves_on_another_thread():
    # The engine's World is Send + Sync: a World made here can be stepped by
    # another thread (its moves release the GIL), with the same numbers.
    import threading

    def make():
        w = kreisel.World(0.01)
        w.add_body(1.0, moments=(1.0, 2.0, 3.0), omega_body=(0.01, 1.0, 0.0))
        return w

    here, there = make(), make()
    here.advance_to(5.0)
    thread = threading.Thread(target=there.advance_to, args=(5.0,))
    thread.start()
    thread.join()
    assert there.time == here.time
    for key, value in here.state(0).items():
        assert np.array_equal(there.state(0)[key], value), key


@pytest.mark.skipif(not hasattr(os, "symlink") or not os.path.exists("/dev/zero"), reason="no /dev/zero")
def test_an_endless_scene_file_is_refused_at_its_size_limit(tmp_path):
    # Regression: kreisel.simulate read the scene with no limit, so a link
    # to /dev/zero took memory until the process was killed.
    link = tmp_path / "zero.toml"
    os.symlink("/dev/zero", link)
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.simulate(link)
    assert "larger than 64 MiB" in str(e.value)
    assert str(e.value) == cli.error_line("simulate", link)
