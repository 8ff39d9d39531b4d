//! # The tippe top: spun with its stem up, it turns itself over onto its stem
//!
//! Leine & Glocker's tippe top (Eur. J. Mech. A/Solids 22 (2003) 193): a
//! ball of radius R = 15 mm whose centre of mass lies a = 3 mm below its
//! centre, m = 6 g, I₁ = 8e-7, I₃ = 7e-7 kg m², and a stem ending in a ball
//! of radius 5 mm whose centre is 16 mm from the centre of mass; started on
//! its ball at a tilt of 0.1 rad spinning at 180 rad/s. Coulomb friction
//! (μ = 0.3) with Contensou's drilling friction (a contact patch of radius
//! 0.5 mm) makes the axis rise through the horizontal until the stem lands;
//! the top then spins on its stem.
//!
//! ```text
//! cargo run --release --example tippe_top                  # window (or headless without a display)
//! cargo run --release --example tippe_top -- --headless \
//!     --gif target/tippe_top.gif --plot target/tippe_top.png
//! cargo run --release --example tippe_top -- --help        # every option
//! ```
//!
//! The simulation is a body on the table of the library's
//! [`kreisel::dynamics::World`], which moves it by its nonsmooth engine,
//! [`kreisel::dynamics::TableMotion`]: the ball and the stem's ball are
//! unilateral contacts (Signorini), friction is set-valued (stick and slip
//! on the cone), a contact that closes with speed is an impact (Newton's
//! law, `--restitution`, plastic by default), and the engine adapts its
//! own steps (`--tolerance`, default 1e-10) between events it locates to
//! rounding. The demo only observes, at its output grid (chart samples
//! and frames at `1/--fps` s) and at each of the library's events (the
//! world stops there: `World::advance_until_event`). It
//! prints the setup, then one line per event of interest with its time —
//! the axis passing the horizontal (located by bisection on the library's
//! run), the stem's landing, the ball lifting off, touching down again,
//! the rocking impacts — (`--events` adds the library's full list), the
//! end state, and the budgets: the energy never rises; Jellett's
//! λ = −L·ρ about the touching sphere is constant only while that sphere
//! alone touches and without drilling friction (`--contensou-radius 0`).
//!
//! `--plot` charts θ(t) on bands shaded by which contacts touch, E(t)/E₀
//! and a strip of the contacts with the impacts ticked (PNG or SVG by the
//! file's extension); `--gif` animates the top seen from the side (a red
//! and a yellow marker on the ball's equator show the spin; at 180 rad/s
//! they are sampled stroboscopically) beside θ(t).

use std::ffi::OsString;
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

pub mod chart;
pub mod drawing;
pub mod headless;
pub mod live;
pub mod options;
pub mod report;
pub mod simulation;

/// The Dzhanibekov demo's GIF writer and whole-or-nothing output files,
/// shared rather than copied.
#[allow(dead_code)]
#[path = "../dzhanibekov"]
pub mod shared {
    use super::DemoError;
    pub mod gif_out;
    pub mod output_file;
}

use options::Options;

/// Why the demo stopped.
#[derive(Debug, thiserror::Error)]
pub enum DemoError {
    /// The command line does not parse.
    #[error("{0}")]
    Usage(String),
    /// A number is out of range.
    #[error("{name} = {value} is out of range (must be {range})")]
    Option {
        /// The option.
        name: &'static str,
        /// Its value.
        value: f64,
        /// What it must be.
        range: &'static str,
    },
    /// The library refused the top or a step failed.
    #[error(transparent)]
    Dynamics(#[from] kreisel::dynamics::DynamicsError),
    /// A chart or frame could not be rendered.
    #[error("plot: {0}")]
    Plot(#[from] kreisel_plot::PlotError),
    /// The GIF could not be encoded or written.
    #[error("{path}: {source}")]
    Gif {
        /// The file.
        path: PathBuf,
        /// What went wrong.
        source: shared::gif_out::GifError,
    },
    /// An output file could not be written.
    #[error("{path}: {source}")]
    Write {
        /// The file.
        path: PathBuf,
        /// What went wrong.
        source: std::io::Error,
    },
    /// `--gif` names a file that does not end in `.gif`.
    #[error("{path}: the GIF is written to a .gif file")]
    GifFormat {
        /// The file.
        path: PathBuf,
    },
    /// `--plot` names a format other than PNG or SVG.
    #[error("{path}: the plot is written as .png or .svg")]
    PlotFormat {
        /// The file.
        path: PathBuf,
    },
    /// Standard output is closed.
    #[error("standard output: {0}")]
    Stdout(#[from] std::io::Error),
}

/// Runs the demo with command-line `args` (the program name first),
/// `display` the value of `DISPLAY`, printing to `out`.
///
/// # Errors
/// [`DemoError`]: bad options, a failed step, unwritable outputs.
pub fn run<I, T>(args: I, display: Option<OsString>, out: &mut dyn Write) -> Result<(), DemoError>
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let options = match <Options as clap::Parser>::try_parse_from(args) {
        Ok(options) => options,
        Err(e) if !e.use_stderr() => {
            write!(out, "{e}")?;
            return Ok(());
        }
        Err(e) => {
            // clap's first paragraph (the error and, for a bad value, the
            // possible values) on one line.
            let text = e.to_string();
            let line: Vec<&str> = text
                .lines()
                .map(str::trim)
                .take_while(|l| !l.is_empty())
                .collect();
            return Err(DemoError::Usage(
                line.join(" ").trim_start_matches("error: ").to_owned(),
            ));
        }
    };
    options.validate()?;
    let mut sim = simulation::Simulation::try_new(options.law()?, options.tolerance)?;
    for line in report::setup_lines(&options) {
        writeln!(out, "{line}")?;
    }
    let files = options.gif.is_some() || options.plot.is_some();
    if !options.headless && !files {
        match display.filter(|d| !d.is_empty()) {
            Some(_) => match live::run(&options, &mut sim, out)? {
                live::Outcome::Closed => return Ok(()),
                live::Outcome::NoWindow(reason) => {
                    writeln!(out, "no window ({reason}): running headless")?;
                }
            },
            None => writeln!(out, "no display (DISPLAY is not set): running headless")?,
        }
    }
    headless::run(&options, sim, out)
}

fn main() -> ExitCode {
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    match run(std::env::args_os(), std::env::var_os("DISPLAY"), &mut out) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            let _ = out.flush();
            eprintln!("tippe_top: error: {e}");
            ExitCode::FAILURE
        }
    }
}
