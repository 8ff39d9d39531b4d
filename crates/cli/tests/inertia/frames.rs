//! `--about`, `--transform`, `--principal`, `--digits` (issue 16, single
//! meshes in any frame), against closed forms built here by hand: a box's
//! tensor `m/12 (b² + c², …)`, the parallel-axis theorem written out
//! element by element, rotation matrices multiplied out from roll, pitch,
//! yaw, and eigenvalues from the trigonometric closed form (not the CLI's
//! Jacobi solver).

use std::path::PathBuf;

use glam::{DMat3, DQuat, DVec3};

use crate::support::{
    attribute, cube_obj, element, inertia, max_abs, numbers, raw_list, scratch, workspace,
};

/// An OBJ box with its lowest corner at `lo` and edges `size` (mesh units).
fn box_obj(name: &str, lo: DVec3, size: DVec3) -> PathBuf {
    let unit = cube_obj("box", 0.0, 1, false, false);
    let text: String = unit
        .lines()
        .map(|line| match line.strip_prefix("v ") {
            Some(v) => {
                let c = numbers(v);
                let p = lo + DVec3::new(c[0], c[1], c[2]) * size;
                format!("v {} {} {}\n", p.x, p.y, p.z)
            }
            None => format!("{line}\n"),
        })
        .collect();
    scratch(name, text)
}

/// An open rectangle `a × b` in its own xy plane, turned by `tilt` (for `--shell`).
fn sheet_obj(name: &str, a: f64, b: f64, tilt: DQuat) -> PathBuf {
    let corners = [(0.0, 0.0), (a, 0.0), (a, b), (0.0, b)]
        .map(|(x, y)| tilt * DVec3::new(x - 0.3 * a, y - 0.6 * b, 0.0));
    let mut text = String::new();
    for p in corners {
        text.push_str(&format!("v {:e} {:e} {:e}\n", p.x, p.y, p.z));
    }
    text.push_str("f 1 2 3\nf 1 3 4\n");
    scratch(name, text)
}

/// `Rz(yaw) · Ry(pitch) · Rx(roll)`, multiplied out.
fn rpy_matrix(rpy: DVec3) -> DMat3 {
    let (sr, cr) = rpy.x.sin_cos();
    let (sp, cp) = rpy.y.sin_cos();
    let (sy, cy) = rpy.z.sin_cos();
    DMat3::from_cols(
        DVec3::new(cy * cp, sy * cp, -sp),
        DVec3::new(cy * sp * sr - sy * cr, sy * sp * sr + cy * cr, cp * sr),
        DVec3::new(cy * sp * cr + sy * sr, sy * sp * cr - cy * sr, cp * cr),
    )
}

/// The tensor of a point mass `m` at offset `d`, element by element:
/// `m (|d|² δ_ab − d_a d_b)`.
fn parallel_axis(m: f64, d: DVec3) -> DMat3 {
    let d = d.to_array();
    let r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    let e = |a: usize, b: usize| m * (if a == b { r2 } else { 0.0 } - d[a] * d[b]);
    DMat3::from_cols(
        DVec3::new(e(0, 0), e(1, 0), e(2, 0)),
        DVec3::new(e(0, 1), e(1, 1), e(2, 1)),
        DVec3::new(e(0, 2), e(1, 2), e(2, 2)),
    )
}

/// A box's mass and tensor about its centre (edges `size` in metres).
fn box_closed_form(density: f64, size: DVec3) -> (f64, DMat3) {
    let (a, b, c) = (size.x, size.y, size.z);
    let m = density * a * b * c;
    let i =
        DMat3::from_diagonal(DVec3::new(b * b + c * c, a * a + c * c, a * a + b * b) * (m / 12.0));
    (m, i)
}

/// The matrix of a JSON list of rows, parsed by Rust.
fn raw_rows(json: &str, key: &str) -> DMat3 {
    let start = json
        .find(&format!("\"{key}\": ["))
        .unwrap_or_else(|| panic!("no {key}"));
    let rest = &json[start + key.len() + 4..];
    let end = rest.find("]]").expect("end of rows") + 2;
    let v = numbers(&rest[..end].replace([',', '[', ']'], " "));
    assert_eq!(v.len(), 9, "{key}");
    DMat3::from_cols_array(&[v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]]).transpose()
}

