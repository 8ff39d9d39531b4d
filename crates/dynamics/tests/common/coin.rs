//! A coin on the table (issue 26), the shared test problem of
//! `tests/table_coin.rs` and `tests/table_regressions.rs`: 5 g, radius
//! 12 mm, thin (`I = m a² (¼, ¼, ½)`), Coulomb μ = 0.3, Newton e = 0.5,
//! its centre of mass 10 cm above the table, tilted 0.6 rad about x.

use glam::{DMat3, DQuat, DVec3};
use kreisel_dynamics::{
    AdaptiveTolerance, ContactLaw, ContactShape, DiskContact, GroundTopState, TableBody,
    TableContact, TableMotion,
};

/// The coin's mass, kg.
pub const M: f64 = 0.005;
/// Its radius, m.
pub const A: f64 = 0.012;
/// Its tilt at the start, rad.
pub const TILT: f64 = 0.6;
/// Its centre's height at the start, m.
pub const HEIGHT: f64 = 0.1;

/// The coin released with `velocity_world` and `l_world`, tolerance
/// `rtol` = atol.
pub fn dropped_coin(velocity_world: DVec3, l_world: DVec3, rtol: f64) -> TableMotion {
    let rim = DiskContact::try_new(A, DVec3::ZERO, DVec3::Z).unwrap();
    let law = ContactLaw::new(0.3).try_with_restitution(0.5).unwrap();
    let inertia = DMat3::from_diagonal(DVec3::new(0.25, 0.25, 0.5) * M * A * A);
    let contacts = vec![TableContact {
        shape: ContactShape::Disk(rim),
        law,
    }];
    let body = TableBody::try_new(M, inertia, contacts, 9.81).unwrap();
    let start = GroundTopState {
        com_world: DVec3::new(0.0, 0.0, HEIGHT),
        velocity_world,
        world_from_body: DQuat::from_rotation_x(TILT),
        l_world,
    };
    TableMotion::try_new(body, start, AdaptiveTolerance::new(rtol, rtol)).unwrap()
}

/// Advances `run` over `frames` frames of `dt`, asserting at each that the
/// energy is at most the previous frame's plus `1e-12 E₀`.
pub fn advance_never_gaining(run: &mut TableMotion, frames: u32, dt: f64) {
    let e0 = run.body().energy(run.state());
    let mut previous = e0;
    for k in 1..=frames {
        run.try_advance_to(dt * f64::from(k)).unwrap();
        previous = energy_not_above(run, previous, e0);
    }
}

/// The energy of `run` now, asserted at most `previous + 1e-12 E₀`.
pub fn energy_not_above(run: &TableMotion, previous: f64, e0: f64) -> f64 {
    let e = run.body().energy(run.state());
    assert!(
        e <= previous + 1e-12 * e0,
        "energy rose at {} s",
        run.time()
    );
    e
}
