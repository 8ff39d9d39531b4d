"""kreisel.stability and kreisel.stability_map against the closed forms (the
sleeping top, the T-handle), the map's boundaries to 1e-12, the executor
path (concurrent.futures, dask.distributed) bit for bit against the default
threads, pickling, and every error path."""

import math
import pickle
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import kreisel

G = 9.81

# Symmetric tops on a pivot (mass kg, I1 = I2 and I3 about the centre of
# mass kg m^2, l m from the pivot to the centre of mass, above it).
TOPS = [
    (1.0, 0.02, 0.04, 0.1),
    (0.5, 0.002, 0.001, 0.05),
    (2.0, 0.3, 0.1, 0.4),
]


def sleeping(mass, i1, i3, l, spin, gravity=G):
    """A World with one top standing upright on its pivot, spinning at `spin`."""
    w = kreisel.World(dt=0.01, gravity=(0.0, 0.0, -gravity))
    b = w.add_body(mass, moments=(i1, i1, i3), omega_body=(0.0, 0.0, spin), pivot=(0.0, 0.0, -l))
    return w, b


def j1(mass, i1, l):
    """The transverse moment about the pivot."""
    return i1 + mass * l * l


def critical_spin(mass, i1, i3, l, gravity=G):
    """I3^2 w^2 = 4 J1 M g l."""
    return math.sqrt(4 * j1(mass, i1, l) * mass * gravity * l) / i3


def rel(a, b):
    return abs(a - b) / abs(b)


@pytest.mark.parametrize("top", TOPS)
@pytest.mark.parametrize("factor", [1.3, 2.0, 10.0])
def test_sleeping_top_above_the_threshold_is_stable_with_the_closed_form_frequencies(top, factor):
    mass, i1, i3, l = top
    spin = factor * critical_spin(*top)
    w, b = sleeping(*top, spin)
    s = kreisel.stability(w, b)
    assert s["kind"] == "sleeping top"
    assert s["verdict"] == "stable" and s["asymptotic"] is False
    assert "growth_rate" not in s and "reason" not in s
    assert s["parameters"] == {"spin": spin, "com_offset": pytest.approx(l, rel=1e-15), "gravity": G}
    assert s["frame"] in ("body", "space")
    n = len(s["state_names"])
    assert s["state"].dtype == np.float64 and s["state"].shape == (n,)
    ev = s["eigenvalues"]
    assert ev.dtype == np.complex128 and s["modes"].dtype == np.complex128
    assert s["modes"].shape == (len(ev), n)
    assert np.allclose(np.linalg.norm(s["modes"], axis=1), 1.0, rtol=0, atol=1e-14)
    assert len(ev) + len(s["zero_modes"]) == n
    assert ("Casimir", "|γ|²") in s["zero_modes"]
    assert all(isinstance(k, str) and isinstance(q, str) for k, q in s["zero_modes"])
    # Every eigenvalue on the imaginary axis; the precession frequencies in space.
    assert np.all(np.abs(ev.real) <= 1e-7 * np.abs(ev).max())
    root = math.sqrt((i3 * spin) ** 2 - 4 * j1(mass, i1, l) * mass * G * l)
    fast = (i3 * spin + root) / (2 * j1(mass, i1, l))
    slow = 2 * mass * G * l / (i3 * spin + root)  # = (I3 ω3 − root)/(2 J1), without the cancellation
    space = s["space_frequencies"]
    assert space.shape == ev.shape and not np.isnan(space).any()
    # Each frequency is one of the two, and each of the two is there, to
    # 1e-12 of the eigenvalues' scale (the fast one): the slow one is seen in
    # space as a difference of body-frame frequencies of the fast one's size
    # (measured: 1.5e-12 of itself, 3.9e-15 of the fast one, at 10 Ω_c).
    for f in space:
        assert min(abs(abs(f) - e) for e in (slow, fast)) < 1e-12 * fast
    for e in (slow, fast):
        assert min(abs(abs(f) - e) for f in space) < 1e-12 * fast
    assert rel(max(abs(space)), fast) < 1e-12


