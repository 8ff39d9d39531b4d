"""kreisel.mass_properties and mass_properties_from_arrays: against trimesh
(an independent implementation), against closed forms, bit for bit against
`kreisel inertia --format json`, and every error path."""

import json
import math

import numpy as np
import pytest

import kreisel
import kreisel_cli_runner as cli

REPO = cli.REPO
T_HANDLE = REPO / "assets" / "t_handle.obj"
FIXTURES = REPO / "crates" / "inertia" / "tests" / "fixtures"
POLYHEDRA = REPO / "tests" / "data" / "polyhedra"
OPEN_SHEET = REPO / "tests" / "data" / "flat_shells" / "sheet_00.obj"

ASSEMBLY_KEYS = [
    "file", "units", "scale", "model", "density", "density_source", "frame",
    "mass", "volume", "area", "triangles", "center_of_mass", "inertia",
    "principal_moments", "principal_axes", "principal_orientation",
    "warnings", "bodies",
]  # fmt: skip


# The CLI's advice names its options; Python's names the keywords.
KEYWORDS = [
    ("--shell models a thin-walled part (see --thickness) and --hull a convex one",
     'model="shell" models a thin-walled part (see thickness) and model="hull" a convex one'),
    ("--shell models it as a thin wall (see --thickness)", 'model="shell" models it as a thin wall (see thickness)'),
    ("(set with --units or --scale S, metres per mesh unit)", "(set with units or scale, metres per mesh unit)"),
    ("rerun with --merge to", "rerun with merge=True to"),
    ("rerun with --weld ", "rerun with weld="),
]  # fmt: skip


def in_keywords(cli_line):
    """The CLI's error line as Python words it (its advice in keywords)."""
    for option, keyword in KEYWORDS:
        cli_line = cli_line.replace(option, keyword)
    assert "--" not in cli_line, cli_line
    return cli_line


def assert_same_as_json(from_json, value, where="report"):
    """`value` (the dict) holds exactly what the CLI's JSON holds: the same
    keys in the same order, strings equal, numbers equal as f64 (JSON's
    shortest round-trip digits parse back to the same bits; JSON spells
    -0.0 as 0 and a non-finite number as null), lists as numpy arrays."""
    if isinstance(from_json, dict):
        assert isinstance(value, dict), where
        assert list(value) == list(from_json), where
        for key in from_json:
            assert_same_as_json(from_json[key], value[key], f"{where}.{key}")
    elif isinstance(from_json, list) and all(isinstance(x, str) for x in from_json):
        assert value == from_json, where
    elif isinstance(from_json, list) and from_json and isinstance(from_json[0], dict):
        assert isinstance(value, list) and len(value) == len(from_json), where
        for i, (a, b) in enumerate(zip(from_json, value)):
            assert_same_as_json(a, b, f"{where}[{i}]")
    elif isinstance(from_json, list):
        assert isinstance(value, np.ndarray) and value.dtype == np.float64, where
        expected = np.array(
            [[np.nan if x is None else x for x in row] if isinstance(row, list)
             else (np.nan if row is None else row) for row in from_json],
            dtype=np.float64,
        )  # fmt: skip
        assert value.shape == expected.shape, where
        assert np.array_equal(value, expected, equal_nan=True), (where, value, expected)
    elif isinstance(from_json, bool) or isinstance(from_json, str):
        assert value == from_json and type(value) is type(from_json), where
    elif isinstance(from_json, int) and not isinstance(value, float):
        assert value == from_json and type(value) is int, where
    elif from_json is None:
        assert isinstance(value, float) and math.isnan(value), where
    else:
        assert isinstance(value, float), where
        assert value == float(from_json), (where, value, from_json)


