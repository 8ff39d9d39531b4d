//! Accuracy as an input: a [`World`] given a [`Tolerance`] meets it on every
//! reference that does not come from kreisel — the eight forced references
//! of `tests/data/forced/` (mpmath Gragg–Bulirsch–Stoer) and the free-body
//! references of `tests/data/free_body/` (mpmath Taylor, 60 digits) — and
//! spends less work than the default plan where the tolerance allows.
//!
//! `cargo test -p kreisel-dynamics --release --test world_tolerance -- --nocapture`
//! prints each choice and the error reached.

use glam::DVec3;
use kreisel_dynamics::{Body, FreeBodyMethod, Plan, Tolerance, World};
use kreisel_inertia::MassProperties;
use kreisel_kinematics::rotation_angle_between;

mod common;
use common::forced_refs::{NAMES, load};

use common::free_body;

const TOLERANCES: [f64; 4] = [1e-3, 1e-5, 1e-7, 1e-9];

/// Every forced reference, at every tolerance, on the references' own
/// sampling step (0.1 s) as the world's `dt`: the worst attitude error over
/// the 10 s stays within the tolerance, and a loose tolerance costs less
/// than the default (splitting6 at one step per dt).
#[test]
fn forced_bodies_meet_the_tolerance_on_every_reference() {
    let mut cheaper = 0;
    for name in NAMES {
        let r = load(name);
        let dt = r.sample_dt();
        let horizon = r.samples.last().unwrap()[0];
        let rigid = *r.body.body();
        let s0 = &r.start;
        let body =
            Body::from_mass_properties(MassProperties::new(r.body.mass(), DVec3::ZERO, r.inertia))
                .world_from_body(s0.rotation.world_from_body(&rigid))
                .omega_body(s0.rotation.omega_body(&rigid))
                .free(s0.position_world, s0.velocity_world)
                .try_build()
                .unwrap()
                .with_inputs(r.body.inputs().clone())
                .unwrap();
        for tol in TOLERANCES {
            let mut world = World::try_new(r.body.gravity_world(), dt).unwrap();
            world
                .set_tolerance(Some(Tolerance::new(tol, horizon)))
                .unwrap();
            let id = world.add(body.clone()).unwrap();
            let choice = *world.choice(id).expect("a forced body gets a choice");
            assert!(matches!(world.plan(id), Some(Plan::Forced { .. })));
            let mut worst: f64 = 0.0;
            for (k, sample) in r.samples.iter().enumerate().skip(1) {
                world.advance_to(sample[0]).unwrap();
                let q = world.state(id).unwrap().world_from_body;
                worst = worst.max(rotation_angle_between(
                    q,
                    common::forced_refs::Reference::attitude(&r.samples[k]),
                ));
            }
            println!("{name:>24} {tol:.0e}: {worst:.1e} rad  ({choice})");
            assert!(worst <= tol, "{name} at {tol:e}: {worst:e} rad ({choice})");
            assert!(choice.predicted <= tol, "{choice}");
            if tol == 1e-3 && choice.work < choice.default_work {
                cheaper += 1;
            }
        }
    }
    // A loose tolerance buys speed on every reference.
    assert_eq!(cheaper, NAMES.len());
}

/// The asymmetric free-body references, read every frame of a game loop
/// (dt = 1/60): the tolerance is met, RK4 is chosen where it is predicted
/// to meet it (half the exact solution's work per frame), and the exact
/// solution otherwise.
#[test]
fn free_bodies_meet_the_tolerance_read_every_frame() {
    let dt = 1.0 / 60.0;
    for name in [
        "rapier",
        "hlw",
        "near_separatrix_7",
        "near_separatrix_12",
        "separatrix",
        "ratio_1000",
        "ratio_1000b",
    ] {
        let r = free_body::load(name);
        let (_, q0, l0) = r.samples[0];
        let horizon = r.samples.last().unwrap().0;
        let body = Body::from_principal_moments(1.0, r.moments)
            .world_from_body(q0)
            .omega_body(l0 / r.moments)
            .try_build()
            .unwrap();
        for tol in TOLERANCES {
            let mut world = World::try_new(DVec3::ZERO, dt).unwrap();
            world
                .set_tolerance(Some(Tolerance::new(tol, horizon)))
                .unwrap();
            let id = world.add(body.clone()).unwrap();
            let choice = world.choice(id).copied();
            let mut worst: f64 = 0.0;
            for &(t, q, _) in &r.samples[1..] {
                world.advance_to(t).unwrap();
                worst = worst.max(rotation_angle_between(
                    world.state(id).unwrap().world_from_body,
                    q,
                ));
            }
            let plan = *world.plan(id).unwrap();
            let shown = choice.map_or("none".to_owned(), |c| c.to_string());
            println!("{name:>20} {tol:.0e}: {worst:.1e} rad  {plan:?}  ({shown})");
            assert!(worst <= tol, "{name} at {tol:e}: {worst:e} rad ({shown})");
            if let Some(c) = choice {
                let expected = match c.method {
                    "rk4" => Plan::Stepping(FreeBodyMethod::Rk4),
                    "pdmv6" => Plan::Stepping(FreeBodyMethod::Pdmv6),
                    _ => Plan::Asymmetric,
                };
                assert_eq!(plan, expected);
            }
        }
    }
}

/// A tolerance at the rounding level keeps the default plans bit for bit.
#[test]
fn a_tolerance_at_rounding_level_changes_nothing() {
    let r = load("asymmetric_world_torque");
    let rigid = *r.body.body();
    let body = Body::from_mass_properties(MassProperties::new(1.0, DVec3::ZERO, r.inertia))
        .world_from_body(r.start.rotation.world_from_body(&rigid))
        .omega_body(r.start.rotation.omega_body(&rigid))
        .try_build()
        .unwrap()
        .with_inputs(r.body.inputs().clone())
        .unwrap();
    let mut states = Vec::new();
    for tol in [None, Some(Tolerance::new(1e-11, 10.0))] {
        let mut world = World::try_new(DVec3::ZERO, 0.01).unwrap();
        world.set_tolerance(tol).unwrap();
        let id = world.add(body.clone()).unwrap();
        assert!(world.choice(id).is_none());
        world.advance_to(3.0).unwrap();
        states.push(world.state(id).unwrap());
    }
    assert_eq!(states[0], states[1]);
}
