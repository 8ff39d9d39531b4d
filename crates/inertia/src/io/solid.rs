//! From a mesh file to a solid: the one entry point the CLI's `simulate`
//! and `inertia` commands and the demos share.
//!
//! ```text
//! file ──load (weld, merge)──▶ bodies ──scale to metres──▶ TriMesh per body
//!      ──check, repair, integrate (model, material)──▶ MassProperties per body
//!      ──compound (parallel axis)──▶ the file's solid
//! ```
//!
//! The file's solid is all its bodies as one rigid compound, in the file's
//! axes (scaled to metres); the per-body results stay available. Nothing is
//! printed: what the loader and the mesh checks repaired comes back as
//! [`SolidWarning`]s, each with the name of its body.

use std::path::{Path, PathBuf};

use core::fmt;

use super::{Body, LoadOptions, LoadWarning};
use crate::mass_properties::check_positive;
use crate::mesh_mass::integrate_model;
use crate::{InertiaError, MassModel, MassProperties, Material, MeshWarning, mesh_mass_properties};

/// How a mesh file becomes a solid: loading, units, model and material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolidOptions {
    /// Welding (tolerances in the file's units) and merging of bodies.
    pub load: LoadOptions,
    /// Metres per file unit (`0.001` for a file in millimetres).
    pub scale: f64,
    /// Solid, thin shell or convex hull; the same for every body.
    pub model: MassModel,
    /// The density of every body, or the total mass of the file's bodies
    /// together (one density for all: `ρ = M / Σ V`).
    pub material: Material,
}

impl SolidOptions {
    /// Default loading, metres, the solid model, and the given material.
    ///
    /// ```
    /// use kreisel_inertia::io::SolidOptions;
    /// use kreisel_inertia::{MassModel, Material};
    /// let options = SolidOptions::new(Material::Density(7850.0));
    /// assert_eq!((options.scale, options.model), (1.0, MassModel::Solid));
    /// assert!(!options.load.merge);
    /// ```
    pub fn new(material: Material) -> Self {
        Self {
            load: LoadOptions::default(),
            scale: 1.0,
            model: MassModel::Solid,
            material,
        }
    }

    /// Loads every body of a mesh file and scales it to metres: the first
    /// half of [`load_solid`], for callers that need the meshes (to draw
    /// them, or to check them) before [`SolidOptions::solid`] integrates them.
    ///
    /// Loader warnings keep the file's units (the weld tolerance and moves).
    ///
    /// # Errors
    /// [`InertiaError::NonPositive`] for a scale that is not positive and
    /// finite; the errors of [`LoadOptions::load`];
    /// [`InertiaError::ScaleOverflow`] naming the body whose coordinates
    /// overflow when scaled.
    pub fn load_bodies(&self, path: &Path) -> Result<Vec<Body>, InertiaError> {
        let scale = check_positive("scale", self.scale)?;
        let bodies = self.load.load(path)?;
        if scale == 1.0 {
            return Ok(bodies);
        }
        bodies
            .into_iter()
            .map(|mut body| {
                body.mesh =
                    body.mesh
                        .try_scaled(scale)
                        .map_err(|_| InertiaError::ScaleOverflow {
                            path: path.to_path_buf(),
                            body: body.name.clone(),
                            scale,
                        })?;
                Ok(body)
            })
            .collect()
    }

