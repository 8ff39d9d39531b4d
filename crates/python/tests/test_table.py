"""Bodies on the table from Python: `kreisel.World(...).add_body(...,
contacts=[...])` and `World.events`, `kreisel.simulate(..., events=True)`;
the dropped ball against its closed form, the events against the CLI's
`--events` file bit for bit, and every bad input a KreiselError naming its
key."""

import csv
import math

import pytest

import kreisel
import kreisel_cli_runner as cli

REPO = cli.REPO
SCENES = REPO / "examples" / "scenes"
G = 9.81
# The dropped ball of examples/scenes/bouncing_ball.toml.
E, RADIUS, HEIGHT = 0.9, 0.1, 1.0
KINDS = {
    "impact", "impacts_accumulate", "touchdown", "lift_off", "stick", "slip",
    "stops_rolling", "starts_rolling", "lands_flat", "rest",
}


def ball_world(dt=0.01, **contact):
    """A World with the ball of bouncing_ball.toml (contact keys overridable)."""
    world = kreisel.World(dt, gravity=(0.0, 0.0, -G))
    law = dict(shape="sphere", radius=RADIUS, friction="coulomb", mu=0.0, restitution=E)
    law.update(contact)
    body = world.add_body(0.5, moments=(0.002, 0.002, 0.002), position=(0.0, 0.0, HEIGHT), contacts=[law])
    return world, body


def cli_events(scene, tmp_path):
    """The rows of `kreisel simulate SCENE --events FILE`, as str fields."""
    path = tmp_path / "events.csv"
    done = cli.run("simulate", scene, "--events", path, "--output", tmp_path / "rows.csv")
    assert done.returncode == 0, done.stderr
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0] == "time,body,contact,kind,approach_speed,rebound_speed,accumulation_time".split(",")
    return rows[1:]


def parsed(row):
    """A CSV row with its numbers parsed (the shortest round-trip digits give
    back the same bits) and empty fields None."""
    time, body, contact, kind, *values = row
    numbers = [float(v) if v else None for v in values]
    return (float(time), body, int(contact) if contact else None, kind, *numbers)


def test_the_dropped_ball_strikes_and_comes_to_rest_at_the_closed_form_times():
    world, ball = ball_world()
    world.advance_to(10.0)
    events = world.events(ball)
    t1 = math.sqrt(2.0 * (HEIGHT - RADIUS) / G)  # 0.42835 s
    zeno = t1 * (1.0 + E) / (1.0 - E)  # 8.1387 s: the bounces accumulate
    first = events[0]
    assert first[1:3] == (0, "impact") and first[5] is None
    assert abs(first[0] - t1) < 1e-12, first
    v1 = G * t1
    assert abs(first[3] - v1) < 1e-10 * v1 and abs(first[4] - E * first[3]) < 1e-12
    # The n-th impact at t1 (1 + 2 e + ... + 2 e^(n-1)), each rebound e times the approach.
    impacts = [e for e in events if e[2] == "impact"]
    assert len(impacts) > 10
    for n, (t, contact, _, v_in, v_out, _) in enumerate(impacts[:10]):
        expected = t1 * (1.0 + 2.0 * E * (1.0 - E**n) / (1.0 - E))
        assert abs(t - expected) < 1e-11, (n, t, expected)
        assert abs(v_out - E * v_in) < 1e-12 * v_in
    accumulate = [e for e in events if e[2] == "impacts_accumulate"]
    assert len(accumulate) == 1 and abs(accumulate[0][5] - zeno) < 1e-9, (accumulate, zeno)
    last = events[-1]
    assert last[1:] == (None, "rest", None, None, None)
    assert abs(last[0] - zeno) < 1e-9, (last[0], zeno)
    # At rest on the table at 10 s.
    s = world.state(ball)
    assert abs(s["position"][2] - RADIUS) < 1e-12 and abs(s["velocity"][2]) < 1e-12


