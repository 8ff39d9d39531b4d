//! `kreisel top`: the heavy symmetric (Lagrange) top from its parameters and
//! initial conditions: the constants of the motion, the roots of the cubic
//! f(u), the nutation limits, period and mean precession, the type of motion,
//! and optionally a figure of it.
//!
//! All physics is the library's ([`kreisel_dynamics::LagrangeTop`]); this
//! module parses the arguments, copies the library's answers into a
//! [`Summary`] and writes it ([`output`]), and samples the motion for the
//! plot ([`figure`]).

#![forbid(unsafe_code)]

mod figure;
mod labels;
mod output;
pub mod series;

use std::path::PathBuf;

use glam::DVec3;
use kreisel_dynamics::LagrangeTopMotion;
use kreisel_plot::ImageFormat;
use kreisel_scene::top_summary::{Summary, TopRequest, on_the_vertical, solve_and_summarise};

use crate::error::CliError;
use kreisel_scene::numbers::Shortest;

/// The `--help` text of `kreisel top` after the option list.
const AFTER_LONG_HELP: &str = "\
Model:
  A symmetric top spinning about a fixed pivot on its symmetry axis, in
  gravity: I1 is the transverse moment of inertia about the pivot, I3 the
  moment about the symmetry axis, MGL = M g l with l the distance from the
  pivot to the centre of mass (J). Euler angles z-x-z: theta is the angle of
  the symmetry axis from the upward vertical (theta = 0: upright), phi the
  precession about the vertical, psi the spin about the symmetry axis.
  Every real body has I3 <= 2 I1 (I3 <= I1 + I2 about the centre of mass;
  I1 about the pivot is larger still); theta0 lies in [0, pi].
  With u = cos theta, du/dt^2 = f(u) = (1 - u^2)(alpha - beta u) - (b - a u)^2.

Output (SI units, radians; numbers in shortest round-trip form; with
--degrees theta0 is read in degrees and theta0, theta_min, theta_max are
written in degrees as theta0_deg, theta_min_deg, theta_max_deg, the CSV's
angles as theta_deg, phi_deg, psi_deg; rates and the rest stay as below):
  a, b          p_psi / I1 and p_phi / I1, rad/s
  alpha, beta   2 E' / I1 and 2 M g l / I1, 1/s^2
  omega3        spin I1 a / I3, rad/s
  roots         the real roots of f, ascending
  theta_min, theta_max    nutation limits, rad
  nutation_period         s
  mean_precession_rate    rad/s (mean dphi/dt over a nutation period)
  motion        no_loops, loops or cusps (sign of dphi/dt at the limits);
                none when theta stays constant: the sleeping top, the axis
                on the downward vertical (theta0 = pi, theta_dot0 = 0),
                steady precession (then nutation_period is none too, and
                mean_precession_rate is dphi/dt, none on the vertical)
  sleeping      theta0 = 0 and theta_dot0 = 0 (nutation fields: null/none);
                theta0 = 1e-15 is not sleeping: it nutates in a tiny band
  sleeping_stable         omega3^2 > 4 I1 M g l / I3^2
--plot FILE.svg or FILE.png draws the path of the symmetry axis on the unit
sphere over three or more nutation periods, and f(u) with its roots.

--csv FILE writes the motion sampled every --dt H seconds from t = 0 to
--duration T (the last row at T exactly), written whole or not at all:
  t,theta,phi,psi,theta_dot,phi_dot,psi_dot,qw,qx,qy,qz
  theta, phi, psi       ZXZ Euler angles as above, rad (phi and psi not
                        wrapped: continuous, except jumps by pi where the
                        axis passes exactly through the vertical)
  theta_dot...psi_dot   their rates, rad/s
  qw..qz                attitude, world_from_body quaternion w,x,y,z =
                        Rz(phi) Rx(theta) Rz(psi) (euler:ZXZ of kreisel
                        convert), continuous in time (no sign flips)
  Defaults: 3 nutation periods at period/200; with theta constant (sleeping
  top, steady precession) one turn of the slowest angle, 2 pi / (the
  smallest nonzero |phi_dot|, |psi_dot|), in 600 steps; at rest 1 s at
  0.005 s. At most 1e6 rows.

