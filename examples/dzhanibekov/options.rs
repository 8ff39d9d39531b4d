//! The demo's command line.

use std::path::PathBuf;

use clap::Parser;

use super::physics::{Spin, SpinAxis};

/// The default handle: the T-handle of `assets/`, in steel.
pub const DEFAULT_MESH: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/assets/t_handle.obj");

/// The Dzhanibekov effect: a T-handle spun about its intermediate principal
/// axis flips over and over; spun about the minor or major axis it only
/// wobbles. Opens a window when there is a display (keys: space pause,
/// r restart, 1/2/3 spin axis, +/− speed, q or Esc quit), else runs
/// headless. Always prints the physics, one line each.
#[derive(Debug, Clone, Parser)]
#[command(name = "dzhanibekov", version, about, long_about = None)]
pub struct Options {
    /// Run without a window (automatic when no display is available).
    #[arg(long)]
    pub headless: bool,
    /// Write an animated GIF of the rendering (headless).
    #[arg(long, value_name = "FILE")]
    pub gif: Option<PathBuf>,
    /// Write the ω(t) chart with the flips marked (.png or .svg; headless).
    #[arg(long, value_name = "FILE")]
    pub plot: Option<PathBuf>,
    /// Simulated time in seconds [default: 10 headless; the window runs
    /// until closed].
    #[arg(long, value_name = "S")]
    pub duration: Option<f64>,
    /// The principal axis spun about.
    #[arg(long, value_enum, default_value_t = SpinAxis::Intermediate)]
    pub spin_axis: SpinAxis,
    /// Spin rate |ω| at t = 0, rad/s (up to 1e6, and 0.5 rad per --dt).
    #[arg(long, value_name = "RAD_PER_S", default_value_t = std::f64::consts::TAU)]
    pub spin_rate: f64,
    /// Angle between ω and the spin axis at t = 0, rad.
    #[arg(long, value_name = "RAD", default_value_t = 0.05)]
    pub perturbation: f64,
    /// Integration method: any of `kreisel simulate --list-methods` for a
    /// free body (auto = the exact solution).
    #[arg(long, default_value = "auto")]
    pub method: String,
    /// Time step, s (1e-7 to 1).
    #[arg(long, value_name = "S", default_value_t = 1e-3)]
    pub dt: f64,
    /// The body: a closed triangle mesh (STL, OBJ, PLY, glTF); its first
    /// body is used.
    #[arg(long, value_name = "FILE", default_value = DEFAULT_MESH)]
    pub mesh: PathBuf,
    /// Density of the body, kg/m³ (7850: steel).
    #[arg(long, value_name = "KG_PER_M3", default_value_t = 7850.0)]
    pub density: f64,
    /// Frames per second of the GIF.
    #[arg(long, value_name = "N", default_value_t = 15.0)]
    pub fps: f64,
    /// Width of the GIF in pixels (the height is half of it).
    #[arg(long, value_name = "PX", default_value_t = 640)]
    pub gif_width: u32,
    /// Playback speed of the window at the start (real time = 1).
    #[arg(long, default_value_t = 1.0)]
    pub speed: f64,
}

/// Simulated seconds of a headless run without `--duration`.
pub const HEADLESS_DURATION: f64 = 10.0;

/// The fastest spin accepted, rad/s (some 10⁷ rpm: beyond any material;
/// far below where the energy ½Iω² or the growth rate would overflow).
pub const MAX_SPIN_RATE: f64 = 1e6;

/// The shortest and longest time steps accepted, s (the window and a
/// headless run step at least this fast; 1e8 steps are the most a run takes).
pub const MIN_DT: f64 = 1e-7;
/// See [`MIN_DT`].
pub const MAX_DT: f64 = 1.0;

/// The most the handle may turn in one step, rad: a flip (a sign change of
/// ω along the spin axis) is found within a step, so a step must not span
/// two; it also keeps the fixed-step methods near their accuracy.
pub const MAX_TURN_PER_STEP: f64 = 0.5;

impl Options {
    /// The spin the options describe.
    pub fn spin(&self) -> Spin {
        Spin {
            axis: self.spin_axis,
            rate: self.spin_rate,
            perturbation: self.perturbation,
        }
    }

    /// Checks the numbers that clap cannot: every one finite and in range,
    /// the step short enough for the spin and the duration, and `--gif`
    /// naming a `.gif` file; all before anything runs.
    ///
    /// # Errors
    /// [`super::DemoError::Option`] naming the option, its value and the
    /// range; [`super::DemoError::GifFormat`] for a `--gif` file not ending
    /// in `.gif`.
    pub fn validate(&self) -> Result<(), super::DemoError> {
        let check = |name: &'static str, value: f64, ok: bool, range: &'static str| {
            if value.is_finite() && ok {
                Ok(())
            } else {
                Err(super::DemoError::Option { name, value, range })
            }
        };
        check(
            "--spin-rate",
            self.spin_rate,
            self.spin_rate > 0.0 && self.spin_rate <= MAX_SPIN_RATE,
            "in (0, 1e6] rad/s",
        )?;
        check(
            "--perturbation",
            self.perturbation,
            self.perturbation.abs() < std::f64::consts::FRAC_PI_2,
            "between −π/2 and π/2",
        )?;
        check(
            "--dt",
            self.dt,
            (MIN_DT..=MAX_DT).contains(&self.dt),
            "in [1e-7, 1] s",
        )?;
        check(
            "--dt",
            self.dt,
            self.spin_rate * self.dt <= MAX_TURN_PER_STEP,
            "at most 0.5 rad / --spin-rate: the handle may turn at most 0.5 rad per step, \
             or the flips between steps are missed",
        )?;
        if let Some(d) = self.duration {
            check("--duration", d, d > 0.0 && d <= 1e5, "in (0, 100000] s")?;
        }
        let duration = self.duration.unwrap_or(HEADLESS_DURATION);
        check(
            "--duration",
            duration,
            duration / self.dt <= 1e8,
            "at most 1e8 steps of --dt",
        )?;
        check(
            "--dt",
            self.dt,
            self.dt <= duration,
            "at most --duration (10 s unless given)",
        )?;
        if let Some(path) = &self.gif {
            let gif = path
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("gif"));
            if !gif {
                return Err(super::DemoError::GifFormat { path: path.clone() });
            }
        }
        check("--density", self.density, self.density > 0.0, "> 0")?;
        check(
            "--fps",
            self.fps,
            self.fps >= 1.0 && self.fps <= 100.0,
            "in [1, 100]",
        )?;
        check(
            "--gif-width",
            f64::from(self.gif_width),
            (160..=1920).contains(&self.gif_width),
            "in [160, 1920]",
        )?;
        check(
            "--speed",
            self.speed,
            self.speed > 0.0 && self.speed <= 64.0,
            "in (0, 64]",
        )?;
        Ok(())
    }
}