@pytest.mark.parametrize("top", TOPS)
@pytest.mark.parametrize("factor", [0.0, 0.3, 0.9])
def test_sleeping_top_below_the_threshold_grows_at_the_closed_form_rate(top, factor):
    mass, i1, i3, l = top
    spin = factor * critical_spin(*top)
    w, b = sleeping(*top, spin)
    s = kreisel.stability(w, b)
    assert s["verdict"] == "unstable"
    growth = math.sqrt(4 * j1(mass, i1, l) * mass * G * l - (i3 * spin) ** 2) / (2 * j1(mass, i1, l))
    assert rel(s["growth_rate"], growth) < 1e-12
    assert s["max_real_part"] == s["growth_rate"] == s["eigenvalues"].real.max()


def test_hanging_top_is_stable():
    mass, i1, i3, l = TOPS[0]
    w = kreisel.World(dt=0.01, gravity=(0.0, 0.0, -G))
    b = w.add_body(mass, moments=(i1, i1, i3), omega_body=(0, 0, 0.5), pivot=(0.0, 0.0, l))
    s = kreisel.stability(w, b)
    assert s["kind"] == "hanging top" and s["verdict"] == "stable"


@pytest.mark.parametrize(
    "moments, axis",
    [((1.0, 2.0, 3.0), 1), ((3.0, 1.0, 2.0), 2), ((0.5, 0.9, 0.7), 2), ((2.0, 5.0, 3.0), 2)],
)
@pytest.mark.parametrize("omega", [2.0, -0.7])
def test_t_handle_grows_at_the_closed_form_rate(moments, axis, omega):
    """A free body spinning about its intermediate axis: σ = ω √((I2 − I1)(I3 − I2)/(I1 I3))."""
    w = kreisel.World(dt=0.01)
    spin = [0.0, 0.0, 0.0]
    spin[axis] = omega
    b = w.add_body(1.0, moments=moments, omega_body=spin)
    s = kreisel.stability(w, b)
    i1, i2, i3 = sorted(moments)
    assert moments[axis] == i2
    assert s["kind"] == "free rotation about a principal axis"
    assert s["verdict"] == "unstable"
    growth = abs(omega) * math.sqrt((i2 - i1) * (i3 - i2) / (i1 * i3))
    assert rel(s["growth_rate"], growth) < 1e-12
    assert sorted(s["eigenvalues"].real) == pytest.approx([-growth, growth], rel=1e-12)
    assert np.isnan(s["space_frequencies"]).all()
    assert s["zero_modes"] == [("Casimir", "|L|²")]


@pytest.mark.parametrize("axis", [0, 2])
def test_spin_about_the_largest_or_smallest_axis_is_stable(axis):
    w = kreisel.World(dt=0.01)
    spin = [0.0, 0.0, 0.0]
    spin[axis] = 3.0
    s = kreisel.stability(w, w.add_body(1.0, moments=(1.0, 2.0, 3.0), omega_body=spin))
    assert s["verdict"] == "stable"
    # ω √((I_a − I_b)(I_a − I_c)/(I_b I_c)) about axis a
    others = [m for k, m in enumerate((1.0, 2.0, 3.0)) if k != axis]
    ia = (1.0, 2.0, 3.0)[axis]
    f = 3.0 * math.sqrt((ia - others[0]) * (ia - others[1]) / (others[0] * others[1]))
    assert sorted(np.abs(s["eigenvalues"].imag)) == pytest.approx([f, f], rel=1e-12)