Examples:
  kreisel top --i1 0.3 --i3 0.1 --mgl 2 --theta0 0.5 --psi-dot0 60 --plot top.svg
  kreisel top --i1 1 --i3 0.5 --mgl 1 --theta0 1 --phi-dot0 -1 --psi-dot0 8 --format json
  kreisel top --i1 0.3 --i3 0.1 --mgl 2 --theta0 0.5 --psi-dot0 60 --csv top.csv --dt 0.001
  kreisel top --i1 0.3 --i3 0.1 --mgl 2 --theta0 30 --degrees --psi-dot0 60";

/// The command line of `kreisel top`: the top ([`TopArgs`]) and the time
/// series to write.
#[derive(Debug, Clone, clap::Args)]
#[command(after_long_help = AFTER_LONG_HELP)]
pub struct TopCommand {
    /// The top, its initial conditions, the report and the figure.
    #[command(flatten)]
    pub top: TopArgs,

    /// Write the motion sampled in time as CSV to FILE (see below)
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,

    /// Time covered by --csv, s [default: 3 nutation periods]
    #[arg(long, value_name = "T", requires = "csv", allow_hyphen_values = true)]
    pub duration: Option<f64>,

    /// Time between the --csv rows, s [default: nutation period / 200]
    #[arg(long, value_name = "H", requires = "csv", allow_hyphen_values = true)]
    pub dt: Option<f64>,

    /// Read --theta0 and write the angles (theta0, theta_min, theta_max, the
    /// CSV's theta, phi, psi, the figure's) in degrees; rates stay in rad/s
    #[arg(long)]
    pub degrees: bool,
}

/// Arguments of `kreisel top` that describe the top and its report.
#[derive(Debug, Clone, clap::Args)]
pub struct TopArgs {
    /// Transverse moment of inertia about the pivot, kg m^2 (positive)
    #[arg(long, value_name = "I1", allow_hyphen_values = true)]
    pub i1: f64,

    /// Moment of inertia about the symmetry axis, kg m^2 (positive, at most 2 I1)
    #[arg(long, value_name = "I3", allow_hyphen_values = true)]
    pub i3: f64,

    /// M g l: weight times the distance from the pivot to the centre of mass, J
    #[arg(long, value_name = "MGL", allow_hyphen_values = true)]
    pub mgl: f64,

    /// Initial angle of the symmetry axis from the upward vertical, rad, in [0, pi] (deg with --degrees)
    #[arg(long, value_name = "TH", allow_hyphen_values = true)]
    pub theta0: f64,

    /// Initial nutation rate d(theta)/dt, rad/s
    #[arg(
        long,
        value_name = "TD",
        default_value_t = 0.0,
        allow_hyphen_values = true
    )]
    pub theta_dot0: f64,

    /// Initial precession rate d(phi)/dt, rad/s
    #[arg(
        long,
        value_name = "PD",
        default_value_t = 0.0,
        allow_hyphen_values = true
    )]
    pub phi_dot0: f64,

    /// Initial spin rate d(psi)/dt, rad/s
    #[arg(
        long,
        value_name = "SD",
        default_value_t = 0.0,
        allow_hyphen_values = true
    )]
    pub psi_dot0: f64,

    /// Output format
    #[arg(long, value_name = "FORMAT", value_enum, default_value_t = Format::Text)]
    pub format: Format,

    /// Draw the axis path and f(u) into FILE (.svg or .png)
    #[arg(long, value_name = "FILE")]
    pub plot: Option<PathBuf>,
}

/// What `kreisel top` writes on standard output (`--format`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// `name: value unit`, one per line.
    Text,
    /// One JSON object.
    Json,
}

impl TopArgs {
    /// The top and its initial state, for the library.
    pub fn request(&self) -> TopRequest {
        TopRequest {
            i1: self.i1,
            i3: self.i3,
            mgl: self.mgl,
            theta0: self.theta0,
            theta_dot0: self.theta_dot0,
            phi_dot0: self.phi_dot0,
            psi_dot0: self.psi_dot0,
        }
    }