CASES = [
    (T_HANDLE, dict(density=2700.0), ["--density", "2700"]),
    (T_HANDLE, dict(mass=0.35, model="hull"), ["--mass", "0.35", "--hull"]),
    (T_HANDLE, dict(units="mm", model="shell", thickness=0.002),
     ["--units", "mm", "--shell", "--thickness", "0.002"]),
    (T_HANDLE, dict(model="shell"), ["--shell"]),
    (T_HANDLE, dict(units="in", density=7850.0, weld="off"),
     ["--units", "in", "--density", "7850", "--weld", "off"]),
    (FIXTURES / "two_cubes.obj", dict(), []),
    (FIXTURES / "two_cubes.obj", dict(merge=True, mass=2.0), ["--merge", "--mass", "2"]),
    (FIXTURES / "transforms.gltf", dict(units="cm"), ["--units", "cm"]),
    (FIXTURES / "cube.glb", dict(), []),
    (FIXTURES / "cube_binary_be.ply", dict(), []),
    (FIXTURES / "closed_in_practice" / "near_duplicates.stl", dict(), []),
    (FIXTURES / "closed_in_practice" / "mm_part.stl", dict(), []),
    (REPO / "assets" / "top_ascii.stl", dict(density=1200.0, weld=1e-9),
     ["--density", "1200", "--weld", "1e-9"]),
    (OPEN_SHEET, dict(model="shell", thickness=1e-3), ["--shell", "--thickness", "1e-3"]),
    (T_HANDLE, dict(scale=0.5, density=10.0), ["--scale", "0.5", "--density", "10"]),
    (T_HANDLE, dict(scale=1000.0), ["--scale", "1000"]),
]  # fmt: skip


@pytest.mark.parametrize("path,kwargs,args", CASES, ids=lambda c: str(c))
def test_bit_for_bit_as_the_cli_json(path, kwargs, args):
    done = cli.run("inertia", path, "--format", "json", *args)
    assert done.returncode == 0, done.stderr
    from_json = json.loads(done.stdout)
    value = kreisel.mass_properties(path, **kwargs)
    assert_same_as_json(from_json, value)
    # The CLI's warnings on stderr are the assembly's (the file's, then each body's).
    assert len(done.stderr.splitlines()) == len(value["warnings"])


def test_keys_are_those_of_the_json():
    value = kreisel.mass_properties(T_HANDLE)
    assert list(value) == ASSEMBLY_KEYS
    assert list(value["bodies"][0]) == ["name"] + ASSEMBLY_KEYS[:-1]
    shell = kreisel.mass_properties(T_HANDLE, model="shell")
    assert list(shell)[:5] == ["file", "units", "scale", "model", "thickness"]
    assert shell["thickness"] == 0.001 and shell["model"] == "shell"
    assert value["density"] == 1000.0 and value["density_source"] == "default (water)"
    assert value["center_of_mass"].shape == (3,) and value["inertia"].shape == (3, 3)
    assert value["principal_orientation"].shape == (4,)
    assert isinstance(value["triangles"], int) and value["warnings"] == []


def trimesh_properties(path, density):
    import trimesh
    mesh = trimesh.load(str(path), force="mesh")
    mesh.density = density
    return mesh, mesh.mass_properties


@pytest.mark.parametrize("path", [T_HANDLE, POLYHEDRA / "l_shape.obj", POLYHEDRA / "prism_hex.obj"])
def test_agrees_with_trimesh(path):
    mesh, ref = trimesh_properties(path, 2700.0)
    p = kreisel.mass_properties(path, density=2700.0)
    scale = np.abs(ref["inertia"]).max()
    assert math.isclose(p["mass"], ref["mass"], rel_tol=1e-12)
    assert math.isclose(p["volume"], ref["volume"], rel_tol=1e-12)
    assert math.isclose(p["area"], mesh.area, rel_tol=1e-12)
    assert np.allclose(p["center_of_mass"], ref["center_mass"], rtol=0, atol=1e-14 * mesh.scale)
    assert np.abs(p["inertia"] - ref["inertia"]).max() <= 1e-12 * scale
    # The principal frame diagonalises the tensor: R^T I R = diag(moments).
    axes = p["principal_axes"].T
    assert np.allclose(axes.T @ p["inertia"] @ axes, np.diag(p["principal_moments"]), rtol=0, atol=1e-13 * scale)
    assert np.allclose(p["principal_moments"], np.linalg.eigvalsh(ref["inertia"]), rtol=1e-12)
    assert np.isclose(np.linalg.det(axes), 1.0)


