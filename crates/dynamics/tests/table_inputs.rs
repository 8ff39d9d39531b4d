//! Applied inputs on a body on the table (issue 26): a solid ball pushed
//! through its centre by a constant horizontal force, with Coulomb
//! friction μ. Closed forms (Newton and Euler about the centre, the
//! contact force `f` at the bottom):
//!
//! ```text
//! rolls when (2/7) F ≤ μ m g:   a = (5/7) F/m,   ω̇ = a/R,   f = (2/7) F
//! slips otherwise:              a = (F − μ m g)/m,  ω̇ = (5/2) μ g/R
//! ```

use glam::{DMat3, DQuat, DVec3};
use kreisel_dynamics::{
    AdaptiveTolerance, ContactLaw, ContactMode, ContactShape, GroundTopState, Inputs,
    SphereContact, TableBody, TableContact, TableMotion,
};

const M: f64 = 0.2;
const R: f64 = 0.05;
const G: f64 = 9.81;
const MU: f64 = 0.2;

fn pushed(force: f64) -> TableMotion {
    let shape = ContactShape::Sphere(SphereContact::try_new(R, DVec3::ZERO).unwrap());
    let body = TableBody::try_new(
        M,
        DMat3::from_diagonal(DVec3::splat(0.4 * M * R * R)),
        vec![TableContact {
            shape,
            law: ContactLaw::new(MU),
        }],
        G,
    )
    .unwrap()
    .try_with_inputs(Inputs::default().with_force_world(DVec3::new(force, 0.0, 0.0)))
    .unwrap();
    let start = GroundTopState {
        com_world: DVec3::new(0.0, 0.0, R),
        velocity_world: DVec3::ZERO,
        world_from_body: DQuat::IDENTITY,
        l_world: DVec3::ZERO,
    };
    TableMotion::try_new(body, start, AdaptiveTolerance::new(1e-12, 1e-12)).unwrap()
}

#[test]
fn a_gentle_push_rolls_the_ball() {
    let force = 0.3 * MU * M * G; // (2/7) F < μ m g
    let mut run = pushed(force);
    assert_eq!(run.modes(), vec![ContactMode::Sticking]);
    run.try_advance_to(1.0).unwrap();
    let a = 5.0 / 7.0 * force / M;
    let s = run.state();
    assert!(
        (s.com_world.x - 0.5 * a).abs() < 1e-12,
        "{} vs {}",
        s.com_world.x,
        0.5 * a
    );
    assert!((s.velocity_world.x - a).abs() < 1e-12);
    // Rolling: ω_y = v/R.
    let omega = run.body().omega_world(s);
    assert!((omega.y - a / R).abs() < 1e-10, "{omega:?}");
    assert_eq!(run.modes(), vec![ContactMode::Sticking]);
}

#[test]
fn a_hard_push_slips_the_ball() {
    let force = 5.0 * MU * M * G;
    let mut run = pushed(force);
    assert_eq!(run.modes(), vec![ContactMode::Slipping]);
    run.try_advance_to(0.5).unwrap();
    let a = (force - MU * M * G) / M;
    let s = run.state();
    assert!(
        (s.velocity_world.x - 0.5 * a).abs() < 1e-12,
        "{} vs {}",
        s.velocity_world.x,
        0.5 * a
    );
    let omega = run.body().omega_world(s);
    assert!((omega.y - 2.5 * MU * G / R * 0.5).abs() < 1e-9, "{omega:?}");
    // Still slipping: v − ω R = (a − (5/2) μ g) t > 0.
    assert_eq!(run.modes(), vec![ContactMode::Slipping]);
}