def test_errors_are_the_library_s_one_line():
    w = kreisel.World(dt=0.01, gravity=(0, 0, -G))
    # A ball on the table with a drilling (Contensou) torque: its spin slows, nothing is steady.
    ball = w.add_body(1.0, moments=(0.002,) * 3,
                      contacts=[dict(shape="sphere", radius=0.1, mu=0.5, contensou_radius=1e-3)])
    with pytest.raises(kreisel.KreiselError, match=r"^no steady motion on the table: its contact law has a drilling torque"):
        kreisel.stability(w, ball)
    tumbling = w.add_body(1.0, moments=(1.0, 2.0, 3.0), omega_body=(1.0, 1.0, 1.0))
    with pytest.raises(ValueError, match=r"^no steady motion near this state: relative residual") as e:
        kreisel.stability(w, tumbling)
    assert "\n" not in str(e.value)
    with pytest.raises(kreisel.KreiselError, match=r"^body: no body 7 in this world \(it has 2 bodies: 0 to 1\)$"):
        kreisel.stability(w, 7)
    with pytest.raises(kreisel.KreiselError, match=r"^body: no body 7"):
        kreisel.stability_map(w, 7, {"spin": (0.0, 1.0, 3)})


# --- maps ---------------------------------------------------------------------


@pytest.mark.parametrize("top", TOPS)
def test_spin_map_boundary_is_the_closed_form_to_1e_12(top):
    crit = critical_spin(*top)
    w, b = sleeping(*top, 2 * crit)
    m = kreisel.stability_map(w, b, {"spin": (-3 * crit, 3 * crit, 14)})
    assert m["names"] == ["spin"] and m["kind"] == "sleeping top"
    spins = m["values"][0]
    assert spins.shape == (14,) and spins[0] == -3 * crit and spins[-1] == 3 * crit
    assert m["max_real_part"].shape == (14,) and m["verdict"].dtype == np.int8
    assert m["boundaries"].shape == (2, 1)
    assert list(m["boundary_axis"]) == [0, 0]
    for at, expected in zip(sorted(m["boundaries"][:, 0]), [-crit, crit]):
        assert rel(at, expected) < 1e-12
    assert np.all(m["boundary_width"] <= 4 * np.finfo(float).eps * crit * 1.01)
    assert m["closed_form"]["spin"] == pytest.approx([-crit, crit], rel=1e-14)
    # The grid: unstable (code 1) inside ±Ω_c at the closed-form rate, stable (0) outside.
    mass, i1, i3, l = top
    for spin, code, mrp in zip(spins, m["verdict"], m["max_real_part"]):
        if abs(spin) < crit:
            growth = math.sqrt(4 * j1(mass, i1, l) * mass * G * l - (i3 * spin) ** 2) / (2 * j1(mass, i1, l))
            assert code == 1 and rel(mrp, growth) < 1e-12
        else:
            assert code == 0 and abs(mrp) <= 1e-7 * abs(i3 * spin / j1(mass, i1, l))
    assert kreisel.VERDICT_CODES[0] == "stable" and kreisel.VERDICT_CODES[1] == "unstable"


def test_gravity_and_offset_map_boundaries_are_the_closed_form_to_1e_12():
    mass, i1, i3, l = TOPS[0]
    spin = 12.0
    w, b = sleeping(mass, i1, i3, l, spin)
    m = kreisel.stability_map(w, b, {"gravity": (0.5, 40.0, 9)})
    g_crit = (i3 * spin) ** 2 / (4 * j1(mass, i1, l) * mass * l)
    assert m["boundaries"].shape == (1, 1) and rel(m["boundaries"][0, 0], g_crit) < 1e-12
    m = kreisel.stability_map(w, b, {"com_offset": (0.01, 0.5, 9)})
    # 4 M^2 g l^3 + 4 I1 M g l − I3^2 Ω^2 = 0
    (l_crit,) = m["closed_form"]["com_offset"]
    assert abs(4 * mass**2 * G * l_crit**3 + 4 * i1 * mass * G * l_crit - (i3 * spin) ** 2) < 1e-12 * (i3 * spin) ** 2
    assert m["boundaries"].shape == (1, 1) and rel(m["boundaries"][0, 0], l_crit) < 1e-12