/// `max |a − b| / max |b|`.
fn rel_matrix(a: DMat3, b: DMat3) -> f64 {
    max_abs(a - b) / max_abs(b)
}

/// The tensor `ixx ixy ixz iyy iyz izz` of a URDF `<inertia>`.
fn urdf_tensor(xml: &str) -> DMat3 {
    let e = |name: &str| -> f64 { attribute(xml, name).parse().expect("number") };
    let (xy, xz, yz) = (e("ixy"), e("ixz"), e("iyz"));
    DMat3::from_cols(
        DVec3::new(e("ixx"), xy, xz),
        DVec3::new(xy, e("iyy"), yz),
        DVec3::new(xz, yz, e("izz")),
    )
}

/// Eigenvalues of a symmetric matrix, ascending, by the trigonometric
/// closed form (Smith, CACM 4:168, 1961).
fn eigenvalues(m: DMat3) -> [f64; 3] {
    let (a11, a22, a33) = (m.x_axis.x, m.y_axis.y, m.z_axis.z);
    let (a12, a13, a23) = (m.y_axis.x, m.z_axis.x, m.z_axis.y);
    let p1 = a12 * a12 + a13 * a13 + a23 * a23;
    let q = (a11 + a22 + a33) / 3.0;
    let p2 = (a11 - q).powi(2) + (a22 - q).powi(2) + (a33 - q).powi(2) + 2.0 * p1;
    if p2 == 0.0 {
        return [q; 3];
    }
    let p = (p2 / 6.0).sqrt();
    let b = (m - DMat3::IDENTITY * q) * (1.0 / p);
    let r = (b.determinant() / 2.0).clamp(-1.0, 1.0);
    let phi = r.acos() / 3.0;
    let largest = q + 2.0 * p * phi.cos();
    let smallest = q + 2.0 * p * (phi + 2.0 * std::f64::consts::FRAC_PI_3).cos();
    [smallest, 3.0 * q - largest - smallest, largest]
}

/// Whether the tensor is physical as a reader checks it: positive
/// definite and `A + B ≥ C`.
fn physical(t: DMat3) -> bool {
    let [a, b, c] = eigenvalues(t);
    a > 0.0 && a + b >= c
}

#[test]
fn about_a_point_is_the_parallel_axis_theorem_in_mesh_units() {
    // A 40 × 20 × 10 mm box at (100, −50, 30) mm; the point in mm too.
    let (lo, size) = (DVec3::new(100.0, -50.0, 30.0), DVec3::new(40.0, 20.0, 10.0));
    let path = box_obj("about_box.obj", lo, size);
    let run = inertia(
        &path,
        &[
            "--units",
            "mm",
            "--density",
            "2700",
            "--about",
            "-5,12.5,7",
            "--format",
            "json",
        ],
    );
    let json = &run.json();
    let (m, ic) = box_closed_form(2700.0, size * 1e-3);
    let c = (lo + size / 2.0) * 1e-3;
    let p = DVec3::new(-5.0, 12.5, 7.0) * 1e-3;
    let expect = ic + parallel_axis(m, c - p);
    let text = &run.stdout;
    let found = raw_rows(text, "inertia_about_point");
    let error = rel_matrix(found, expect);
    println!("--about: box in mm, tensor about a point, max rel. error {error:.1e}");
    assert!(error <= 1e-13, "{error:e}\n{found}\n{expect}");
    assert_eq!(raw_list(text, "about_point"), vec![-0.005, 0.0125, 0.007]);
    assert_eq!(raw_list(text, "about_point_mesh"), vec![-5.0, 12.5, 7.0]);
    // The tensor about the centre of mass and the frame are unchanged.
    assert!(rel_matrix(raw_rows(text, "inertia"), ic) <= 1e-12);
    assert_eq!(json["frame"], "center of mass, mesh axes");
    // Every body gets the keys as well.
    assert!(json["bodies"][0].get("inertia_about_point").is_some());
    // The text report shows the point and the tensor.
    let text = inertia(&path, &["--units", "mm", "--about", "-5,12.5,7"]).stdout;
    assert!(text.contains("about point             -0.005  0.0125  0.007  m, mesh axes (mesh coordinates -5  12.5  7)"), "{text}");
    assert!(text.contains("inertia about point"), "{text}");
}

