//! Quaternion ⇄ matrix, rotation vector, axis–angle and scalar-last
//! quaternion against `representations.csv`, `--degrees`, and round trips of
//! every representation pair.

use glam::{DQuat, DVec3};
use kreisel_kinematics::{
    EulerSequence, canonical_quat, quat_from_rotation_vector, rotation_angle_between,
    try_normalize_quat,
};

use crate::support::{MaxError, Row, Table, convert, norm, parse_rows, stdin_of, wxyz};

/// Bound on rotation errors (radians) and relative errors.
const BOUND: f64 = 1e-14;
/// Bound on matrix elements (absolute).
const MATRIX_BOUND: f64 = 2e-15;

const QUAT: [&str; 4] = ["qw", "qx", "qy", "qz"];
const MATRIX: [&str; 9] = [
    "m00", "m01", "m02", "m10", "m11", "m12", "m20", "m21", "m22",
];
const ROTVEC: [&str; 3] = ["rx", "ry", "rz"];

fn load() -> Table {
    Table::load("representations.csv")
}

fn input_quat(row: &Row<'_>) -> DQuat {
    try_normalize_quat(row.quat()).expect("reference quaternion")
}

/// `|a − b| / |b|`, or `|a|` when `b = 0`.
fn relative(a: DVec3, b: DVec3) -> f64 {
    let scale = norm(b);
    if scale == 0.0 {
        norm(a)
    } else {
        norm(a - b) / scale
    }
}

#[test]
fn quat_to_matrix_and_back() {
    let table = load();
    let rows: Vec<Row<'_>> = table.rows().collect();
    let out = convert("quat", "matrix", &[], stdin_of(&rows, &QUAT)).rows(9);
    let mut element = MaxError::new("quat->matrix: element (abs)", MATRIX_BOUND);
    for (row, m) in rows.iter().zip(&out) {
        for (value, column) in m.iter().zip(MATRIX) {
            let err = (value - row.num(column)).abs();
            element.record(err, || format!("{column} of {}: {m:?}", row.describe()));
        }
    }
    element.check();

    let out = convert("matrix", "quat", &[], stdin_of(&rows, &MATRIX)).rows(4);
    let mut rotation = MaxError::new("matrix->quat: rotation", BOUND);
    let mut component = MaxError::new("matrix->quat: component vs canonical q", BOUND);
    for (row, q) in rows.iter().zip(&out) {
        assert!(q[0] >= 0.0, "not canonical: {q:?}");
        let at = || format!("{} -> {q:?}", row.describe());
        rotation.record(rotation_angle_between(wxyz(q), input_quat(row)), at);
        // The reference has w ≥ 0 but, at exactly π (w = 0), not always a
        // positive first non-zero component: compare with its canonical form.
        let c = canonical_quat(row.quat());
        let reference = [c.w, c.x, c.y, c.z];
        let diff = q
            .iter()
            .zip(reference)
            .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
        component.record(diff, at);
    }
    rotation.check();
    component.check();
}

#[test]
fn quat_to_rotvec_and_back() {
    let table = load();
    let rows: Vec<Row<'_>> = table.rows().collect();
    let out = convert("quat", "rotvec", &[], stdin_of(&rows, &QUAT)).rows(3);
    let mut rotation = MaxError::new("quat->rotvec: rotation", BOUND);
    let mut rel_all = MaxError::new("quat->rotvec: relative to reference (all)", BOUND);
    let mut rel_tiny = MaxError::new("quat->rotvec: relative to reference (tiny)", BOUND);
    for (row, r) in rows.iter().zip(&out) {
        let found = DVec3::new(r[0], r[1], r[2]);
        let expect = row.vec3("rx", "ry", "rz");
        let at = || format!("{} -> {found}", row.describe());
        assert!(
            found.length() <= std::f64::consts::PI * (1.0 + 1e-15),
            "{}",
            at()
        );
        let q = quat_from_rotation_vector(found);
        rotation.record(rotation_angle_between(q, input_quat(row)), at);
        rel_all.record(relative(found, expect), at);
        if row.str("case") == "tiny" {
            rel_tiny.record(relative(found, expect), at);
        }
    }
    rotation.check();
    rel_all.check();
    rel_tiny.check();

    let out = convert("rotvec", "quat", &[], stdin_of(&rows, &ROTVEC)).rows(4);
    let mut rotation = MaxError::new("rotvec->quat: rotation", BOUND);
    let mut rel_tiny = MaxError::new("rotvec->quat: rotation / angle (tiny)", BOUND);
    for (row, q) in rows.iter().zip(&out) {
        assert!(q[0] >= 0.0, "not canonical: {q:?}");
        let err = rotation_angle_between(wxyz(q), input_quat(row));
        let at = || format!("{} -> {q:?}", row.describe());
        rotation.record(err, at);
        if row.str("case") == "tiny" {
            rel_tiny.record(err / norm(row.vec3("rx", "ry", "rz")), at);
        }
    }
    rotation.check();
    rel_tiny.check();
}

