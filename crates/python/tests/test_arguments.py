"""Every bad argument of every public callable (issue 25, item 5): a
KreiselError for a bad value, a TypeError for a wrong type, and in both
cases a message that begins with the Python argument's name (never a CLI
flag such as `--i3`, never a bare `expected a sequence of length 3`, never
an OverflowError). Table-driven: each callable x each argument x bad
values; then one regression test per case the issue reported."""

import re
from pathlib import Path

import numpy as np
import pytest

import kreisel

NAN, INF = float("nan"), float("inf")
HUGE = 10**400  # an int no float, i64 or u64 holds

TETRA_V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
TETRA_F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
SCENE = "[simulation]\nduration = 1.0\ndt = 0.5\n[[body]]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\nangular_velocity = [0.0, 0.0, 1.0]\n"
TOP = dict(i1=0.3, i3=0.1, mgl=2.0, theta0=0.5)

KE, TE = kreisel.KreiselError, TypeError

# Bad values shared by many arguments: (value, exception).
VEC3 = [((1.0, 2.0), KE), ((1.0, 2.0, 3.0, 4.0), KE), ([], KE), (5.0, TE), ("abc", TE),
        ((1.0, "x", 3.0), TE), ((1.0, HUGE, 3.0), KE), ({"a": 1}, TE)]  # fmt: skip
QUAT = [((1.0, 0.0, 0.0), KE), ((1.0, 0.0, 0.0, 0.0, 0.0), KE), (1.0, TE), ("wxyz", TE),
        ((1.0, None, 0.0, 0.0), TE)]  # fmt: skip
FLOAT = [("abc", TE), (HUGE, KE), ([1.0], TE)]  # None: the default of an optional one
POSITIVE = FLOAT + [(0.0, KE), (-1.0, KE), (NAN, KE), (INF, KE)]
FINITE = FLOAT + [(NAN, KE), (INF, KE)]
REQUIRED = [(None, TE)]
INDEX = [(-1, KE), (7, KE), (2**64, KE), (HUGE, KE), (1.0, TE), ("0", TE), (None, TE)]
COUNT = [(-1, KE), (2**64, KE), (-HUGE, KE), (1.5, TE), ("3", TE)]
BOOL = [("yes", TE), (None, TE)]
SEQ = [("ZZX", KE), ("", KE), (3, TE)]
FRAME = [("space", KE), (1, TE)]
ANGLES = [([1.0, 2.0], KE), ("abc", KE), ([NAN, 0.0, 0.0], KE), ([[1, 2, 3], [4, 5]], KE)]
QUATS = [([1.0, 0.0, 0.0], KE), ([0.0, 0.0, 0.0, 0.0], KE), ([NAN, 0.0, 0.0, 0.0], KE)]
PATH = [("", KE), (3, TE), (None, TE)]
UNITS = [("ft", KE), (3, TE)]
MODEL = [("foam", KE), (None, TE)]
WELD = [(-1.0, KE), ("sometimes", KE), (NAN, KE)]


def world():
    w = kreisel.World(0.01)
    w.add_body(1.0, moments=(1.0, 2.0, 3.0))
    return w


def spinning():
    w = kreisel.World(0.01)
    w.add_body(1.0, moments=(1.0, 2.0, 3.0), omega_body=(0.0, 0.0, 1.0))
    return w


def lagrange_top():
    return kreisel.LagrangeTop(**TOP, psi_dot0=60.0)


