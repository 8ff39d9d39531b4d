//! The demo's command line.

use std::path::PathBuf;

use clap::Parser;
use kreisel::dynamics::ContactLaw;
use kreisel_plot::ImageFormat;

use super::DemoError;

/// The tippe top of Leine & Glocker (2003) on a table, ball and stem: spun
/// with its stem up, it turns itself over onto its stem. Opens a window
/// when there is a display (q or Esc quits), else runs headless. Always
/// prints the physics, one line each.
#[derive(Debug, Clone, Parser)]
#[command(name = "tippe_top", version, about, long_about = None, allow_negative_numbers = true)]
pub struct Options {
    /// Run without a window (automatic when no display is available).
    #[arg(long)]
    pub headless: bool,
    /// Write an animated GIF of the top seen from the side (headless).
    #[arg(long, value_name = "FILE")]
    pub gif: Option<PathBuf>,
    /// Write the chart of θ(t), the energy and the contacts (.png or .svg; headless).
    #[arg(long, value_name = "FILE")]
    pub plot: Option<PathBuf>,
    /// Print every event of the library's run (impacts, lift-offs,
    /// touchdowns, stick, slip), one line each, after the events of interest.
    #[arg(long)]
    pub events: bool,
    /// Simulated time, s (up to 60).
    #[arg(long, value_name = "S", default_value_t = 8.0)]
    pub duration: f64,
    /// Coulomb's friction coefficient μ at the ball and the stem.
    #[arg(long, value_name = "MU", default_value_t = 0.3)]
    pub mu: f64,
    /// Radius of Contensou's contact patch (drilling friction), mm (0: point
    /// contacts, no drilling friction).
    #[arg(long, value_name = "MM", default_value_t = 0.5)]
    pub contensou_radius: f64,
    /// Newton's restitution coefficient e of the impacts (0: plastic).
    #[arg(long, value_name = "E", default_value_t = 0.0)]
    pub restitution: f64,
    /// Relative (and scaled absolute) tolerance of the engine's adaptive
    /// steps (1e-12 to 1e-4, the world's range for a body on the table).
    #[arg(long, value_name = "TOL", default_value = "1e-10")]
    pub tolerance: f64,
    /// Frames per second of simulated time in the GIF and the window's
    /// chart (the GIF is shown at a quarter of real speed; the engine
    /// adapts its own steps between frames).
    #[arg(long, value_name = "N", default_value_t = 40.0)]
    pub fps: f64,
}

/// The longest run accepted, s.
pub const MAX_DURATION: f64 = 60.0;
/// The loosest and tightest tolerances accepted.
pub const TOLERANCE_RANGE: (f64, f64) = (1e-12, 1e-4);
/// The largest Contensou radius accepted, mm (a third of the stem's ball).
pub const MAX_CONTENSOU_RADIUS: f64 = 1.5;

/// `Err(DemoError::Option)` unless `ok`.
fn check(ok: bool, name: &'static str, value: f64, range: &'static str) -> Result<(), DemoError> {
    if ok {
        Ok(())
    } else {
        Err(DemoError::Option { name, value, range })
    }
}

impl Options {
    /// Checks the numbers and the output files (before the run is spent on them).
    ///
    /// # Errors
    /// [`DemoError::Option`] naming the first option out of range;
    /// [`DemoError::GifFormat`], [`DemoError::PlotFormat`], [`DemoError::Write`]
    /// for an output of the wrong kind or in a missing directory.
    pub fn validate(&self) -> Result<(), DemoError> {
        check(
            self.duration > 0.0 && self.duration <= MAX_DURATION,
            "--duration",
            self.duration,
            "in (0, 60] s",
        )?;
        check(
            self.tolerance >= TOLERANCE_RANGE.0 && self.tolerance <= TOLERANCE_RANGE.1,
            "--tolerance",
            self.tolerance,
            "in [1e-12, 1e-4]",
        )?;
        check(
            self.fps >= 1.0 && self.fps <= 1000.0,
            "--fps",
            self.fps,
            "in [1, 1000]",
        )?;
        check(
            self.mu.is_finite() && self.mu >= 0.0,
            "--mu",
            self.mu,
            "finite and not negative",
        )?;
        check(
            self.contensou_radius >= 0.0 && self.contensou_radius <= MAX_CONTENSOU_RADIUS,
            "--contensou-radius",
            self.contensou_radius,
            "in [0, 1.5] mm",
        )?;
        check(
            (0.0..=1.0).contains(&self.restitution),
            "--restitution",
            self.restitution,
            "in [0, 1]",
        )?;
        if let Some(path) = &self.gif {
            let ext = path.extension().and_then(|e| e.to_str());
            if !ext.is_some_and(|e| e.eq_ignore_ascii_case("gif")) {
                return Err(DemoError::GifFormat { path: path.clone() });
            }
        }
        if let Some(path) = &self.plot
            && ImageFormat::from_path(path).is_none()
        {
            return Err(DemoError::PlotFormat { path: path.clone() });
        }
        for path in self.gif.iter().chain(&self.plot) {
            super::shared::output_file::check_directory(path)?;
        }
        Ok(())
    }

    /// The contact law of the ball and the stem.
    ///
    /// # Errors
    /// [`DemoError::Dynamics`] for parameters the library refuses.
    pub fn law(&self) -> Result<ContactLaw, DemoError> {
        Ok(ContactLaw::try_new(self.mu)?
            .try_with_restitution(self.restitution)?
            .try_with_contensou_radius(self.contensou_radius * 1e-3)?)
    }

    /// The contact law in words, for the printed setup.
    pub fn law_words(&self) -> String {
        let drilling = if self.contensou_radius > 0.0 {
            format!(
                "Contensou's drilling friction on a patch of radius {} mm",
                self.contensou_radius
            )
        } else {
            "point contacts (no drilling friction)".to_owned()
        };
        let impacts = if self.restitution == 0.0 {
            "plastic impacts (e = 0)".to_owned()
        } else {
            format!("impacts with restitution e = {}", self.restitution)
        };
        format!("Coulomb friction μ = {}, {drilling}, {impacts}", self.mu)
    }
}