#[test]
fn axis_angle_both_ways() {
    let table = load();
    let rows: Vec<Row<'_>> = table.rows().collect();
    let out = convert("quat", "axis-angle", &[], stdin_of(&rows, &QUAT)).rows(4);
    let mut relative_err = MaxError::new("quat->axis-angle: axis*angle vs rotvec", BOUND);
    for (row, aa) in rows.iter().zip(&out) {
        let axis = DVec3::new(aa[0], aa[1], aa[2]);
        let at = || format!("{} -> {aa:?}", row.describe());
        assert!((0.0..=std::f64::consts::PI).contains(&aa[3]), "{}", at());
        assert!((axis.length() - 1.0).abs() < 4e-16, "{}", at());
        relative_err.record(relative(axis * aa[3], row.vec3("rx", "ry", "rz")), at);
    }
    relative_err.check();

    // Unit axes (normalised here), and the unnormalised rotation vector as axis.
    let mut unit_input = String::new();
    let mut scaled_input = String::new();
    for row in &rows {
        let r = row.vec3("rx", "ry", "rz");
        let angle = norm(r);
        let axis = if angle == 0.0 { DVec3::ZERO } else { r / angle };
        unit_input += &format!("{},{},{},{angle}\n", axis.x, axis.y, axis.z);
        scaled_input += &format!("{},{},{},{angle}\n", r.x, r.y, r.z);
    }
    let mut rotation = MaxError::new("axis-angle->quat: rotation / min(angle, 1)", BOUND);
    for input in [unit_input, scaled_input] {
        let out = convert("axis-angle", "quat", &[], input).rows(4);
        for (row, q) in rows.iter().zip(&out) {
            let angle = norm(row.vec3("rx", "ry", "rz"));
            let scale = if angle == 0.0 { 1.0 } else { angle.min(1.0) };
            let err = rotation_angle_between(wxyz(q), input_quat(row)) / scale;
            rotation.record(err, || format!("{} -> {q:?}", row.describe()));
        }
    }
    rotation.check();
}

#[test]
fn quat_xyzw_both_ways() {
    let table = load();
    let rows: Vec<Row<'_>> = table.rows().collect();
    let canonical = convert("quat", "quat", &[], stdin_of(&rows, &QUAT)).rows(4);
    let xyzw = convert("quat", "quat-xyzw", &[], stdin_of(&rows, &QUAT)).rows(4);
    let back = convert(
        "quat-xyzw",
        "quat",
        &[],
        stdin_of(&rows, &["qx", "qy", "qz", "qw"]),
    )
    .rows(4);
    let mut rotation = MaxError::new("quat->quat: rotation", BOUND);
    for (((row, c), x), b) in rows.iter().zip(&canonical).zip(&xyzw).zip(&back) {
        assert_eq!(
            [x[3], x[0], x[1], x[2]],
            [c[0], c[1], c[2], c[3]],
            "{}",
            row.describe()
        );
        assert_eq!(b, c, "{}", row.describe());
        rotation.record(rotation_angle_between(wxyz(c), input_quat(row)), || {
            row.describe()
        });
    }
    rotation.check();
}

