//! From the options to the numbers: the library's [`SolidOptions`] loads the
//! bodies, scales them, integrates each under the model and material and
//! sums them into the assembly; this file states the setup, words the
//! warnings in metres and turns a rejected body into advice.

use std::path::PathBuf;

use glam::DVec3;
use kreisel_inertia::io::{Body, LoadOptions, LoadWarning, SolidBody, SolidOptions, SolidWarning};
use kreisel_inertia::{
    InertiaError, MassModel, MassProperties, Material, PrincipalAxes, prepare_solid,
};

use crate::error::{BodyProblem, SceneError};
use crate::mesh_options::{DEFAULT_DENSITY, Units, WeldChoice};
use crate::numbers::Shortest;

/// The frame every tensor and axis of a [`Report`] is given in.
pub const FRAME: &str = "center of mass, mesh axes";

/// Where the density comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DensityChoice {
    /// Neither `--density` nor `--mass`: [`DEFAULT_DENSITY`] (water).
    Default,
    /// `--density RHO`, kg/m³.
    Given(f64),
    /// `--mass M`: the assembly's mass, kg; density = M / total volume.
    TotalMass(f64),
}

/// Everything the options decide, stated in every output.
#[derive(Debug, Clone, PartialEq)]
pub struct Setup {
    /// The mesh file.
    pub file: PathBuf,
    /// The named unit of `--units` (metres by default); `None` for `--scale`.
    pub units: Option<Units>,
    /// Metres per mesh unit.
    pub scale: f64,
    /// Solid, shell or convex hull.
    pub model: MassModel,
    /// The density, or how it is derived.
    pub density: DensityChoice,
    /// How vertices are welded on loading.
    pub weld: WeldChoice,
    /// All bodies of the file as one (`--merge`).
    pub merge: bool,
}

impl Setup {
    /// How the library turns the file into a solid, merging its bodies or not.
    fn solid_options(&self, merge: bool) -> SolidOptions {
        let material = match self.density {
            DensityChoice::Default => Material::Density(DEFAULT_DENSITY),
            DensityChoice::Given(d) => Material::Density(d),
            DensityChoice::TotalMass(m) => Material::TotalMass(m),
        };
        SolidOptions {
            load: LoadOptions {
                weld: self.weld.weld(self.scale),
                merge,
            },
            scale: self.scale,
            model: self.model,
            material,
        }
    }

    /// `m (scale 1)`, `mm (scale 0.001)`, or `1 unit = 2 m (scale 2)`.
    pub fn units_text(&self) -> String {
        match self.units {
            Some(u) => format!("{} (scale {})", u.symbol(), Shortest(self.scale)),
            None => format!(
                "1 unit = {} m (scale {})",
                Shortest(self.scale),
                Shortest(self.scale)
            ),
        }
    }

    /// The unit's symbol, or `custom` for `--scale`.
    pub fn units_name(&self) -> &'static str {
        self.units.map_or("custom", Units::symbol)
    }

    /// `solid`, `shell` or `convex hull`.
    pub fn model_name(&self) -> &'static str {
        match self.model {
            MassModel::Solid => "solid",
            MassModel::Shell { .. } => "shell",
            MassModel::ConvexHull => "convex hull",
        }
    }

    /// The shell thickness in metres, for the shell model.
    pub fn thickness(&self) -> Option<f64> {
        match self.model {
            MassModel::Shell { thickness } => Some(thickness),
            _ => None,
        }
    }

    /// `solid`, `shell of thickness 0.001 m` or `convex hull (solid)`.
    pub fn model_text(&self) -> String {
        match self.thickness() {
            Some(t) => format!("shell of thickness {} m", Shortest(t)),
            None if self.model == MassModel::ConvexHull => "convex hull (solid)".into(),
            None => "solid".into(),
        }
    }

    /// `default`, `given` or `from total mass`.
    pub fn density_source(&self) -> &'static str {
        match self.density {
            DensityChoice::Default => "default (water)",
            DensityChoice::Given(_) => "given",
            DensityChoice::TotalMass(_) => "from total mass",
        }
    }

    /// `1000 kg/m^3 (default: water)`, `2700 kg/m^3`, or
    /// `12.5 kg/m^3 (from total mass 2 kg)`.
    pub fn density_text(&self, density: f64) -> String {
        let rho = Shortest(density);
        match self.density {
            DensityChoice::Default => format!("{rho} kg/m^3 (default: water)"),
            DensityChoice::Given(_) => format!("{rho} kg/m^3"),
            DensityChoice::TotalMass(m) => {
                format!("{rho} kg/m^3 (from total mass {} kg)", Shortest(m))
            }
        }
    }
}