def test_events_come_in_time_order_with_known_kinds():
    world, ball = ball_world()
    world.advance_to(10.0)
    events = world.events(ball)
    times = [e[0] for e in events]
    assert times == sorted(times) and len(events) > 10
    assert {e[2] for e in events} <= KINDS
    for time, contact, kind, v_in, v_out, accumulation in events:
        assert isinstance(time, float) and contact in (0, None)
        assert (v_in is not None) == (v_out is not None) == (kind == "impact")
        assert (accumulation is not None) == (kind == "impacts_accumulate")


def test_the_world_gives_the_events_of_the_cli_for_the_same_scene(tmp_path):
    # The scene's grid: one step of dt per row, the last to t = duration, as the CLI moves it.
    rows = [parsed(r) for r in cli_events(SCENES / "bouncing_ball.toml", tmp_path)]
    world, ball = ball_world(dt=0.01)
    for _ in range(999):
        world.advance_steps(1)
    world.advance_to(10.0)
    mine = [(t, "ball", None if c is None else c + 1, *rest) for t, c, *rest in world.events(ball)]
    assert mine == rows


@pytest.mark.parametrize(
    "scene", ["bouncing_ball.toml", "tippe_top_coulomb.toml", "superball.toml", "billiard_ball.toml"]
)
def test_simulate_gives_the_events_file_bit_for_bit(scene, tmp_path):
    rows = [parsed(r) for r in cli_events(SCENES / scene, tmp_path)]
    assert rows
    columns, events = kreisel.simulate(SCENES / scene, events=True)
    assert events == rows
    # Without events=True: the rows alone, the same ones.
    alone = kreisel.simulate(SCENES / scene)
    assert list(alone) == list(columns)
    assert all((alone[k] == columns[k]).all() for k in columns)


def test_a_scene_without_table_bodies_has_no_events():
    rows, events = kreisel.simulate(SCENES / "heavy_top.toml", events=True)
    assert events == [] and len(rows["t"]) > 0
    world = kreisel.World(0.01)
    free = world.add_body(1.0, moments=(1.0, 2.0, 3.0))
    assert world.events(free) == []


def test_a_body_thrown_with_spin_and_a_patch():
    # Every key of a scene's [[body.contact]] accepted; the ball thrown sideways bounces, then rolls.
    world = kreisel.World(1.0 / 60.0, gravity=(0.0, 0.0, -G))
    contact = dict(
        shape="sphere", radius=0.02, center=(0.0, 0.0, 0.0), mu=0.4, restitution=0.5,
        tangential_restitution=0.3, contensou_radius=5e-4,
    )  # fmt: skip
    ball = world.add_body(
        0.1, moments=(1.6e-5,) * 3, position=(0.0, 0.0, 0.3), velocity=(1.0, 0.0, 0.0),
        omega_body=(0.0, 30.0, 5.0), contacts=[contact],
    )  # fmt: skip
    e0 = world.state(ball)["energy"]
    world.advance_to(1.5)
    kinds = [e[2] for e in world.events(ball)]
    assert kinds[0] == "impact" and kinds[-1] == "impacts_accumulate", kinds
    s = world.state(ball)
    assert s["energy"] < e0
    # It ends rolling on the table: the contact point at rest, v_P = v + w x (-r z) = 0.
    w = s["l_world"] / 1.6e-5
    v_p = (s["velocity"][0] - 0.02 * w[1], s["velocity"][1] + 0.02 * w[0], s["velocity"][2])
    assert max(map(abs, v_p)) < 1e-9, v_p
    assert abs(s["position"][2] - 0.02) < 1e-12 and s["velocity"][0] > 0.5


def test_without_position_the_lowest_contact_touches():
    world = kreisel.World(0.01, gravity=(0.0, 0.0, -G))
    disk = dict(shape="disk", radius=0.05, normal=(0.0, 0.0, 1.0), mu=0.3)
    tilt = math.radians(30.0)
    body = world.add_body(
        0.2, moments=(1.25e-4, 1.25e-4, 2.5e-4), attitude=(math.cos(tilt / 2), math.sin(tilt / 2), 0.0, 0.0),
        omega_body=(0.0, 0.0, 20.0), contacts=[disk],
    )  # fmt: skip
    # The rim's lowest point at the table: the centre at r sin(tilt).
    assert abs(world.state(body)["position"][2] - 0.05 * math.sin(tilt)) < 1e-15
    assert world.events(body)[0][1:3] == (0, "touchdown")


