//! From the options to the numbers: load the bodies, scale them, integrate
//! each under the model and material, and sum them into the assembly.

use std::path::PathBuf;

use kreisel_inertia::io::{Body, load_bodies};
use kreisel_inertia::{
    MassModel, MassProperties, Material, MeshMassReport, PrincipalAxes, mesh_mass_properties,
};

use super::{DEFAULT_DENSITY, Units};
use crate::error::{BodyProblem, CliError};
use crate::numbers::Shortest;

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
}

impl Setup {
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
    /// Repairs made to the mesh (for the assembly: prefixed with the body).
    pub warnings: Vec<String>,
}

impl Summary {
    /// One body's summary from the library's report.
    fn of_body(name: String, report: MeshMassReport) -> Self {
        Self {
            name,
            principal: report.properties.principal(),
            properties: report.properties,
            density: report.density,
            volume: report.volume,
            area: report.area,
            triangles: report.triangles,
            warnings: report.warnings.iter().map(ToString::to_string).collect(),
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
}

/// Loads the mesh file and computes every body and the assembly.
///
/// # Errors
/// [`CliError::LoadMesh`], [`CliError::NoBodies`], [`CliError::Body`] (naming the body; for an open
/// mesh suggesting `--shell` or `--hull`), [`CliError::DerivedDensity`].
pub fn compute(setup: Setup) -> Result<Report, CliError> {
    let bodies = load_bodies(&setup.file).map_err(|source| CliError::LoadMesh { source })?;
    if bodies.is_empty() {
        return Err(CliError::NoBodies {
            path: setup.file.clone(),
        });
    }
    let mut scaled = Vec::with_capacity(bodies.len());
    for Body { name, mesh } in bodies {
        let mesh = if setup.scale == 1.0 {
            mesh
        } else {
            mesh.scaled(setup.scale)
        };
        if !mesh.vertices().iter().all(|v| v.is_finite()) {
            let problem = BodyProblem::ScaleOverflow { scale: setup.scale };
            return Err(body_error(&setup, name, problem));
        }
        scaled.push(Body { name, mesh });
    }
    let density = match setup.density {
        DensityChoice::Default => DEFAULT_DENSITY,
        DensityChoice::Given(d) => d,
        DensityChoice::TotalMass(mass) => {
            // One density for the whole file: integrate once for the volumes.
            let mut volume = 0.0;
            for body in &scaled {
                let unit =
                    mesh_mass_properties(body.mesh.clone(), setup.model, Material::Density(1.0))
                        .map_err(|e| body_error(&setup, body.name.clone(), e.into()))?;
                volume += unit.volume;
            }
            let density = mass / volume;
            if !(density.is_finite() && density > 0.0) {
                return Err(CliError::DerivedDensity {
                    path: setup.file.clone(),
                    mass,
                    volume,
                });
            }
            density
        }
    };
    let mut summaries = Vec::with_capacity(scaled.len());
    for Body { name, mesh } in scaled {
        match mesh_mass_properties(mesh, setup.model, Material::Density(density)) {
            Ok(report) => summaries.push(Summary::of_body(name, report)),
            Err(e) => return Err(body_error(&setup, name, e.into())),
        }
    }
    let assembly = assemble(&summaries, density);
    Ok(Report {
        setup,
        bodies: summaries,
        assembly,
    })
}

/// The rigid sum of the bodies (all in the mesh frame).
fn assemble(bodies: &[Summary], density: f64) -> Summary {
    let properties: MassProperties = bodies.iter().map(|b| b.properties).sum();
    let warnings = bodies
        .iter()
        .flat_map(|b| {
            b.warnings
                .iter()
                .map(move |w| format!("body '{}': {w}", b.name))
        })
        .collect();
    Summary {
        name: "assembly".into(),
        principal: properties.principal(),
        properties,
        density,
        volume: bodies.iter().map(|b| b.volume).sum(),
        area: bodies.iter().map(|b| b.area).sum(),
        triangles: bodies.iter().map(|b| b.triangles).sum(),
        warnings,
    }
}

/// The error of one body of the setup's file.
fn body_error(setup: &Setup, body: String, problem: BodyProblem) -> CliError {
    CliError::Body {
        path: setup.file.clone(),
        body,
        problem,
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