/// The mass properties of one body, or of the assembly.
#[derive(Debug, Clone, PartialEq)]
pub struct Summary {
    /// The body's name (`assembly` for the sum).
    pub name: String,
    /// Mass, centre of mass, inertia tensor about it in mesh axes.
    pub properties: MassProperties,
    /// Principal moments and axes of `properties.inertia`.
    pub principal: PrincipalAxes,
    /// Density, kg/m³.
    pub density: f64,
    /// Volume of material, m³ (a shell: area × thickness).
    pub volume: f64,
    /// Surface area, m².
    pub area: f64,
    /// Triangles integrated (after repairs; of the hull for `--hull`).
    pub triangles: usize,
    /// Repairs made to the mesh (for the assembly: the file's warnings, then
    /// each body's prefixed with its name).
    pub warnings: Vec<String>,
}

impl Summary {
    /// One body's summary from the library's, with the warnings in words
    /// (lengths in metres for a file scaled by `scale`).
    fn of_body(body: SolidBody, density: f64, scale: f64) -> Self {
        let warnings = body
            .warnings
            .iter()
            .map(|w| match w {
                SolidWarning::Load(w) => load_warning_text(w, scale),
                other => other.to_string(),
            })
            .collect();
        Self {
            name: body.name,
            principal: body.properties.principal(),
            properties: body.properties,
            density,
            volume: body.volume,
            area: body.area,
            triangles: body.triangles,
            warnings,
        }
    }
}

/// The result of `kreisel inertia`: the setup, each body, and their sum.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// Units, model and material.
    pub setup: Setup,
    /// Every body in file order.
    pub bodies: Vec<Summary>,
    /// The rigid sum of all bodies (equal to the body when there is one).
    pub assembly: Summary,
    /// Warnings about the file as a whole (implausible units).
    pub file_warnings: Vec<String>,
}

/// A loader warning in the CLI's terms: lengths in metres, the option that
/// controls it.
fn load_warning_text(warning: &LoadWarning, scale: f64) -> String {
    match warning {
        LoadWarning::Welded {
            vertices,
            tolerance,
            max_move,
        } => format!(
            "welded {vertices} vertices lying within {:.2e} m of another (largest move {:.2e} m); \
             --weld sets the tolerance",
            tolerance * scale,
            max_move * scale
        ),
        other => other.to_string(),
    }
}

/// Smallest and largest plausible size of a part, m.
const PLAUSIBLE_SIZE: (f64, f64) = (1e-3, 10.0);

