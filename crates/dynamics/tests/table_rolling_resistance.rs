//! The set-valued rolling resistance (issue 26: "optional rolling
//! resistance"): a solid ball (I = ⅖ m R²) on the table with Coulomb
//! friction μ and rolling resistance δ — the rolling torque at most δ N,
//! holding the rolling below that. Closed forms from Newton and Euler
//! about the centre (contact force `f x̂` at the bottom, rolling torque
//! `−δ m g ŷ` while it rolls along +x):
//!
//! ```text
//! rolling, no slip:   m v̇ = f,   I ω̇_y = −R f − δ m g,   v = ω_y R
//!                     ⇒ v̇ = −δ g/(R (1 + I/(m R²))) = −(5/7) δ g/R, stops at v₀/|v̇|
//! thrown sliding:     v̇ = −μ g,   I ω̇_y = m g (μ R − δ)   until v = ω_y R
//! pushed by F:        holds while F ≤ δ m g/R; else v̇ = (F − δ m g/R)/(m + I/R²)
//! ```

use glam::{DMat3, DQuat, DVec3};
use kreisel_dynamics::{
    AdaptiveTolerance, ContactLaw, ContactMode, ContactShape, GroundTopState, Inputs,
    SphereContact, TableBody, TableContact, TableEventKind, TableMotion,
};

const M: f64 = 0.2;
const R: f64 = 0.05;
const G: f64 = 9.81;
const MU: f64 = 0.3;
/// The rolling resistance δ, m.
const DELTA: f64 = 1e-3;
/// `I/(m R²)` of a solid ball.
const K: f64 = 0.4;

/// The ball on the table with velocity `v0` along x and spin `omega_y`.
fn ball(v0: f64, omega_y: f64, push: f64) -> TableMotion {
    let shape = ContactShape::Sphere(SphereContact::try_new(R, DVec3::ZERO).unwrap());
    let law = ContactLaw::try_new(MU)
        .and_then(|l| l.try_with_rolling_resistance(DELTA))
        .unwrap();
    let inertia = K * M * R * R;
    let mut body = TableBody::try_new(
        M,
        DMat3::from_diagonal(DVec3::splat(inertia)),
        vec![TableContact { shape, law }],
        G,
    )
    .unwrap();
    if push != 0.0 {
        body = body
            .try_with_inputs(Inputs::default().with_force_world(DVec3::new(push, 0.0, 0.0)))
            .unwrap();
    }
    let start = GroundTopState {
        com_world: DVec3::new(0.0, 0.0, R),
        velocity_world: DVec3::new(v0, 0.0, 0.0),
        world_from_body: DQuat::IDENTITY,
        l_world: DVec3::new(0.0, inertia * omega_y, 0.0),
    };
    TableMotion::try_new(body, start, AdaptiveTolerance::new(1e-12, 1e-12)).unwrap()
}

/// The time of the first event of `kind`.
fn time_of(run: &TableMotion, kind: TableEventKind) -> f64 {
    run.events()
        .iter()
        .find(|e| e.kind == kind)
        .unwrap_or_else(|| panic!("no {kind:?} in {:?}", run.events()))
        .time
}

#[test]
fn a_rolling_ball_slows_uniformly_and_stops_at_the_closed_form_time() {
    let v0 = 1.0;
    let mut run = ball(v0, v0 / R, 0.0);
    assert_eq!(run.modes(), vec![ContactMode::Sticking]);
    let a = DELTA * G / (R * (1.0 + K));
    let t_stop = v0 / a;
    // Mid-way: the uniform deceleration, rolling without slipping.
    run.try_advance_to(3.0).unwrap();
    let s = *run.state();
    assert!((s.velocity_world.x - (v0 - 3.0 * a)).abs() < 1e-12);
    assert!((s.com_world.x - (3.0 * v0 - 4.5 * a)).abs() < 1e-11);
    let omega = run.body().omega_world(&s);
    assert!((omega.y * R - s.velocity_world.x).abs() < 1e-12);
    run.try_advance_to(t_stop + 1.0).unwrap();
    let stop = time_of(&run, TableEventKind::StopsRolling);
    assert!((stop - t_stop).abs() < 1e-9 * t_stop, "{stop} vs {t_stop}");
    assert!(run.is_resting(), "{:?}", run.events());
    let x = run.state().com_world.x;
    assert!((x - v0 * v0 / (2.0 * a)).abs() < 1e-9, "{x}");
    assert!(run.state().velocity_world.length() < 1e-12);
}

