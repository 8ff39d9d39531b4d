//! Property tests: round trips of every representation, for all 24 Euler
//! conventions, on random rotations and on grids through gimbal lock.

use std::f64::consts::PI;

use kreisel::kinematics::glam::{DQuat, DVec3};
use kreisel::kinematics::{
    AxisAngle, EulerSequence, ORTHONORMALITY_TOLERANCE, quat_from_rotation_vector,
    rotation_angle_between, rotation_matrix_from_quat, rotation_vector_from_quat,
    try_normalize_quat, try_quat_from_rotation_matrix,
};
use proptest::prelude::*;

/// Worst-case recomposition error allowed (issue #2).
const WORST: f64 = 1e-14;

fn sequence() -> impl Strategy<Value = EulerSequence> {
    (0..24usize).prop_map(|i| EulerSequence::all()[i])
}

/// A random unit quaternion (uniform on the 3-sphere up to rejection of tiny norms).
fn unit_quat() -> impl Strategy<Value = DQuat> {
    prop::array::uniform4(-1.0..1.0f64)
        .prop_filter("non-degenerate", |c| {
            c.iter().map(|v| v * v).sum::<f64>() > 1e-6
        })
        .prop_map(|[w, x, y, z]| try_normalize_quat(DQuat::from_xyzw(x, y, z, w)).unwrap())
}

fn in_ranges(seq: EulerSequence, a: DVec3) -> bool {
    let first_third = |v: f64| v > -PI && v <= PI;
    let middle = if seq.is_proper() {
        (0.0..=PI).contains(&a.y)
    } else {
        (-PI / 2.0..=PI / 2.0).contains(&a.y)
    };
    first_third(a.x) && first_third(a.z) && middle
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn quat_euler_quat(seq in sequence(), q in unit_quat()) {
        let d = seq.from_quat(q);
        prop_assert!(in_ranges(seq, d.angles), "{seq}: {:?}", d.angles);
        prop_assert!(rotation_angle_between(q, seq.to_quat(d.angles)) <= WORST);
        // q ≡ −q: bit-identical angles.
        prop_assert_eq!(seq.from_quat(-q), d);
    }

    #[test]
    fn euler_quat_euler(seq in sequence(), a in -10.0..10.0f64, b in -10.0..10.0f64, c in -10.0..10.0f64) {
        let q = seq.to_quat(DVec3::new(a, b, c));
        let d = seq.from_quat(q);
        prop_assert!(in_ranges(seq, d.angles));
        prop_assert!(rotation_angle_between(q, seq.to_quat(d.angles)) <= WORST);
    }

    /// Grid through the singularities: middle angle = lock ± 10^-k for k = 0..300, and exactly at it.
    #[test]
    fn through_gimbal_lock(seq in sequence(), which in 0..2usize, k in 0..=301i32, negative in any::<bool>(),
                           a in -PI..PI, c in -PI..PI) {
        let lock = seq.gimbal_lock_angles()[which];
        let delta = if k == 301 { 0.0 } else { 10f64.powi(-k) };
        // Step towards the inside of the valid middle-angle range.
        let inward = if which == 0 { 1.0 } else { -1.0 };
        let middle = lock + inward * delta;
        let angles = DVec3::new(a, middle, c);
        let q = seq.to_quat(if negative { -angles } else { angles });
        let d = seq.from_quat(q);
        prop_assert!(in_ranges(seq, d.angles));
        let err = rotation_angle_between(q, seq.to_quat(d.angles));
        prop_assert!(err <= WORST, "{seq} δ={delta:e}: error {err:e}");
        if d.gimbal_lock {
            prop_assert_eq!(d.angles.z, 0.0);
        }
    }

    #[test]
    fn rotation_vector_round_trip(q in unit_quat()) {
        let r = rotation_vector_from_quat(q);
        prop_assert!(r.length() <= PI * (1.0 + 1e-15));
        prop_assert!(rotation_angle_between(q, quat_from_rotation_vector(r)) <= WORST);
        prop_assert_eq!(rotation_vector_from_quat(-q), r);
    }

    #[test]
    fn axis_angle_round_trip(q in unit_quat()) {
        let aa = AxisAngle::from_quat(q);
        prop_assert!((aa.axis.length() - 1.0).abs() < 1e-15);
        prop_assert!(rotation_angle_between(q, aa.to_quat()) <= WORST);
        let again = AxisAngle::try_new(aa.axis * 7.5, aa.angle).unwrap();
        prop_assert!(rotation_angle_between(q, again.to_quat()) <= WORST);
    }

    #[test]
    fn matrix_round_trip(q in unit_quat()) {
        let m = rotation_matrix_from_quat(q);
        let back = try_quat_from_rotation_matrix(m, ORTHONORMALITY_TOLERANCE).unwrap();
        prop_assert!(rotation_angle_between(q, back) <= WORST);
    }

    #[test]
    fn euler_rates_invert(seq in sequence(), q in unit_quat(), w in prop::array::uniform3(-5.0..5.0f64)) {
        let angles = seq.from_quat(q).angles;
        let omega = DVec3::from_array(w);
        let det = seq.rate_matrix_determinant(angles).abs();
        prop_assume!(det > 1e-3);
        let rates = seq.rates_from_omega_body(angles, omega).unwrap();
        prop_assert!((seq.rate_matrix_body(angles) * rates - omega).length() <= 1e-13 / det);
        let rates = seq.rates_from_omega_world(angles, omega).unwrap();
        prop_assert!((seq.rate_matrix_world(angles) * rates - omega).length() <= 1e-13 / det);
    }
}