def two_parameter_map(**kw):
    mass, i1, i3, l = TOPS[0]
    w, b = sleeping(mass, i1, i3, l, 20.0)
    return kreisel.stability_map(w, b, {"spin": (2.0, 20.0, 7), "gravity": (1.0, 30.0, 5)}, **kw)


def test_two_parameter_map_shape_order_and_boundaries():
    mass, i1, i3, l = TOPS[0]
    m = two_parameter_map()
    spins, gs = m["values"]
    assert m["names"] == ["spin", "gravity"]
    assert m["max_real_part"].shape == (5, 7) and m["verdict"].shape == (5, 7)
    jj = j1(mass, i1, l)
    # max_real_part[j, i] is at (spin = values[0][i], gravity = values[1][j]).
    for j, g in enumerate(gs):
        for i, spin in enumerate(spins):
            under = 4 * jj * mass * g * l - (i3 * spin) ** 2
            if under > 0:
                assert m["verdict"][j, i] == 1
                assert rel(m["max_real_part"][j, i], math.sqrt(under) / (2 * jj)) < 1e-12
            else:
                assert m["verdict"][j, i] == 0
    # Every boundary point on I3^2 Ω^2 = 4 J1 M g l, in the parameter bisected.
    assert m["boundaries"].shape[1] == 2 and len(m["boundaries"]) >= 5
    for (spin, g), axis in zip(m["boundaries"], m["boundary_axis"]):
        if axis == 0:
            assert g in gs and rel(spin, critical_spin(mass, i1, i3, l, g)) < 1e-12
        else:
            assert spin in spins and rel(g, (i3 * spin) ** 2 / (4 * jj * mass * l)) < 1e-12
    assert set(m["boundary_axis"]) == {0, 1}


def same(a, b):
    """Bit for bit: every array's bytes, dtype and shape; every other value equal."""
    assert a.keys() == b.keys()
    for k in a:
        x, y = a[k], b[k]
        if k == "values":
            assert len(x) == len(y) and all(p.tobytes() == q.tobytes() for p, q in zip(x, y))
        elif k == "closed_form":
            assert x.keys() == y.keys() and all(x[n].tobytes() == y[n].tobytes() for n in x)
        elif isinstance(x, np.ndarray):
            assert x.dtype == y.dtype and x.shape == y.shape and x.tobytes() == y.tobytes(), k
        else:
            assert x == y, k


def test_threads_and_a_thread_pool_give_the_same_map_bit_for_bit():
    default = two_parameter_map()
    same(default, two_parameter_map(threads=1))
    with ThreadPoolExecutor(max_workers=3) as pool:
        same(default, two_parameter_map(executor=pool))
        same(default, two_parameter_map(executor=pool, chunk=4))
        # One sweep, with points where there is no steady motion (a slow
        # precession too slow for its tilt): the reasons travel too.
        w, b = precessing()
        sweeps = {"spin": (1.0, 40.0, 9)}
        one = kreisel.stability_map(w, b, sweeps)
        assert one["missing"] and all(isinstance(r, str) and r.startswith("no ") for _, r in one["missing"])
        assert np.isnan(one["max_real_part"][[k for k, _ in one["missing"]]]).all()
        assert (one["verdict"][[k for k, _ in one["missing"]]] == -1).all()
        same(one, kreisel.stability_map(w, b, sweeps, executor=pool))


def test_a_process_pool_gives_the_same_map_bit_for_bit():
    # The steady motion and the chunk functions travel by pickle.
    from concurrent.futures import ProcessPoolExecutor

    with ProcessPoolExecutor(max_workers=2) as pool:
        same(two_parameter_map(), two_parameter_map(executor=pool))