    /// The solid of bodies loaded from `path` (which names the file in
    /// errors and in the result): each body integrated under the model and
    /// material, and their compound.
    ///
    /// ```text
    /// Density(ρ):    m_k = ρ V_k
    /// TotalMass(M):  ρ = M / Σ_k V_k      (V = t A for a shell)
    /// compound:      m = Σ m_k,  c = Σ m_k c_k / m,
    ///                I = Σ_k [I_k + m_k (|d_k|² E − d_k d_kᵀ)],  d_k = c_k − c
    /// ```
    ///
    /// # Errors
    /// [`InertiaError::NonPositive`] for a density or mass that is not
    /// positive and finite; [`InertiaError::NoBodies`] for no bodies;
    /// [`InertiaError::InFile`] naming the body and, as its source, why
    /// [`mesh_mass_properties`] rejects it (an open mesh under the solid
    /// model, …); [`InertiaError::DerivedDensity`] when a total mass over
    /// the total volume gives no finite positive density.
    pub fn solid(&self, path: &Path, bodies: Vec<Body>) -> Result<Solid, InertiaError> {
        match self.material {
            Material::Density(d) => check_positive("density", d)?,
            Material::TotalMass(m) => check_positive("mass", m)?,
        };
        if bodies.is_empty() {
            return Err(InertiaError::NoBodies {
                path: path.to_path_buf(),
            });
        }
        let in_body = |body: &str, source: InertiaError| InertiaError::InFile {
            path: path.to_path_buf(),
            body: body.to_owned(),
            source: Box::new(source),
        };
        let density = match self.material {
            Material::Density(d) => d,
            Material::TotalMass(mass) => {
                // One density for the whole file: integrate once for the volumes.
                let mut volume = 0.0;
                for body in &bodies {
                    // Only the volume: at unit density the mass or moments
                    // could leave f64 where those at the real density do not.
                    volume += integrate_model(body.mesh.clone(), self.model)
                        .map_err(|e| in_body(&body.name, e))?
                        .volume;
                }
                let density = mass / volume;
                if !(density.is_finite() && density > 0.0) {
                    return Err(InertiaError::DerivedDensity {
                        path: path.to_path_buf(),
                        mass,
                        volume,
                    });
                }
                density
            }
        };
        let mut parts = Vec::with_capacity(bodies.len());
        for body in bodies {
            let Body {
                name,
                mesh,
                warnings: loaded,
            } = body;
            let report = mesh_mass_properties(mesh, self.model, Material::Density(density))
                .map_err(|e| in_body(&name, e))?;
            let warnings = loaded
                .into_iter()
                .map(SolidWarning::Load)
                .chain(report.warnings.into_iter().map(SolidWarning::Mesh))
                .collect();
            parts.push(SolidBody {
                name,
                properties: report.properties,
                volume: report.volume,
                area: report.area,
                triangles: report.triangles,
                warnings,
            });
        }
        Ok(Solid {
            path: path.to_path_buf(),
            // A single body's properties come back unchanged.
            properties: parts.iter().map(|p| p.properties).sum(),
            model: self.model,
            density,
            volume: parts.iter().map(|p| p.volume).sum(),
            area: parts.iter().map(|p| p.area).sum(),
            triangles: parts.iter().map(|p| p.triangles).sum(),
            bodies: parts,
        })
    }
}

/// The mass properties of a mesh file's bodies as one rigid solid.
///
/// A file of several bodies (OBJ objects, glTF meshes, STL solids) is their
/// compound: the bodies are parts of one rigid object in the file's frame.
/// Use [`LoadOptions::merge`] for bodies that are closed only together.
///
/// ```text
/// file ─load, weld─▶ bodies ─scale─▶ meshes ─check, integrate─▶ parts ─Σ─▶ solid
/// ```
///
/// ```
/// use std::path::Path;
/// use kreisel_inertia::io::{load_solid, SolidOptions, SolidWarning};
/// use kreisel_inertia::{Material, MeshWarning};
/// // A unit cube in millimetres, its triangles all wound inwards.
/// let dir = std::env::temp_dir().join(format!("kreisel-solid-doc-{}", std::process::id()));
/// std::fs::create_dir_all(&dir).unwrap();
/// let path = dir.join("cube.obj");
/// let mut obj = String::new();
/// for i in 0..8 {
///     obj += &format!("v {} {} {}\n", i & 1, (i >> 1) & 1, (i >> 2) & 1);
/// }
/// for [a, b, c] in [[1, 3, 4], [1, 4, 2], [5, 6, 8], [5, 8, 7], [1, 2, 6], [1, 6, 5],
///                   [3, 7, 8], [3, 8, 4], [1, 5, 7], [1, 7, 3], [2, 4, 8], [2, 8, 6]] {
///     obj += &format!("f {a} {c} {b}\n");
/// }
/// std::fs::write(&path, obj).unwrap();
/// let options = SolidOptions { scale: 1e-3, ..SolidOptions::new(Material::TotalMass(2.0)) };
/// let solid = load_solid(&path, &options)?;
/// // m = 2 kg, c = (0.5, 0.5, 0.5) mm, I = m a²/6 on the diagonal.
/// let i = 2.0 * 1e-6 / 6.0;
/// assert!((solid.properties.mass - 2.0).abs() < 1e-15);
/// assert!((solid.properties.center_of_mass - glam::DVec3::splat(5e-4)).length() < 1e-18);
/// let expected = glam::DMat3::from_diagonal(glam::DVec3::splat(i));
/// assert!(solid.properties.inertia.abs_diff_eq(expected, 1e-20));
/// assert!((solid.density - 2e9).abs() < 1e-3);
/// let warnings: Vec<_> = solid.warnings().collect();
/// assert_eq!(warnings, vec![("cube", &SolidWarning::Mesh(MeshWarning::InsideOut { surfaces: 1 }))]);
/// # std::fs::remove_dir_all(&dir).unwrap();
/// # Ok::<(), kreisel_inertia::InertiaError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Solid {
    /// The mesh file.
    pub path: PathBuf,
    /// Mass, centre of mass and inertia about it of all bodies together,
    /// in the file's axes scaled to metres.
    pub properties: MassProperties,
    /// The model every body was integrated under.
    pub model: MassModel,
    /// The density of every body, kg/m³ (given, or derived from the total mass).
    pub density: f64,
    /// Volume of material of all bodies, m³ (a shell: area × thickness).
    pub volume: f64,
    /// Surface area of all bodies (repaired meshes or hulls), m².
    pub area: f64,
    /// Triangles integrated in all bodies.
    pub triangles: usize,
    /// Every body in file order.
    pub bodies: Vec<SolidBody>,
}

