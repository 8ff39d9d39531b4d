//! Re-synchronisation: rapier state set by user code between steps
//! (angular velocity, rotation, a teleport) is taken over by the adapter's
//! `f64` state, and the free motion after it is again the exact one —
//! `ExactSolution` (f64) started from the `f32` state read after the
//! change.

mod common;

use common::{
    angle, attitude, d, exact_attitude, exact_from, exact_from_managed, free_world, managed,
    tumbling_body,
};
use kreisel_rapier::{Carrier, ExactRotation};
use rapier3d::math::Pose;
use rapier3d::prelude::*;

/// Steps after the change compared with the exact motion (1 s).
const STEPS: usize = 60;

/// An asymmetric body, principal axes tilted against rapier's local axes,
/// centre of mass off the origin, tumbling; managed and carried 20 steps.
fn tumbling() -> (PhysicsWorld, RigidBodyHandle, ExactRotation) {
    let mut world = free_world();
    let handle = tumbling_body(&mut world);
    let mut exact = managed(&mut world, handle);
    for _ in 0..20 {
        exact.step_world(&mut world).unwrap();
    }
    (world, handle, exact)
}

/// What `follows` measured, worst over the `STEPS` steps after a change.
struct Followed {
    /// The adapter's attitude against the exact motion from its own
    /// `f64` state right after the change, rad.
    from_own: f64,
    /// Its `L_world` against that motion's, relative.
    l_from_own: f64,
    /// The adapter's attitude against the exact motion from rapier's
    /// `f32` state read after the change, rad.
    from_f32: f64,
    /// Its `L_world` right after the change against that motion's, relative.
    l_from_f32: f64,
    /// How far the exact motion without the change is after `STEPS`
    /// steps from the one with it, rad (that the change mattered).
    apart: f64,
}

/// Applies `change` to the body mid-flight, then checks that the adapter
/// takes the new state over to `f32` rounding, that the next `STEPS`
/// steps are the exact motion from it, that rapier's `f32` attitude
/// follows, and that the centre of mass stays where rapier put it.
fn follows(change: impl FnOnce(&mut RigidBody)) -> Followed {
    let (mut world, handle, mut exact) = tumbling();
    let dt = f64::from(world.integration_parameters.dt);
    let (unchanged, lfp) = exact_from(&world.bodies[handle]);
    change(&mut world.bodies[handle]);
    let rb = &world.bodies[handle];
    let (from_f32, _) = exact_from(rb);
    let com = d(rb.center_of_mass());

    exact.before_step(&mut world.bodies).unwrap();
    let now = exact.rotation(handle).unwrap();
    let rb = &world.bodies[handle];
    let (q_error, w_error) = (
        angle(now.world_from_body, attitude(rb)),
        (now.omega_world - d(rb.angvel())).length() / d(rb.angvel()).length(),
    );
    // f32 rounding: the attitude is converted exactly, ω within a few ε.
    assert!(
        q_error <= 1e-12 && w_error <= 1e-6,
        "{q_error:e}, {w_error:e}"
    );
    let (from_own, _) = exact_from_managed(rb, &now);
    let l_f32 = from_f32.state_at(0.0).l_world();
    let l_from_f32 = (now.l_world - l_f32).length() / l_f32.length();

    let (mut worst_own, mut worst_l, mut worst_f32) = (0.0f64, 0.0f64, 0.0f64);
    for k in 1..=STEPS {
        exact.step_world(&mut world).unwrap();
        assert_eq!(exact.carrier(handle), Some(Carrier::Kreisel));
        let t = k as f64 * dt;
        let now_k = exact.rotation(handle).unwrap();
        worst_own = worst_own.max(angle(
            now_k.world_from_body,
            exact_attitude(&from_own, lfp, t),
        ));
        worst_l = worst_l.max((now_k.l_world - now.l_world).length() / now.l_world.length());
        let q_f32 = exact_attitude(&from_f32, lfp, t);
        worst_f32 = worst_f32.max(angle(now_k.world_from_body, q_f32));
        // rapier's f32 attitude is the adapter's, rounded.
        let rounding = angle(attitude(&world.bodies[handle]), now_k.world_from_body);
        assert!(rounding <= 3e-7, "{rounding:e} rad");
    }
    println!(
        "exact from own f64 state: attitude {worst_own:.1e} rad, L {worst_l:.1e}; \
         from rapier's f32 state: attitude {worst_f32:.1e} rad, L {l_from_f32:.1e}"
    );
    assert!(worst_own <= 1e-9, "{worst_own:e} rad");
    assert!(worst_l <= 1e-12, "{worst_l:e}");
    // The centre of mass stays where rapier put it (no linear velocity).
    let moved = (d(world.bodies[handle].center_of_mass()) - com).length();
    assert!(moved <= 1e-5, "centre of mass moved {moved:e} m");
    let t = STEPS as f64 * dt;
    Followed {
        from_own: worst_own,
        l_from_own: worst_l,
        from_f32: worst_f32,
        l_from_f32,
        apart: angle(
            exact_attitude(&unchanged, lfp, t),
            exact_attitude(&from_f32, lfp, t),
        ),
    }
}

