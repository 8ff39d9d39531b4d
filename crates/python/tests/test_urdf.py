"""`kreisel inertia --urdf` read back by a URDF parser nobody here wrote
(yourdfpy): every filled link's mass, centre of mass and tensor, in the full
and in the principal form, against the exact reference of the toy robot
(tests/data/robot/expected.json, from tests/data/gen/urdf_robot.py)."""

import json
import shutil

import numpy as np
import pytest

from conftest import DATA

yourdfpy = pytest.importorskip("yourdfpy")

EXPECTED = json.loads((DATA / "robot" / "expected.json").read_text())["links"]


def full_tensor(six):
    ixx, ixy, ixz, iyy, iyz, izz = six
    return np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])


@pytest.mark.parametrize("form", [[], ["--principal"]])
def test_filled_robot_loads_with_the_exact_inertials(cli, tmp_path, form):
    shutil.copytree(DATA / "robot" / "toy_robot", tmp_path / "toy_robot")
    urdf = tmp_path / "toy_robot" / "urdf" / "toy.urdf"
    filled = urdf.with_name("filled.urdf")
    code, _, err = cli("inertia", "--urdf", str(urdf), "--output", str(filled), *form)
    assert code == 0, err
    robot = yourdfpy.URDF.load(
        str(filled),
        build_scene_graph=False,
        load_meshes=False,
        build_collision_scene_graph=False,
        load_collision_meshes=False,
    ).robot
    links = {link.name: link for link in robot.links}
    assert set(EXPECTED) <= set(links)
    for name, want in EXPECTED.items():
        inertial = links[name].inertial
        pose = inertial.origin  # 4x4: link_from_inertial
        rotation, com = pose[:3, :3], pose[:3, 3]
        tensor = rotation @ inertial.inertia @ rotation.T
        expected = full_tensor(want["inertia"])
        size = (want["mass"] / want["density"]) ** (1 / 3)
        assert inertial.mass == pytest.approx(want["mass"], rel=1e-12)
        assert np.abs(com - want["com"]).max() <= 1e-12 * max(np.linalg.norm(want["com"]), size)
        assert np.abs(tensor - expected).max() <= 1e-12 * np.abs(expected).max(), name
        if form:
            assert np.count_nonzero(inertial.inertia - np.diag(np.diag(inertial.inertia))) == 0
    # Links without geometry keep what they had: the sensor's given inertial.
    assert links["sensor"].inertial.mass == 0.01