@pytest.mark.parametrize(
    "contact, message",
    [
        (dict(mu=-0.1), "contacts[0].mu: must be finite and ≥ 0, got -0.1"),
        (dict(mu=float("nan")), "contacts[0].mu: NaN is not a finite number"),
        (dict(restitution=1.5), "contacts[0].restitution: must lie in [0, 1], got 1.5"),
        (dict(restitution=-0.5), "contacts[0].restitution: must lie in [0, 1], got -0.5"),
        (dict(tangential_restitution=2.0), "contacts[0].tangential_restitution: must lie in [0, 1], got 2"),
        (dict(contensou_radius=-1e-3), "contacts[0].contensou_radius: must be finite and ≥ 0, got -0.001"),
        (dict(rolling_resistance=-1e-3), "contacts[0].rolling_resistance: must be finite and ≥ 0, got -0.001"),
        (dict(radius=0.0), "contacts[0].radius:"),
        (dict(mu=None), "contacts[0].mu: is missing"),
        (dict(shape="cube"), "contacts[0].shape: unknown contact shape 'cube'"),
        (dict(friction="sliding"), "contacts[0].friction:"),
        (dict(slip_velocity=1e-3), "contacts[0].slip_velocity: unknown key"),
        (dict(normal=(0, 0, 1)), "contacts[0].normal: is only for a disk"),
        (
            dict(shape="ellipsoid", radius=None, semi_axes=(0.2, -0.03, 0.02)),
            "contacts[0].semi_axes: must be positive and finite, got -0.03",
        ),
        (dict(air_viscosity=1.8e-5), "contacts[0].air_viscosity: is Moffatt's air layer under a disk rim"),
        (dict(air_gap=1e-6), "contacts[0].air_gap: needs air_viscosity"),
    ],
)
def test_bad_contact_keys_are_named(contact, message):
    with pytest.raises(kreisel.KreiselError) as e:
        ball_world(**contact)
    assert str(e.value).startswith(message), str(e.value)


@pytest.mark.parametrize(
    "air, message",
    [
        (
            dict(air_viscosity=-1.0),
            "contacts[0].air_viscosity: the air's viscosity must be finite and not negative, got -1",
        ),
        (
            dict(air_viscosity=1.8e-5, air_gap=0.0),
            "contacts[0].air_gap: the air layer's floor must be finite and positive, got 0",
        ),
    ],
)
def test_bad_air_layers_are_named(air, message):
    world = kreisel.World(0.01, gravity=(0.0, 0.0, -G))
    disk = dict(shape="disk", radius=0.05, normal=(0.0, 0.0, 1.0), mu=0.3, **air)
    with pytest.raises(kreisel.KreiselError) as e:
        world.add_body(0.2, moments=(1.25e-4, 1.25e-4, 2.5e-4), contacts=[disk])
    assert str(e.value) == message
    assert len(world) == 0


def test_eulers_disk_takes_the_air_layer_of_its_scene(tmp_path):
    # examples/scenes/euler_disk.toml from Python, on the CLI's grid: the air
    # layer brings the disk down to Moffatt's breakdown, its first hop
    # (lift_off) at the CLI's time; without the layer it rolls on.
    rows = [parsed(r) for r in cli_events(SCENES / "euler_disk.toml", tmp_path)]
    cli_hop = next(r[0] for r in rows if r[3] == "lift_off")

    def hops(**air):
        world = kreisel.World(0.01, gravity=(0.0, 0.0, -G))
        rim = dict(shape="disk", radius=0.0375, normal=(0.0, 0.0, 1.0), friction="coulomb", mu=0.5, **air)
        disk = world.add_body(
            0.4, moments=(1.40625e-4, 1.40625e-4, 2.8125e-4), attitude=kreisel.from_euler("XYZ", [0.0, 0.2, 0.0]),
            omega_body=(-14.418307381379831, 0.0, 0.0), contacts=[rim],
        )  # fmt: skip
        for _ in range(int(round(cli_hop / 0.01)) + 1):
            world.advance_steps(1)
        return [e[0] for e in world.events(disk) if e[2] == "lift_off"]

    with_air = hops(air_viscosity=2.5e-3, air_gap=3.75e-5)
    assert with_air and abs(with_air[0] - cli_hop) < 1e-9, (with_air, cli_hop)
    assert hops() == []


