//! Accuracy as an input for heavy tops: a World given a tolerance moves each
//! reference top of `tests/data/heavy_top/` (60-digit mpmath Taylor series,
//! `python3 tests/data/gen/heavy_top.py`) by the cheapest splitting and
//! sub-steps predicted to meet it (a Lagrange top by its closed form), and
//! meets it.
//!
//! `cargo test --release --test heavy_top_tolerance -- --nocapture` prints
//! each choice and the error reached.

mod common;

use common::heavy_top::{NAMES, load};
use kreisel_dynamics::{Plan, Tolerance, World};
use kreisel_kinematics::rotation_angle_between;

#[test]
fn heavy_tops_meet_the_tolerance_on_every_reference() {
    for name in NAMES {
        let r = load(name);
        let horizon = r.samples.last().unwrap().0;
        let top = r.world_body();
        for tol in [1e-3, 1e-6, 1e-9] {
            let mut world = World::try_new(r.gravity, 0.01).unwrap();
            world
                .set_tolerance(Some(Tolerance::new(tol, horizon)))
                .unwrap();
            let id = world.add(top.clone()).unwrap();
            // A Lagrange top takes its closed form (rounding level, nothing
            // to choose); any other top the cheapest splitting.
            let choice = world
                .choice(id)
                .map_or("closed form".to_owned(), |c| c.to_string());
            if r.top.symmetry_axis().is_some() {
                assert_eq!(world.plan(id), Some(&Plan::LagrangeTop));
                assert!(world.choice(id).is_none());
            } else {
                assert!(
                    matches!(
                        world.plan(id),
                        Some(Plan::HeavyTop(_) | Plan::HeavyTopSeries)
                    ),
                    "{choice}"
                );
            }
            let mut worst: f64 = 0.0;
            for &(t, q, _) in &r.samples[1..] {
                world.advance_to(t).unwrap();
                worst = worst.max(rotation_angle_between(
                    world.state(id).unwrap().world_from_body,
                    q,
                ));
            }
            println!("{name:>16} {tol:.0e}: {worst:.1e} rad ({choice})");
            assert!(worst <= tol, "{name} at {tol:e}: {worst:e} rad ({choice})");
        }
    }
}
