//! Random free bodies (physical moments, principal frames, attitudes,
//! angular velocities): after each of N free steps the adapter's `f64`
//! `L_world` is the start's to 1e-12 relative, and its attitude is the
//! exact motion's (`ExactSolution`, f64, from the same start) to 1e-9 rad.

mod common;

use common::{angle, exact_attitude, exact_from_managed, free_world};
use kreisel_rapier::{Carrier, ExactRotation};
use proptest::prelude::*;
use rapier3d::prelude::*;

/// Free steps per case (1 s at rapier's 1/60).
const STEPS: usize = 60;

fn vector(range: f32) -> impl Strategy<Value = Vector> {
    (-range..range, -range..range, -range..range).prop_map(|(x, y, z)| Vector::new(x, y, z))
}

/// Principal moments of some mass distribution: `Iᵢ = Σ_{j≠i} s_j` with
/// second moments `s ≥ 0.01` (so the triangle inequality holds); one case
/// in four symmetric (`s₁ = s₂`, so `I₁ = I₂`).
fn moments() -> impl Strategy<Value = Vector> {
    (
        0.01f32..1.0,
        0.01f32..1.0,
        0.01f32..1.0,
        prop::bool::weighted(0.25),
    )
        .prop_map(|(s1, s2, s3, symmetric)| {
            let s2 = if symmetric { s1 } else { s2 };
            Vector::new(s2 + s3, s1 + s3, s1 + s2)
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, ..ProptestConfig::default() })]

    #[test]
    fn free_flight_conserves_l_and_follows_the_exact_motion(
        moments in moments(),
        frame in vector(3.0),
        com in vector(0.5),
        rotation in vector(3.0),
        omega in vector(6.0),
    ) {
        prop_assume!(omega.length() > 0.05);
        let mut world = free_world();
        let dt = f64::from(world.integration_parameters.dt);
        let handle = common::body_with_moments(
            &mut world,
            moments,
            Rotation::from_scaled_axis(frame),
            com,
            Rotation::from_scaled_axis(rotation),
            omega,
        );
        let mut exact = ExactRotation::new();
        exact.manage(&mut world.bodies, &world.colliders, handle).unwrap();
        let start = exact.rotation(handle).unwrap();
        let (reference, lfp) = exact_from_managed(&world.bodies[handle], &start);
        for k in 1..=STEPS {
            exact.step_world(&mut world).unwrap();
            prop_assert_eq!(exact.carrier(handle), Some(Carrier::Kreisel));
            let now = exact.rotation(handle).unwrap();
            let drift = (now.l_world - start.l_world).length() / start.l_world.length();
            prop_assert!(drift <= 1e-12, "step {}: L_world drift {:e}", k, drift);
            let error = angle(now.world_from_body, exact_attitude(&reference, lfp, k as f64 * dt));
            prop_assert!(error <= 1e-9, "step {}: attitude error {:e} rad", k, error);
        }
    }
}
