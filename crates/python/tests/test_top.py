"""kreisel.top bit for bit against `kreisel top --format json`;
kreisel.LagrangeTop's motion against an independent integration of the
Euler-Lagrange equations (scipy, DOP853) and its own conserved quantities;
every error path."""

import json
import math

import numpy as np
import pytest

import kreisel
import kreisel_cli_runner as cli

KEYS = [
    "i1", "i3", "mgl", "theta0", "theta_dot0", "phi_dot0", "psi_dot0", "a", "b",
    "alpha", "beta", "omega3", "roots", "theta_min", "theta_max", "nutation_period",
    "mean_precession_rate", "motion", "sleeping", "sleeping_stable",
]  # fmt: skip

NAMES = ["i1", "i3", "mgl", "theta0", "theta_dot0", "phi_dot0", "psi_dot0"]
OPTIONS = ["--i1", "--i3", "--mgl", "--theta0", "--theta-dot0", "--phi-dot0", "--psi-dot0"]

CASES = [
    (0.3, 0.1, 2.0, 0.5, 0.0, 0.0, 60.0),  # cusps
    (1.0, 0.5, 1.0, 1.0, 0.0, -1.0, 8.0),  # the CLI's help example
    (1.0, 0.5, 1.0, 1.0, 0.0, 1.5, 8.0),  # loops
    (1.0, 0.5, 1.0, 1.0, 0.7, 0.4, 8.0),
    (0.02, 0.01, 0.05, 0.0, 0.0, 0.0, 300.0),  # sleeping, stable
    (0.02, 0.01, 0.05, 0.0, 0.0, 0.0, 1.0),  # sleeping, unstable
    (1.0, 2.0, 1.0, 2.5, 0.1, 0.0, 0.5),  # I3 = 2 I1, below the horizontal
    (1.0, 0.5, -1.0, 1.0, 0.0, 0.2, 3.0),  # centre of mass below the pivot
    (1.0, 0.5, 1.0, math.pi, 0.0, 0.0, 5.0),  # hanging straight down
    (1.0, 0.5, 0.0, 1.0, 0.3, 0.2, 5.0),  # no gravity
]


def cli_json(params):
    args = [f"{o}={v!r}" for o, v in zip(OPTIONS, params)]
    done = cli.run("top", *args, "--format", "json")
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


@pytest.mark.parametrize("params", CASES, ids=str)
def test_bit_for_bit_as_the_cli_json(params):
    expected = cli_json(params)
    value = kreisel.top(*params)
    assert list(value) == list(expected) == KEYS
    for key in KEYS:
        e, v = expected[key], value[key]
        if key == "roots":
            assert isinstance(v, np.ndarray) and np.array_equal(v, np.array(e, float)), key
        elif e is None:
            # JSON null: None (no nutation, no kind of motion) or a non-finite number.
            assert v is None or (isinstance(v, float) and not math.isfinite(v)), key
        elif isinstance(e, (bool, str)):
            assert v == e and type(v) is type(e), key
        else:
            assert isinstance(v, float) and v == float(e), (key, v, e)
    obj = kreisel.LagrangeTop(*params)
    assert list(obj.summary) == KEYS
    assert obj.summary["theta_min"] == value["theta_min"]
    assert kreisel.top(**dict(zip(NAMES, params)))["a"] == value["a"]


def lagrange_reference(params, times):
    """theta, phi, psi and their rates by integrating the Euler-Lagrange
    equations of L = I1/2 (th'^2 + ph'^2 sin^2 th) + I3/2 (ps' + ph' cos th)^2
    - mgl cos th with scipy's DOP853 (p_phi, p_psi conserved)."""
    from scipy import integrate
    i1, i3, mgl, th0, thd0, phd0, psd0 = params
    w3 = psd0 + phd0 * math.cos(th0)
    p_phi = i1 * phd0 * math.sin(th0) ** 2 + i3 * w3 * math.cos(th0)
    p_psi = i3 * w3

    def rates(th):
        phd = (p_phi - p_psi * np.cos(th)) / (i1 * np.sin(th) ** 2)
        return phd, w3 - phd * np.cos(th)

    def rhs(t, y):
        th, thd = y[0], y[1]
        phd, psd = rates(th)
        thdd = (i1 * phd**2 * math.sin(th) * math.cos(th) - i3 * w3 * phd * math.sin(th)
                + mgl * math.sin(th)) / i1  # fmt: skip
        return [thd, thdd, phd, psd]

    sol = integrate.solve_ivp(rhs, (0.0, times[-1]), [th0, thd0, 0.0, 0.0], method="DOP853",
                              t_eval=times, rtol=1e-13, atol=1e-14)  # fmt: skip
    assert sol.success
    th, thd, ph, ps = sol.y
    phd, psd = rates(th)
    return dict(theta=th, theta_dot=thd, phi=ph, psi=ps, phi_dot=phd, psi_dot=psd)


