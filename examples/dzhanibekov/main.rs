//! # The Dzhanibekov effect: a T-handle that flips
//!
//! A T-handle (the steel wing nut of `assets/t_handle.obj`, its mass
//! properties computed from the mesh by kreisel-inertia) is spun mostly
//! about its intermediate principal axis. Notes §3.7: small perturbations
//! of that spin grow like `e^{λt}`, and the handle turns over again and
//! again, each time after the same interval, the half period `2K(m)/λ` of
//! the exact elliptic-function solution (Landau & Lifshitz, *Mechanics*,
//! §37). Spun about the minor or major axis it only wobbles.
//!
//! ```text
//! cargo run --release --example dzhanibekov                 # window (or headless without a display)
//! cargo run --release --example dzhanibekov -- --headless \
//!     --gif target/dzhanibekov.gif --plot target/dzhanibekov_omega.png
//! cargo run --release --example dzhanibekov -- --help       # every option
//! ```
//!
//! The window (minifb, X11, software rendering): the shaded handle, its
//! principal axes 1, 2, 3, the fixed angular momentum L and ω, and a strip
//! chart of ω in body principal axes. Keys: space pause, r restart,
//! 1/2/3 spin about the minor/intermediate/major axis, +/− speed,
//! q or Esc quit. Without a display, or with `--headless`, `--gif` or
//! `--plot`, it runs headless and writes the files asked for.
//!
//! Every run prints the physics, one line each: the body, the principal
//! moments, the spin, the linear growth rate of §3.7, then
//! `flip period: predicted X s, simulated Y s` — X from
//! [`kreisel::dynamics::elliptic_motion`], Y the mean interval between the
//! simulated sign changes of ω along the spin axis — and the drift of the
//! energy and of |L|. The simulation is the library's
//! [`kreisel::dynamics::World`] holding the handle as one body, moved by
//! the free-body method `--method` (default `auto`: the exact solution) in
//! steps of `--dt`; the demo only observes the states it reports.

use std::ffi::OsString;
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

pub mod chart;
pub mod frame;
pub mod gif_out;
pub mod headless;
pub mod live;
pub mod options;
pub mod output_file;
pub mod physics;
pub mod render;
pub mod report;

use options::Options;
use physics::Handle;

/// Why the demo stopped.
#[derive(Debug, thiserror::Error)]
pub enum DemoError {
    /// The command line does not parse.
    #[error("{0}")]
    Usage(String),
    /// A number is out of range.
    #[error("{name} = {} is out of range (must be {range})", short(*.value))]
    Option {
        /// The option.
        name: &'static str,
        /// Its value.
        value: f64,
        /// What it must be.
        range: &'static str,
    },
    /// The file's bodies have more vertices together than a drawing can number.
    #[error("{path}: more than 2^32 vertices in all bodies together")]
    TooManyVertices {
        /// The mesh file.
        path: PathBuf,
    },
    /// The mesh cannot be read or is not a closed solid.
    #[error(transparent)]
    Mesh(#[from] kreisel::inertia::InertiaError),
    /// The body or method is not one the dynamics accepts.
    #[error(transparent)]
    Dynamics(#[from] kreisel::dynamics::DynamicsError),
    /// A chart could not be rendered.
    #[error("plot: {0}")]
    Plot(#[from] kreisel_plot::PlotError),
    /// The GIF could not be encoded or written.
    #[error("{path}: {source}")]
    Gif {
        /// The file.
        path: PathBuf,
        /// What went wrong.
        source: gif_out::GifError,
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

/// `value` as Rust prints it, in exponent form outside [1e-4, 1e15)
/// (`1e300`, not 301 digits).
fn short(value: f64) -> String {
    if value == 0.0 || !value.is_finite() || (1e-4..1e15).contains(&value.abs()) {
        format!("{value}")
    } else {
        format!("{value:e}")
    }
}

/// Runs the demo with command-line `args` (the program name first),
/// `display` the value of `DISPLAY`, printing to `out`.
///
/// # Errors
/// [`DemoError`]: bad options, an unreadable mesh, unwritable outputs.
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
            let text = e.to_string();
            let line = text.lines().next().unwrap_or("bad arguments");
            return Err(DemoError::Usage(
                line.trim_start_matches("error: ").to_owned(),
            ));
        }
    };
    options.validate()?;
    let handle = Handle::load(&options.mesh, options.density)?;
    let method: kreisel::dynamics::FreeBodyMethod = options.method.parse()?;
    for line in report::setup_lines(&handle, &options.mesh, options.density, &options.spin()) {
        writeln!(out, "{line}")?;
    }
    let files = options.gif.is_some() || options.plot.is_some();
    if !options.headless && !files {
        match live::display_available(display.as_deref()) {
            Ok(()) => match live::run(&options, &handle, method, out)? {
                live::Outcome::Closed => return Ok(()),
                live::Outcome::NoWindow(reason) => {
                    writeln!(out, "no window ({reason}): running headless")?;
                }
            },
            Err(reason) => writeln!(out, "no display ({reason}): running headless")?,
        }
    }
    headless::run(&options, &handle, method, out)
}

fn main() -> ExitCode {
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    match run(std::env::args_os(), std::env::var_os("DISPLAY"), &mut out) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            let _ = out.flush();
            eprintln!("dzhanibekov: error: {e}");
            ExitCode::FAILURE
        }
    }
}