/// A warning when the bodies' bounding box (m) is implausibly large or
/// small for the stated units, naming the unit that makes it plausible.
fn units_warning(setup: &Setup, bodies: &[Body]) -> Option<String> {
    let (lo, hi) = bodies
        .iter()
        .flat_map(|b| b.mesh.vertices())
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        });
    let extent = hi - lo;
    let size = extent.max_element();
    let (small, large) = PLAUSIBLE_SIZE;
    if !size.is_finite() || (small..=large).contains(&size) || size == 0.0 {
        return None;
    }
    let raw = size / setup.scale;
    let order = if size > large {
        [Units::Mm, Units::Cm, Units::In, Units::M]
    } else {
        [Units::M, Units::In, Units::Cm, Units::Mm]
    };
    let advice = order
        .into_iter()
        .filter(|&u| setup.units != Some(u))
        .find(|&u| (small..=large).contains(&(raw * u.scale())))
        .map_or_else(
            || "if that is not its size, rerun with --scale S (metres per mesh unit)".to_owned(),
            |u| {
                format!(
                    "if its coordinates are in {}, rerun with --units {} ({} m across)",
                    u.name(),
                    u.symbol(),
                    three_digits(raw * u.scale())
                )
            },
        );
    Some(format!(
        "the mesh is {} m across ({} x {} x {} m) with mesh units {}, implausible for a part; {advice}",
        three_digits(size),
        three_digits(extent.x),
        three_digits(extent.y),
        three_digits(extent.z),
        setup.units_text()
    ))
}

/// `x` rounded to three significant digits, in shortest form (`49.3`).
fn three_digits(x: f64) -> Shortest {
    Shortest(format!("{x:.2e}").parse().unwrap_or(x))
}

/// Loads the mesh file and computes every body and the assembly.
///
/// # Errors
/// [`SceneError::LoadMesh`], [`SceneError::NoBodies`], [`SceneError::Body`] (naming the body; for an open
/// mesh suggesting `--shell` or `--hull`), [`SceneError::DerivedDensity`].
pub fn compute(setup: Setup) -> Result<Report, SceneError> {
    let options = setup.solid_options(setup.merge);
    let bodies = load_scaled(&setup, &options)?;
    compute_scaled(setup, bodies)
}

/// [`compute`] for bodies already loaded and scaled to metres (meshes that
/// come from memory, e.g. vertex and face arrays from Python); `setup.file`
/// names them in messages. The advice that reloads the file (`--merge`,
/// `--weld`) is given only when `setup.file` can be read.
///
/// # Errors
/// As [`compute`], but for loading.
pub fn compute_scaled(setup: Setup, bodies: Vec<Body>) -> Result<Report, SceneError> {
    let options = setup.solid_options(setup.merge);
    if bodies.is_empty() {
        return Err(SceneError::NoBodies {
            path: setup.file.clone(),
        });
    }
    let file_warnings: Vec<String> = units_warning(&setup, &bodies).into_iter().collect();
    let several = bodies.len() > 1;
    let solid = options.solid(&setup.file, bodies).map_err(|e| match e {
        InertiaError::InFile { body, source, .. } => body_error(&setup, body, several, *source),
        InertiaError::DerivedDensity { mass, volume, .. } => SceneError::DerivedDensity {
            path: setup.file.clone(),
            mass,
            volume,
        },
        source => SceneError::LoadMesh { source },
    })?;
    let density = solid.density;
    let summaries: Vec<Summary> = solid
        .bodies
        .into_iter()
        .map(|body| Summary::of_body(body, density, setup.scale))
        .collect();
    let assembly = Summary {
        name: "assembly".into(),
        principal: solid.properties.principal(),
        properties: solid.properties,
        density,
        volume: solid.volume,
        area: solid.area,
        triangles: solid.triangles,
        warnings: assembly_warnings(&summaries, &file_warnings),
    };
    Ok(Report {
        setup,
        bodies: summaries,
        assembly,
        file_warnings,
    })
}

/// The file's bodies, scaled to metres.
fn load_scaled(setup: &Setup, options: &SolidOptions) -> Result<Vec<Body>, SceneError> {
    options.load_bodies(&setup.file).map_err(|e| match e {
        InertiaError::ScaleOverflow { body, scale, .. } => SceneError::Body {
            path: setup.file.clone(),
            body,
            problem: BodyProblem::ScaleOverflow { scale },
        },
        source => SceneError::LoadMesh { source },
    })
}

