//! The ball dropped on the table (issue 26), the shared test problem of
//! `tests/table_bouncing_ball.rs`, `benches/table.rs` and
//! `examples/table_work_precision.rs`: radius 0.1 m, mass 0.5 kg (a solid
//! sphere), its centre at 1 m, frictionless, Newton's e = 0.9, g = 9.81.

use glam::{DMat3, DQuat, DVec3};
use kreisel_dynamics::{
    AdaptiveTolerance, ContactLaw, ContactShape, GroundTopState, SphereContact, TableBody,
    TableContact, TableMotion,
};

/// Gravity, m/s².
pub const G: f64 = 9.81;
/// The ball's radius, m.
pub const R: f64 = 0.1;
/// Its centre's height at the start, m.
pub const H0: f64 = 1.0;
/// Newton's restitution.
pub const E: f64 = 0.9;

/// The dropped ball run by the nonsmooth engine at `rtol` (= atol).
pub fn dropped_ball(rtol: f64) -> TableMotion {
    let shape = ContactShape::Sphere(SphereContact::try_new(R, DVec3::ZERO).unwrap());
    let law = ContactLaw::new(0.0).try_with_restitution(E).unwrap();
    let m = 0.5;
    let inertia = DMat3::from_diagonal(DVec3::splat(0.4 * m * R * R));
    let body = TableBody::try_new(m, inertia, vec![TableContact { shape, law }], G).unwrap();
    let start = GroundTopState {
        com_world: DVec3::new(0.0, 0.0, H0),
        velocity_world: DVec3::ZERO,
        world_from_body: DQuat::IDENTITY,
        l_world: DVec3::ZERO,
    };
    TableMotion::try_new(body, start, AdaptiveTolerance::new(rtol, rtol)).unwrap()
}
