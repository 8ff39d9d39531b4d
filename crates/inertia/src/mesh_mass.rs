//! From a mesh to a body: the model (solid, thin shell, convex hull), the
//! material (density or total mass), checks and repairs, and the result with
//! everything a report needs to state.

use core::fmt;

use glam::DMat3;

use crate::mass_properties::check_positive;
use crate::mesh_unit::{MeshUnit, bounds, extent_exponent};
use crate::{
    CheckedMesh, InertiaError, MassProperties, MeshMoments, MeshWarning, TriMesh, convex_hull,
    prepare_shell, prepare_solid,
};

/// How a mesh becomes a body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MassModel {
    /// The volume enclosed by a closed surface (the default).
    Solid,
    /// The surface as a thin shell of uniform `thickness` (m); open meshes
    /// are allowed. Thin-shell approximation: exact as `thickness → 0`, with
    /// a relative error of order `thickness / size` otherwise.
    Shell {
        /// Wall thickness, m.
        thickness: f64,
    },
    /// The solid convex hull of the vertices (open or broken meshes too).
    ConvexHull,
}

impl fmt::Display for MassModel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MassModel::Solid => f.write_str("solid"),
            MassModel::Shell { thickness } => write!(f, "shell (thickness {thickness} m)"),
            MassModel::ConvexHull => f.write_str("convex hull (solid)"),
        }
    }
}

/// The amount of material: a uniform density or the total mass.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Material {
    /// Uniform density, kg/m³.
    Density(f64),
    /// Total mass, kg; the density follows from the volume.
    TotalMass(f64),
}

/// Mass properties of a mesh with what was assumed and found on the way.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshMassReport {
    /// Mass, centre of mass and inertia about it, in mesh axes.
    pub properties: MassProperties,
    /// The model used.
    pub model: MassModel,
    /// The density used, kg/m³ (given, or derived from a total mass).
    pub density: f64,
    /// Volume of material, m³ (for a shell: area × thickness).
    pub volume: f64,
    /// Surface area of the (repaired) mesh or hull, m².
    pub area: f64,
    /// Number of triangles integrated.
    pub triangles: usize,
    /// What was repaired in the mesh.
    pub warnings: Vec<MeshWarning>,
}

/// A mesh checked and integrated under a model, in its own power-of-two
/// unit, with the volume and area of material back in metres (both
/// checked to be normal f64 numbers).
pub(crate) struct Integrated {
    unit: MeshUnit,
    extent_log10: f64,
    checked: CheckedMesh,
    moments: MeshMoments,
    /// Thickness of a shell, 1 for a solid.
    scale: f64,
    /// Powers of length of the region's measure and of its second moments.
    powers: (i32, i32),
    /// Volume of material, m³.
    pub(crate) volume: f64,
    /// Surface area, m².
    area: f64,
}

impl Integrated {
    fn out_of_range(
        &self,
        quantity: &'static str,
        unit: &'static str,
        value_log10: f64,
    ) -> InertiaError {
        InertiaError::MeshOutOfRange {
            quantity,
            unit,
            extent_log10: self.extent_log10,
            value_log10,
        }
    }
}

/// A result must be a normal f64: not ∞, not 0 or subnormal (digits lost).
fn normal(x: f64) -> bool {
    x.is_finite() && x.abs() >= f64::MIN_POSITIVE
}