# Each public callable: (name, a call that succeeds as keywords, its
# arguments with their bad values). `make` returns the bound callable
# (methods need a fresh object).
CALLABLES = [
    ("from_euler", lambda: kreisel.from_euler, dict(seq="ZXZ", angles=[0.1, 0.2, 0.3]),
     dict(seq=SEQ, angles=ANGLES, degrees=BOOL)),
    ("as_euler", lambda: kreisel.as_euler, dict(seq="ZXZ", quats=[1.0, 0.0, 0.0, 0.0]),
     dict(seq=SEQ, quats=QUATS, degrees=BOOL)),
    ("convert", lambda: kreisel.convert, dict(values=[1.0, 0.0, 0.0, 0.0], src="quat", dst="rotvec"),
     dict(values=QUATS, src=[("quaternion", KE), (4, TE)], dst=[("euler:ZZX", KE), (None, TE)],
          degrees=BOOL)),
    ("rates_from_omega", lambda: kreisel.rates_from_omega,
     dict(seq="ZXZ", angles=[0.1, 0.5, 0.2], omega=[0.0, 0.0, 1.0]),
     dict(seq=SEQ, angles=ANGLES + [([0.1, 0.0, 0.2], KE)], omega=ANGLES, frame=FRAME, degrees=BOOL)),
    ("omega_from_rates", lambda: kreisel.omega_from_rates,
     dict(seq="ZXZ", angles=[0.1, 0.5, 0.2], rates=[0.0, 0.0, 1.0]),
     dict(seq=SEQ, angles=ANGLES, rates=ANGLES, frame=FRAME, degrees=BOOL)),
    ("omega_from_attitudes", lambda: kreisel.omega_from_attitudes,
     dict(quats=[[1.0, 0.0, 0.0, 0.0], [1.0, 0.1, 0.0, 0.0]], t=0.1),
     dict(quats=QUATS + [([[1.0, 0.0, 0.0, 0.0]], KE)], t=[(0.0, KE), (-1.0, KE), ([0.0], KE),
          ([1.0, 0.0], KE), ("abc", KE)], frame=FRAME)),
    ("mass_properties", lambda: kreisel.mass_properties, dict(path="tetra.obj"),
     dict(path=PATH, density=POSITIVE, mass=POSITIVE, units=UNITS, model=MODEL,
          thickness=POSITIVE, weld=WELD, merge=BOOL, scale=POSITIVE)),
    ("mass_properties_from_arrays", lambda: kreisel.mass_properties_from_arrays,
     dict(vertices=TETRA_V, faces=TETRA_F),
     dict(vertices=[(TETRA_V[:, :2], KE), ("abc", KE), (None, KE)],
          faces=[(TETRA_F + 1, KE), (-TETRA_F, KE), (TETRA_F.astype(float), KE), (TETRA_F[:, :2], KE),
                 (TETRA_F.astype(np.uint64) + np.uint64(2**63), KE)],
          density=POSITIVE, mass=POSITIVE, units=UNITS, model=MODEL, thickness=POSITIVE,
          weld=WELD, name=[(5, TE)], scale=POSITIVE)),
    ("simulate", lambda: kreisel.simulate, dict(scene=SCENE),
     dict(scene=PATH + [(b"[simulation]\n", TE)], method=[("euler", KE), (3, TE)],
          threads=COUNT + [(0, KE)], events=BOOL)),
    ("World", lambda: kreisel.World, dict(dt=0.01),
     dict(dt=POSITIVE + REQUIRED, gravity=VEC3 + [((0.0, NAN, 0.0), KE)], method=[("euler", KE), (3, TE)])),
    ("World.add_body", lambda: kreisel.World(0.01).add_body, dict(mass=1.0, moments=(1.0, 2.0, 3.0)),
     dict(mass=POSITIVE + REQUIRED, moments=VEC3 + [((1.0, -2.0, 3.0), KE)], attitude=QUAT + [((0.0,) * 4, KE)],
          omega_body=VEC3 + [((NAN, 0.0, 0.0), KE)], position=VEC3 + [((INF, 0.0, 0.0), KE)],
          velocity=VEC3 + [((NAN, 0.0, 0.0), KE)], pivot=VEC3 + [((NAN, 0.0, 0.0), KE)],
          torque=VEC3 + [((NAN, 0.0, 0.0), KE)], torque_body=VEC3 + [((INF, 0.0, 0.0), KE)],
          force=VEC3 + [((NAN, 0.0, 0.0), KE)], angular_damping=FINITE + [(-1.0, KE)])),
    ("World.add_body(inertia)", lambda: kreisel.World(0.01).add_body,
     dict(mass=1.0, inertia=np.diag([1.0, 2.0, 3.0])),
     dict(inertia=[(np.eye(2), KE), ([[1.0, 0.0, 0.0], [0.0, 1.0]], KE), ([1.0, 2.0, 3.0], TE),
                   ("eye", TE), (-np.eye(3), KE), ([[1, 0, 0], [0, 1, 0], [0, 0, "x"]], TE)])),
    ("World.set_inputs", lambda: world().set_inputs, dict(body=0),
     dict(body=INDEX, torque=VEC3, torque_body=VEC3, force=VEC3 + [((NAN, 0.0, 0.0), KE)],
          angular_damping=FINITE)),
    ("World.set_rotation", lambda: world().set_rotation,
     dict(body=0, attitude=(1.0, 0.0, 0.0, 0.0), omega_body=(0.0, 0.0, 1.0)),
     dict(body=INDEX, attitude=QUAT, omega_body=VEC3)),
    ("World.step", lambda: world().step, dict(h=0.01), dict(h=POSITIVE + REQUIRED)),
    ("World.advance_steps", lambda: world().advance_steps, dict(n=3), dict(n=COUNT)),
    ("World.advance_to", lambda: world().advance_to, dict(t=0.5), dict(t=FINITE + REQUIRED + [(-1.0, KE)])),
    ("World.states", lambda: world().states, {}, {}),
    ("World.plan", lambda: world().plan, dict(body=0), dict(body=INDEX)),
    ("World.state", lambda: world().state, dict(body=0), dict(body=INDEX)),
    ("World.events", lambda: world().events, dict(body=0), dict(body=INDEX)),
    ("World.add_body(contacts)", lambda: kreisel.World(0.01, gravity=(0.0, 0.0, -9.81)).add_body,
     dict(mass=1.0, moments=(0.004, 0.004, 0.004), contacts=[dict(shape="sphere", radius=0.1, mu=0.3)]),
     dict(contacts=[("sphere", TE), ([], KE), ([1.0], TE), ([dict(shape="sphere", radius=0.1)], KE),
                    ([dict(shape="sphere", radius=-0.1, mu=0.3)], KE), ([dict(shape=3, mu=0.3)], TE)])),
    ("top", lambda: kreisel.top, TOP,
     dict(i1=POSITIVE + REQUIRED, i3=FINITE + REQUIRED + [(0.7, KE), (-0.1, KE)], mgl=FINITE + REQUIRED,
          theta0=FINITE + REQUIRED,
          theta_dot0=FINITE, phi_dot0=FINITE, psi_dot0=FINITE)),
    ("LagrangeTop", lambda: kreisel.LagrangeTop, TOP,
     dict(i1=POSITIVE + REQUIRED, i3=FINITE + [(0.7, KE)], mgl=FINITE, theta0=FINITE + REQUIRED,
          theta_dot0=FINITE,
          phi_dot0=FINITE, psi_dot0=FINITE)),
    ("LagrangeTop.euler_at", lambda: lagrange_top().euler_at, dict(t=[0.0, 1.0]),
     dict(t=[([0.0, NAN], KE), ("soon", KE), (None, KE), ([[1.0], [2.0, 3.0]], KE)])),
    ("LagrangeTop.world_from_body_at", lambda: lagrange_top().world_from_body_at, dict(t=0.5),
     dict(t=[(INF, KE), ("soon", KE)])),
    ("LagrangeTop.omega_body_at", lambda: lagrange_top().omega_body_at, dict(t=0.5),
     dict(t=[(-INF, KE), ({}, KE)])),
    ("stability", lambda: kreisel.stability, dict(world=spinning(), body=0),
     dict(world=[(None, TE), (3, TE)], body=INDEX)),
    ("stability_map", lambda: kreisel.stability_map, dict(world=spinning(), body=0, sweeps={"spin": (0.5, 1.0, 2)}),
     dict(world=[(None, TE)], body=INDEX, threads=COUNT + [(0, KE)],
          sweeps=[([("spin", (0.5, 1.0, 2))], TE), ({"spin": (0.5, 1.0)}, KE), ({"spin": (0.5, NAN, 2)}, KE),
                  ({"spin": ("a", 1.0, 2)}, TE), ({"spin": (0.5, 1.0, 2.5)}, TE), ({3: (0.5, 1.0, 2)}, TE)],
          executor=[(3, TE), ("pool", TE)])),
]  # fmt: skip