#[test]
fn new_keys_appear_only_with_their_options() {
    let json = inertia(&workspace("assets/t_handle.obj"), &["--format", "json"]).json();
    for key in [
        "about_point",
        "about_point_mesh",
        "inertia_about_point",
        "transform_xyz",
        "transform_rpy",
        "digits",
    ] {
        assert!(json.get(key).is_none(), "{key}");
    }
}

/// Roll, pitch, yaw of the placements tried, including pitch ±π/2.
const PLACEMENTS: [[f64; 3]; 5] = [
    [0.3, -0.4, 1.1],
    [0.0, 0.0, std::f64::consts::FRAC_PI_2],
    [2.5, std::f64::consts::FRAC_PI_2, -0.7],
    [-1.0, -std::f64::consts::FRAC_PI_2, 3.0],
    [0.1, 1.2, -2.9],
];

#[test]
fn transform_places_the_box_in_the_link_frame() {
    let (lo, size) = (DVec3::new(-20.0, 5.0, -3.0), DVec3::new(30.0, 12.0, 7.0));
    let path = box_obj("placed_box.obj", lo, size);
    let (m, ic) = box_closed_form(1000.0, size * 1e-3);
    let c_mesh = (lo + size / 2.0) * 1e-3;
    let xyz = DVec3::new(0.12, -0.034, 0.5);
    let mut worst: f64 = 0.0;
    for rpy in PLACEMENTS.map(DVec3::from_array) {
        let spec = format!(
            "xyz={} {} {} rpy={} {} {}",
            xyz.x, xyz.y, xyz.z, rpy.x, rpy.y, rpy.z
        );
        let r = rpy_matrix(rpy);
        let c = r * c_mesh + xyz;
        let i = r * ic * r.transpose();
        let point_mesh = DVec3::new(3.0, -4.0, 8.0);
        let about = i + parallel_axis(m, c - (r * point_mesh * 1e-3 + xyz));
        let run = inertia(
            &path,
            &[
                "--units",
                "mm",
                "--transform",
                &spec,
                "--about",
                "3 -4 8",
                "--format",
                "json",
            ],
        );
        let json = run.json();
        let text = &run.stdout;
        assert_eq!(json["frame"], "center of mass, link axes");
        assert_eq!(raw_list(text, "transform_xyz"), xyz.to_array().to_vec());
        assert_eq!(raw_list(text, "transform_rpy"), rpy.to_array().to_vec());
        let com = DVec3::from_slice(&raw_list(text, "center_of_mass"));
        worst = worst
            .max((com - c).abs().max_element() / c.abs().max_element())
            .max(rel_matrix(raw_rows(text, "inertia"), i))
            .max(rel_matrix(raw_rows(text, "inertia_about_point"), about));
        // The URDF of the same placement holds the same numbers.
        let urdf = inertia(
            &path,
            &["--units", "mm", "--transform", &spec, "--format", "urdf"],
        );
        assert_eq!(urdf.code, Some(0), "{}", urdf.stderr);
        let origin = DVec3::from_slice(&numbers(attribute(&urdf.stdout, "xyz")));
        assert_eq!(origin, com);
        worst = worst.max(rel_matrix(urdf_tensor(&urdf.stdout), i));
        assert!(
            urdf.stdout.contains("in link axes (mesh placed at xyz="),
            "{}",
            urdf.stdout
        );
    }
    println!("--transform: rotated box, max rel. error {worst:.1e}");
    assert!(worst <= 1e-13, "{worst:e}");
}