#[test]
fn a_ball_thrown_sliding_rolls_then_stops_as_the_closed_forms_say_on_any_grid() {
    let v0 = 2.0;
    // Sliding: v = v0 − μ g t, ω_y R = m g R (μ R − δ) t/I, until they meet.
    let spin_rate = (MU * R - DELTA) * G / (K * R * R) * R;
    let t1 = v0 / (MU * G + spin_rate);
    let v1 = v0 - MU * G * t1;
    let x1 = v0 * t1 - 0.5 * MU * G * t1 * t1;
    let a = DELTA * G / (R * (1.0 + K));
    let (t2, x2) = (t1 + v1 / a, x1 + v1 * v1 / (2.0 * a));
    let end = t2 + 0.5;
    // One call, and frames of a game step, 1e-3 and 1e-5 s.
    for dt in [end, 1.0 / 60.0, 1e-3] {
        let mut run = ball(v0, 0.0, 0.0);
        assert_eq!(run.modes(), vec![ContactMode::Slipping]);
        let mut energy = f64::INFINITY;
        let frames = (end / dt).ceil() as usize;
        for k in 1..=frames {
            run.try_advance_to((k as f64 * dt).min(end)).unwrap();
            let s = run.state();
            let omega = run.body().omega_world(s);
            let e = 0.5 * M * s.velocity_world.length_squared() + 0.5 * s.l_world.dot(omega);
            assert!(
                e <= energy + 1e-15,
                "energy rose at {}: {e} > {energy}",
                run.time()
            );
            energy = e;
        }
        let stick = time_of(&run, TableEventKind::Stick);
        assert!((stick - t1).abs() < 1e-10, "dt {dt}: stick {stick} vs {t1}");
        let stop = time_of(&run, TableEventKind::StopsRolling);
        assert!((stop - t2).abs() < 1e-9 * t2, "dt {dt}: {stop} vs {t2}");
        assert!(run.is_resting());
        let x = run.state().com_world.x;
        assert!((x - x2).abs() < 1e-9, "dt {dt}: {x} vs {x2}");
    }
}

#[test]
fn a_push_below_delta_m_g_over_r_is_held_and_above_it_rolls() {
    let threshold = DELTA * M * G / R;
    let mut held = ball(0.0, 0.0, 0.5 * threshold);
    held.try_advance_to(1.0).unwrap();
    assert!(
        held.state().com_world.x.abs() < 1e-15,
        "{}",
        held.state().com_world.x
    );
    assert_eq!(held.modes(), vec![ContactMode::Sticking]);
    // Only the start's touchdown: it never starts to roll or slip.
    let kinds: Vec<_> = held.events().iter().map(|e| e.kind).collect();
    assert_eq!(kinds, vec![TableEventKind::Touchdown]);

    let push = 3.0 * threshold;
    let mut rolled = ball(0.0, 0.0, push);
    rolled.try_advance_to(1.0).unwrap();
    let a = (push - threshold) / (M * (1.0 + K));
    let x = rolled.state().com_world.x;
    assert!((x - 0.5 * a).abs() < 1e-12, "{x} vs {}", 0.5 * a);
    let omega = rolled.body().omega_world(rolled.state());
    assert!((omega.y - a / R).abs() < 1e-10, "{omega}");
}