def test_box_closed_form():
    # box_1x2x3.obj: a 1 x 2 x 3 m box; I = m/12 (b^2 + c^2, ...).
    p = kreisel.mass_properties(POLYHEDRA / "box_1x2x3.obj", density=500.0)
    m = 500.0 * 6.0
    assert math.isclose(p["mass"], m, rel_tol=1e-15)
    expected = m / 12.0 * np.array([4.0 + 9.0, 1.0 + 9.0, 1.0 + 4.0])
    assert np.allclose(np.diag(p["inertia"]), expected, rtol=1e-14)
    assert np.allclose(p["principal_moments"], np.sort(expected), rtol=1e-14)


def test_arrays_agree_with_trimesh_and_the_file():
    import trimesh
    mesh = trimesh.load(str(T_HANDLE), force="mesh")
    mesh.density = 2700.0
    ref = mesh.mass_properties
    p = kreisel.mass_properties_from_arrays(mesh.vertices, mesh.faces, density=2700.0)
    assert p["file"] == "<arrays>" and p["bodies"][0]["name"] == "mesh"
    assert list(p) == ASSEMBLY_KEYS
    scale = np.abs(ref["inertia"]).max()
    assert math.isclose(p["mass"], ref["mass"], rel_tol=1e-12)
    assert np.abs(p["inertia"] - ref["inertia"]).max() <= 1e-12 * scale
    from_file = kreisel.mass_properties(T_HANDLE, density=2700.0)
    assert math.isclose(p["mass"], from_file["mass"], rel_tol=1e-14)
    assert np.abs(p["inertia"] - from_file["inertia"]).max() <= 1e-14 * scale
    # int32 faces, list inputs, units and model work as for files.
    q = kreisel.mass_properties_from_arrays(
        mesh.vertices.tolist(), mesh.faces.astype(np.int32), density=2700.0, name="handle"
    )
    assert q["bodies"][0]["name"] == "handle" and q["mass"] == p["mass"]
    mm = kreisel.mass_properties_from_arrays(mesh.vertices * 1000.0, mesh.faces, density=2700.0, units="mm")
    assert math.isclose(mm["mass"], p["mass"], rel_tol=1e-14)
    hull = kreisel.mass_properties_from_arrays(mesh.vertices, mesh.faces, model="hull", mass=1.0)
    assert math.isclose(hull["mass"], 1.0, rel_tol=1e-15) and hull["model"] == "convex hull"


def test_arrays_bit_for_bit_as_the_same_mesh_in_an_obj(tmp_path):
    # A mesh whose vertices are all used, in order of first use: the file
    # and the arrays are the same mesh, so the numbers are the same bits.
    rng = np.random.default_rng(7)
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float) + rng.normal(0, 0.1, (4, 3))
    f = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    path = tmp_path / "tetra.obj"
    path.write_text("".join(f"v {x!r} {y!r} {z!r}\n" for x, y, z in v.tolist()) + "".join(
        f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in f))  # fmt: skip
    a = kreisel.mass_properties_from_arrays(v, f, density=3.0, name="tetra")
    b = kreisel.mass_properties(path, density=3.0)
    for key in ["mass", "volume", "area", "center_of_mass", "inertia", "principal_moments"]:
        assert np.array_equal(a[key], b[key]), key
    assert a["warnings"] == b["warnings"] == []


def test_inside_out_arrays_are_repaired_with_a_warning():
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
    f = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    good = kreisel.mass_properties_from_arrays(v, f)
    flipped = kreisel.mass_properties_from_arrays(v, f[:, ::-1])
    assert flipped["mass"] == good["mass"] > 0
    assert flipped["warnings"] and "body 'mesh'" in flipped["warnings"][0]


# --- errors: the CLI's one line, a KreiselError (ValueError), never a panic