/// A named change made by user code between steps.
type Change = (&'static str, Box<dyn Fn(&mut RigidBody)>);

/// The changes tried, each far from the motion without it.
fn changes() -> Vec<Change> {
    vec![
        (
            "angvel",
            Box::new(|rb: &mut RigidBody| rb.set_angvel(Vector::new(-1.5, 0.3, 2.2), false)),
        ),
        (
            "angvel, waking",
            Box::new(|rb: &mut RigidBody| rb.set_angvel(Vector::new(-1.5, 0.3, 2.2), true)),
        ),
        (
            "rotation",
            Box::new(|rb: &mut RigidBody| {
                rb.set_rotation(
                    Rotation::from_scaled_axis(Vector::new(2.0, -0.5, 0.7)),
                    true,
                )
            }),
        ),
        (
            "teleport",
            Box::new(|rb: &mut RigidBody| {
                let pose = Pose::from_parts(
                    Vector::new(3.0, -2.0, 1.0),
                    Rotation::from_scaled_axis(Vector::new(0.0, 2.5, -1.0)),
                );
                rb.set_position(pose, true);
                rb.set_angvel(Vector::new(0.1, -0.2, 4.0), true);
            }),
        ),
    ]
}

#[test]
fn user_changes_are_followed_and_the_motion_after_them_is_exact() {
    for (name, change) in changes() {
        print!("{name}: ");
        let f = follows(change);
        assert!(f.apart > 0.1, "{name}: {}", f.apart);
        assert!(f.from_own <= 1e-9 && f.l_from_own <= 1e-12);
        // Against the motion from rapier's f32 state: f32 rounding.
        assert!(f.l_from_f32 <= 3e-7, "{name}: {:e}", f.l_from_f32);
        assert!(f.from_f32 <= 1e-6, "{name}: {:e} rad", f.from_f32);
    }
}

/// Regression: `manage` and the re-synchronisation rotate rapier's ω into the
/// principal frame with the `f32` quaternion `rotation ⊗ frame` converted
/// to `f64` but not normalised; glam's `q * v` assumes `|q| = 1`, so ω and
/// L come out scaled by `|q|²` (1 ± 1e-7), and the attitude drifts from the
/// exact motion from rapier's state by ~1e-7·|ω|·t (2e-7 rad after 1 s
/// here, measured). Fix: normalise `world_from_principal` before
/// `world_from_principal.conjugate() * ω` in `manage` and `resync` (and
/// store `local_from_principal` normalised).
#[test]
fn the_motion_after_a_change_is_exact_from_rapiers_f32_state() {
    for (name, change) in changes() {
        let f = follows(change);
        assert!(f.l_from_f32 <= 1e-14, "{name}: L off by {:e}", f.l_from_f32);
        assert!(f.from_f32 <= 1e-9, "{name}: {:e} rad", f.from_f32);
    }
}