    /// Checks the numbers ([`TopRequest::validate`]), then the plot format.
    ///
    /// # Errors
    /// [`CliError::Argument`] naming the option.
    fn validate(&self) -> Result<Option<ImageFormat>, CliError> {
        self.request().validate()?;
        match &self.plot {
            None => Ok(None),
            Some(path) => ImageFormat::from_path(path).map(Some).ok_or_else(|| {
                CliError::argument(
                    "--plot",
                    format!(
                        "{}: unknown image format (use a .svg or .png file name)",
                        path.display()
                    ),
                )
            }),
        }
    }
}

/// Samples per nutation period in the plot.
const SAMPLES_PER_PERIOD: usize = 400;

/// The axis e₃ in world coordinates over three or more nutation periods
/// (more while the precession over them is under a quarter turn, up to 12),
/// and a caption saying what it covers.
pub(crate) fn axis_path(motion: &LagrangeTopMotion) -> (Vec<DVec3>, String, Option<usize>) {
    // The report's period and precession (none without nutation, none on
    // the vertical).
    let period = motion
        .motion()
        .and(motion.nutation_period())
        .filter(|p| p.is_finite() && *p > 0.0);
    let precession = motion
        .mean_precession_rate()
        .filter(|w| w.is_finite() && *w != 0.0 && !on_the_vertical(motion));
    let (duration, periods, caption) = match (period, precession) {
        (Some(p), w) => {
            let per_period = w.map_or(0.0, |w| (w * p).abs());
            let wanted = if per_period > 0.0 {
                (std::f64::consts::FRAC_PI_2 / per_period).ceil()
            } else {
                3.0
            };
            let n = wanted.clamp(3.0, 12.0) as usize;
            let duration = p * n as f64;
            (
                duration,
                n,
                format!(
                    "t = 0 \u{2026} {} s ({n} nutation periods)",
                    short_time(duration)
                ),
            )
        }
        (None, Some(w)) => {
            // Steady precession: one turn.
            let duration = std::f64::consts::TAU / w.abs();
            (
                duration,
                3,
                format!(
                    "t = 0 \u{2026} {} s (one precession turn)",
                    short_time(duration)
                ),
            )
        }
        (None, None) => (0.0, 1, "the axis stays where it is".to_owned()),
    };
    let n = if duration > 0.0 {
        periods * SAMPLES_PER_PERIOD
    } else {
        0
    };
    let path = (0..=n)
        .map(|k| {
            let t = if n == 0 {
                0.0
            } else {
                duration * k as f64 / n as f64
            };
            motion.world_from_body_at(t) * DVec3::Z
        })
        .collect();
    let per_period = period.map(|_| SAMPLES_PER_PERIOD);
    (path, caption, per_period)
}

/// A time with 4 significant digits.
fn short_time(t: f64) -> String {
    let rounded: f64 = format!("{t:.3e}").parse().unwrap_or(t);
    Shortest(rounded).to_string()
}

/// The figure's title: the parameters (θ₀ as given: in degrees with
/// `degrees`).
fn title(args: &TopArgs, degrees: bool) -> String {
    format!(
        "Heavy symmetric top: I\u{2081} = {} kg m\u{b2}, I\u{2083} = {} kg m\u{b2}, Mgl = {} J;  \
         \u{3b8}\u{2080} = {}{}, d\u{3b8}/dt = {}, d\u{3c6}/dt = {}, d\u{3c8}/dt = {} rad/s",
        Shortest(args.i1),
        Shortest(args.i3),
        Shortest(args.mgl),
        Shortest(args.theta0),
        if degrees { "\u{b0}" } else { " rad" },
        Shortest(args.theta_dot0),
        Shortest(args.phi_dot0),
        Shortest(args.psi_dot0),
    )
}

