//! Euler's disk rolling steadily on its rim under Moffatt's air layer
//! (issue 26), the shared test problem of `tests/table_euler_disk.rs` and
//! `examples/table_work_precision.rs`: a thin disk, 0.4 kg, radius
//! 37.5 mm, started in the exact steady rolling with its centre at rest
//! (`Ω² sin α₀ = 4 g/a`, `ω = −Ω sin α₀ û`, û the rim's lowest direction).

use glam::{DMat3, DQuat, DVec3};
use kreisel_dynamics::{
    AdaptiveTolerance, AirLayer, ContactLaw, ContactShape, DiskContact, GroundTopState, TableBody,
    TableContact, TableMotion,
};

/// The disk's mass, kg.
pub const M: f64 = 0.4;
/// Its radius, m.
pub const A: f64 = 0.0375;
/// Gravity, m/s².
pub const G: f64 = 9.81;
/// The air layer's viscosity, Pa s.
pub const MU_AIR: f64 = 2.5e-3;

/// The disk rolling steadily at tilt `alpha0` (centre at rest), friction
/// `mu`, the air layer's floor `floor`, tolerance `rtol` = atol.
pub fn rolling_disk(mu: f64, floor: f64, alpha0: f64, rtol: f64) -> TableMotion {
    let rim = DiskContact::try_new(A, DVec3::ZERO, DVec3::Z).unwrap();
    let law = ContactLaw::new(mu).with_air_layer(AirLayer::try_new(MU_AIR, floor).unwrap());
    let i1 = M * A * A / 4.0;
    let inertia = DMat3::from_diagonal(DVec3::new(i1, i1, 2.0 * i1));
    let contacts = vec![TableContact {
        shape: ContactShape::Disk(rim),
        law,
    }];
    let body = TableBody::try_new(M, inertia, contacts, G).unwrap();
    let q = DQuat::from_rotation_y(alpha0);
    let n = q * DVec3::Z;
    let s = alpha0.sin();
    let u = (n.z * n - DVec3::Z) / s;
    let precession = (4.0 * G / (A * s)).sqrt();
    let start = GroundTopState {
        com_world: DVec3::new(0.0, 0.0, A * s),
        velocity_world: DVec3::ZERO,
        world_from_body: q,
        l_world: -i1 * precession * s * u,
    };
    TableMotion::try_new(body, start, AdaptiveTolerance::new(rtol, rtol)).unwrap()
}