/// The assembly's warnings: the file's, then each body's prefixed with its name.
fn assembly_warnings(bodies: &[Summary], file_warnings: &[String]) -> Vec<String> {
    file_warnings
        .iter()
        .cloned()
        .chain(bodies.iter().flat_map(|b| {
            b.warnings
                .iter()
                .map(move |w| format!("body '{}': {w}", b.name))
        }))
        .collect()
}

/// The error of one body of the setup's file: when the body is open but
/// the file's bodies merged form a solid, the error says to use `--merge`.
fn body_error(setup: &Setup, body: String, several: bool, error: InertiaError) -> SceneError {
    let topology = matches!(
        error,
        InertiaError::OpenMesh { .. } | InertiaError::NonManifold { .. }
    );
    let closing_weld = match error {
        InertiaError::OpenMesh {
            weld_gap: Some(gap),
            ..
        } => Some(round_up(1.5 * gap)),
        _ => None,
    };
    let problem = if several && topology && !setup.merge && merged_is_solid(setup) {
        BodyProblem::ClosedOnlyMerged { source: error }
    } else if let Some(weld) = closing_weld.filter(|&w| welded_is_solid(setup, &body, w)) {
        BodyProblem::Cracks {
            source: error,
            weld,
        }
    } else {
        BodyProblem::from(error)
    };
    SceneError::Body {
        path: setup.file.clone(),
        body,
        problem,
    }
}

/// Whether body `name` is a closed surface when welded within `weld` metres.
fn welded_is_solid(setup: &Setup, name: &str, weld: f64) -> bool {
    let trial = Setup {
        weld: WeldChoice::Metres(weld),
        ..setup.clone()
    };
    match load_scaled(&trial, &trial.solid_options(setup.merge)) {
        Ok(bodies) => bodies
            .into_iter()
            .find(|body| body.name == name)
            .is_some_and(|body| prepare_solid(body.mesh).is_ok()),
        Err(_) => false,
    }
}

/// `x` rounded up to one significant digit (`1.3e-7` → `2e-7`).
fn round_up(x: f64) -> f64 {
    let unit = 10f64.powf(x.log10().floor());
    let up = (x / unit).ceil() * unit;
    if up.is_finite() && up >= x { up } else { x }
}

/// Whether all bodies of the file together form a closed surface.
fn merged_is_solid(setup: &Setup) -> bool {
    match load_scaled(setup, &setup.solid_options(true)) {
        Ok(bodies) => bodies
            .into_iter()
            .all(|body| prepare_solid(body.mesh).is_ok()),
        Err(_) => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn setup(units: Option<Units>, scale: f64, model: MassModel, density: DensityChoice) -> Setup {
        Setup {
            file: PathBuf::from("x.obj"),
            units,
            scale,
            model,
            density,
            weld: WeldChoice::Default,
            merge: false,
        }
    }

    #[test]
    fn setup_states_units_model_and_density() {
        let s = setup(
            Some(Units::Mm),
            0.001,
            MassModel::Solid,
            DensityChoice::Default,
        );
        assert_eq!(s.units_text(), "mm (scale 0.001)");
        assert_eq!(s.model_text(), "solid");
        assert_eq!(s.density_text(1000.0), "1000 kg/m^3 (default: water)");
        let s = setup(
            None,
            2.0,
            MassModel::Shell { thickness: 0.002 },
            DensityChoice::TotalMass(3.0),
        );
        assert_eq!(s.units_text(), "1 unit = 2 m (scale 2)");
        assert_eq!((s.units_name(), s.model_name()), ("custom", "shell"));
        assert_eq!(s.model_text(), "shell of thickness 0.002 m");
        assert_eq!(s.density_text(1.5), "1.5 kg/m^3 (from total mass 3 kg)");
        let s = setup(
            Some(Units::M),
            1.0,
            MassModel::ConvexHull,
            DensityChoice::Given(7.0),
        );
        assert_eq!(s.model_text(), "convex hull (solid)");
        assert_eq!(s.thickness(), None);
    }
}
