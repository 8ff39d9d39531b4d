//! `kreisel stability`: is each body's motion in a scene stable? Its
//! steady motion (found near the scene's initial state), the eigenvalues
//! and modes of the linearisation, the verdict; `--sweep` maps it over
//! one or two parameters, `--plot` draws the map.
//!
//! All the physics is in kreisel-analysis ([`SteadyProblem`],
//! [`StabilityMap`]); this module reads the arguments, asks the library
//! and writes what it says.

mod figure;
mod json;
mod sweep_arg;
mod text;

use std::path::PathBuf;

use kreisel_analysis::{Linearisation, Parameter, StabilityMap, SteadyKind, SteadyProblem};
use kreisel_plot::ImageFormat;
use kreisel_scene::error::SceneError;
use kreisel_scene::scene_file;

pub use self::sweep_arg::SweepArg;
use crate::error::CliError;

/// The `--help` text after the options.
const AFTER_HELP: &str = "\
Each body's steady motion is the one its `steady` key names (sleeping,
hanging, slow_precession, fast_precession: a top on a pivot at its state's
spin and tilt) or, by default (nearest), the one nearest the scene's initial
state with the same Casimirs and momenta (a free body: rotation about a
principal axis; a top on a pivot: sleeping, hanging, or in slow or fast
steady precession; a body on the ground, or on the table with one contact
shape: spinning about the vertical).
Eigenvalues are in 1/s (real part: growth rate; imaginary: angular
frequency, in the frame printed); every zero eigenvalue is named.

Sweep keys: spin (rad/s), tilt (rad), com_offset (m), gravity (m/s^2).

Examples:
  kreisel stability examples/scenes/sleeping_top.toml
  kreisel stability examples/scenes/dzhanibekov.toml --format json
  kreisel stability examples/scenes/sleeping_top.toml --body fast --sweep spin=0:80:200 --plot map.svg";

/// The arguments of `kreisel stability`.
#[derive(Debug, Clone, clap::Args)]
#[command(after_help = AFTER_HELP)]
pub struct StabilityArgs {
    /// The scene (TOML, as `kreisel simulate` reads it)
    pub scene: PathBuf,

    /// Only the body with this name
    #[arg(long, value_name = "NAME")]
    pub body: Option<String>,

    /// What to print
    #[arg(long, value_enum, default_value = "text")]
    pub format: Format,

    /// Map the largest real part over KEY from FROM to TO in N values (give
    /// one or two); stability boundaries are located by bisection
    #[arg(long, value_name = "KEY=FROM:TO:N")]
    pub sweep: Vec<SweepArg>,

    /// Draw the map to FILE (.png or .svg; needs --sweep and one body)
    #[arg(long, value_name = "FILE")]
    pub plot: Option<PathBuf>,
}

/// What `kreisel stability` prints.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// Words and tables.
    Text,
    /// `{"bodies": [{"name", "steady_motions": [{"kind", "eigenvalues", "verdict", …}]}]}`.
    Json,
}

/// One body's answer.
pub struct BodyReport {
    /// Its name in the scene.
    pub name: String,
    /// Its steady motion.
    pub problem: SteadyProblem,
    /// The linearisation there.
    pub linearisation: Linearisation,
    /// The map, when asked for.
    pub map: Option<MapReport>,
}

/// A map with the closed-form boundary beside it.
pub struct MapReport {
    /// The swept parameters.
    pub parameters: Vec<Parameter>,
    /// The map.
    pub map: StabilityMap,
    /// Points `[p₀, p₁]` of the closed-form boundary (`p₁` NaN for one
    /// sweep); empty where stability never changes, `None` without a
    /// closed form.
    pub closed_form: Option<Vec<[f64; 2]>>,
    /// At each boundary point, the closed form's value of the parameter it
    /// was bisected along (the others as there), when there is one.
    pub closed_form_at_boundaries: Vec<Option<f64>>,
}