#[test]
fn degrees_for_euler_and_axis_angle() {
    let table = load();
    let rows: Vec<Row<'_>> = table.rows().collect();
    let input = stdin_of(&rows, &QUAT);
    let mut rotation = MaxError::new("--degrees round trip: rotation", BOUND);
    for to in ["euler:ZYX", "euler:zxz", "axis-angle", "rotvec"] {
        let width = if to == "axis-angle" { 4 } else { 3 };
        let radians = convert("quat", to, &[], input.as_str()).rows(width);
        let degrees_out = convert("quat", to, &["--degrees"], input.as_str());
        let degrees = degrees_out.rows(width);
        for (r, d) in radians.iter().zip(&degrees) {
            let expect: Vec<f64> = match to {
                "axis-angle" => vec![r[0], r[1], r[2], r[3].to_degrees()],
                "rotvec" => r.clone(), // always radians
                _ => r.iter().map(|a| a.to_degrees()).collect(),
            };
            assert_eq!(d, &expect, "{to}");
        }
        let back = convert(to, "quat", &["--degrees"], degrees_out.stdout).rows(4);
        for (row, q) in rows.iter().zip(&back) {
            rotation.record(rotation_angle_between(wxyz(q), input_quat(row)), || {
                format!("{to}: {}", row.describe())
            });
        }
    }
    rotation.check();

    // Hand-checked values.
    let out = convert("euler:ZYX", "quat", &["--degrees"], "90,0,0\n").rows(4);
    let expect = DQuat::from_rotation_z(std::f64::consts::FRAC_PI_2);
    assert!(
        rotation_angle_between(wxyz(&out[0]), expect) < 1e-16,
        "{out:?}"
    );
    let out = convert("axis-angle", "quat", &["--degrees"], "0,0,2,180\n").rows(4);
    assert!(
        rotation_angle_between(wxyz(&out[0]), DQuat::from_rotation_z(std::f64::consts::PI)) < 1e-15
    );
    let out = convert("quat", "axis-angle", &["--degrees"], "0,0,0,1\n");
    assert_eq!(out.stdout, "0,0,1,180\n");
    let out = convert("quat", "euler:xyz", &["--degrees"], "1,0,0,0\n");
    assert_eq!(out.stdout, "0,0,0\n");
}

/// Every ordered pair of these representations is converted A → B → quat.
fn pair_representations() -> Vec<String> {
    let mut reprs: Vec<String> = ["quat", "quat-xyzw", "matrix", "rotvec", "axis-angle"]
        .map(String::from)
        .to_vec();
    for seq in ["ZXZ", "zxz", "XYZ", "zyx", "YXY", "xzy"] {
        let seq: EulerSequence = seq.parse().expect("sequence");
        reprs.push(format!("euler:{seq}"));
    }
    reprs
}

fn width(repr: &str) -> usize {
    match repr {
        "matrix" => 9,
        "quat" | "quat-xyzw" | "axis-angle" => 4,
        _ => 3,
    }
}

#[test]
fn every_pair_round_trips_on_random_rows() {
    let table = load();
    let rows: Vec<Row<'_>> = table.rows().filter(|r| r.str("case") == "random").collect();
    let input = stdin_of(&rows, &QUAT);
    let reprs = pair_representations();
    let mut rotation = MaxError::new("pair round trips A->B->quat: rotation", BOUND);
    let mut rotation_deg = MaxError::new("pair round trips --degrees: rotation", BOUND);
    for (degrees, max) in [(false, &mut rotation), (true, &mut rotation_deg)] {
        let extra: &[&str] = if degrees { &["--degrees"] } else { &[] };
        for a in &reprs {
            if degrees && !(a.starts_with("euler") || a == "axis-angle" || a == "quat") {
                continue;
            }
            let a_text = convert("quat", a, extra, input.as_str());
            assert_eq!(
                parse_rows(&a_text.stdout, width(a)).len(),
                rows.len(),
                "{a}"
            );
            for b in &reprs {
                if a == b {
                    continue;
                }
                let b_text = convert(a, b, extra, a_text.stdout.as_str());
                assert_eq!(b_text.rows(width(b)).len(), rows.len(), "{a} -> {b}");
                let q = convert(b, "quat", extra, b_text.stdout).rows(4);
                for (row, q) in rows.iter().zip(&q) {
                    max.record(rotation_angle_between(wxyz(q), input_quat(row)), || {
                        format!("{a} -> {b}: {}", row.describe())
                    });
                }
            }
        }
    }
    rotation.check();
    rotation_deg.check();
}
