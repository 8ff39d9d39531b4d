"""Bodies on the ground are guarded (issue 25): the tippe-top scene at a
game frame (dt = 1/60 s), or with friction too stiff for an explicit step,
raises the CLI's one line with the time the check failed, never returns
wrong rows; at a step that resolves the motion it runs."""

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


@pytest.mark.parametrize(
    "changes, what",
    [
        (dict(dt="0.016666666666666666", output_interval="0.016666666666666666"), "|q| went from"),
        (dict(mu="1000"), "the energy rose"),
    ],
    ids=["game_frame", "stiff_friction"],
)
def test_a_step_too_large_raises_the_cli_line_with_its_time(tmp_path, changes, what):
    path = scene(tmp_path, **changes)
    with pytest.raises(kreisel.KreiselError) as e:
        kreisel.simulate(path)
    message = str(e.value)
    assert message == cli.error_line("simulate", path)
    assert "body `tippe`: the ground contact's check failed at t = " in message
    assert what in message


def test_a_step_that_resolves_the_motion_runs(tmp_path):
    path = scene(tmp_path, dt="1e-4", duration="0.5", output_interval="0.1")
    result = kreisel.simulate(path)
    assert result["t"][-1] == pytest.approx(0.5)
    # the centre of mass stays above the table, the attitude a unit quaternion
    assert (result["z"] > 0.0).all()
