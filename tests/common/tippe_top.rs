//! Leine & Glocker's tippe top (Eur. J. Mech. A/Solids 22 (2003) 193), the
//! shared test problem of `tests/contact_*.rs` and `benches/tippe_top.rs`.

use glam::{DMat3, DQuat, DVec2, DVec3};
use kreisel::dynamics::{Friction, GroundTop, GroundTopState, SphereContact};

/// Mass, kg.
pub const M: f64 = 0.006;
/// Ball radius, m.
pub const R: f64 = 0.015;
/// The ball's centre from the centre of mass towards the stem, m (the
/// centre of mass is `A` below the ball's centre with the stem up).
pub const A: f64 = 0.003;
/// Transverse and axial moments of inertia, kg m².
pub const I1: f64 = 8e-7;
/// See [`I1`].
pub const I3: f64 = 7e-7;
/// Initial tilt, rad, and spin about the axis, rad/s.
pub const THETA0: f64 = 0.1;
/// See [`THETA0`].
pub const OMEGA0: f64 = 180.0;
/// The published friction coefficient (Coulomb's μ; s/m for viscous).
pub const MU: f64 = 0.3;
/// Gravity, m/s².
pub const G: f64 = 9.81;

/// The top with `friction`, tilted by θ₀ about x, spinning at ω₀ about its
/// axis, touching the floor: centre of mass at rest, or, with
/// [`Friction::Rolling`], moving so that the contact point is at rest
/// (`v_G = −ω × ρ`).
pub fn leine_glocker(friction: Friction) -> (GroundTop, GroundTopState) {
    let sphere = SphereContact::try_new(R, DVec3::new(0.0, 0.0, A)).unwrap();
    let inertia = DMat3::from_diagonal(DVec3::new(I1, I1, I3));
    let top = GroundTop::try_new(M, inertia, sphere, friction, G).unwrap();
    let q = DQuat::from_rotation_x(THETA0);
    let omega = q * DVec3::new(0.0, 0.0, OMEGA0);
    let s = match friction {
        Friction::Rolling => top.try_rolling_state_on_ground(q, omega),
        _ => top.try_state_on_ground(q, omega, DVec2::ZERO),
    }
    .unwrap();
    (top, s)
}

/// The state as one vector of comparable size: positions over R,
/// velocities over R ω₀, the attitude, L over |L₀| (`l0`).
pub fn flat(s: &GroundTopState, l0: f64) -> Vec<f64> {
    let q = s.world_from_body.normalize();
    let mut v = Vec::new();
    v.extend((s.com_world / R).to_array());
    v.extend((s.velocity_world / (R * OMEGA0)).to_array());
    v.extend(q.to_array());
    v.extend((s.l_world / l0).to_array());
    v
}

/// The Euclidean distance of two [`flat`] states.
pub fn distance(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).powi(2))
        .sum::<f64>()
        .sqrt()
}