def test_a_body_inside_the_table_names_position():
    world = kreisel.World(0.01, gravity=(0.0, 0.0, -G))
    law = dict(shape="sphere", radius=0.1, mu=0.3)
    with pytest.raises(kreisel.KreiselError) as e:
        world.add_body(1.0, moments=(0.004,) * 3, position=(0.0, 0.0, 0.09), contacts=[law])
    assert str(e.value).startswith("position: contacts[0] is below the table at the start"), str(e.value)
    assert "z = -0.01" in str(e.value)
    assert len(world) == 0


def test_other_bad_table_bodies():
    world = kreisel.World(0.01, gravity=(0.0, 0.0, -G))
    law = dict(shape="sphere", radius=0.1, mu=0.3)
    cases = [
        (dict(contacts=[]), "contacts: 0 contacts"),
        (dict(contacts=[law] * 9), "contacts: 9 contacts"),
        (dict(contacts=[law], pivot=(0, 0, 0.1)), "pivot cannot be given with contacts"),
        (dict(contacts=[law], torque=(0, 0, 1)), "torque: applied loads are not modelled"),
        (dict(contacts=[law], angular_damping=0.1), "angular_damping: applied loads are not modelled"),
    ]
    for kwargs, message in cases:
        with pytest.raises(kreisel.KreiselError) as e:
            world.add_body(1.0, moments=(0.004,) * 3, **kwargs)
        assert str(e.value).startswith(message), str(e.value)
    with pytest.raises(TypeError):
        world.add_body(1.0, moments=(0.004,) * 3, contacts="sphere")
    with pytest.raises(TypeError):
        world.add_body(1.0, moments=(0.004,) * 3, contacts=[1.0])
    # Gravity not along -z: the library's error, named.
    sideways = kreisel.World(0.01, gravity=(0.0, -G, 0.0))
    with pytest.raises(kreisel.KreiselError) as e:
        sideways.add_body(1.0, moments=(0.004,) * 3, contacts=[law])
    assert str(e.value).startswith("gravity:"), str(e.value)
    assert len(world) == 0 and len(sideways) == 0


def test_painleves_rod_beyond_the_bound_names_mu():
    # Painlevé's rod (1 kg, 1 m, I = m L^2/12, a 1 mm ball at its lower end)
    # leaning at atan 2 and sliding end first: the normal force's coefficient
    # kappa = 1/m + (l c)^2/I - mu l c (l s + r)/I is negative beyond
    # mu* = 4/3 (r -> 0); at mu = 2 the World refuses it, naming mu.
    theta, l, r, inertia, mu = math.atan(2.0), 0.5, 0.001, 1.0 / 12.0, 2.0
    s, c = math.sin(theta), math.cos(theta)
    kappa = 1.0 + (l * c) ** 2 / inertia - mu * l * c * (l * s + r) / inertia
    world = kreisel.World(0.01, gravity=(0.0, 0.0, -G))
    half = theta / 2.0
    end = dict(shape="sphere", radius=r, center=(-l, 0.0, 0.0), mu=mu)
    with pytest.raises(kreisel.KreiselError) as e:
        world.add_body(
            1.0, moments=(0.001, inertia, inertia), attitude=(math.cos(half), 0.0, -math.sin(half), 0.0),
            velocity=(-1.0, 0.0, 0.0), contacts=[end],
        )  # fmt: skip
    message = str(e.value)
    assert message.startswith("contacts[0].mu: 2 is beyond the Painlevé bound of its slip"), message
    printed = float(message.split("(compliance ")[1].split(" ")[0])
    assert abs(printed - kappa) < 1e-12, (printed, kappa)
    assert len(world) == 0