CASES = [
    pytest.param(make, good, argument, value, kind, id=f"{name}-{argument}-{k}")
    for name, make, good, bad in CALLABLES
    for argument, values in bad.items()
    for k, (value, kind) in enumerate(values)
]


def names_the_argument(message, argument):
    """The message begins with the argument's name (`threads: …`,
    `faces[3, 2] = …`, `moments must be …`)."""
    name = re.escape(argument)
    return re.match(rf"(argument '{name}': |{name}\b(?![-_]))", message) is not None


@pytest.fixture(autouse=True)
def in_fixtures(tmp_path, monkeypatch):
    # mass_properties' good call needs a mesh file: a tetrahedron.
    monkeypatch.chdir(tmp_path)
    (tmp_path / "tetra.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n")


def test_the_good_calls_succeed():
    for _, make, good, _ in CALLABLES:
        make()(**good)


@pytest.mark.parametrize("make,good,argument,value,kind", CASES)
def test_every_bad_argument_is_named(make, good, argument, value, kind):
    with pytest.raises(Exception) as e:
        make()(**{**good, argument: value})
    message = str(e.value)
    assert type(e.value) is kind, f"{type(e.value).__name__}: {message}"
    assert names_the_argument(message, argument), message
    assert "--" not in message, message
    assert "\n" not in message


