//! # rapier's T-handle, with and without kreisel
//!
//! rapier's Dzhanibekov scenario (I = (1, 2, 3) kg·m², ω₀ = (0.01, 1, 0)
//! rad/s, no gravity, no colliders) in rapier3d (`f32`, its defaults), once
//! as rapier moves it and once with [`kreisel_rapier::ExactRotation`]
//! carrying the rotation, and the exact period of ω (two flips) from
//! [`kreisel::dynamics::elliptic_motion`]:
//!
//! ```text
//! cargo run --release --example rapier_tumble [-- --dt DT --duration T]
//! ```
//!
//! prints `period of ω: exact X s, rapier Y s, rapier+kreisel Z s` (Y and Z
//! from the sign changes of ω₂ in body axes, read from rapier's state) and
//! the relative drifts of |L| and of the energy of both over the run.

use std::process::ExitCode;

use clap::Parser;
use kreisel::kinematics::glam::DVec3;

pub mod tumble;

use tumble::{Engine, MOMENTS, OMEGA0};

/// rapier's T-handle flipping, in rapier alone and with kreisel's exact
/// rotation.
#[derive(Debug, Parser)]
#[command(name = "rapier_tumble", about, long_about = None)]
struct Options {
    /// Time step, s (rapier's `IntegrationParameters::dt`).
    #[arg(long, value_name = "S", default_value_t = 1.0 / 60.0)]
    dt: f64,
    /// Simulated time, s.
    #[arg(long, value_name = "S", default_value_t = 100.0)]
    duration: f64,
}

/// The report, or the one line that says what is wrong.
pub fn report(dt: f64, duration: f64) -> Result<String, String> {
    if !(dt.is_finite() && dt > 0.0 && dt <= 1.0) {
        return Err(format!("--dt {dt}: must be in (0, 1] s"));
    }
    if !(duration.is_finite() && duration >= dt && duration / dt <= 1e8) {
        return Err(format!(
            "--duration {duration}: must be at least --dt and at most 1e8 steps"
        ));
    }
    // The state both engines start from: the f32 values, exactly.
    let moments = DVec3::from_array(MOMENTS.map(f64::from));
    let l0 = moments * DVec3::from_array(OMEGA0.map(f64::from));
    let exact = kreisel::dynamics::elliptic_motion(moments, l0)
        .map(|m| m.period)
        .ok_or("the scenario is not an elliptic motion")?;
    let dt32 = dt as f32;
    let rapier = tumble::run(Engine::Rapier, dt32, duration).map_err(|e| e.to_string())?;
    let both = tumble::run(Engine::RapierKreisel, dt32, duration).map_err(|e| e.to_string())?;
    let period =
        |p: Option<f64>| p.map_or("— (fewer than two flips)".into(), |p| format!("{p:.9} s"));
    Ok(format!(
        "period of ω: exact {exact:.9} s, rapier {}, rapier+kreisel {}\n\
         drift of |L| and energy over {duration} s (relative, at the end): \
         rapier {:+.1e}, {:+.1e}; rapier+kreisel {:+.1e}, {:+.1e}\n",
        period(rapier.period()),
        period(both.period()),
        rapier.end.0,
        rapier.end.1,
        both.end.0,
        both.end.1,
    ))
}

fn main() -> ExitCode {
    let options = Options::parse();
    match report(options.dt, options.duration) {
        Ok(text) => {
            print!("{text}");
            ExitCode::SUCCESS
        }
        Err(message) => {
            eprintln!("rapier_tumble: {message}");
            ExitCode::FAILURE
        }
    }
}
