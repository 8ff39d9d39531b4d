//! Mass properties of meshes against exact rational references
//! (`tests/data/gen/inertia.py`, Python `fractions`), against parry, and
//! against the closed forms of primitives.
//!
//! Regenerate the data with `python3 tests/data/gen/inertia.py`.

mod common;

use std::path::{Path, PathBuf};

use common::Table;
use kreisel::inertia::io::load_bodies;
use kreisel::inertia::{
    MassModel, MassProperties, Material, MeshMoments, MeshWarning, TriMesh, mesh_mass_properties,
    parry_mass_properties, prepare_solid,
};
use kreisel::kinematics::glam::{DMat3, DQuat, DVec3};

/// Worst relative error allowed (issue #3): 1e-13.
const WORST: f64 = 1e-13;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The mesh file behind a row of `polyhedra_expected.csv`.
fn mesh_path(name: &str) -> PathBuf {
    match name {
        "t_handle" => root().join("assets/t_handle.obj"),
        "top" => root().join("assets/top.stl"),
        "top_ascii" => root().join("assets/top_ascii.stl"),
        _ => root()
            .join("tests/data/polyhedra")
            .join(format!("{name}.obj")),
    }
}

fn load_one(path: &Path) -> TriMesh {
    let mut bodies = load_bodies(path).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(bodies.len(), 1, "{}", path.display());
    bodies.remove(0).mesh
}

fn tensor(t: &Table, row: &[String], prefix: &str) -> DMat3 {
    let n = |k: &str| t.num(row, &format!("{prefix}{k}"));
    DMat3::from_cols(
        DVec3::new(n("ixx"), n("ixy"), n("ixz")),
        DVec3::new(n("ixy"), n("iyy"), n("iyz")),
        DVec3::new(n("ixz"), n("iyz"), n("izz")),
    )
}

fn max_abs(m: DMat3) -> f64 {
    m.to_cols_array()
        .iter()
        .fold(0.0_f64, |a, v| a.max(v.abs()))
}

/// Relative errors of mass, centre of mass (against the radius of
/// gyration) and tensor (against its largest element).
fn relative_errors(got: &MassProperties, mass: f64, com: DVec3, inertia: DMat3) -> [f64; 3] {
    let gyration = (max_abs(inertia) / mass).sqrt();
    [
        (got.mass - mass).abs() / mass,
        (got.center_of_mass - com).abs().max_element() / gyration,
        max_abs(got.inertia - inertia) / max_abs(inertia),
    ]
}

#[test]
fn solids_match_exact_rational_references() {
    let t = Table::load("polyhedra_expected.csv");
    let mut worst: f64 = 0.0;
    for row in &t.rows {
        let name = t.text(row, "name");
        let mesh = load_one(&mesh_path(name));
        assert_eq!(
            mesh.triangles().len() as f64,
            t.num(row, "triangles"),
            "{name}"
        );
        let report = mesh_mass_properties(mesh, MassModel::Solid, Material::Density(1.0)).unwrap();
        assert!(report.warnings.is_empty(), "{name}: {:?}", report.warnings);
        let com = t.vec3(row, ["cx", "cy", "cz"]);
        let e = relative_errors(
            &report.properties,
            t.num(row, "volume"),
            com,
            tensor(&t, row, ""),
        );
        eprintln!(
            "{name:>18}: mass {:.1e}, com {:.1e}, inertia {:.1e}",
            e[0], e[1], e[2]
        );
        worst = worst.max(e.into_iter().fold(0.0, f64::max));
    }
    eprintln!("worst relative error {worst:e}");
    assert!(worst <= WORST);
}

#[test]
fn shells_match_exact_rational_references() {
    let t = Table::load("polyhedra_expected.csv");
    let mut checked = 0;
    for row in t.rows.iter().filter(|r| !t.text(r, "area").is_empty()) {
        let name = t.text(row, "name");
        let thickness = 1e-3;
        let model = MassModel::Shell { thickness };
        let report =
            mesh_mass_properties(load_one(&mesh_path(name)), model, Material::Density(1.0))
                .unwrap();
        // Areal density ρ t = 1e-3: reference values are at areal density 1.
        let area = t.num(row, "area");
        let com = t.vec3(row, ["shell_cx", "shell_cy", "shell_cz"]);
        let mut p = report.properties;
        p.mass /= thickness;
        p.inertia /= thickness;
        let e = relative_errors(&p, area, com, tensor(&t, row, "shell_"));
        assert!(e.iter().all(|&x| x <= WORST), "{name}: {e:?}");
        assert!((report.area - area).abs() <= WORST * area);
        checked += 1;
    }
    assert!(checked >= 5);
}

