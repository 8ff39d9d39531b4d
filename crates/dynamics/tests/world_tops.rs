//! Heavy tops with inputs (a motor spinning a top up against damping; an
//! asymmetric top pushed by a world torque and a force at a body point)
//! against the references `top_motor` and `top_pushed` of
//! `tests/data/forced/` (`python3 tests/data/gen/forced.py`: the equations
//! about the pivot written from the physics, mpmath Gragg–Bulirsch–Stoer at
//! 32 digits, checked against scipy DOP853), through the splitting and
//! through the World, with and without a tolerance.
//!
//! `cargo test -p kreisel-dynamics --release --test world_tops -- --nocapture`
//! prints the measured errors and orders.

use glam::DVec3;
use kreisel_dynamics::{Body, ForcedSplitting, HeavyTopMethod, Plan, Tolerance, World};
use kreisel_inertia::MassProperties;

mod common;
use common::forced_refs::{Reference, TOP_NAMES, load};

/// The worst attitude error over the samples with `n` steps per sample
/// interval.
fn splitting_error(r: &Reference, method: ForcedSplitting, n: usize) -> f64 {
    r.run(method, n).0
}

/// The reference's body on its pivot with its inputs, as a World body.
fn body(r: &Reference) -> Body {
    let (pivot_body, pivot_world) = r.pivot.expect("a top reference");
    let s0 = &r.samples[0];
    Body::from_mass_properties(MassProperties::new(r.body.mass(), DVec3::ZERO, r.inertia))
        .world_from_body(Reference::attitude(s0))
        .omega_body(DVec3::new(s0[5], s0[6], s0[7]))
        .pivot(pivot_body, pivot_world)
        .try_build()
        .unwrap()
        .with_inputs(r.body.inputs().clone())
        .unwrap()
}

/// The splittings about the pivot converge at their orders, and order 8 at
/// dt = 0.01 is within 1e-10 rad over the 10 s.
#[test]
fn the_splittings_about_the_pivot_converge_at_their_orders() {
    for name in TOP_NAMES {
        let r = load(name);
        for (method, n) in [(ForcedSplitting::ORDER_4, 2), (ForcedSplitting::ORDER_6, 2)] {
            let (coarse, fine) = (
                splitting_error(&r, method, n),
                splitting_error(&r, method, 2 * n),
            );
            let order = (coarse / fine).log2();
            println!(
                "{name:>10} {}: {coarse:.1e} → {fine:.1e}, order {order:.2}",
                method.name()
            );
            assert!(
                (f64::from(method.order()) - order).abs() < 0.5,
                "{name} {}: {order}",
                method.name()
            );
        }
        let err = splitting_error(&r, ForcedSplitting::ORDER_8, 10);
        println!("{name:>10} splitting8 at dt = 0.01: {err:.1e} rad");
        assert!(err <= 1e-10, "{name}: {err:e}");
    }
}

/// Through the World (heavy-top method auto: order 8 within its
/// stability limit) at dt = 0.01: the attitude and the centre of mass
/// follow the reference, and the energy column changes by the work done.
#[test]
fn the_world_drives_tops_as_the_references() {
    for name in TOP_NAMES {
        let r = load(name);
        let mut world = World::try_new(r.body.gravity_world(), 0.01).unwrap();
        let id = world.add(body(&r)).unwrap();
        assert_eq!(
            world.plan(id),
            Some(&Plan::DrivenTop {
                method: ForcedSplitting::ORDER_8
            })
        );
        let e0 = world.state(id).unwrap().energy;
        let (mut worst, mut worst_x, mut worst_work): (f64, f64, f64) = (0.0, 0.0, 0.0);
        for sample in &r.samples[1..] {
            world.advance_to(sample[0]).unwrap();
            let s = world.state(id).unwrap();
            worst = worst.max(kreisel_kinematics::rotation_angle_between(
                s.world_from_body,
                Reference::attitude(sample),
            ));
            worst_x =
                worst_x.max((s.position - DVec3::new(sample[8], sample[9], sample[10])).length());
            let scale = e0.abs().max(sample[14].abs());
            worst_work = worst_work.max(((s.energy - e0) - sample[14]).abs() / scale);
        }
        println!(
            "{name:>10}: {worst:.1e} rad, |Δx| {worst_x:.1e} m, energy − work {worst_work:.1e}"
        );
        assert!(worst <= 1e-10, "{name}: {worst:e} rad");
        assert!(worst_x <= 1e-10, "{name}: {worst_x:e} m");
        assert!(worst_work <= 1e-12, "{name}: {worst_work:e}");
    }
}

/// With a tolerance the World picks a cheaper splitting for the driven tops
/// and meets it.
#[test]
fn driven_tops_meet_a_tolerance() {
    for name in TOP_NAMES {
        let r = load(name);
        for tol in [1e-4, 1e-7] {
            let mut world = World::try_new(r.body.gravity_world(), 0.1).unwrap();
            world
                .set_tolerance(Some(Tolerance::new(tol, 10.0)))
                .unwrap();
            let id = world.add(body(&r)).unwrap();
            let choice = *world.choice(id).expect("a driven top gets a choice");
            let mut worst: f64 = 0.0;
            for sample in &r.samples[1..] {
                world.advance_to(sample[0]).unwrap();
                worst = worst.max(kreisel_kinematics::rotation_angle_between(
                    world.state(id).unwrap().world_from_body,
                    Reference::attitude(sample),
                ));
            }
            println!("{name:>10} {tol:.0e}: {worst:.1e} rad ({choice})");
            assert!(worst <= tol, "{name} {tol:e}: {worst:e} ({choice})");
        }
    }
}

/// A tolerance on a heavy top without inputs under a method the user chose
/// changes nothing: the tolerance chooses only under `auto`.
#[test]
fn a_tolerance_leaves_a_chosen_heavy_top_method_alone() {
    let r = load("top_motor");
    let top = body(&r)
        .with_inputs(kreisel_dynamics::Inputs::default())
        .unwrap();
    let mut world = World::try_new(r.body.gravity_world(), 0.01).unwrap();
    world
        .set_heavy_top_method(HeavyTopMethod::Splitting4)
        .unwrap();
    world
        .set_tolerance(Some(Tolerance::new(1e-6, 10.0)))
        .unwrap();
    let id = world.add(top).unwrap();
    assert_eq!(
        world.plan(id),
        Some(&Plan::HeavyTop(HeavyTopMethod::Splitting4))
    );
    assert!(world.choice(id).is_none());
}
