"""Bodies on the ground at any dt (issues 25 and 26): the tippe-top scene at
a game frame (dt = 1/60 s), which fixed RK4 steps got wrong (issue 25: then
a stop at the first frame), runs to the independent generator's state with
error-controlled steps within each frame; at a fine step it runs too."""

import re

import pytest

import kreisel
import kreisel_cli_runner as cli

TIPPE = (cli.REPO / "examples" / "scenes" / "tippe_top.toml").read_text()


def scene(tmp_path, **changes):
    """The tippe-top scene with `key = value` lines replaced, written to a file."""
    text = TIPPE
    for key, value in changes.items():
        text, n = re.subn(rf"(?m)^{key} = .*$", f"{key} = {value}", text)
        assert n == 1, key
    path = tmp_path / "tippe.toml"
    path.write_text(text)
    return path


FRAME = "0.016666666666666666"


def generator_sample(t):
    """The sliding generator's `sample` row at `t` (tests/data/gen/tippe_top.py,
    scipy DOP853 at rtol 1e-13): x, y, z, qw, qx, qy, qz."""
    text = (cli.REPO / "tests" / "data" / "contact" / "tippe_top_sliding.csv").read_text()
    for line in text.splitlines():
        if line.startswith("sample,"):
            x = [float(v) for v in line.split(",")[1:]]
            if x[0] == t:
                return x[1:4] + x[7:11]
    raise AssertionError(f"no sample at {t}")


def test_a_game_frame_runs_to_the_generators_state(tmp_path):
    # Error-controlled steps within each frame (issue 26): where fixed RK4
    # steps of 1/60 s stopped at the first frame, the run reaches the
    # independent generator's state at 3 s.
    path = scene(tmp_path, dt=FRAME, output_interval=FRAME, duration="3.0")
    result = kreisel.simulate(path)
    assert len(result["t"]) == 181
    assert result["t"][-1] == pytest.approx(3.0, abs=1e-12)
    x, y, z, qw, qx, qy, qz = generator_sample(3.0)
    for key, want in dict(x=x, y=y, z=z).items():
        assert result[key][-1] == pytest.approx(want, abs=1e-9), key
    for key, want in dict(qw=qw, qx=qx, qy=qy, qz=qz).items():
        assert result[key][-1] == pytest.approx(want, abs=1e-7), key


def test_a_step_that_resolves_the_motion_runs(tmp_path):
    path = scene(tmp_path, dt="1e-4", duration="0.5", output_interval="0.1")
    result = kreisel.simulate(path)
    assert result["t"][-1] == pytest.approx(0.5)
    # the centre of mass stays above the table, the attitude a unit quaternion
    assert (result["z"] > 0.0).all()


def test_friction_too_stiff_for_a_fixed_step_runs_without_an_energy_rise(tmp_path):
    # mu = 1000: fixed RK4 steps gained energy (issue 25: a stop); the
    # error-controlled steps follow the stiff field (slowly: the first 0.1 s).
    path = scene(tmp_path, mu="1000", duration="0.1", output_interval="0.01")
    result = kreisel.simulate(path)
    energy = result["energy"]
    assert len(energy) == 11
    assert (energy[1:] <= energy[:-1]).all()
