//! Euler angles through the CLI against the scipy/mpmath reference data, for
//! all 24 conventions (one process per convention and direction).

use std::f64::consts::{FRAC_PI_2, PI};

use glam::DVec3;
use kreisel_kinematics::{EulerSequence, rotation_angle_between, try_normalize_quat};

use crate::support::{MaxError, Row, Table, angle_diff, convert, stdin_of, wxyz};

/// Bound on every angle and rotation error against the reference, radians.
const BOUND: f64 = 1e-14;

/// `true` when `angles` are in the documented output ranges of `seq`.
fn in_range(seq: EulerSequence, angles: DVec3) -> bool {
    let outer = |a: f64| a > -PI && a <= PI;
    let middle = if seq.is_proper() {
        (0.0..=PI).contains(&angles.y)
    } else {
        (-FRAC_PI_2..=FRAC_PI_2).contains(&angles.y)
    };
    outer(angles.x) && middle && outer(angles.z)
}

#[test]
fn quat_to_euler_matches_reference_in_all_24_conventions() {
    let table = Table::load("quat_to_euler.csv");
    let mut random_outer = MaxError::new("quat->euler random: first/third angle", BOUND);
    let mut random_middle = MaxError::new("quat->euler random: middle angle", BOUND);
    let mut random_rotation = MaxError::new("quat->euler random: recomposed rotation", BOUND);
    let mut lock_middle = MaxError::new("quat->euler (near_)lock: middle angle", BOUND);
    let mut lock_rotation = MaxError::new("quat->euler (near_)lock: recomposed rotation", BOUND);
    for seq in EulerSequence::all() {
        let name = seq.to_string();
        let rows: Vec<Row<'_>> = table.rows().filter(|r| r.str("seq") == name).collect();
        assert!(rows.len() > 50, "{name}: {} rows", rows.len());
        let to = format!("euler:{name}");
        let out = convert("quat", &to, &[], stdin_of(&rows, &["qw", "qx", "qy", "qz"])).rows(3);
        assert_eq!(out.len(), rows.len(), "{name}");
        for (row, angles) in rows.iter().zip(&out) {
            let found = DVec3::new(angles[0], angles[1], angles[2]);
            let expect = row.vec3("a0", "a1", "a2");
            assert!(in_range(seq, found), "{name}: {found} out of range");
            let q_in = try_normalize_quat(row.quat()).expect("reference quaternion");
            let rotation = rotation_angle_between(q_in, seq.to_quat(found));
            let at = || format!("{name}: {} -> {found}", row.describe());
            let middle = (found.y - expect.y).abs();
            match row.str("case") {
                "random" => {
                    let outer = angle_diff(found.x, expect.x).max(angle_diff(found.z, expect.z));
                    random_outer.record(outer, at);
                    random_middle.record(middle, at);
                    random_rotation.record(rotation, at);
                }
                "near_lock" | "lock" => {
                    lock_middle.record(middle, at);
                    lock_rotation.record(rotation, at);
                }
                other => panic!("unknown case {other}"),
            }
        }
    }
    for m in [
        &random_outer,
        &random_middle,
        &random_rotation,
        &lock_middle,
        &lock_rotation,
    ] {
        m.check();
    }
}

#[test]
fn euler_to_quat_matches_reference_in_all_24_conventions() {
    let table = Table::load("euler_to_quat.csv");
    let mut random = MaxError::new("euler->quat random: rotation", BOUND);
    let mut lock = MaxError::new("euler->quat (near_)lock: rotation", BOUND);
    for seq in EulerSequence::all() {
        let name = seq.to_string();
        let rows: Vec<Row<'_>> = table.rows().filter(|r| r.str("seq") == name).collect();
        assert!(rows.len() > 50, "{name}: {} rows", rows.len());
        let from = format!("euler:{name}");
        let out = convert(&from, "quat", &[], stdin_of(&rows, &["a0", "a1", "a2"])).rows(4);
        assert_eq!(out.len(), rows.len(), "{name}");
        for (row, q) in rows.iter().zip(&out) {
            assert!(
                q[0] >= 0.0,
                "{name}: quaternion output not canonical: {q:?}"
            );
            let err = rotation_angle_between(wxyz(q), row.quat());
            let at = || format!("{name}: {} -> {q:?}", row.describe());
            match row.str("case") {
                "random" => random.record(err, at),
                _ => lock.record(err, at),
            }
        }
    }
    random.check();
    lock.check();
}

#[test]
fn exact_gimbal_lock_prints_just_the_angles() {
    let out = convert("quat", "euler:ZXZ", &[], "1,0,0,0\n");
    assert_eq!(out.code, Some(0));
    assert_eq!(out.stdout, "0,0,0\n");
    assert!(out.stderr.is_empty(), "{}", out.stderr);
    // The identity in every convention (locked for proper Euler angles).
    for seq in EulerSequence::all() {
        let out = convert("quat", &format!("euler:{seq}"), &[], "1,0,0,0\n");
        assert_eq!(out.stdout, "0,0,0\n", "{seq}: {}", out.stderr);
    }
    // Half a turn about z is locked for ZXZ: all of it goes to the first angle.
    let out = convert("quat", "euler:ZXZ", &[], "0,0,0,1\n");
    assert_eq!(out.stdout, "3.141592653589793,0,0\n");
    // A quarter turn about y is the Tait–Bryan lock of XYZ: middle π/2, third 0.
    let half = 0.5_f64.sqrt().to_string();
    let out = convert("quat", "euler:XYZ", &[], format!("{half},0,{half},0\n"));
    assert_eq!(out.stdout, "0,1.5707963267948966,0\n");
    assert!(out.stderr.is_empty(), "{}", out.stderr);
}