def precessing():
    """A symmetric top tilted 0.5 rad in slow steady precession, ω3 = 40 rad/s."""
    mass, i1, i3, l = TOPS[0]
    theta, w3 = 0.5, 40.0
    jj = j1(mass, i1, l)
    c = math.cos(theta)
    slow = (i3 * w3 - math.sqrt((i3 * w3) ** 2 - 4 * jj * c * mass * G * l)) / (2 * jj * c)
    w = kreisel.World(dt=0.01, gravity=(0.0, 0.0, -G))
    omega = (0.0, slow * math.sin(theta), w3)
    b = w.add_body(
        mass, moments=(i1, i1, i3), attitude=(math.cos(theta / 2), math.sin(theta / 2), 0, 0),
        omega_body=omega, pivot=(0.0, 0.0, -l),
    )  # fmt: skip
    return w, b


def test_the_steady_motion_pickles_as_plain_numbers():
    free = kreisel.World(dt=0.01)
    fb = free.add_body(1.0, moments=(1.0, 2.0, 3.0), omega_body=(0.0, 0.0, 2.0))
    cases = [
        (free, fb, {"spin": (-1.0, 1.0, 4)}),
        (*sleeping(*TOPS[1], 50.0), {"spin": (1.0, 90.0, 4), "com_offset": (0.01, 0.1, 3)}),
        (*precessing(), {"tilt": (0.2, 1.2, 4)}),
    ]
    kinds = set()
    for w, b, sweeps in cases:
        p = kreisel._native._steady_problem(w, b)
        cls, (numbers,) = p.__reduce__()
        assert all(type(x) is float for x in numbers)
        q = pickle.loads(pickle.dumps(p))
        assert repr(q) == repr(p) and q.parameters == p.parameters
        kinds.add(q.kind)
        same(kreisel._native._stability_map(p, sweeps), kreisel._native._stability_map(q, sweeps))
    assert kinds == {"free rotation about a principal axis", "sleeping top", "slow steady precession"}
    with pytest.raises(kreisel.KreiselError, match="^numbers: not the state of a steady motion"):
        kreisel._native._SteadyProblem([7.0, 1.0])


def test_dask_distributed_executor_gives_the_same_map_bit_for_bit():
    # A requirement (tests/requirements.txt): CI runs this, never skips it.
    import dask.distributed as distributed

    default = two_parameter_map()
    start = time.perf_counter()
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, distributed.Client(cluster) as client:
        up = time.perf_counter()
        on_cluster = two_parameter_map(executor=client.get_executor())
        done = time.perf_counter()
    same(default, on_cluster)
    print(f"dask: cluster up in {up - start:.2f} s, map in {done - up:.2f} s")


@pytest.mark.parametrize(
    "sweeps, message",
    [
        ({"tilt": (0.1, 1.0, 5)}, "sweep tilt: a sleeping top has no tilt (it has spin, com_offset, gravity)"),
        ({"speed": (0.1, 1.0, 5)}, "sweep speed: a sleeping top has no speed (it has spin, com_offset, gravity)"),
        ({"spin": (0.0, 10.0, 1)}, "sweep spin: N = 1: a sweep needs at least 2 values"),
        ({"spin": (0.0, 10.0, -4)}, "sweep spin: N = -4: a sweep needs at least 2 values"),
        ({"spin": (3.0, 3.0, 5)}, "sweep spin: the range 3:3 is empty"),
        ({"omega": (0.0, 1.0, 5)}, 'sweep omega: unknown parameter "omega" (one of spin, tilt, com_offset, gravity, speed)'),
        ({}, "sweep : 0 parameters: a map sweeps one or two"),
        (
            {"spin": (0.0, 1.0, 3), "gravity": (1.0, 2.0, 3), "com_offset": (0.1, 0.2, 3)},
            "sweep spin, gravity, com_offset: 3 parameters: a map sweeps one or two",
        ),
        ({"gravity": (-1.0, 2.0, 3)}, "sweep gravity: -1 m/s²: gravity must not be negative"),
    ],
)
@pytest.mark.parametrize("pool", [False, True])
def test_bad_sweeps_raise_value_error_with_the_library_s_line(sweeps, message, pool):
    w, b = sleeping(*TOPS[0], 20.0)
    with ThreadPoolExecutor(1) as ex:
        with pytest.raises(ValueError) as e:
            kreisel.stability_map(w, b, sweeps, executor=ex if pool else None)
    assert str(e.value) == message