/// Runs `kreisel stability`.
///
/// # Errors
/// The scene's errors; [`CliError::Argument`] for more than two sweeps or
/// a plot without exactly one body and a sweep; [`CliError::Analysis`]
/// for a body without a steady motion near its state or a sweep key it
/// has not.
pub fn run(args: &StabilityArgs) -> Result<(), CliError> {
    if args.sweep.len() > 2 {
        return Err(CliError::argument(
            "--sweep",
            "give one or two sweeps (a map of one or two parameters)".into(),
        ));
    }
    let plot = match &args.plot {
        Some(path) => Some((image_format(path)?, path.as_path())),
        None => None,
    };
    let text =
        kreisel_inertia::io::read_limited_text(&args.scene, "a scene file").map_err(|source| {
            SceneError::ReadScene {
                path: args.scene.clone(),
                source,
            }
        })?;
    let scene = scene_file::parse(&args.scene, &text)?;
    let gravity = scene.world.gravity();
    // Each body's `steady` key, checked before any analysis.
    let mut kinds = Vec::with_capacity(scene.bodies.len());
    for ((name, _), steady) in scene.bodies.iter().zip(&scene.steady) {
        kinds.push(match steady {
            None => SteadyKind::Nearest,
            Some((kind, line)) => kind.parse().map_err(|message: String| SceneError::Scene {
                path: args.scene.clone(),
                line: Some(*line),
                message: format!("body `{name}`: `steady`: {message}"),
            })?,
        });
    }
    let chosen: Vec<(&(String, kreisel_dynamics::BodyId), SteadyKind)> = scene
        .bodies
        .iter()
        .zip(kinds)
        .filter(|((name, _), _)| args.body.as_ref().is_none_or(|b| b == name))
        .collect();
    if let Some(name) = &args.body
        && chosen.is_empty()
    {
        let names: Vec<&str> = scene.bodies.iter().map(|(n, _)| n.as_str()).collect();
        return Err(CliError::argument(
            "--body",
            format!(
                "no body {name:?} in the scene (it has {})",
                names.join(", ")
            ),
        ));
    }
    if plot.is_some() && (chosen.len() != 1 || args.sweep.is_empty()) {
        return Err(CliError::argument(
            "--plot",
            "draws one body's map: give --sweep, and --body when the scene has several bodies"
                .into(),
        ));
    }
    let mut reports = Vec::new();
    for ((name, id), kind) in chosen {
        let fail = |error| CliError::Analysis {
            path: args.scene.clone(),
            body: name.clone(),
            error,
        };
        // `id` is one the scene's world returned when it added the body:
        // the world holds it (bodies are never removed).
        let body = scene.world.body(*id).expect("the scene's own body");
        let problem = SteadyProblem::named(body, gravity, kind).map_err(fail)?;
        let linearisation = problem.linearise().map_err(fail)?;
        let map = if args.sweep.is_empty() {
            None
        } else {
            Some(map(&problem, &args.sweep).map_err(fail)?)
        };
        reports.push(BodyReport {
            name: name.clone(),
            problem,
            linearisation,
            map,
        });
    }
    if let (Some((format, path)), Some(report)) = (plot, reports.first()) {
        figure::write(report, format, path)?;
    }
    let out = match args.format {
        Format::Text => text::render(&reports),
        Format::Json => json::render(&reports),
    };
    crate::output::print_stdout(&out)
}

/// The map of `problem` over `sweeps`, with the closed-form boundary.
fn map(
    problem: &SteadyProblem,
    sweeps: &[SweepArg],
) -> Result<MapReport, kreisel_analysis::AnalysisError> {
    // A key the motion has not fails here, once, naming the keys it has.
    let mut checked = problem.clone();
    for s in sweeps {
        checked.set(s.parameter, s.sweep.from)?;
    }
    let parameters: Vec<Parameter> = sweeps.iter().map(|s| s.parameter).collect();
    let axes: Vec<kreisel_analysis::Sweep> = sweeps.iter().map(|s| s.sweep.clone()).collect();
    let at = |p: &[f64]| {
        let mut here = problem.clone();
        for (parameter, value) in parameters.iter().zip(p) {
            here.set(*parameter, *value)?;
        }
        Ok(here)
    };
    let map = StabilityMap::try_new(&axes, None, |p| at(p)?.linearise())?;
    let closed_form = closed_form(problem, &parameters, &axes, &at);
    let closed_form_at_boundaries = map
        .boundaries
        .iter()
        .map(|b| {
            let found = b.at[b.axis];
            let here = at(&b.at[..parameters.len()]).ok()?;
            here.closed_form_boundary(parameters[b.axis])?
                .into_iter()
                .min_by(|x, y| (x - found).abs().total_cmp(&(y - found).abs()))
        })
        .collect();
    Ok(MapReport {
        parameters,
        map,
        closed_form,
        closed_form_at_boundaries,
    })
}

/// The closed-form boundary over the map's range: the values of the first
/// parameter where stability changes, at 400 values of the second.
fn closed_form(
    problem: &SteadyProblem,
    parameters: &[Parameter],
    axes: &[kreisel_analysis::Sweep],
    at: &dyn Fn(&[f64]) -> Result<SteadyProblem, kreisel_analysis::AnalysisError>,
) -> Option<Vec<[f64; 2]>> {
    let (lo, hi) = (axes[0].from.min(axes[0].to), axes[0].from.max(axes[0].to));
    let inside = |v: &f64| *v >= lo && *v <= hi;
    match axes.get(1) {
        None => Some(
            problem
                .closed_form_boundary(parameters[0])?
                .into_iter()
                .filter(inside)
                .map(|v| [v, f64::NAN])
                .collect(),
        ),
        Some(second) => {
            let samples = 400;
            let mut points = Vec::new();
            for k in 0..=samples {
                let y = second.from + (second.to - second.from) * (k as f64 / samples as f64);
                let here = at(&[axes[0].from, y]).ok()?;
                for x in here
                    .closed_form_boundary(parameters[0])?
                    .into_iter()
                    .filter(inside)
                {
                    points.push([x, y]);
                }
            }
            Some(points)
        }
    }
}

/// The image format of `--plot FILE`.
fn image_format(path: &std::path::Path) -> Result<ImageFormat, CliError> {
    ImageFormat::from_path(path).ok_or_else(|| CliError::Plot {
        path: path.to_owned(),
        message: "the file name must end in .png or .svg".into(),
    })
}