impl Solid {
    /// Every warning of every body, in file order, with the body's name.
    pub fn warnings(&self) -> impl Iterator<Item = (&str, &SolidWarning)> {
        self.bodies
            .iter()
            .flat_map(|b| b.warnings.iter().map(move |w| (b.name.as_str(), w)))
    }
}

/// One body of a [`Solid`]: its own mass properties and repairs.
#[derive(Debug, Clone, PartialEq)]
pub struct SolidBody {
    /// The body's name in the file.
    pub name: String,
    /// Mass, centre of mass and inertia about it, in the file's axes (m).
    pub properties: MassProperties,
    /// Volume of material, m³ (a shell: area × thickness).
    pub volume: f64,
    /// Surface area of the repaired mesh or hull, m².
    pub area: f64,
    /// Triangles integrated (after repairs; of the hull for the hull model).
    pub triangles: usize,
    /// What the loader and then the mesh checks repaired, in that order.
    pub warnings: Vec<SolidWarning>,
}

/// Something repaired or skipped on the way from a file to a solid; the
/// result is still usable.
#[derive(Debug, Clone, PartialEq)]
pub enum SolidWarning {
    /// From the loader (lengths in the file's units).
    Load(LoadWarning),
    /// From the mesh checks before integration.
    Mesh(MeshWarning),
}

impl fmt::Display for SolidWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SolidWarning::Load(w) => w.fmt(f),
            SolidWarning::Mesh(w) => w.fmt(f),
        }
    }
}

/// Loads a mesh file as one solid: every body loaded, scaled to metres,
/// integrated under the model and material of `options`, and compounded.
///
/// See [`Solid`] for an example.
///
/// # Errors
/// Those of [`SolidOptions::load_bodies`] and [`SolidOptions::solid`]:
/// each names the file, and the body where one is at fault.
pub fn load_solid(path: &Path, options: &SolidOptions) -> Result<Solid, InertiaError> {
    options.solid(path, options.load_bodies(path)?)
}

#[cfg(test)]
mod tests {
    use glam::{DMat3, DVec3};

    use super::*;

    /// The triangles of the box with corners `i = x + 2y + 4z` (0-based),
    /// wound counter-clockwise seen from outside.
    const BOX_FACES: [[usize; 3]; 12] = [
        [0, 2, 3],
        [0, 3, 1],
        [4, 5, 7],
        [4, 7, 6],
        [0, 1, 5],
        [0, 5, 4],
        [2, 6, 7],
        [2, 7, 3],
        [0, 4, 6],
        [0, 6, 2],
        [1, 3, 7],
        [1, 7, 5],
    ];

    /// An OBJ object `name`: the box from `corner` of `size`, its vertices
    /// numbered after `first` earlier ones; `faces` picks (and may reverse)
    /// the triangles.
    fn obj_box(
        name: &str,
        corner: DVec3,
        size: DVec3,
        first: usize,
        faces: &[[usize; 3]],
    ) -> String {
        let mut text = format!("o {name}\n");
        for i in 0..8 {
            let bit = |k: usize| f64::from(((i >> k) & 1) as u8);
            let v = corner + size * DVec3::new(bit(0), bit(1), bit(2));
            text += &format!("v {} {} {}\n", v.x, v.y, v.z);
        }
        for [a, b, c] in faces {
            text += &format!("f {} {} {}\n", first + a + 1, first + b + 1, first + c + 1);
        }
        text
    }

