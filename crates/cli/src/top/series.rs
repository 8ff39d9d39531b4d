//! `kreisel top --csv FILE`: the closed-form motion sampled on a time grid.
//!
//! ```text
//! t,theta,phi,psi,theta_dot,phi_dot,psi_dot,qw,qx,qy,qz
//! q = Rz(φ) · Rx(θ) · Rz(ψ)   (world_from_body, intrinsic ZXZ as in `kreisel convert --from euler:ZXZ`)
//! ```
//!
//! The grid is `kreisel simulate`'s ([`Schedule`]): rows at t = k·dt and a
//! last row at t = duration exactly. Every number is the library's
//! ([`LagrangeTopMotion::euler_at`], [`LagrangeTopMotion::world_from_body_at`]);
//! this module only chooses the grid and writes the rows. The defaults
//! ([`default_grid`]):
//!
//! ```text
//! nutating top (period T):            duration 3 T,       dt T / 200
//! θ constant (sleeping top, steady precession), ω = min of the nonzero |φ̇|, |ψ̇|:
//!                                     duration 2π/ω,      dt duration / 600
//! at rest (θ₀ = 0, no rates):         duration 1 s,       dt 0.005 s
//! ```
//!
//! Without nutation the angles turn uniformly: one turn of the slowest
//! (the precession, for a steady precession) shows the whole motion.

use std::io::{BufWriter, Write};
use std::path::Path;

use kreisel_dynamics::LagrangeTopMotion;

use crate::error::{CliError, Stream};
use kreisel_scene::numbers::{Shortest, write_numbers};
use kreisel_scene::schedule::{Schedule, ScheduleProblem};

/// The header line of the CSV, without its newline.
pub const HEADER: &str = "t,theta,phi,psi,theta_dot,phi_dot,psi_dot,qw,qx,qy,qz";

/// The header line with `--degrees` (θ, φ, ψ in degrees; rates in rad/s).
pub const HEADER_DEGREES: &str =
    "t,theta_deg,phi_deg,psi_deg,theta_dot,phi_dot,psi_dot,qw,qx,qy,qz";

/// The most rows a `--csv` file may hold (about 200 bytes each).
pub const MAX_ROWS: u64 = 1_000_000;

/// Rows per nutation period by default.
pub const ROWS_PER_PERIOD: f64 = 200.0;

/// Nutation periods covered by default.
pub const DEFAULT_PERIODS: f64 = 3.0;

/// Steps over one turn of the slowest angle when θ is constant.
pub const STEPS_PER_TURN: f64 = 600.0;

/// The default duration and step, s (see the module docs).
pub fn default_grid(motion: &LagrangeTopMotion) -> (f64, f64) {
    let nutates = motion.motion().is_some();
    if let Some(period) = motion
        .nutation_period()
        .filter(|p| nutates && p.is_finite() && *p > 0.0)
    {
        return (DEFAULT_PERIODS * period, period / ROWS_PER_PERIOD);
    }
    let e = motion.euler_at(0.0);
    let slowest = [e.phi_dot.abs(), e.psi_dot.abs()]
        .into_iter()
        .filter(|w| *w > 0.0 && w.is_finite())
        .fold(f64::INFINITY, f64::min);
    if slowest.is_finite() {
        let turn = std::f64::consts::TAU / slowest;
        (turn, turn / STEPS_PER_TURN)
    } else {
        (1.0, 1.0 / ROWS_PER_PERIOD)
    }
}

/// The grid of `--duration` and `--dt` (either may be left to the default).
///
/// # Errors
/// [`CliError::Argument`] naming the option for a value that is not finite
/// and positive, or for more than [`MAX_ROWS`] rows.
pub fn schedule(
    motion: &LagrangeTopMotion,
    duration: Option<f64>,
    dt: Option<f64>,
) -> Result<Schedule, CliError> {
    let (default_duration, default_dt) = default_grid(motion);
    for (name, value) in [("--duration", duration), ("--dt", dt)] {
        if let Some(value) = value
            && !(value.is_finite() && value > 0.0)
        {
            return Err(CliError::argument(
                name,
                format!("{} s: must be a positive finite time", Shortest(value)),
            ));
        }
    }
    let duration = duration.unwrap_or(default_duration);
    let dt = dt.unwrap_or(default_dt);
    let too_many = |ratio: f64| {
        CliError::argument(
            "--dt",
            format!(
                "{} s over --duration {} s makes {} rows; at most {MAX_ROWS} (use a larger --dt)",
                Shortest(dt),
                Shortest(duration),
                Shortest(ratio.floor() + 1.0)
            ),
        )
    };
    if duration / dt >= MAX_ROWS as f64 {
        return Err(too_many(duration / dt));
    }
    Schedule::new(duration, dt, None).map_err(|problem| match problem {
        ScheduleProblem::TooManySteps { ratio }
        | ScheduleProblem::IntervalNotMultiple { ratio } => too_many(ratio),
    })
}