/// The first half of [`mesh_mass_properties`]: check, repair and integrate
/// the mesh under the model (no material yet).
pub(crate) fn integrate_model(mesh: TriMesh, model: MassModel) -> Result<Integrated, InertiaError> {
    // Checked and integrated in the mesh's power-of-two unit 2^k, so that
    // nothing depends on the units (exact scaling; k = 0 for every mesh
    // between 2^-64 and 2^64 m across), then scaled back.
    let unit = MeshUnit::of(mesh.vertices());
    let extent_log10 = extent_exponent(mesh.vertices()).map_or(f64::NEG_INFINITY, |_| {
        let (lo, hi) = bounds(mesh.vertices()).unwrap_or_default();
        unit.log10_back(
            (unit.point_in_unit(hi) - unit.point_in_unit(lo)).max_element(),
            1,
        )
    });
    let mesh = if unit.is_identity() {
        mesh
    } else {
        mesh.in_unit(&unit)
    };
    let (checked, thickness) = match model {
        MassModel::Solid => (prepare_solid(mesh).map_err(|e| unit.error_back(e))?, None),
        MassModel::Shell { thickness } => (
            prepare_shell(mesh).map_err(|e| unit.error_back(e))?,
            Some(check_positive("thickness", thickness)?),
        ),
        MassModel::ConvexHull => (
            CheckedMesh {
                mesh: convex_hull(&mesh)?,
                warnings: Vec::new(),
            },
            None,
        ),
    };
    let surface = MeshMoments::shell(&checked.mesh);
    // The powers of length of the integrated region's measure and of its
    // second moments: volume and ∫r² dV (solid), area and ∫r² dA (shell).
    let (moments, scale, (p0, p2)) = match thickness {
        // A shell's material per unit area is ρ t.
        Some(t) => (surface, t, (2, 4)),
        None => (MeshMoments::solid(&checked.mesh), 1.0, (3, 5)),
    };
    // `>` is false for NaN too.
    if moments.zeroth.partial_cmp(&0.0) != Some(core::cmp::Ordering::Greater) {
        return Err(InertiaError::ZeroVolume);
    }
    let out_of_range = |quantity, unit_name, value_log10| InertiaError::MeshOutOfRange {
        quantity,
        unit: unit_name,
        extent_log10,
        value_log10,
    };
    // The region's own measure first (the volume of a solid, the area of a
    // shell), as the quantity a reader checks against the mesh's size.
    let area = unit.scale_back(surface.zeroth, 2);
    let area_error = || out_of_range("area", "m^2", unit.log10_back(surface.zeroth, 2));
    if thickness.is_some() && !normal(area) {
        return Err(area_error());
    }
    let volume = match thickness {
        Some(t) => area * t,
        None => unit.scale_back(moments.zeroth, 3),
    };
    if !normal(volume) {
        let log10 = unit.log10_back(moments.zeroth, p0) + scale.log10();
        return Err(out_of_range("volume", "m^3", log10));
    }
    if !normal(area) {
        return Err(area_error());
    }
    Ok(Integrated {
        unit,
        extent_log10,
        checked,
        moments,
        scale,
        powers: (p0, p2),
        volume,
        area,
    })
}