def test_missing_file_has_the_cli_message(tmp_path):
    missing = tmp_path / "nope.stl"
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.mass_properties(missing)
    assert str(e.value) == cli.error_line("inertia", missing)
    assert isinstance(e.value, ValueError)


@pytest.mark.parametrize(
    "path,kwargs,args",
    [
        (OPEN_SHEET, {}, []),
        (FIXTURES / "two_cubes.obj", dict(model="hull", mass=-1.0), None),
        (REPO / "README.md", {}, []),
    ],
)
def test_bad_files_have_the_cli_message(path, kwargs, args):
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.mass_properties(path, **kwargs)
    message = str(e.value)
    assert "\n" not in message
    if args is not None:
        assert message == in_keywords(cli.error_line("inertia", path, *args))


def test_garbage_and_truncated_files(tmp_path):
    for name, data in [
        ("empty.stl", b""),
        ("short.stl", b"\0" * 83),
        ("count.stl", b"\0" * 80 + (10).to_bytes(4, "little") + b"\0" * 50),
        ("junk.obj", b"v 1 2\nf 1 2 3\n"),
        ("nan.obj", b"v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
        ("bad.ply", b"ply\nformat ascii 1.0\nelement vertex 99999999999\nend_header\n"),
        ("bad.glb", b"glTF\x02\0\0\0\xff\xff\xff\xff"),
        ("bad.gltf", b"{\"asset\": 3}"),
        ("utf.obj", b"\xff\xfe\x00v"),
    ]:
        path = tmp_path / name
        path.write_bytes(data)
        with pytest.raises(kreisel.KreiselError) as e:
            kreisel.mass_properties(path)
        assert str(e.value) == cli.error_line("inertia", path), name


@pytest.mark.parametrize(
    "kwargs,fragment",
    [
        (dict(density=-1.0), "density (kg/m^3) must be a positive finite number"),
        (dict(density=float("nan")), "density (kg/m^3) must be a positive finite number"),
        (dict(mass=0.0), "mass (kg) must be a positive finite number"),
        (dict(mass=float("inf")), "mass (kg) must be a positive finite number"),
        (dict(density=1.0, mass=1.0), "density and mass exclude each other"),
        (dict(units="ft"), "units must be one of"),
        (dict(model="foam"), "model must be one of"),
        (dict(thickness=0.1), "thickness is the wall of model=\"shell\""),
        (dict(model="shell", thickness=-0.1), "thickness (m) must be a positive finite number"),
        (dict(weld=-1.0), "weld must be \"off\" or a non-negative finite number"),
        (dict(weld="sometimes"), "weld must be \"off\""),
        (dict(scale=0.0), "scale (metres per mesh unit) must be a positive finite number"),
        (dict(scale=2.0, units="mm"), "scale and units exclude each other"),
    ],
)
def test_bad_options(kwargs, fragment):
    with pytest.raises(kreisel.KreiselError, match=None) as e:
        kreisel.mass_properties(T_HANDLE, **kwargs)
    assert fragment in str(e.value)
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
    f = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.mass_properties_from_arrays(v, f, **kwargs)
    assert fragment in str(e.value)


TETRA_V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
TETRA_F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])