#[test]
fn translation_far_from_origin_loses_no_digits() {
    // Meshes with dyadic coordinates, moved by exactly representable offsets:
    // the moved vertices are exact, so the reference is the same shape.
    let t = Table::load("polyhedra_expected.csv");
    for name in [
        "box_rotated_exact",
        "l_shape",
        "t_handle_exact",
        "prism_hex",
    ] {
        let row = t.rows.iter().find(|r| t.text(r, "name") == name).unwrap();
        let mesh = load_one(&mesh_path(name));
        let com = t.vec3(row, ["cx", "cy", "cz"]);
        for offset in [
            DVec3::new(1024.0, 0.0, 0.0),
            DVec3::new(1e6, -2e6, 3e6),
            DVec3::splat(2f64.powi(30)),
        ] {
            let moved = mesh.clone().translated(offset);
            assert_eq!(
                moved.clone().translated(-offset),
                mesh,
                "{name}: offset not exact"
            );
            let p = MeshMoments::solid(&moved).mass_properties(1.0).unwrap();
            // The centre of mass itself lives at `offset`: it can be no more
            // precise than the spacing of f64 there.
            let spacing = (com + offset).abs().max_element() * f64::EPSILON;
            assert!(
                (p.center_of_mass - (com + offset)).abs().max_element() <= spacing,
                "{name}"
            );
            let [em, _, ei] =
                relative_errors(&p, t.num(row, "volume"), com + offset, tensor(&t, row, ""));
            assert!(
                em <= WORST && ei <= WORST,
                "{name} at {offset}: mass {em:e}, inertia {ei:e}"
            );
        }
    }
    // The same integrals summed about the coordinate origin instead lose the
    // far box entirely: the shift to a point of the mesh is what saves it.
    let far = load_one(&mesh_path("box_1x2x3_far"));
    let (mut vol, mut first, mut second) = (0.0, DVec3::ZERO, DMat3::ZERO);
    for tri in far.triangles() {
        let [a, b, c] = far.corners(*tri);
        let d = a.dot(b.cross(c));
        let s = a + b + c;
        vol += d / 6.0;
        first += s * (d / 24.0);
        let outer = |u: DVec3| DMat3::from_cols(u * u.x, u * u.y, u * u.z);
        second += (outer(s) + outer(a) + outer(b) + outer(c)) * (d / 120.0);
    }
    let c = first / vol;
    let cov = second - DMat3::from_cols(c * c.x, c * c.y, c * c.z) * vol;
    let naive = DMat3::IDENTITY * (cov.x_axis.x + cov.y_axis.y + cov.z_axis.z) - cov;
    let exact = MassProperties::solid_box(1.0, DVec3::new(1.0, 2.0, 3.0)).unwrap();
    let naive_error = max_abs(naive - exact.inertia) / max_abs(exact.inertia);
    let ours = MeshMoments::solid(&far).mass_properties(1.0).unwrap();
    let our_error = max_abs(ours.inertia - exact.inertia) / max_abs(exact.inertia);
    eprintln!("1×2×3 box at 1e6 m: summed about the origin {naive_error:e}, kreisel {our_error:e}");
    assert!(naive_error > 1.0);
    assert!(our_error <= WORST);
}