#[test]
fn principal_form_rebuilds_the_full_tensor() {
    // A box whose principal frame is at pitch −π/2 exactly (long along z,
    // then x, then y: axes z, x, y), the same 1e-9 rad from it, and general tilts.
    let path = box_obj("principal_box.obj", DVec3::ZERO, DVec3::new(2.0, 1.0, 3.0));
    let mut worst: f64 = 0.0;
    let placements = [
        "rpy=0 0 0",
        "rpy=1e-9 0 0",
        "rpy=0 1e-9 0",
        "xyz=1 2 3 rpy=0.3 -0.4 1.1",
        "rpy=2.5 1.5707963267948966 -0.7",
        "rpy=0.1 1.2 -2.9",
    ];
    for spec in placements {
        let args = ["--transform", spec, "--format", "urdf"];
        let full = inertia(&path, &args);
        assert_eq!(full.code, Some(0), "{}", full.stderr);
        let tensor = urdf_tensor(&full.stdout);
        let with = |format: &str| {
            let run = inertia(
                &path,
                &["--transform", spec, "--format", format, "--principal"],
            );
            assert_eq!(run.code, Some(0), "{}", run.stderr);
            run.stdout
        };
        // URDF: origin rpy and a diagonal.
        let urdf = with("urdf");
        let diag = urdf_tensor(&urdf);
        assert_eq!(
            [diag.x_axis.y, diag.x_axis.z, diag.y_axis.z],
            [0.0; 3],
            "{urdf}"
        );
        let rpy = DVec3::from_slice(&numbers(attribute(&urdf, "rpy")));
        let r = rpy_matrix(rpy);
        worst = worst.max(rel_matrix(r * diag * r.transpose(), tensor));
        assert!(urdf.contains("in principal axes"), "{urdf}");
        assert_eq!(attribute(&urdf, "xyz"), attribute(&full.stdout, "xyz"));
        // SDFormat: the pose's last three numbers, the same diagonal.
        let sdf = with("sdf");
        let pose = numbers(element(&sdf, "pose"));
        let r = rpy_matrix(DVec3::new(pose[3], pose[4], pose[5]));
        let d: Vec<f64> = ["ixx", "iyy", "izz"]
            .iter()
            .map(|n| element(&sdf, n).parse().expect("number"))
            .collect();
        let sdf_diag = DMat3::from_diagonal(DVec3::from_slice(&d));
        worst = worst.max(rel_matrix(r * sdf_diag * r.transpose(), tensor));
        // MJCF: quat (w x y z) and diaginertia.
        let mjcf = with("mjcf");
        let q = numbers(attribute(&mjcf, "quat"));
        let r = DMat3::from_quat(DQuat::from_xyzw(q[1], q[2], q[3], q[0]));
        let d = numbers(attribute(&mjcf, "diaginertia"));
        let mj_diag = DMat3::from_diagonal(DVec3::from_slice(&d));
        worst = worst.max(rel_matrix(r * mj_diag * r.transpose(), tensor));
        assert!(!mjcf.contains("fullinertia"), "{mjcf}");
    }
    println!("--principal: R(rpy) diag R^T vs the full tensor, max rel. error {worst:.1e}");
    // A few ulps: the test's own sin/cos and products round as well.
    assert!(worst <= 1e-15, "{worst:e}");
}