/// Draws the figure of `motion` into `path`.
///
/// # Errors
/// [`CliError::Plot`] when rendering fails or the file cannot be written.
fn plot(
    args: &TopArgs,
    degrees: bool,
    motion: &LagrangeTopMotion,
    summary: &Summary,
    (format, path): (ImageFormat, &std::path::Path),
) -> Result<(), CliError> {
    let (axis, caption, samples_per_period) = axis_path(motion);
    let f = |u: f64| motion.f(u);
    let figure = figure::figure(&figure::TopPlot {
        title: title(args, degrees),
        axis_path: &axis,
        path_caption: caption,
        theta_min: summary.theta_min,
        theta_max: summary.theta_max,
        f: &f,
        roots: &summary.roots,
        beta: summary.beta,
        samples_per_period,
        degrees,
    });
    crate::output::write_figure(&figure, format, path)
}

/// The arguments with --theta0 in radians (`degrees`: given in degrees).
///
/// # Errors
/// [`CliError::Argument`] for a finite --theta0 outside [0, 180] degrees
/// (the library's message would show it in radians).
fn in_radians(args: &TopArgs, degrees: bool) -> Result<TopArgs, CliError> {
    let mut radians = args.clone();
    if degrees {
        if args.theta0.is_finite() && !(0.0..=180.0).contains(&args.theta0) {
            return Err(CliError::argument(
                "--theta0",
                format!(
                    "{} deg: must lie in [0, 180] (the angle of the axis from the upward vertical)",
                    Shortest(args.theta0)
                ),
            ));
        }
        radians.theta0 = args.theta0.to_radians();
    }
    Ok(radians)
}

/// Runs `kreisel top`.
///
/// # Errors
/// [`CliError::Argument`] for a bad option value (naming it), [`CliError::Plot`]
/// for the figure, [`CliError::CreateOutput`] / [`CliError::Write`] for the
/// `--csv` file and standard output.
pub fn run(command: &TopCommand) -> Result<(), CliError> {
    let degrees = command.degrees;
    let args = &in_radians(&command.top, degrees)?;
    let format = args.validate()?;
    let (motion, summary) = solve_and_summarise(&args.request())?;
    if command.csv.is_some() && command.csv == args.plot {
        return Err(CliError::argument(
            "--csv",
            "is also the --plot file; give them different names".to_owned(),
        ));
    }
    // The grid is checked before anything is written.
    let grid = match &command.csv {
        Some(path) => Some((
            series::schedule(&motion, command.duration, command.dt)?,
            path,
        )),
        None => None,
    };
    if let (Some(format), Some(path)) = (format, &args.plot) {
        plot(&command.top, degrees, &motion, &summary, (format, path))?;
    }
    if let Some((schedule, path)) = grid {
        series::write_csv(&motion, &schedule, path, degrees)?;
    }
    let report = if degrees {
        summary.in_degrees(command.top.theta0)
    } else {
        summary
    };
    let text = match args.format {
        Format::Text => output::text(&report, degrees),
        Format::Json => output::json(&report, degrees),
    };
    crate::output::print_stdout(&text)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The top of the CLI's tests (also `output.rs`'s).
    pub(super) fn args() -> TopArgs {
        TopArgs {
            i1: 0.3,
            i3: 0.1,
            mgl: 2.0,
            theta0: 0.5,
            theta_dot0: 0.0,
            phi_dot0: 0.0,
            psi_dot0: 60.0,
            format: Format::Text,
            plot: None,
        }
    }

    #[test]
    fn validation_names_the_option() {
        // The numbers are the library's to check (TopRequest::validate).
        let mut a = args();
        a.i1 = 0.0;
        let e = a.validate().unwrap_err().to_string();
        assert!(e.starts_with("--i1: "), "{e}");
        for bad in ["top.jpg", "top"] {
            let mut a = args();
            a.plot = Some(bad.into());
            let e = a.validate().unwrap_err().to_string();
            assert!(e.starts_with("--plot: "), "{bad}: {e}");
        }
        let mut ok = args();
        ok.plot = Some("x.PNG".into());
        assert_eq!(ok.validate().unwrap(), Some(ImageFormat::Png));
    }
}