/// Writes the header and one row per time of `schedule` to `out`.
///
/// # Errors
/// The writer's errors.
pub fn write_rows<W: Write + ?Sized>(
    motion: &LagrangeTopMotion,
    schedule: &Schedule,
    out: &mut W,
    degrees: bool,
) -> std::io::Result<()> {
    let header = if degrees { HEADER_DEGREES } else { HEADER };
    // Degrees by `to_degrees`, as the report's angles.
    let angle = |x: f64| if degrees { x.to_degrees() } else { x };
    writeln!(out, "{header}")?;
    for k in 0..=schedule.steps() {
        let t = schedule.time(k);
        let e = motion.euler_at(t);
        let q = motion.world_from_body_at(t);
        write_numbers(
            out,
            &[
                t,
                angle(e.theta),
                angle(e.phi),
                angle(e.psi),
                e.theta_dot,
                e.phi_dot,
                e.psi_dot,
                q.w,
                q.x,
                q.y,
                q.z,
            ],
        )?;
    }
    Ok(())
}

/// Writes the CSV of `motion` on `schedule` to `path`, whole or not at all.
///
/// # Errors
/// [`CliError::CreateOutput`] when the file cannot be created,
/// [`CliError::Write`] when writing or renaming it fails (no file is left).
pub fn write_csv(
    motion: &LagrangeTopMotion,
    schedule: &Schedule,
    path: &Path,
    degrees: bool,
) -> Result<(), CliError> {
    let (file, pending) =
        crate::output::atomic_file::create(path).map_err(|source| CliError::CreateOutput {
            path: path.to_owned(),
            source,
        })?;
    let output = Stream::File(path.to_owned());
    let mut writer = BufWriter::with_capacity(1 << 16, file);
    write_rows(motion, schedule, &mut writer, degrees)
        .and_then(|()| writer.flush())
        .map_err(|source| CliError::Write {
            output: output.clone(),
            source,
        })?;
    drop(writer);
    crate::output::commit_output(Some(pending), output)
}

#[cfg(test)]
mod tests {
    use super::*;
    use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};

    fn motion(theta: f64, phi_dot: f64, psi_dot: f64) -> LagrangeTopMotion {
        LagrangeTop::new(1.0, 0.5, 1.0)
            .try_solve(LagrangeTopInitial {
                theta,
                phi_dot,
                psi_dot,
                ..LagrangeTopInitial::default()
            })
            .unwrap()
    }

    #[test]
    fn default_grid_covers_three_periods_or_turns() {
        let m = motion(0.5, 0.0, 20.0);
        let period = m.nutation_period().unwrap();
        let (duration, dt) = default_grid(&m);
        assert_eq!((duration, dt), (3.0 * period, period / 200.0));
        // Sleeping: one turn of the spin.
        let m = motion(0.0, 0.0, 20.0);
        assert!(m.is_sleeping());
        let turn = std::f64::consts::TAU / 20.0;
        assert_eq!(default_grid(&m), (turn, turn / 600.0));
        // Steady precession: one turn of the (slow) precession.
        let top = LagrangeTop::new(1.0, 0.5, 1.0);
        let slow = top.steady_precession_rates(20.0, 0.5).unwrap().slow;
        let psi_dot = 20.0 - slow * 0.5f64.cos();
        let m = motion(0.5, slow, psi_dot);
        assert!(m.motion().is_none(), "steady");
        let turn = std::f64::consts::TAU / slow.abs();
        assert_eq!(default_grid(&m), (turn, turn / 600.0));
        // At rest upright.
        assert_eq!(default_grid(&motion(0.0, 0.0, 0.0)), (1.0, 0.005));
    }

    #[test]
    fn bad_grids_name_the_option() {
        let m = motion(0.5, 0.0, 20.0);
        for (duration, dt, name) in [
            (Some(0.0), None, "--duration"),
            (Some(-1.0), None, "--duration"),
            (Some(f64::NAN), None, "--duration"),
            (None, Some(0.0), "--dt"),
            (None, Some(f64::INFINITY), "--dt"),
            (Some(1.0), Some(1e-7), "--dt"),
        ] {
            let e = schedule(&m, duration, dt).unwrap_err().to_string();
            assert!(e.starts_with(&format!("{name}: ")), "{e}");
        }
        let s = schedule(&m, Some(1.0), Some(0.3)).unwrap();
        assert_eq!(
            (s.steps(), s.time(3), s.time(4)),
            (4, 0.8999999999999999, 1.0)
        );
    }
}
