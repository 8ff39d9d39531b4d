//! Matrices, rotation vectors and axis–angle pairs against 50-digit mpmath
//! reference data cross-checked with scipy 1.17 (`tests/data/gen/rotations.py`).

mod common;

use common::Table;
use kreisel::kinematics::glam::{DMat3, DVec3};
use kreisel::kinematics::{
    AxisAngle, ORTHONORMALITY_TOLERANCE, quat_from_rotation_vector, rotation_angle_between,
    rotation_matrix_from_quat, rotation_vector_from_quat, try_quat_from_rotation_matrix,
};

fn matrix(t: &Table, row: &[String]) -> DMat3 {
    let names = [
        "m00", "m01", "m02", "m10", "m11", "m12", "m20", "m21", "m22",
    ];
    let rows: Vec<f64> = names.iter().map(|n| t.num(row, n)).collect();
    DMat3::from_cols_slice(&rows).transpose()
}

#[test]
fn matrix_both_ways() {
    let t = Table::load("representations.csv");
    let (mut to_m, mut from_m) = (0.0_f64, 0.0_f64);
    for row in &t.rows {
        let q = t.quat(row);
        let m_ref = matrix(&t, row);
        let m = rotation_matrix_from_quat(q);
        let d = (m - m_ref)
            .to_cols_array()
            .iter()
            .fold(0.0_f64, |a, v| a.max(v.abs()));
        to_m = to_m.max(d);
        let back = try_quat_from_rotation_matrix(m_ref, ORTHONORMALITY_TOLERANCE).unwrap();
        from_m = from_m.max(rotation_angle_between(back, q));
    }
    eprintln!("quat→matrix max element error {to_m:e}; matrix→quat max {from_m:e} rad");
    assert!(to_m <= 1e-15);
    assert!(from_m <= 1e-15);
}

#[test]
fn rotation_vector_both_ways_tiny_to_pi() {
    let t = Table::load("representations.csv");
    let (mut rel, mut back) = (0.0_f64, 0.0_f64);
    for row in &t.rows {
        let q = t.quat(row);
        let r_ref = t.vec3(row, ["rx", "ry", "rz"]);
        let r = rotation_vector_from_quat(q);
        let scale = r_ref.abs().max_element().max(f64::MIN_POSITIVE);
        if r_ref == DVec3::ZERO {
            assert_eq!(r, DVec3::ZERO);
        } else {
            // Relative error: meaningful down to 1e-300 rad.
            rel = rel.max((r - r_ref).abs().max_element() / scale);
        }
        let q_back = quat_from_rotation_vector(r_ref);
        back = back.max(rotation_angle_between(q_back, q));
    }
    eprintln!("quat→rotvec max relative error {rel:e}; rotvec→quat max {back:e} rad");
    assert!(rel <= 1e-15);
    assert!(back <= 1e-15);
}

#[test]
fn axis_angle_round_trip_and_reference() {
    let t = Table::load("representations.csv");
    let mut worst = 0.0_f64;
    for row in &t.rows {
        let q = t.quat(row);
        let r_ref = t.vec3(row, ["rx", "ry", "rz"]);
        let aa = AxisAngle::from_quat(q);
        // |r| without underflow (the data goes down to 1e-300 rad).
        let m = r_ref.abs().max_element().max(f64::MIN_POSITIVE);
        let angle_ref = (r_ref / m).length() * m;
        assert!((aa.angle - angle_ref).abs() <= 1e-15 * angle_ref, "{row:?}");
        assert!((0.0..=std::f64::consts::PI).contains(&aa.angle));
        worst = worst.max(rotation_angle_between(aa.to_quat(), q));
    }
    eprintln!("quat→axis-angle→quat max {worst:e} rad");
    assert!(worst <= 1e-15);
}