@pytest.mark.parametrize("params", [CASES[1], CASES[2], CASES[3], CASES[6], CASES[7]], ids=str)
def test_euler_at_against_an_integration(params):
    top = kreisel.LagrangeTop(*params)
    assert top.summary["theta_min"] > 0.05  # the reference's sin(theta) stays away from 0
    period = top.summary["nutation_period"]
    times = np.linspace(0.0, 3.0 * period, 301)
    e = top.euler_at(times)
    ref = lagrange_reference(params, times)
    for name in ["theta", "phi", "psi", "theta_dot", "phi_dot", "psi_dot"]:
        scale = max(1.0, np.abs(ref[name]).max())
        err = np.abs(e[name] - ref[name]).max() / scale
        assert err < 1e-9, (name, err)
    assert e["theta"][0] == params[3]
    assert np.all(e["theta"] >= top.summary["theta_min"] - 1e-15)
    assert np.all(e["theta"] <= top.summary["theta_max"] + 1e-15)


def quat_mul(a, b):
    w1, x1, y1, z1 = np.moveaxis(a, -1, 0)
    w2, x2, y2, z2 = np.moveaxis(b, -1, 0)
    return np.stack([
        w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
        w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
        w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
        w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
    ], axis=-1)  # fmt: skip


def axis_quat(axis, angle):
    z = np.zeros_like(angle)
    c, s = np.cos(angle / 2), np.sin(angle / 2)
    parts = [c, z, z, z]
    parts[1 + axis] = s
    return np.stack(parts, axis=-1)


def test_attitude_and_omega_follow_from_the_angles():
    top = kreisel.LagrangeTop(*CASES[3])
    t = np.linspace(0.0, 7.0, 24).reshape(2, 3, 4)
    e = top.euler_at(t)
    assert all(v.shape == (2, 3, 4) for v in e.values())
    q = top.world_from_body_at(t)
    w = top.omega_body_at(t)
    assert q.shape == (2, 3, 4, 4) and w.shape == (2, 3, 4, 3)
    expected = quat_mul(quat_mul(axis_quat(2, e["phi"]), axis_quat(0, e["theta"])), axis_quat(2, e["psi"]))
    sign = np.sign(np.sum(q * expected, axis=-1, keepdims=True))
    assert np.abs(q - sign * expected).max() < 1e-13
    st, ct = np.sin(e["theta"]), np.cos(e["theta"])
    sp, cp = np.sin(e["psi"]), np.cos(e["psi"])
    omega = np.stack([
        e["phi_dot"] * st * sp + e["theta_dot"] * cp,
        e["phi_dot"] * st * cp - e["theta_dot"] * sp,
        e["phi_dot"] * ct + e["psi_dot"],
    ], axis=-1)  # fmt: skip
    assert np.abs(w - omega).max() < 1e-12
    # The spin is constant and so is the energy I1/2 (th'^2 + ph'^2 sin^2) + I3/2 w3^2 + mgl cos th.
    assert np.abs(w[..., 2] - top.summary["omega3"]).max() < 1e-12
    i1, i3, mgl = CASES[3][:3]
    energy = 0.5 * i1 * (e["theta_dot"] ** 2 + (e["phi_dot"] * st) ** 2) + 0.5 * i3 * w[..., 2] ** 2 + mgl * ct
    assert np.ptp(energy) < 1e-12 * np.abs(energy).max()
    # Scalars and lists.
    assert top.euler_at(1.5)["theta"].shape == ()
    assert top.world_from_body_at(1.5).shape == (4,)
    assert top.euler_at([0.0, 1.0])["phi"].shape == (2,)
    assert np.array_equal(top.omega_body_at(np.float32(2.0)), top.omega_body_at(2.0))
    big = np.linspace(0.0, 100.0, 5000)  # evaluated without the GIL
    assert np.array_equal(top.euler_at(big)["theta"][[0, -1]], top.euler_at(big[[0, -1]])["theta"])