#[test]
fn agrees_with_parry_on_closed_meshes() {
    let t = Table::load("polyhedra_expected.csv");
    for row in &t.rows {
        let name = t.text(row, "name");
        let mesh = load_one(&mesh_path(name));
        let ours = MeshMoments::solid(&mesh).mass_properties(1.0).unwrap();
        let parry = parry_mass_properties(&mesh, 1.0);
        let [em, ec, ei] = relative_errors(&parry, ours.mass, ours.center_of_mass, ours.inertia);
        let moments = ours.principal().moments;
        let ep = (parry.principal().moments - moments).abs().max_element() / moments.z;
        eprintln!(
            "{name:>18}: mass {em:.1e}, com {ec:.1e}, inertia {ei:.1e}, principal moments {ep:.1e}"
        );
        assert!(em <= WORST && ec <= WORST && ep <= WORST, "{name}");
        // parry stores the tensor in principal form; with two equal moments
        // (the tetrahedron: 1/96, 1/96, 1/60) its principal frame comes out
        // wrong and the rebuilt tensor is off by 17 % (measured, parry 0.31),
        // so compare whole tensors only where the moments are distinct.
        let distinct = (moments.y - moments.x).min(moments.z - moments.y) > 1e-9 * moments.z;
        if distinct {
            assert!(ei <= WORST, "{name}: inertia {ei:e}");
        }
    }
}

#[test]
fn parry_fails_where_kreisel_repairs() {
    // Every second triangle flipped: parry's mass is wrong, ours is exact and warns.
    let mesh = load_one(&mesh_path("unit_cube"));
    let (v, mut tris) = mesh.into_parts();
    for tri in tris.iter_mut().step_by(2) {
        tri.swap(1, 2);
    }
    let mixed = TriMesh::new(v, tris);
    let parry = parry_mass_properties(&mixed, 1.0);
    assert!((parry.mass - 1.0).abs() > 0.1, "parry got {}", parry.mass);
    let ours = mesh_mass_properties(mixed, MassModel::Solid, Material::Density(1.0)).unwrap();
    assert!((ours.properties.mass - 1.0).abs() < 1e-15);
    assert!(matches!(
        ours.warnings[..],
        [MeshWarning::Reoriented { triangles: 6 }]
    ));
}

#[test]
fn inside_out_gives_positive_result_and_warning() {
    let mesh = load_one(&mesh_path("l_shape"));
    let exact = MeshMoments::solid(&mesh).mass_properties(1.0).unwrap();
    let (v, tris) = mesh.into_parts();
    let inverted = TriMesh::new(v, tris.into_iter().map(|[a, b, c]| [a, c, b]).collect());
    let checked = prepare_solid(inverted).unwrap();
    assert_eq!(
        checked.warnings,
        vec![MeshWarning::InsideOut { surfaces: 1 }]
    );
    let p = MeshMoments::solid(&checked.mesh)
        .mass_properties(1.0)
        .unwrap();
    assert_eq!(p, exact);
}

#[test]
fn parts_summed_equal_the_fused_mesh() {
    // t_handle_exact (tests/data/gen/inertia.py): crossbar [−2,2]×[−½,½]×[0,1]
    // fused with stem [−¼,¼]×[−¼,¼]×[−2,0]; the same from closed-form boxes.
    let t = Table::load("polyhedra_expected.csv");
    let row = t
        .rows
        .iter()
        .find(|r| t.text(r, "name") == "t_handle_exact")
        .unwrap();
    let bar = MassProperties::solid_box(1.0, DVec3::new(4.0, 1.0, 1.0)).unwrap();
    let stem = MassProperties::solid_box(1.0, DVec3::new(0.5, 0.5, 2.0)).unwrap();
    let sum =
        bar.translated(DVec3::new(0.0, 0.0, 0.5)) + stem.translated(DVec3::new(0.0, 0.0, -1.0));
    let expect = (
        t.num(row, "volume"),
        t.vec3(row, ["cx", "cy", "cz"]),
        tensor(&t, row, ""),
    );
    let e = relative_errors(&sum, expect.0, expect.1, expect.2);
    assert!(e.iter().all(|&x| x <= WORST), "{e:?}");
    let mesh = MeshMoments::solid(&load_one(&mesh_path("t_handle_exact")))
        .mass_properties(1.0)
        .unwrap();
    let e = relative_errors(&mesh, expect.0, expect.1, expect.2);
    assert!(e.iter().all(|&x| x <= WORST), "{e:?}");
    // Placing the assembly rotated keeps its principal moments.
    let rotated = sum.placed(DQuat::from_rotation_z(0.3), DVec3::X);
    let dm = rotated.principal().moments - sum.principal().moments;
    assert!(dm.abs().max_element() <= 1e-13 * max_abs(sum.inertia));
}