#[test]
fn digits_round_and_snap_round_off_to_zero() {
    // The README's T-handle: ixy = 6.4e-23 next to moments of ~1e-5.
    let path = workspace("assets/t_handle.obj");
    let exact = inertia(&path, &["--format", "urdf"]).stdout;
    assert!(attribute(&exact, "ixy").contains("e-23"), "{exact}");
    let rounded = inertia(&path, &["--format", "urdf", "--digits", "6"]).stdout;
    for name in ["ixy", "ixz", "iyz"] {
        assert_eq!(attribute(&rounded, name), "0", "{rounded}");
    }
    for name in ["ixx", "iyy", "izz", "value"] {
        let (e, r): (f64, f64) = (
            attribute(&exact, name).parse().expect("number"),
            attribute(&rounded, name).parse().expect("number"),
        );
        // Six significant digits, within half a unit of the sixth.
        let digits = attribute(&rounded, name)
            .split('e')
            .next()
            .expect("mantissa")
            .chars()
            .filter(char::is_ascii_digit)
            .collect::<String>();
        assert!(
            digits.trim_start_matches('0').len() <= 6,
            "{name}: {digits}"
        );
        let unit = 10f64.powf(e.abs().log10().floor() - 5.0);
        assert!(
            (r - e).abs() <= 0.5 * unit * (1.0 + 1e-9),
            "{name}: {r} vs {e}"
        );
    }
    // The centre of mass's round-off (7e-19 next to −0.0034) is 0 as well.
    assert_eq!(attribute(&rounded, "xyz"), "0 0 -0.00338257");
    let json = inertia(&path, &["--format", "json", "--digits", "6"]).json();
    assert_eq!(json["digits"], 6);
    assert_eq!(json["inertia"][0][1], 0.0);
    assert_eq!(json["mass"], 0.01652);
}

/// Rounds the six elements of a full-precision tensor to `digits` as naive
/// printing would (no snapping, no raise).
fn naive(t: DMat3, digits: usize) -> DMat3 {
    let round = |x: f64| -> f64 {
        format!("{x:.prec$e}", prec = digits - 1)
            .parse()
            .expect("number")
    };
    DMat3::from_cols_array(&t.to_cols_array().map(round))
}

/// Runs URDF output of `path` with `args` and `--digits`, checks it is
/// physical and close to the exact tensor; returns (naive rounding is
/// physical, largest change relative to the largest moment).
fn rounded_check(path: &std::path::Path, args: &[&str], digits: usize) -> (bool, f64) {
    let mut all = args.to_vec();
    all.extend(["--format", "urdf"]);
    let exact = urdf_tensor(&inertia(path, &all).stdout);
    let d = digits.to_string();
    all.extend(["--digits", &d]);
    let run = inertia(path, &all);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let written = urdf_tensor(&run.stdout);
    assert!(
        physical(written),
        "{args:?} {digits}: {:?}\n{}",
        eigenvalues(written),
        run.stdout
    );
    let largest = eigenvalues(exact)[2];
    let change = max_abs(written - exact) / largest;
    // Principal form: the diagonal itself.
    all.push("--principal");
    let principal = inertia(path, &all);
    let diag = urdf_tensor(&principal.stdout);
    let [a, b, c] = [diag.x_axis.x, diag.y_axis.y, diag.z_axis.z];
    assert!(
        a > 0.0 && a <= b && b <= c && a + b >= c,
        "{}",
        principal.stdout
    );
    (physical(naive(exact, digits)), change)
}

#[test]
fn digits_keep_flat_sheets_physical() {
    // A sheet has A + B = C exactly: rounding puts it on either side.
    let mut naive_broken = 0;
    let mut worst: [f64; 3] = [0.0; 3];
    for k in 0..12 {
        let kf = f64::from(k);
        let tilt = DQuat::from_euler(glam::EulerRot::ZYX, 0.37 * kf, 0.21 * kf - 1.0, 0.1 * kf);
        let path = sheet_obj(&format!("sheet_{k}.obj"), 0.3, 0.2, tilt);
        for (j, digits) in [2, 3, 5].into_iter().enumerate() {
            let (ok, change) = rounded_check(&path, &["--shell"], digits);
            naive_broken += usize::from(!ok);
            worst[j] = worst[j].max(change * 10f64.powi(digits as i32 - 1));
        }
    }
    println!(
        "--digits: tilted sheets, largest change in units of the last digit of C: {worst:.2?}; naive rounding unphysical in {naive_broken} of 36"
    );
    // The test can fail: naive rounding breaks some of these sheets.
    assert!(naive_broken > 0);
    assert!(worst.iter().all(|&w| w <= 2.0), "{worst:?}");
}