@pytest.mark.parametrize(
    "vertices,faces,fragment",
    [
        (TETRA_V, TETRA_F + 1, "faces[1, 2] = 4 is not a vertex index (0 <= index < 4)"),
        (TETRA_V, -TETRA_F, "is not a vertex index"),
        (TETRA_V, TETRA_F.astype(float), "faces must be an (M, 3) array of integer vertex indices: got dtype float64"),
        (TETRA_V, TETRA_F[:, :2], "got shape [4, 2]"),
        (TETRA_V, TETRA_F.ravel(), "got 1 dimensions"),
        (TETRA_V, [[0, 1], [2]], "faces must be an (M, 3) array"),
        (TETRA_V, "abc", "faces must be an (M, 3) array"),
        (TETRA_V, np.zeros((0, 3), int), "mesh"),
        (TETRA_V[:, :2], TETRA_F, "vertices must be an (N, 3) array of numbers: got shape [4, 2]"),
        (TETRA_V.ravel(), TETRA_F, "got 1 dimensions"),
        (np.where(TETRA_V == 1.0, np.nan, TETRA_V), TETRA_F, "mesh"),
        (TETRA_V * 1e308, TETRA_F, "mesh"),
        (["a", "b"], TETRA_F, "vertices must be an (N, 3) array of numbers"),
        (None, TETRA_F, "vertices must be an (N, 3) array of numbers"),
        (TETRA_V, TETRA_F[:3], "body 'mesh'"),  # open: the CLI's advice
    ],
)
def test_bad_arrays(vertices, faces, fragment):
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.mass_properties_from_arrays(vertices, faces)
    assert fragment in str(e.value), str(e.value)
    assert "\n" not in str(e.value)


def test_open_arrays_say_what_the_cli_says(tmp_path):
    # The same open mesh as a file and as arrays: the same words, but for
    # the file's name.
    path = tmp_path / "open.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n")
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.mass_properties_from_arrays(TETRA_V, TETRA_F[:3], name="open")
    expected = in_keywords(cli.error_line("inertia", path)).replace(str(path), "<arrays>")
    assert str(e.value) == expected


def test_wrong_argument_types_raise_type_error_not_panic():
    for call in [
        lambda: kreisel.mass_properties(None),
        lambda: kreisel.mass_properties(T_HANDLE, density="heavy"),
        lambda: kreisel.mass_properties(T_HANDLE, units=3),
        lambda: kreisel.mass_properties_from_arrays(TETRA_V, TETRA_F, name=5),
    ]:
        with pytest.raises((TypeError, ValueError)):
            call()


@pytest.mark.parametrize("suffix", [".stl", ".obj", ".ply", ".gltf", ".glb"])
def test_random_and_mutated_files_never_panic(tmp_path, suffix):
    # Random bytes, and a real file with bytes flipped or cut: a result or a
    # KreiselError, never a panic caught by the guard ("internal error").
    rng = np.random.default_rng(15)
    seeds = {
        ".stl": REPO / "assets" / "top.stl",
        ".obj": T_HANDLE,
        ".ply": FIXTURES / "cube_binary_le.ply",
        ".gltf": FIXTURES / "cube.gltf",
        ".glb": FIXTURES / "cube.glb",
    }
    original = seeds[suffix].read_bytes()
    for k in range(40):
        if k < 10:
            data = rng.integers(0, 256, int(rng.integers(0, 400)), dtype=np.uint8).tobytes()
        else:
            data = bytearray(original)
            for i in rng.integers(0, len(data), int(rng.integers(1, 8))):
                data[i] = int(rng.integers(0, 256))
            data = bytes(data[: int(rng.integers(len(data) // 2, len(data) + 1))])
        path = tmp_path / f"m{k}{suffix}"
        path.write_bytes(data)
        for kwargs in [{}, dict(model="shell"), dict(model="hull", mass=1.0)]:
            try:
                kreisel.mass_properties(path, **kwargs)
            except kreisel.KreiselError as e:
                assert "internal error" not in str(e) and "\n" not in str(e), (path, str(e))


def test_random_arrays_never_panic():
    rng = np.random.default_rng(16)
    for k in range(200):
        n = int(rng.integers(0, 12))
        v = rng.choice([0.0, 1.0, -1.0, 1e-300, 1e300, np.nan, np.inf], size=(n, 3)) if k % 3 == 0 else rng.normal(size=(n, 3))
        f = rng.integers(-1, n + 1, size=(int(rng.integers(0, 20)), 3))
        for kwargs in [{}, dict(model="shell"), dict(model="hull"), dict(units="mm", mass=2.0)]:
            try:
                kreisel.mass_properties_from_arrays(v, f, **kwargs)
            except kreisel.KreiselError as e:
                assert "internal error" not in str(e), str(e)