#[test]
fn shell_is_the_limit_of_a_difference_of_solids() {
    // Cube of side 1: a shell of thickness t versus solid(1 + t) − solid(1 − t), centred.
    let rho = 7.0;
    for t in [1e-2, 1e-3, 1e-4] {
        let outer = MassProperties::solid_box(rho, DVec3::splat(1.0 + t)).unwrap();
        let inner = MassProperties::solid_box(rho, DVec3::splat(1.0 - t)).unwrap();
        let diff_mass = outer.mass - inner.mass;
        let diff_i = outer.inertia.x_axis.x - inner.inertia.x_axis.x;
        let mesh = load_one(&mesh_path("unit_cube"));
        let shell = mesh_mass_properties(
            mesh,
            MassModel::Shell { thickness: t },
            Material::Density(rho),
        )
        .unwrap()
        .properties;
        let em = (shell.mass - diff_mass).abs() / diff_mass;
        let ei = (shell.inertia.x_axis.x - diff_i).abs() / diff_i;
        eprintln!("t = {t:e}: mass {em:e}, I_xx {ei:e}");
        // Thin-shell error is O(t²) here (the t-linear terms cancel by symmetry).
        assert!(em <= 2.0 * t * t && ei <= 4.0 * t * t, "{em} {ei}");
    }
}

/// Closed forms of the primitives against fine meshes: the error falls like
/// h² (second order in the segment count) towards zero.
#[test]
fn primitives_are_the_limit_of_fine_meshes() {
    use common::shapes;
    type Case = (&'static str, MassProperties, fn(usize) -> TriMesh);
    let cases: [Case; 6] = [
        (
            "sphere",
            MassProperties::solid_sphere(1.0, 1.0).unwrap(),
            |n| shapes::sphere(1.0, n),
        ),
        (
            "cylinder",
            MassProperties::solid_cylinder(1.0, 0.5, 2.0).unwrap(),
            |n| shapes::cylinder(0.5, 2.0, n),
        ),
        (
            "cone",
            MassProperties::solid_cone(1.0, 1.0, 3.0).unwrap(),
            |n| shapes::cone(1.0, 3.0, n),
        ),
        (
            "capsule",
            MassProperties::solid_capsule(1.0, 0.5, 1.5).unwrap(),
            |n| shapes::capsule(0.5, 1.5, n),
        ),
        (
            "torus",
            MassProperties::solid_torus(1.0, 2.0, 0.5).unwrap(),
            |n| shapes::torus(2.0, 0.5, n),
        ),
        (
            "ellipsoid",
            MassProperties::solid_ellipsoid(1.0, DVec3::new(1.0, 2.0, 3.0)).unwrap(),
            |n| shapes::ellipsoid(DVec3::new(1.0, 2.0, 3.0), n),
        ),
    ];
    for (name, exact, mesh) in cases {
        let props = |n: usize| {
            let p =
                mesh_mass_properties(mesh(n), MassModel::Solid, Material::Density(1.0)).unwrap();
            assert!(p.warnings.is_empty(), "{name}: {:?}", p.warnings);
            p.properties
        };
        let err = |p: &MassProperties| {
            let e = relative_errors(p, exact.mass, exact.center_of_mass, exact.inertia);
            e.into_iter().fold(0.0, f64::max)
        };
        let (coarse, fine) = (props(64), props(128));
        let order = (err(&coarse) / err(&fine)).log2();
        // Richardson extrapolation with the measured order 2 removes the h² term.
        let extrapolated = MassProperties {
            mass: (4.0 * fine.mass - coarse.mass) / 3.0,
            center_of_mass: (fine.center_of_mass * 4.0 - coarse.center_of_mass) / 3.0,
            inertia: (fine.inertia * 4.0 - coarse.inertia) * (1.0 / 3.0),
        };
        eprintln!(
            "{name:>10}: error {:.2e} at 64, {:.2e} at 128 segments (order {order:.2}), extrapolated {:.2e}",
            err(&coarse),
            err(&fine),
            err(&extrapolated)
        );
        assert!((1.9..2.1).contains(&order), "{name}: order {order}");
        // What is left is the h⁴ term: far below the h² error.
        assert!(err(&extrapolated) < err(&fine) / 100.0, "{name}");
    }
}