def test_a_free_rotation_has_only_spin():
    w = kreisel.World(dt=0.01, gravity=(0, 0, -G))
    b = w.add_body(1.0, moments=(1.0, 2.0, 3.0), omega_body=(0.0, 2.0, 0.0))
    with pytest.raises(ValueError, match=r"^sweep gravity: a free rotation about a principal axis has no gravity \(it has spin\)$"):
        kreisel.stability_map(w, b, {"gravity": (0.0, 1.0, 3)})
    m = kreisel.stability_map(w, b, {"spin": (0.5, 3.0, 6)})
    growth = m["values"][0] * math.sqrt(1 * 1 / 3)
    assert (m["verdict"] == 1).all() and len(m["boundaries"]) == 0
    assert np.allclose(m["max_real_part"], growth, rtol=1e-12, atol=0)
    assert m["boundaries"].shape == (0, 1)
    with ThreadPoolExecutor(2) as pool:  # no boundary: no bisection task
        same(m, kreisel.stability_map(w, b, {"spin": (0.5, 3.0, 6)}, executor=pool))


def test_bad_arguments_are_type_errors_or_name_themselves():
    w, b = sleeping(*TOPS[0], 20.0)
    with pytest.raises(TypeError, match="^sweeps: expected a dict"):
        kreisel.stability_map(w, b, [("spin", (0.0, 1.0, 3))])
    with pytest.raises(kreisel.KreiselError, match=r'^sweeps\["spin"\]: expected a sequence of 3'):
        kreisel.stability_map(w, b, {"spin": (0.0, 1.0)})
    with pytest.raises(kreisel.KreiselError, match=r"^threads: 0 is out of range"):
        kreisel.stability_map(w, b, {"spin": (0.0, 1.0, 3)}, threads=0)
    with ThreadPoolExecutor(1) as ex, pytest.raises(kreisel.KreiselError, match=r"^chunk: 0: must be a positive"):
        kreisel.stability_map(w, b, {"spin": (0.0, 1.0, 3)}, executor=ex, chunk=0)


def test_docstring_examples():
    import doctest

    for obj in [kreisel.stability, kreisel.stability_map]:
        assert ">>>" in obj.__doc__, obj
        runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
        for test in doctest.DocTestFinder(recurse=False).find(obj, obj.__name__, globs={}):
            runner.run(test)
        assert runner.failures == 0 and runner.tries > 0, obj


def test_a_spinning_top_on_the_table_sticks_and_is_the_rolling_one():
    """A tippe top spinning upright on the table: with μ > 0 nothing slips at
    the contact, so it is analysed rolling (state γ, ω; two zeros named,
    four eigenvalues); with μ = 0 it slides freely (γ, ω, v; three zeros,
    six). The Rust tests compare the rolling one with the tippe-top family."""
    w = kreisel.World(dt=0.01, gravity=(0, 0, -G))
    sticking = w.add_body(0.006, moments=(8e-7, 8e-7, 7e-7), omega_body=(0, 0, 180.0),
                          contacts=[dict(shape="sphere", radius=0.015, center=(0, 0, 0.003), mu=0.3)])
    sliding = w.add_body(0.006, moments=(8e-7, 8e-7, 7e-7), omega_body=(0, 0, 180.0),
                         contacts=[dict(shape="sphere", radius=0.015, center=(0, 0, 0.003), mu=0.0)])
    a, b = kreisel.stability(w, sticking), kreisel.stability(w, sliding)
    assert a["kind"] == b["kind"] == "spin about the vertical on its contact point"
    assert len(a["eigenvalues"]) == 4 and len(b["eigenvalues"]) == 6   # rolling (γ, ω); sliding adds v
    assert sorted(abs(e.imag) for e in a["eigenvalues"]) != pytest.approx(sorted(abs(e.imag) for e in b["eigenvalues"][:4]))
