//! Bodies with a `pivot`: heavy tops under gravity against the 60-digit
//! references of `tests/data/heavy_top/` (`python3 tests/data/gen/heavy_top.py`),
//! their conserved quantities, and one-line errors.

use glam::DQuat;

use crate::support::{Row, max_relative_drift, simulate, simulate_file, workspace};

/// Reference samples `t → world_from_body` and the `# key = (…)` numbers.
struct Reference {
    samples: Vec<(f64, DQuat)>,
    meta: std::collections::HashMap<String, Vec<f64>>,
}

fn reference(name: &str) -> Reference {
    let path = workspace(&format!("tests/data/heavy_top/{name}.csv"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut samples = Vec::new();
    let mut meta = std::collections::HashMap::new();
    for line in text.lines() {
        if let Some((key, value)) = line.strip_prefix("# ").and_then(|l| l.split_once(" = ")) {
            let numbers = value
                .trim_matches(|c| c == '(' || c == ')')
                .split(',')
                .filter_map(|x| x.trim().parse().ok())
                .collect();
            meta.insert(key.to_owned(), numbers);
        } else if !line.starts_with('#') && !line.starts_with('t') {
            let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
            samples.push((v[0], DQuat::from_xyzw(v[2], v[3], v[4], v[1])));
        }
    }
    Reference { samples, meta }
}

/// The largest angle between the rows' attitudes and the reference at the
/// same times (every row must fall on a sample).
fn max_angle(rows: &[Row], r: &Reference) -> f64 {
    assert_eq!(rows.len(), r.samples.len());
    rows.iter()
        .zip(&r.samples)
        .map(|(row, (t, q))| {
            assert!((row.t - t).abs() < 1e-12, "{} vs {t}", row.t);
            // 4 asin(|a − b|/2): accurate for small angles (2 acos(a·b) is not).
            let a = row.q.normalize();
            let chord = (a - *q).length().min((a + *q).length());
            4.0 * (0.5 * chord).asin()
        })
        .fold(0.0, f64::max)
}

/// The goal through the CLI: the default method, dt = 1e-3, the
/// Bruls–Cardona–Arnold fast top (examples/scenes/heavy_top.toml) within
/// 1e-8 rad of the reference for 2 s; energy and the vertical angular
/// momentum about the pivot conserved.
#[test]
fn bruls_scene_matches_the_reference() {
    let rows = simulate_file(&workspace("examples/scenes/heavy_top.toml"), &[]).rows();
    let r = reference("bruls");
    let err = max_angle(&rows, &r);
    eprintln!("bruls scene, auto, dt = 1e-3: max attitude error {err:.2e} rad");
    assert!(err < 1e-8, "{err:e}");
    let energy = r.meta["energy"][0];
    assert!(
        (rows[0].energy - energy).abs() < 1e-12 * energy,
        "{} vs {energy}",
        rows[0].energy
    );
    assert!(max_relative_drift(rows.iter().map(|r| r.energy)) < 1e-12);
    let lz = r.meta["l_world_z"][0];
    for row in &rows {
        assert!(
            (row.l.z - lz).abs() < 1e-12 * lz.abs(),
            "{} vs {lz}",
            row.l.z
        );
    }
}

/// An asymmetric top from a full inertia tensor, its centre of mass off
/// every principal axis, the pivot given from the centre of mass.
#[test]
fn asymmetric_tensor_body_with_a_pivot() {
    let r = reference("asymmetric_fast");
    let m = &r.meta;
    let (c, q, i) = (&m["com"], &m["q0"], &m["inertia_cm"]);
    let scene = format!(
        "[simulation]\nduration = 2.0\ndt = 0.001\noutput_interval = 0.01\ngravity = {:?}\n\
         [[body]]\nmass = {:?}\ninertia_tensor = [[{:?}, {:?}, {:?}], [{:?}, {:?}, {:?}], [{:?}, {:?}, {:?}]]\n\
         orientation = {:?}\nangular_velocity = {:?}\npivot = [{:?}, {:?}, {:?}]\nposition = [1.0, 2.0, 3.0]\n",
        m["gravity"],
        m["mass"][0],
        i[0],
        i[1],
        i[2],
        i[3],
        i[4],
        i[5],
        i[6],
        i[7],
        i[8],
        q,
        m["omega0"],
        -c[0],
        -c[1],
        -c[2],
    );
    let rows = simulate("asymmetric_top.toml", &scene, &[]).rows();
    let err = max_angle(&rows, &r);
    eprintln!("asymmetric top, auto, dt = 1e-3: max attitude error {err:.2e} rad");
    assert!(err < 1e-8, "{err:e}");
    // The pivot's position adds −m g·p to the energy: 2 kg · 9.81 · 3 m.
    let energy = r.meta["energy"][0] + 2.0 * 9.81 * 3.0;
    assert!(
        (rows[0].energy - energy).abs() < 1e-12 * energy,
        "{} vs {energy}",
        rows[0].energy
    );
    assert!(max_relative_drift(rows.iter().map(|r| r.energy)) < 1e-12);
}

/// Without gravity a pivoted body is a free body about the pivot: every
/// method conserves L about the pivot; rk4 is the only non-geometric one.
#[test]
fn pivot_without_gravity_conserves_angular_momentum() {
    let scene = "[simulation]\nduration = 1.0\ndt = 0.01\n\
                 [[body]]\nmass = 2.0\ninertia = [0.1, 0.2, 0.3]\nangular_velocity = [1.0, 5.0, -2.0]\npivot = [0.1, 0.0, 0.0]\n";
    for method in ["auto", "strang", "splitting6", "rk4"] {
        let rows = simulate("free_pivot.toml", scene, &["--method", method]).rows();
        let l0 = rows[0].l;
        let drift = rows.iter().map(|r| (r.l - l0).length()).fold(0.0, f64::max) / l0.length();
        eprintln!("{method}: |ΔL|/|L| = {drift:.1e}");
        assert!(
            drift < if method == "rk4" { 1e-6 } else { 1e-13 },
            "{method}: {drift:e}"
        );
    }
}

#[test]
fn bad_pivots_are_one_line_errors() {
    let base = "[simulation]\nduration = 1.0\ndt = 0.01\ngravity = [0, 0, -9.81]\n[[body]]\nmass = 1\ninertia = [1, 2, 3]\nangular_velocity = [0, 0, 1]\n";
    let e = simulate(
        "pivot_nan.toml",
        &format!("{base}pivot = [0, nan, 0]\n"),
        &[],
    )
    .error_line(1)
    .to_owned();
    assert!(
        e.contains("pivot_nan.toml:9: body `body1`: `pivot` must be finite numbers"),
        "{e}"
    );
    let e = simulate(
        "pivot_v.toml",
        &format!("{base}pivot = [0, 0, -1]\nvelocity = [1, 0, 0]\n"),
        &[],
    )
    .error_line(1)
    .to_owned();
    assert!(
        e.contains(":10: body `body1`: `velocity` cannot be given with `pivot`"),
        "{e}"
    );
    let e = simulate(
        "pivot_exact.toml",
        &format!("{base}pivot = [0, 0, -1]\n"),
        &["--method", "exact"],
    )
    .error_line(1)
    .to_owned();
    assert!(
        e.contains("method `exact` cannot move a body with a `pivot`"),
        "{e}"
    );
    let scene = base.replace("[simulation]\n", "[simulation]\nmethod = \"pdmv6\"\n");
    let e = simulate(
        "pivot_pdmv.toml",
        &format!("{scene}pivot = [0, 0, -1]\n"),
        &[],
    )
    .error_line(1)
    .to_owned();
    assert!(
        e.contains("pivot_pdmv.toml:2: `method`: method `pdmv6` cannot move a body with a `pivot`"),
        "{e}"
    );
}