#[test]
fn digits_keep_a_tilted_thin_rod_physical() {
    // 1 m × 0.1 mm × 0.1 mm: A/C ≈ 2e-8, far below the rounding of the products.
    let path = box_obj("thin_rod.obj", DVec3::ZERO, DVec3::new(1.0, 1e-4, 1e-4));
    let mut naive_broken = 0;
    let mut worst: f64 = 0.0;
    for rpy in ["0.3 -0.4 1.1", "0 0.7 0.2", "1 1 1"] {
        let spec = format!("rpy={rpy}");
        for digits in [3, 4, 6] {
            let (ok, change) = rounded_check(&path, &["--transform", &spec], digits);
            naive_broken += usize::from(!ok);
            worst = worst.max(change * 10f64.powi(digits as i32 - 1));
        }
    }
    println!(
        "--digits: tilted thin rod, largest change {worst:.2} units of the last digit of C; naive rounding unphysical in {naive_broken} of 9"
    );
    assert!(naive_broken > 0);
    assert!(worst <= 2.0, "{worst}");
}

#[test]
fn bad_frame_options_are_usage_errors() {
    let missing = workspace("tests/data/no_such_mesh.obj");
    let cases: [(&[&str], &str); 14] = [
        (&["--about", "1,2"], "expected 3 numbers, found 2"),
        (&["--about", "1,2,3,4"], "found 4"),
        (&["--about", "a,b,c"], "cannot parse `a`"),
        (&["--about", "nan,0,0"], "not finite"),
        (&["--about", ""], "--about"),
        (&["--transform", "xyz=1 2"], "expected 3 numbers, found 2"),
        (&["--transform", "1 2 3"], "has no key"),
        (&["--transform", "pos=1 2 3"], "unknown key `pos`"),
        (&["--transform", "rpy=0 0 1 rpy=0 0 1"], "given twice"),
        (&["--transform", "rpy=0 inf 0"], "not finite"),
        (&["--digits", "0"], "from 1 to 17"),
        (&["--digits", "18"], "from 1 to 17"),
        (&["--digits", "2.5"], "from 1 to 17"),
        (&["--digits", "-3"], "from 1 to 17"),
    ];
    for (args, words) in cases {
        let run = inertia(&missing, args);
        assert_eq!(run.code, Some(2), "{args:?}: {}", run.stderr);
        assert!(run.stdout.is_empty() && !run.stderr.contains("panicked"));
        let first = run.stderr.lines().next().unwrap_or_default();
        assert!(
            first.starts_with("error: invalid value"),
            "{args:?}: {first}"
        );
        assert!(first.contains(words), "{args:?}: {first}");
    }
}

#[test]
fn options_for_other_formats_are_errors() {
    let path = workspace("assets/t_handle.obj");
    for format in ["urdf", "sdf", "mjcf"] {
        let run = inertia(&path, &["--about", "0,0,0", "--format", format]);
        let line = run.error_line(1);
        assert!(
            line.contains("--about: applies to --format text and json"),
            "{line}"
        );
    }
    for format in ["text", "json"] {
        let run = inertia(&path, &["--principal", "--format", format]);
        let line = run.error_line(1);
        assert!(
            line.contains("--principal: applies to --format urdf, sdf and mjcf"),
            "{line}"
        );
    }
}

