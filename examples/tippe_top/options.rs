//! The demo's command line.

use std::path::PathBuf;

use clap::Parser;
use kreisel::dynamics::Friction;
use kreisel_plot::ImageFormat;

use super::DemoError;

/// The tippe top of Leine & Glocker (2003) on a table: spun with its stem
/// up, it turns itself over onto its stem. Opens a window when there is a
/// display (q or Esc quits), else runs headless. Always prints the physics,
/// one line each.
#[derive(Debug, Clone, Parser)]
#[command(name = "tippe_top", version, about, long_about = None, allow_negative_numbers = true)]
pub struct Options {
    /// Run without a window (automatic when no display is available).
    #[arg(long)]
    pub headless: bool,
    /// Write an animated GIF of the top seen from the side (headless).
    #[arg(long, value_name = "FILE")]
    pub gif: Option<PathBuf>,
    /// Write the chart of θ(t), the energy and Jellett's λ (.png or .svg; headless).
    #[arg(long, value_name = "FILE")]
    pub plot: Option<PathBuf>,
    /// Simulated time, s (up to 1000).
    #[arg(long, value_name = "S", default_value_t = 4.0)]
    pub duration: f64,
    /// Friction at the contact: sliding (regularised Coulomb), viscous, rolling (no slip), none.
    #[arg(long, value_enum, default_value_t = FrictionChoice::Sliding)]
    pub friction: FrictionChoice,
    /// Friction coefficient: Coulomb's μ for sliding, s/m for viscous.
    #[arg(long, value_name = "MU", default_value_t = 0.3)]
    pub mu: f64,
    /// Regularisation ε of sliding friction, m/s (slip speeds well above it
    /// feel Coulomb's μ N).
    #[arg(long, value_name = "M_PER_S", default_value_t = 1e-3)]
    pub slip_velocity: f64,
    /// RK4 time step, s (1e-7 to 1e-3).
    #[arg(long, value_name = "S", default_value_t = 1e-5)]
    pub dt: f64,
    /// Frames per second of the GIF (each frame is 1/fps s of simulated
    /// time, shown at a quarter of real speed).
    #[arg(long, value_name = "N", default_value_t = 40.0)]
    pub fps: f64,
}

/// The friction models the demo offers (the library's
/// [`kreisel::dynamics::FrictionModel`]s that [`kreisel::dynamics::GroundTop`] steps).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum FrictionChoice {
    /// Regularised Coulomb friction: F = −μ N v/√(|v|² + ε²).
    Sliding,
    /// Viscous friction: F = −μ N v (μ in s/m).
    Viscous,
    /// Rolling without slipping (the contact point at rest; conservative).
    Rolling,
    /// No friction.
    None,
}

/// The longest run accepted, s.
pub const MAX_DURATION: f64 = 1000.0;
/// The shortest and longest steps accepted, s.
pub const DT_RANGE: (f64, f64) = (1e-7, 1e-3);

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
            "in (0, 1000] s",
        )?;
        check(
            self.dt >= DT_RANGE.0 && self.dt <= DT_RANGE.1,
            "--dt",
            self.dt,
            "in [1e-7, 1e-3] s",
        )?;
        check(
            self.dt <= self.duration,
            "--dt",
            self.dt,
            "at most --duration",
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
            self.slip_velocity.is_finite() && self.slip_velocity > 0.0,
            "--slip-velocity",
            self.slip_velocity,
            "positive and finite",
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

    /// The friction model with its parameters.
    ///
    /// # Errors
    /// [`DemoError::Dynamics`] for parameters the library refuses.
    pub fn friction(&self) -> Result<Friction, DemoError> {
        Ok(match self.friction {
            FrictionChoice::None => Friction::None,
            FrictionChoice::Viscous => Friction::try_viscous(self.mu)?,
            FrictionChoice::Sliding => Friction::try_sliding(self.mu, self.slip_velocity)?,
            FrictionChoice::Rolling => Friction::Rolling,
        })
    }

    /// The friction model's name (`sliding`, `viscous`, `rolling`, `none`).
    pub fn friction_name(&self) -> &'static str {
        match self.friction {
            FrictionChoice::Sliding => "sliding",
            FrictionChoice::Viscous => "viscous",
            FrictionChoice::Rolling => "rolling",
            FrictionChoice::None => "none",
        }
    }

    /// The friction in words, for the printed setup.
    pub fn friction_words(&self) -> String {
        match self.friction {
            FrictionChoice::None => "none".to_owned(),
            FrictionChoice::Rolling => "rolling without slipping".to_owned(),
            FrictionChoice::Viscous => format!("viscous, μ = {} s/m", self.mu),
            FrictionChoice::Sliding => format!(
                "sliding (regularised Coulomb), μ = {}, slip_velocity = {} mm/s",
                self.mu,
                self.slip_velocity * 1e3
            ),
        }
    }
}