def test_the_table_covers_every_public_callable():
    # A new function or method must be added to CALLABLES.
    public = {n for n in dir(kreisel) if not n.startswith("_") and callable(getattr(kreisel, n))}
    listed = {name.split(".")[0].split("(")[0] for name, *_ in CALLABLES}
    assert public - {"KreiselError"} == listed
    for cls in [kreisel.World, kreisel.LagrangeTop]:
        methods = {n for n in dir(cls) if not n.startswith("_") and callable(getattr(cls, n))}
        covered = {name.split(".")[1].split("(")[0] for name, *_ in CALLABLES if name.startswith(cls.__name__ + ".")}
        assert methods == covered, cls


# --- one regression test per case the issue reported


@pytest.mark.parametrize(
    "keyword", ["moments", "omega_body", "position", "velocity", "pivot", "torque", "torque_body", "force"]
)
def test_add_body_short_sequence_names_the_argument(keyword):
    # Was: ValueError: expected a sequence of length 3 (got 2)
    extra = {} if keyword == "moments" else {"moments": (1.0, 2.0, 3.0)}
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.World(0.01).add_body(1.0, **extra, **{keyword: (1.0, 2.0)})
    assert str(e.value) == f"{keyword}: expected a sequence of 3 numbers, got 2 items"


def test_add_body_short_attitude_names_the_argument():
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.World(0.01).add_body(1.0, moments=(1.0, 2.0, 3.0), attitude=(1.0, 0.0, 0.0))
    assert str(e.value) == "attitude: expected a sequence of 4 numbers, got 3 items"


def test_simulate_negative_threads():
    # Was: OverflowError: can't convert negative int to unsigned
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.simulate(SCENE, threads=-1)
    assert str(e.value) == f"threads: -1 is out of range (an integer from 1 to {2**64 - 1})"


def test_advance_steps_negative():
    with pytest.raises(kreisel.KreiselError) as e:
        world().advance_steps(-1)
    assert str(e.value) == f"n: -1 is out of range (an integer from 0 to {2**64 - 1})"


def test_state_negative_body():
    with pytest.raises(kreisel.KreiselError) as e:
        world().state(-1)
    assert str(e.value) == "body: no body -1 in this world (it has 1 body: 0 to 0)"
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.World(0.01).state(0)
    assert str(e.value) == "body: no body 0 in this world (it has no bodies)"


def test_faces_uint64_beyond_i64_keeps_its_value():
    # Was: faces[3, 2] = -9223372036854775808 is not a vertex index
    faces = TETRA_F.astype(np.uint64)
    faces[3, 2] = 2**63
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.mass_properties_from_arrays(TETRA_V, faces)
    assert str(e.value) == (
        "faces must be an (M, 3) array of integer vertex indices: "
        "faces[3, 2] = 9223372036854775808 is not a vertex index (0 <= index < 4)"
    )
    faces[3, 2] = 2**64 - 1
    with pytest.raises(kreisel.KreiselError, match=r"faces\[3, 2\] = 18446744073709551615 "):
        kreisel.mass_properties_from_arrays(TETRA_V, faces)