    /// A file `name` holding `text` in a directory of this test's own.
    fn write(test: &str, name: &str, text: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("kreisel-solid-{}-{test}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(name);
        std::fs::write(&path, text).unwrap();
        path
    }

    /// The closed form of a solid box: `m = ρ abc`, centre in the middle,
    /// `I_xx = m (b² + c²)/12` and cyclically.
    fn box_closed_form(density: f64, corner: DVec3, size: DVec3) -> (f64, DVec3, DMat3) {
        let m = density * size.x * size.y * size.z;
        let s = size * size;
        let diagonal = DVec3::new(s.y + s.z, s.z + s.x, s.x + s.y) * (m / 12.0);
        (m, corner + 0.5 * size, DMat3::from_diagonal(diagonal))
    }

    /// Largest relative difference of mass, centre (against `length`) and tensor.
    fn assert_close(p: &MassProperties, (m, c, i): (f64, DVec3, DMat3), length: f64, tol: f64) {
        assert!((p.mass - m).abs() <= tol * m, "mass {} vs {m}", p.mass);
        let dc = (p.center_of_mass - c).abs().max_element();
        assert!(dc <= tol * length, "centre {} vs {c}", p.center_of_mass);
        let scale = i.abs().to_cols_array().into_iter().fold(0.0, f64::max);
        let di = (p.inertia - i)
            .abs()
            .to_cols_array()
            .into_iter()
            .fold(0.0, f64::max);
        assert!(di <= tol * scale, "inertia {} vs {i}", p.inertia);
    }

    #[test]
    fn a_box_file_matches_the_closed_form() {
        let (corner, size) = (DVec3::new(1.0, -2.0, 0.5), DVec3::new(1.0, 2.0, 3.0));
        let path = write(
            "box",
            "box.obj",
            &obj_box("block", corner, size, 0, &BOX_FACES),
        );
        let solid = load_solid(&path, &SolidOptions::new(Material::Density(7850.0))).unwrap();
        let expected = box_closed_form(7850.0, corner, size);
        assert_close(&solid.properties, expected, 3.0, 1e-14);
        assert_eq!(solid.bodies.len(), 1);
        assert_eq!(solid.bodies[0].name, "block");
        // One body: the solid is that body, bit for bit.
        assert_eq!(solid.bodies[0].properties, solid.properties);
        assert_eq!((solid.volume, solid.area), (6.0, 22.0));
        assert_eq!((solid.triangles, solid.density), (12, 7850.0));
        assert_eq!(solid.path, path);
        assert_eq!(solid.warnings().count(), 0);
    }

    /// Two boxes of one file make one rigid solid: mass, centre and tensor of
    /// the compound from the closed forms and the parallel-axis theorem.
    #[test]
    fn two_bodies_sum_to_the_compound_of_the_closed_forms() {
        let a = (DVec3::new(0.0, 0.0, 0.0), DVec3::new(2.0, 1.0, 1.0));
        let b = (DVec3::new(3.0, 1.0, -1.0), DVec3::new(1.0, 1.0, 4.0));
        let text = obj_box("a", a.0, a.1, 0, &BOX_FACES) + &obj_box("b", b.0, b.1, 8, &BOX_FACES);
        let path = write("two", "two.obj", &text);
        let rho = 2700.0;
        let solid = load_solid(&path, &SolidOptions::new(Material::Density(rho))).unwrap();
        let parts = [
            box_closed_form(rho, a.0, a.1),
            box_closed_form(rho, b.0, b.1),
        ];
        let m: f64 = parts.iter().map(|p| p.0).sum();
        let c = parts.iter().map(|p| p.1 * p.0).sum::<DVec3>() / m;
        let i = parts.iter().fold(DMat3::ZERO, |sum, &(mk, ck, ik)| {
            let d = ck - c;
            let shift = DMat3::from_diagonal(DVec3::splat(d.length_squared()))
                - DMat3::from_cols(d * d.x, d * d.y, d * d.z);
            sum + ik + shift * mk
        });
        assert_close(&solid.properties, (m, c, i), 4.0, 1e-14);
        let names: Vec<&str> = solid.bodies.iter().map(|b| b.name.as_str()).collect();
        assert_eq!(names, ["a", "b"]);
        assert_close(&solid.bodies[0].properties, parts[0], 2.0, 1e-14);
        assert_close(&solid.bodies[1].properties, parts[1], 4.0, 1e-14);
        assert_eq!((solid.volume, solid.triangles), (6.0, 24));
    }

    #[test]
    fn units_and_total_mass_give_the_closed_form_in_metres() {
        // 10 x 20 x 40 mm, 0.5 kg of material in two bodies of one density.
        let size = DVec3::new(10.0, 20.0, 40.0);
        let text = obj_box("big", DVec3::ZERO, size, 0, &BOX_FACES)
            + &obj_box(
                "small",
                DVec3::new(0.0, 0.0, 100.0),
                size * 0.5,
                8,
                &BOX_FACES,
            );
        let path = write("units", "mm.obj", &text);
        let options = SolidOptions {
            scale: 1e-3,
            ..SolidOptions::new(Material::TotalMass(0.5))
        };
        let solid = load_solid(&path, &options).unwrap();
        let volume = 9.0 / 8.0 * 8e-6;
        let rho = 0.5 / volume;
        assert!((solid.density - rho).abs() <= 1e-13 * rho);
        assert!((solid.volume - volume).abs() <= 1e-15 * volume);
        assert!((solid.properties.mass - 0.5).abs() <= 1e-15);
        let big = box_closed_form(rho, DVec3::ZERO, size * 1e-3);
        assert_close(&solid.bodies[0].properties, big, 0.04, 1e-13);
        // The small box holds 1/9 of the mass.
        assert!((solid.bodies[1].properties.mass - 0.5 / 9.0).abs() < 1e-15);
    }

    #[test]
    fn shell_and_hull_models_apply_to_every_body() {
        let size = DVec3::new(1.0, 2.0, 3.0);
        // The box without its top: open, so no solid, but a hull and a shell.
        let open = &BOX_FACES[..2]
            .iter()
            .chain(&BOX_FACES[4..])
            .copied()
            .collect::<Vec<_>>();
        let path = write(
            "models",
            "open.obj",
            &obj_box("cup", DVec3::ZERO, size, 0, open),
        );
        let hull = SolidOptions {
            model: MassModel::ConvexHull,
            ..SolidOptions::new(Material::Density(1000.0))
        };
        let solid = load_solid(&path, &hull).unwrap();
        assert_close(
            &solid.properties,
            box_closed_form(1000.0, DVec3::ZERO, size),
            3.0,
            1e-14,
        );
        let t = 1e-3;
        let shell = SolidOptions {
            model: MassModel::Shell { thickness: t },
            ..hull
        };
        let solid = load_solid(&path, &shell).unwrap();
        // Area without the 1 x 2 top: 22 − 2 = 20 m².
        assert!((solid.area - 20.0).abs() < 1e-13);
        assert!((solid.properties.mass - 1000.0 * t * 20.0).abs() < 1e-12);
        assert_eq!(solid.model, MassModel::Shell { thickness: t });
    }

    #[test]
    fn warnings_of_the_loader_and_the_checks_are_carried_with_the_body() {
        // Body `a` has a two-vertex face (loader); `b` is wound inside out (checks).
        let inward: Vec<[usize; 3]> = BOX_FACES.iter().map(|&[a, b, c]| [a, c, b]).collect();
        let mut text = obj_box("a", DVec3::ZERO, DVec3::ONE, 0, &BOX_FACES);
        text += "f 1 2\n";
        text += &obj_box("b", DVec3::splat(2.0), DVec3::ONE, 8, &inward);
        let path = write("warnings", "w.obj", &text);
        let solid = load_solid(&path, &SolidOptions::new(Material::Density(1.0))).unwrap();
        let warnings: Vec<(&str, &SolidWarning)> = solid.warnings().collect();
        assert_eq!(
            warnings,
            [
                (
                    "a",
                    &SolidWarning::Load(LoadWarning::MalformedFaces { lines: vec![22] })
                ),
                (
                    "b",
                    &SolidWarning::Mesh(MeshWarning::InsideOut { surfaces: 1 })
                ),
            ]
        );
        assert!(warnings[1].1.to_string().contains("inside"));
        // Repaired, the inverted box counts as a positive solid.
        assert!((solid.properties.mass - 2.0).abs() < 1e-15);
    }

    #[test]
    fn bodies_closed_only_together_are_one_solid_when_merged() {
        let (a, b) = BOX_FACES.split_at(6);
        let text = obj_box("low", DVec3::ZERO, DVec3::ONE, 0, a) + "o high\n";
        let text = text
            + &b.iter()
                .map(|[x, y, z]| format!("f {} {} {}\n", x + 1, y + 1, z + 1))
                .collect::<String>();
        let path = write("merge", "halves.obj", &text);
        let error = load_solid(&path, &SolidOptions::new(Material::Density(1.0))).unwrap_err();
        match &error {
            InertiaError::InFile {
                path: p,
                body,
                source,
            } => {
                assert_eq!((p, body.as_str()), (&path, "low"));
                assert!(
                    matches!(**source, InertiaError::OpenMesh { .. }),
                    "{source}"
                );
            }
            other => panic!("{other}"),
        }
        assert!(
            error
                .to_string()
                .starts_with(&format!("{}: body 'low': mesh is open", path.display()))
        );
        let mut merged = SolidOptions::new(Material::Density(1.0));
        merged.load.merge = true;
        let solid = load_solid(&path, &merged).unwrap();
        assert_eq!(solid.bodies[0].name, "halves");
        assert_close(
            &solid.properties,
            box_closed_form(1.0, DVec3::ZERO, DVec3::ONE),
            1.0,
            1e-14,
        );
    }

    #[test]
    fn bad_options_and_files_are_typed_errors_naming_the_file_and_body() {
        let path = write(
            "errors",
            "big.obj",
            &obj_box("huge", DVec3::ZERO, DVec3::splat(1e150), 0, &BOX_FACES),
        );
        let options = SolidOptions::new(Material::Density(1.0));
        let e = load_solid(
            &path,
            &SolidOptions {
                scale: 1e200,
                ..options
            },
        )
        .unwrap_err();
        assert!(
            matches!(&e, InertiaError::ScaleOverflow { path: p, body, scale } if *p == path && body == "huge" && *scale == 1e200),
            "{e}"
        );
        for scale in [0.0, -1.0, f64::NAN] {
            let e = load_solid(&path, &SolidOptions { scale, ..options }).unwrap_err();
            assert!(
                matches!(
                    e,
                    InertiaError::NonPositive {
                        quantity: "scale",
                        ..
                    }
                ),
                "{e}"
            );
        }
        let e = load_solid(&path, &SolidOptions::new(Material::Density(-1.0))).unwrap_err();
        assert!(
            matches!(
                e,
                InertiaError::NonPositive {
                    quantity: "density",
                    ..
                }
            ),
            "{e}"
        );
        let e = load_solid(&path, &SolidOptions::new(Material::TotalMass(0.0))).unwrap_err();
        assert!(
            matches!(
                e,
                InertiaError::NonPositive {
                    quantity: "mass",
                    ..
                }
            ),
            "{e}"
        );
        // A volume of 1e450 m³ overflows: no density from a mass.
        let e = load_solid(&path, &SolidOptions::new(Material::TotalMass(1.0))).unwrap_err();
        assert!(
            matches!(
                e,
                InertiaError::InFile { .. } | InertiaError::DerivedDensity { .. }
            ),
            "{e}"
        );
        let unit = write(
            "errors",
            "unit.obj",
            &obj_box("u", DVec3::ZERO, DVec3::splat(0.5), 0, &BOX_FACES),
        );
        let e = load_solid(&unit, &SolidOptions::new(Material::TotalMass(f64::MAX))).unwrap_err();
        assert!(
            matches!(&e, InertiaError::DerivedDensity { path: p, mass, volume } if *p == unit && *mass == f64::MAX && *volume == 0.125),
            "{e}"
        );
        let e = options.solid(&unit, Vec::new()).unwrap_err();
        assert!(
            matches!(&e, InertiaError::NoBodies { path: p } if *p == unit),
            "{e}"
        );
        assert_eq!(
            e.to_string(),
            format!("{}: the file holds no mesh bodies", unit.display())
        );
        let missing = unit.with_file_name("missing.obj");
        let e = load_solid(&missing, &options).unwrap_err();
        assert!(
            matches!(&e, InertiaError::Io { path: p, .. } if *p == missing),
            "{e}"
        );
    }
}