@pytest.mark.parametrize(
    "params,bad",
    [
        ((0.0, 0.1, 1.0, 0.5), 0),
        ((-1.0, 0.1, 1.0, 0.5), 0),
        ((float("nan"), 0.1, 1.0, 0.5), 0),
        ((1.0, 3.0, 1.0, 0.5), 1),
        ((1.0, -0.1, 1.0, 0.5), 1),
        ((1.0, 0.5, float("inf"), 0.5), 2),
        ((1.0, 0.5, 1.0, 4.0), 3),
        ((1.0, 0.5, 1.0, -0.1), 3),
        ((1.0, 0.5, 1.0, 0.5, float("nan")), 4),
        ((1.0, 0.5, 1.0, 0.5, 0.0, 1e308, 0.0), 5),
        ((1.0, 0.5, 1.0, 0.5, 0.0, 0.0, -float("inf")), 6),
    ],
)
def test_bad_parameters_have_the_cli_message(params, bad):
    args = [f"{o}={v!r}" for o, v in zip(OPTIONS, params)]
    line = cli.error_line("top", *args)
    # The CLI's line, naming the Python argument where it names the option.
    assert line.startswith(OPTIONS[bad] + ": ")
    expected = NAMES[bad] + line[len(OPTIONS[bad]) :]
    for make in [kreisel.top, kreisel.LagrangeTop]:
        with pytest.raises(kreisel.KreiselError) as e:
            make(*params)
        assert str(e.value) == expected


def test_bad_times_and_arguments():
    top = kreisel.LagrangeTop(*CASES[0])
    for bad in [[0.0, float("nan")], "soon", [[1.0], [2.0, 3.0]], None, float("inf")]:
        with pytest.raises(kreisel.KreiselError):
            top.euler_at(bad)
        with pytest.raises(kreisel.KreiselError):
            top.world_from_body_at(bad)
    with pytest.raises(TypeError):
        kreisel.top("a", 1, 1, 1)
    with pytest.raises(TypeError):
        kreisel.top(1.0, 0.5, 1.0)
    assert repr(top).startswith("LagrangeTop(i1=0.3")


def test_docstring_examples_of_this_part(monkeypatch):
    # The examples in the docstrings (mass, simulation, World, top) run and
    # print what they say; paths in them are relative to the repository.
    import doctest

    monkeypatch.chdir(cli.REPO)
    objects = [
        kreisel.mass_properties, kreisel.mass_properties_from_arrays, kreisel.simulate,
        kreisel.World, kreisel.World.add_body, kreisel.World.events, kreisel.top, kreisel.LagrangeTop,
    ]  # fmt: skip
    for obj in objects:
        assert ">>>" in obj.__doc__, obj
        finder = doctest.DocTestFinder(recurse=False)
        runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
        for test in finder.find(obj, obj.__name__, globs={}):
            runner.run(test)
        assert runner.failures == 0 and runner.tries > 0, obj


def test_extreme_parameters_never_panic():
    rng = np.random.default_rng(18)
    values = [0.0, -0.0, 1.0, -1.0, 0.5, 2.0, math.pi, 1e-300, 1e300, -1e300, 5e-324, 1e-8, 1e8, float("nan"), float("inf")]
    for _ in range(400):
        params = [float(rng.choice(values)) * (1.0 + 0.1 * rng.random()) for _ in range(7)]
        try:
            top = kreisel.LagrangeTop(*params)
            top.euler_at([0.0, 1.0, 1e6])
            top.world_from_body_at(1e-3)
            top.omega_body_at(123.4)
        except kreisel.KreiselError as e:
            assert "internal error" not in str(e) and "\n" not in str(e), (params, str(e))


def test_stubs_match_the_module():
    # Every function and method in __init__.pyi has the runtime's
    # parameter names, in order (pyo3's text signatures).
    import ast
    import inspect
    import pathlib

    stubs = pathlib.Path(kreisel.__file__).with_name("__init__.pyi")
    tree = ast.parse(stubs.read_text())
    checked = 0

    def names(fn):
        a = fn.args
        return [x.arg for x in a.posonlyargs + a.args + a.kwonlyargs if x.arg != "self"]

    def runtime(obj):
        return [p for p in inspect.signature(obj).parameters if p != "self"]

    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            assert names(node) == runtime(getattr(kreisel, node.name)), node.name
            checked += 1
        elif isinstance(node, ast.ClassDef):
            cls = getattr(kreisel, node.name)
            for item in node.body:
                if isinstance(item, ast.FunctionDef) and not any(
                    isinstance(d, ast.Name) and d.id == "property" for d in item.decorator_list
                ):
                    if item.name == "__init__":
                        assert names(item) == runtime(cls), node.name
                    elif item.name != "__len__":
                        assert names(item) == runtime(getattr(cls, item.name)), (node.name, item.name)
                    checked += 1
                elif isinstance(item, ast.FunctionDef):
                    assert isinstance(getattr(cls, item.name), property) or hasattr(cls, item.name)
    assert checked >= 15