/// Mass properties of a mesh under a model and a material.
///
/// ```text
/// solid / hull:  m = ρ V,  I from the volume moments
/// shell:         m = ρ t A, I from the surface moments scaled by ρ t
/// TotalMass(M):  ρ = M / V   (V = t A for a shell)
/// ```
///
/// The mesh is checked and repaired first ([`prepare_solid`] or
/// [`prepare_shell`]); the repairs are listed in the report's warnings.
///
/// Units do not matter: the mesh is checked and integrated in its own
/// power-of-two unit of length `2^k` (its extent about 1) and the results
/// scaled back exactly, so scaling a mesh by `2^j` scales the mass by
/// exactly `2^{3j}`, the centre by `2^j` and the tensor by `2^{5j}`.
///
/// # Errors
/// [`InertiaError::NonPositive`] for a density, mass or thickness that is
/// not positive and finite; the errors of [`prepare_solid`] (an open mesh:
/// use [`MassModel::Shell`] or [`MassModel::ConvexHull`]),
/// [`convex_hull`] and [`MassProperties::try_new`];
/// [`InertiaError::MeshOutOfRange`] when the volume, area, mass or inertia
/// tensor overflows f64 or falls below its normal range (a mesh far too
/// large or too small for its units), naming the quantity and the extent.
///
/// ```
/// use glam::DVec3;
/// use kreisel_inertia::{mesh_mass_properties, MassModel, Material, TriMesh};
/// let v = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
/// let tet = TriMesh::new(v, vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]);
/// let report = mesh_mass_properties(tet, MassModel::Solid, Material::TotalMass(2.0))?;
/// assert!((report.density - 12.0).abs() < 1e-13);
/// assert!((report.properties.mass - 2.0).abs() < 1e-15);
/// # Ok::<(), kreisel_inertia::InertiaError>(())
/// ```
pub fn mesh_mass_properties(
    mesh: TriMesh,
    model: MassModel,
    material: Material,
) -> Result<MeshMassReport, InertiaError> {
    match material {
        Material::Density(d) => check_positive("density", d)?,
        Material::TotalMass(m) => check_positive("mass", m)?,
    };
    let integrated = integrate_model(mesh, model)?;
    let Integrated {
        unit,
        moments,
        scale,
        powers: (p0, p2),
        volume,
        ..
    } = integrated;
    let density = match material {
        Material::Density(d) => d,
        Material::TotalMass(m) => check_positive("density", m / volume)?,
    };
    // Material per unit of the region's measure, kg/m³ or kg/m².
    let rho = density * scale;
    let mass = unit.scale_back(rho * moments.zeroth, p0);
    if !normal(mass) {
        let log10 = unit.log10_back(moments.zeroth, p0) + rho.log10();
        return Err(integrated.out_of_range("mass", "kg", log10));
    }
    let (c, inertia) = moments.central(rho);
    let inertia = DMat3::from_cols_array(&inertia.to_cols_array().map(|x| unit.scale_back(x, p2)));
    let trace = inertia.x_axis.x + inertia.y_axis.y + inertia.z_axis.z;
    if !(inertia.is_finite() && normal(trace)) {
        let (_, unit_inertia) = moments.central(1.0);
        let largest = unit_inertia
            .to_cols_array()
            .iter()
            .fold(0.0_f64, |a, x| a.max(x.abs()));
        let log10 = unit.log10_back(largest, p2) + rho.log10();
        return Err(integrated.out_of_range("inertia tensor", "kg m^2", log10));
    }
    let properties = MassProperties::try_new(mass, unit.point_back(moments.origin + c), inertia)?;
    Ok(MeshMassReport {
        properties,
        model,
        density,
        volume,
        area: integrated.area,
        triangles: integrated.checked.mesh.triangles().len(),
        warnings: integrated.checked.warnings,
    })
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::tri_mesh::box_mesh;
    use crate::{Weld, Welded};

    /// `x · 2^e` by repeated doubling or halving: exact while the result is
    /// a normal number (independent of the code under test).
    fn times_pow2(mut x: f64, e: i32) -> f64 {
        for _ in 0..e.unsigned_abs() {
            x = if e > 0 { x * 2.0 } else { x * 0.5 };
        }
        x
    }

    /// An irregular closed octahedron (every product of inertia non-zero)
    /// with one vertex repeated 1e-9 of the size away, for the weld.
    fn octahedron() -> TriMesh {
        let v = vec![
            DVec3::new(1.1, 0.13, -0.07),
            DVec3::new(-0.9, 0.21, 0.05),
            DVec3::new(0.17, 1.3, 0.11),
            DVec3::new(-0.05, -0.8, 0.19),
            DVec3::new(0.23, -0.1, 1.2),
            DVec3::new(0.07, 0.3, -0.7),
            DVec3::new(1.1 + 1e-9, 0.13, -0.07),
        ];
        let t = vec![
            [0, 2, 4],
            [2, 1, 4],
            [1, 3, 4],
            [3, 6, 4],
            [2, 0, 5],
            [1, 2, 5],
            [3, 1, 5],
            [0, 3, 5],
        ];
        TriMesh::new(v, t)
    }

    fn scaled_by(mesh: &TriMesh, f: impl Fn(f64) -> f64) -> TriMesh {
        let v = mesh
            .vertices()
            .iter()
            .map(|p| p.to_array().map(&f).into())
            .collect();
        TriMesh::new(v, mesh.triangles().to_vec())
    }

    fn solid(mesh: TriMesh) -> Result<(MeshMassReport, Welded), InertiaError> {
        let (welded, report) = mesh.welded(Weld::default())?;
        Ok((
            mesh_mass_properties(welded, MassModel::Solid, Material::Density(1000.0))?,
            report,
        ))
    }

    fn normal(x: f64) -> bool {
        x.is_finite() && x.abs() >= f64::MIN_POSITIVE
    }

    #[test]
    fn power_of_two_scales_give_exactly_scaled_results_or_a_range_error() {
        let (base, weld) = solid(octahedron()).unwrap();
        assert_eq!(weld.merged, 1);
        let (m, c, i) = (
            base.properties.mass,
            base.properties.center_of_mass,
            base.properties.inertia.to_cols_array(),
        );
        let (mut ok, mut refused) = (0, 0);
        for k in (-300..=300).step_by(37) {
            let mesh = scaled_by(&octahedron(), |x| times_pow2(x, k));
            let expected_mass = times_pow2(m, 3 * k);
            let expected_i = i.map(|x| times_pow2(x, 5 * k));
            let trace = expected_i[0] + expected_i[4] + expected_i[8];
            let representable = normal(expected_mass)
                && normal(times_pow2(base.area, 2 * k))
                && expected_i.iter().all(|x| x.is_finite())
                && normal(trace);
            match solid(mesh) {
                Ok((r, w)) => {
                    assert!(representable, "k = {k}: accepted {:?}", r.properties);
                    assert_eq!((w.merged, w.tolerance), (1, times_pow2(weld.tolerance, k)));
                    assert_eq!(
                        r.properties.mass.to_bits(),
                        expected_mass.to_bits(),
                        "k = {k}"
                    );
                    assert_eq!(r.volume, times_pow2(base.volume, 3 * k), "k = {k}");
                    assert_eq!(r.area, times_pow2(base.area, 2 * k), "k = {k}");
                    assert_eq!(
                        r.properties.center_of_mass,
                        c.to_array().map(|x| times_pow2(x, k)).into()
                    );
                    for (got, want) in r.properties.inertia.to_cols_array().iter().zip(expected_i) {
                        // Products of inertia below the normal range lose digits in rounding.
                        if normal(want) {
                            assert_eq!(got.to_bits(), want.to_bits(), "k = {k}");
                        }
                    }
                    ok += 1;
                }
                Err(e) => {
                    assert!(!representable, "k = {k}: {e}");
                    assert!(
                        matches!(e, InertiaError::MeshOutOfRange { .. }),
                        "k = {k}: {e}"
                    );
                    refused += 1;
                }
            }
        }
        // Both sides of the range are met: 2^±300 m cubes have moments beyond f64.
        assert!(ok >= 9 && refused >= 4, "{ok} accepted, {refused} refused");
    }

    #[test]
    fn decimal_scales_agree_to_rounding() {
        let (base, _) = solid(octahedron()).unwrap();
        for e in (-60..=60).step_by(7) {
            let s = 10f64.powi(e) * 1.37;
            let (r, w) = solid(scaled_by(&octahedron(), |x| x * s)).unwrap();
            assert_eq!(w.merged, 1, "s = {s:e}");
            let rel = |got: f64, want: f64, scale: f64| ((got - want) / scale).abs();
            let p = r.properties;
            assert!(
                rel(p.mass, base.properties.mass * s.powi(3), p.mass) < 1e-14,
                "s = {s:e}"
            );
            let c = base.properties.center_of_mass * s;
            assert!((p.center_of_mass - c).length() < 1e-14 * s, "s = {s:e}");
            let want = base.properties.inertia * s.powi(5);
            let size = want
                .to_cols_array()
                .iter()
                .fold(0.0_f64, |a, x| a.max(x.abs()));
            for (g, w) in p.inertia.to_cols_array().iter().zip(want.to_cols_array()) {
                assert!(rel(*g, w, size) < 1e-14, "s = {s:e}: {g:e} vs {w:e}");
            }
        }
    }

    /// A cube of half-size `s` about the origin, through the weld and the solid model.
    fn cube(s: f64) -> Result<(MeshMassReport, Welded), InertiaError> {
        solid(box_mesh(DVec3::splat(-s), DVec3::splat(s)))
    }

    fn out_of_range(s: f64) -> (&'static str, f64, f64) {
        match cube(s) {
            Err(InertiaError::MeshOutOfRange {
                quantity,
                extent_log10,
                value_log10,
                ..
            }) => (quantity, extent_log10, value_log10),
            other => panic!("half-size {s:e}: {other:?}"),
        }
    }

    #[test]
    fn huge_cube_welds_to_eight_vertices_and_its_volume_overflows() {
        // Was "mesh is empty (1 vertices, 0 triangles)": the diagonal overflowed
        // and every vertex welded into one.
        let (welded, report) = box_mesh(DVec3::splat(-1e200), DVec3::splat(1e200))
            .welded(Weld::default())
            .unwrap();
        assert_eq!((welded.vertices().len(), report.merged), (8, 0));
        assert!((report.tolerance / (2e200 * 3f64.sqrt()) - 1e-6).abs() < 1e-20);
        let (quantity, extent, volume) = out_of_range(1e200);
        assert_eq!(quantity, "volume");
        assert!((extent - 2e200f64.log10()).abs() < 1e-12);
        assert!((volume - (600.0 + 8f64.log10())).abs() < 1e-9, "{volume}");
        let text = cube(1e200).unwrap_err().to_string();
        assert!(
            text.starts_with(
                "mass properties of a mesh 2e200 m across overflow f64 (volume ≈ 8e600 m^3"
            ),
            "{text}"
        );
    }

    #[test]
    fn volume_beyond_f64_is_named_not_zero() {
        // Was "mesh encloses zero volume".
        let (quantity, _, volume) = out_of_range(1e120);
        assert_eq!(quantity, "volume");
        assert!((volume - (360.0 + 8f64.log10())).abs() < 1e-9, "{volume}");
    }

    #[test]
    fn inertia_beyond_f64_is_named_not_unphysical() {
        // Was "inertia tensor is not physical: tensor has a non-finite element".
        // I = ρ V (2s)²/6 = 1000 · 8e210 · 4e140 / 6.
        let (quantity, _, inertia) = out_of_range(1e70);
        assert_eq!(quantity, "inertia tensor");
        assert!((inertia - (1000.0 * 8.0 * 4.0 / 6.0f64).log10() - 350.0).abs() < 1e-9);
        // Its mirror: the moments of a 2e-70 m cube underflow (were printed as 0).
        let (quantity, _, inertia) = out_of_range(1e-70);
        assert_eq!(quantity, "inertia tensor");
        assert!((inertia - (1000.0 * 8.0 * 4.0 / 6.0f64).log10() + 350.0).abs() < 1e-9);
    }

    #[test]
    fn tiny_cube_is_checked_not_empty_and_its_volume_underflows() {
        // Was "mesh is empty (8 vertices, 0 triangles)": every area underflowed.
        let tiny = box_mesh(DVec3::splat(-1e-200), DVec3::splat(1e-200));
        let checked = prepare_solid(tiny.clone()).unwrap();
        assert_eq!(
            (checked.mesh.triangles().len(), checked.warnings.len()),
            (12, 0)
        );
        assert_eq!(checked.mesh.vertices(), tiny.vertices());
        let (quantity, _, volume) = out_of_range(1e-200);
        assert_eq!(quantity, "volume");
        assert!((volume - (-600.0 + 8f64.log10())).abs() < 1e-9, "{volume}");
        // At 1e-40 everything is representable and exact: m = ρ (2s)³, I = m (2s)²/6.
        let (r, _) = cube(2f64.powi(-133)).unwrap();
        let m = 1000.0 * 2f64.powi(-396);
        assert_eq!(r.properties.mass, m);
        let i = m * 2f64.powi(-264) / 6.0;
        assert!((r.properties.inertia.x_axis.x / i - 1.0).abs() < 1e-15);
    }

    #[test]
    fn open_tiny_mesh_names_its_boundary_in_its_own_units() {
        let (v, mut t) = box_mesh(DVec3::splat(1e-200), DVec3::splat(3e-200)).into_parts();
        t.pop();
        let e = mesh_mass_properties(TriMesh::new(v, t), MassModel::Solid, Material::Density(1.0));
        match e {
            Err(InertiaError::OpenMesh {
                boundary_edges, at, ..
            }) => {
                assert_eq!(boundary_edges, 3);
                assert!(
                    at.min_element() >= 1e-200 && at.max_element() <= 3e-200,
                    "{at}"
                );
            }
            other => panic!("{other:?}"),
        }
    }
}