def test_empty_paths():
    # Was: cannot read scene file : No such file or directory (os error 2)
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.simulate("")
    assert str(e.value) == "scene: path is empty"
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.mass_properties("")
    assert str(e.value) == "path: path is empty"


def test_top_names_the_python_argument_not_the_flag():
    # Was: --i3: 0.7: exceeds 2 i1: …
    for make in [kreisel.top, kreisel.LagrangeTop]:
        with pytest.raises(kreisel.KreiselError) as e:
            make(0.3, 0.7, 2.0, 0.5)
        assert str(e.value).startswith("i3: 0.7: exceeds 2 i1")
        with pytest.raises(kreisel.KreiselError) as e:
            make(0.3, 0.1, 2.0, 0.5, theta_dot0=NAN)
        assert str(e.value) == "theta_dot0: NaN is not a finite number"


# --- the CLI's advice, worded with the Python keywords (typed variants of
# the CLI's error, rebuilt in the Python layer)

FIXTURES = Path(__file__).resolve().parents[3] / "crates" / "inertia" / "tests" / "fixtures"


def test_cracks_advise_the_weld_keyword():
    path = FIXTURES / "closed_in_practice" / "near_duplicates.stl"
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.mass_properties(path, weld="off")
    assert str(e.value).endswith("; rerun with weld=2e-8 to close them")


def test_open_bodies_closed_together_advise_merge(tmp_path):
    path = tmp_path / "halves.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\no a\nf 1 3 2\nf 1 2 4\nf 1 4 3\no b\nf 2 3 4\n")
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.mass_properties(path)
    assert str(e.value).endswith("rerun with merge=True to treat them as one solid")
    assert kreisel.mass_properties(path, merge=True)["volume"] == pytest.approx(1 / 6, rel=1e-15)


def test_open_mesh_advises_model_keywords():
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.mass_properties_from_arrays(TETRA_V, TETRA_F[:3])
    assert str(e.value).endswith(
        'if the surface is open on purpose, model="shell" models a thin-walled part '
        '(see thickness) and model="hull" a convex one'
    )


def test_mesh_out_of_range_advises_units_or_scale():
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.mass_properties_from_arrays(TETRA_V, TETRA_F, scale=1e200)
    assert str(e.value).endswith("(set with units or scale, metres per mesh unit)")


def test_derived_density_names_mass():
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.mass_properties_from_arrays(TETRA_V, TETRA_F, mass=1e300, scale=1e-30)
    assert str(e.value).startswith("mass: <arrays>: total volume ")
    assert str(e.value).endswith("gives no finite positive density for mass 1e300 kg")


def test_a_method_that_cannot_move_a_pivot():
    # The scene's own method: the scene's line names the key; the argument's:
    # the message names the argument.
    scene = SCENE.replace("[simulation]\n", '[simulation]\nmethod = "dmv"\n') + "pivot = [0.0, 0.0, -0.1]\n"
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.simulate(scene)
    assert str(e.value).startswith("<string>:2: `method`: method `dmv` cannot move a body with a `pivot`")
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.simulate(scene.replace('method = "dmv"\n', ""), method="dmv")
    assert str(e.value).startswith("method: method `dmv` cannot move a body with a `pivot`")


def test_numpy_values_are_accepted_where_python_ones_are():
    # numpy arrays as sequences, numpy scalars as numbers and integers.
    w = kreisel.World(np.float32(0.5), gravity=np.zeros(3))
    b = w.add_body(np.float64(2.0), inertia=np.diag([1.0, 2.0, 3.0]), omega_body=np.array([0.0, 0.0, 1.0]),
                   attitude=np.array([2.0, 0.0, 0.0, 0.0]))  # fmt: skip
    w.set_inputs(np.int64(b), torque=np.zeros(3, np.float32), angular_damping=np.float32(0.0))
    w.advance_steps(np.uint64(4))
    s = w.state(np.int32(b))
    assert s["time"] == 2.0 and s["energy"] == 1.5  # 3 * 1^2 / 2, torque-free
    assert kreisel.simulate(SCENE, threads=np.int64(1))["t"].tolist() == [0.0, 0.5, 1.0]
    assert kreisel.top(np.float32(0.25), 0.125, 2, 0.5)["i1"] == 0.25
