//! The printed lines: the setup before the run, the physics after it.

use kreisel::dynamics::GroundTop;

use super::options::Options;
use super::simulation::{
    self, BALL_OFFSET, BALL_RADIUS, I1, I3, MASS, SPIN0, STEM_OFFSET, STEM_RADIUS, Simulation,
    THETA0,
};

/// `value` to `digits` significant digits, without trailing zeros.
fn significant(value: f64, digits: usize) -> String {
    format!("{value:.*e}", digits - 1)
        .parse::<f64>()
        .map_or_else(|_| value.to_string(), |v| v.to_string())
}

/// The lines printed before the run.
pub fn setup_lines(options: &Options) -> Vec<String> {
    vec![
        format!(
            "tippe top (Leine & Glocker 2003): m = {} g, I₁ = {I1:e} kg m², I₃ = {I3:e} kg m², \
             ball R = {} mm, centre of mass a = {} mm below the ball's centre (α = {})",
            MASS * 1e3,
            BALL_RADIUS * 1e3,
            BALL_OFFSET * 1e3,
            significant(BALL_OFFSET / BALL_RADIUS, 6)
        ),
        format!(
            "start: tilt θ₀ = {THETA0} rad, spin ω₀ = {SPIN0} rad/s about the axis; friction: {}",
            options.friction_words()
        ),
        format!(
            "integrator: the library's RK4 (GroundTop::try_step), dt = {:e} s, {} s",
            options.dt, options.duration
        ),
    ]
}

/// The spin a full inversion ends with, from Jellett's λ:
/// `ω₀ (cos θ₀ − α)/(1 + α)` (about the vertical, rad/s).
pub fn final_spin_prediction() -> f64 {
    let alpha = BALL_OFFSET / BALL_RADIUS;
    SPIN0 * (THETA0.cos() - alpha) / (1.0 + alpha)
}

/// The lines printed after the run.
pub fn result_lines(sim: &Simulation) -> Vec<String> {
    let mut lines = Vec::new();
    let e = &sim.events;
    lines.push(match e.inverted_at {
        Some(t) => format!(
            "inverted at t = {t:.6} s (the axis passes the horizontal going down; \
             located by bisection on the RK4 step)"
        ),
        None => format!("not inverted within {} s", significant(sim.time, 6)),
    });
    if let Some((t, theta)) = e.stem_touch {
        lines.push(format!(
            "stem ball (r = {} mm, {} mm from the centre of mass) reaches the floor at t = {t:.3} s, \
             θ = {:.1}°: its contact is not modelled here (ball only)",
            STEM_RADIUS * 1e3,
            STEM_OFFSET * 1e3,
            theta.to_degrees()
        ));
    }
    if let Some(t) = e.lift_off {
        lines.push(format!(
            "lift-off at t = {t:.6} s: the ball leaves the floor, the run stops there"
        ));
    }
    let top: &GroundTop = &sim.top;
    let omega_z = top.omega_world(&sim.state).z;
    lines.push(format!(
        "at t = {} s: θ = {:.2}°, ω_z = {:.3} rad/s (a full inversion ends at \
         ω₀ (cos θ₀ − α)/(1 + α) = {:.3} rad/s)",
        significant(sim.time, 6),
        simulation::tilt(&sim.state).to_degrees(),
        omega_z,
        final_spin_prediction()
    ));
    let rose = if sim.energy_rise <= 0.0 {
        "never rose in a step".to_owned()
    } else {
        format!("rose by up to {:.1e} E₀ in a step", sim.energy_rise)
    };
    lines.push(format!(
        "energy: E/E₀ = {:.4} at the end, {rose}; Jellett's λ: max |Δλ|/|λ₀| = {:.0e}",
        top.energy(&sim.state) / sim.energy0,
        sim.jellett_drift
    ));
    lines
}