#[test]
fn transform_places_every_body_and_the_assembly() {
    // Two unit cubes, at x ∈ [0, 1] and [2, 3].
    let text = cube_obj("left", 0.0, 1, false, false) + &cube_obj("right", 2.0, 9, false, false);
    let path = scratch("two_cubes_placed.obj", text);
    let rpy = DVec3::new(-0.6, 0.25, 2.0);
    let xyz = DVec3::new(1.0, -2.0, 0.5);
    let spec = format!("xyz=1 -2 0.5 rpy={} {} {}", rpy.x, rpy.y, rpy.z);
    let run = inertia(&path, &["--transform", &spec, "--format", "json"]);
    let json = run.json();
    let r = rpy_matrix(rpy);
    let (m, ic) = box_closed_form(1000.0, DVec3::ONE);
    let centres = [DVec3::new(0.5, 0.5, 0.5), DVec3::new(2.5, 0.5, 0.5)].map(|c| r * c + xyz);
    let mut worst: f64 = 0.0;
    for (k, c) in centres.iter().enumerate() {
        let body = &json["bodies"][k];
        assert_eq!(body["frame"], "center of mass, link axes");
        let found = crate::support::vec3(&body["center_of_mass"]);
        worst = worst.max((found - *c).abs().max_element() / c.abs().max_element());
        let i = crate::support::rows(&body["inertia"]);
        worst = worst.max(rel_matrix(i, r * ic * r.transpose()));
    }
    // The assembly: both cubes about their common centre.
    let c = (centres[0] + centres[1]) / 2.0;
    let expect = (r * ic * r.transpose()) * 2.0
        + parallel_axis(m, centres[0] - c)
        + parallel_axis(m, centres[1] - c);
    worst = worst.max(rel_matrix(raw_rows(&run.stdout, "inertia"), expect));
    println!("--transform: two bodies and their assembly, max rel. error {worst:.1e}");
    assert!(worst <= 1e-13, "{worst:e}");
    // The comment's body masses are rounded with the rest.
    let urdf = inertia(
        &path,
        &[
            "--transform",
            &spec,
            "--format",
            "urdf",
            "--digits",
            "2",
            "--density",
            "1234.5",
        ],
    )
    .stdout;
    for words in [
        "density 1200 kg/m^3",
        "'left' (mass 1200 kg), 'right' (mass 1200 kg)",
        "<mass value=\"2500\"/>",
    ] {
        assert!(urdf.contains(words), "{words} in {urdf}");
    }
}

#[test]
fn rounded_principal_form_is_the_tensor_to_its_digits() {
    let path = box_obj(
        "principal_digits_box.obj",
        DVec3::ZERO,
        DVec3::new(2.0, 1.0, 3.0),
    );
    let mut worst = [0.0_f64; 2];
    for spec in [
        "rpy=0.3 -0.4 1.1",
        "rpy=2.5 1.5707963267948966 -0.7",
        "rpy=1e-9 0 0",
    ] {
        let exact = urdf_tensor(&inertia(&path, &["--transform", spec, "--format", "urdf"]).stdout);
        for (k, digits) in ["4", "8"].into_iter().enumerate() {
            let args = ["--transform", spec, "--principal", "--digits", digits];
            let urdf = inertia(&path, &[&args[..], &["--format", "urdf"]].concat()).stdout;
            let r = rpy_matrix(DVec3::from_slice(&numbers(attribute(&urdf, "rpy"))));
            let diag = urdf_tensor(&urdf);
            worst[k] = worst[k].max(rel_matrix(r * diag * r.transpose(), exact));
            let mjcf = inertia(&path, &[&args[..], &["--format", "mjcf"]].concat()).stdout;
            let q = numbers(attribute(&mjcf, "quat"));
            let r = DMat3::from_quat(DQuat::from_xyzw(q[1], q[2], q[3], q[0]).normalize());
            let d =
                DMat3::from_diagonal(DVec3::from_slice(&numbers(attribute(&mjcf, "diaginertia"))));
            worst[k] = worst[k].max(rel_matrix(r * d * r.transpose(), exact));
        }
    }
    println!(
        "--principal --digits 4 and 8: rebuilt vs exact tensor, max rel. error {:.1e} and {:.1e}",
        worst[0], worst[1]
    );
    // Each angle (|a| < 10) is within half a unit of its last digit, so the
    // rotation within δ ≤ 3 · 0.5 · 10^(1−N) rad, which moves the tensor by
    // ≤ 2δ of its largest element; the moments add half a unit.
    for (k, n) in [4, 8].into_iter().enumerate() {
        let bound = 3.5 * 10f64.powi(1 - n);
        assert!(worst[k] <= bound, "{n} digits: {:e} > {bound:e}", worst[k]);
    }
}
