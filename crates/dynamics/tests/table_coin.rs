//! A coin dropped at a tilt on the table (issue 26): it bounces on its rim
//! (Newton e = 0.5, Coulomb μ = 0.3), never gaining energy, rocks through
//! flat (its far rim point strikes), lands on its face and comes to rest
//! there — never with chattering modes or a wrong state (regression: the
//! rim's contact point jumped across the rim and the modes chattered at
//! 0.2869 s; then the run stopped with `DiskFlat` where the face lands).

use glam::DVec3;
use kreisel_dynamics::TableEventKind;

mod common;

use common::coin::{A, HEIGHT, TILT, dropped_coin, energy_not_above};

#[test]
fn a_dropped_coin_bounces_on_its_rim_lands_flat_and_rests() {
    let mut run = dropped_coin(DVec3::ZERO, DVec3::ZERO, 1e-9);
    let e0 = run.body().energy(run.state());
    // The first impact: the rim's lowest point falls from its start height.
    let drop = HEIGHT - A * TILT.sin();
    let mut previous = e0;
    loop {
        match run.try_advance_until_event(3.0) {
            Ok(true) => previous = energy_not_above(&run, previous, e0),
            Ok(false) => break,
            Err(e) => panic!("{e} after {:?}", run.events().last()),
        }
    }
    let first = run.events()[0];
    assert!(matches!(first.kind, TableEventKind::Impact { .. }));
    assert!(
        (first.time - (2.0 * drop / 9.81f64).sqrt()).abs() < 1e-12,
        "{}",
        first.time
    );
    let bounces = run
        .events()
        .iter()
        .filter(|e| matches!(e.kind, TableEventKind::Impact { .. }))
        .count();
    assert!(bounces > 10, "{bounces}");
    // On its face, at rest, its centre of mass on the table (a thin coin).
    assert!(run.is_resting(), "still moving at 3 s");
    assert_eq!(run.lying_flat_on(), Some(0));
    let landing = run
        .events()
        .iter()
        .position(|e| e.kind == TableEventKind::LandsFlat)
        .expect("the face lands");
    assert_eq!(run.events().last().unwrap().kind, TableEventKind::Rest);
    assert!(run.events()[landing].time < run.events().last().unwrap().time + 1e-15);
    let n = run.state().world_from_body.normalize() * DVec3::Z;
    assert!(DVec3::Z.cross(n).length() < 1e-15);
    assert!(run.state().com_world.z.abs() < 1e-15);
    assert_eq!(run.state().velocity_world, DVec3::ZERO);
    assert!(run.body().energy(run.state()) <= previous + 1e-12 * e0);
}
