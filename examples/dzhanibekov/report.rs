//! The physics the demo prints, one line per quantity.

use std::path::Path;

use super::physics::{Handle, Prediction, Simulation, Spin, SpinAxis};
use kreisel::dynamics::AxisStability;

/// `x` with `digits` significant digits (plain notation).
pub fn significant(x: f64, digits: usize) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let magnitude = x.abs().log10().floor() as i64;
    let decimals = (digits as i64 - 1 - magnitude).max(0) as usize;
    format!("{x:.decimals$}")
}

/// The lines known before the run: body, moments, spin, linear theory.
pub fn setup_lines(handle: &Handle, mesh: &Path, density: f64, spin: &Spin) -> Vec<String> {
    let p = &handle.properties;
    let c = p.center_of_mass;
    let m = handle.moments();
    let axis_words: Vec<String> = (0..3)
        .map(|k| {
            let a = handle.principal_axis_body(k);
            format!("({}, {}, {})", tidy(a.x), tidy(a.y), tidy(a.z))
        })
        .collect();
    let intermediate = SpinAxis::Intermediate.index();
    let lambda = match kreisel::dynamics::axis_stability(m, intermediate, spin.rate) {
        AxisStability::Unstable { growth_rate } => Some(growth_rate),
        _ => None,
    };
    let linear = match (Prediction::new(m, spin).stability, lambda) {
        (AxisStability::Unstable { growth_rate }, _) => format!(
            "linear growth rate (notes §3.7): λ = Ω √((I₂−I₁)(I₃−I₂)/(I₁I₃)) = {} 1/s \
             (perturbations grow e-fold every {} s)",
            significant(growth_rate, 6),
            significant(1.0 / growth_rate, 4)
        ),
        (AxisStability::Stable { frequency }, Some(l)) => format!(
            "linear growth rate (notes §3.7): none, the {} axis is stable (the perturbation \
             oscillates at {} rad/s); about the intermediate axis it would be λ = {} 1/s",
            spin.axis.name(),
            significant(frequency, 6),
            significant(l, 6)
        ),
        _ => "linear growth rate (notes §3.7): undecided (two equal moments)".to_owned(),
    };
    vec![
        format!(
            "body: {} from {}, solid of {} kg/m³: mass {} kg, centre of mass ({}, {}, {}) m",
            handle.name,
            // The default mesh as the repository names it.
            mesh.strip_prefix(env!("CARGO_MANIFEST_DIR"))
                .unwrap_or(mesh)
                .display(),
            density,
            significant(p.mass, 6),
            tidy(c.x),
            tidy(c.y),
            tidy(c.z)
        ),
        format!(
            "principal moments: I₁ = {:.6e}, I₂ = {:.6e}, I₃ = {:.6e} kg·m² \
             (axes in mesh coordinates: {}, {}, {})",
            m.x, m.y, m.z, axis_words[0], axis_words[1], axis_words[2]
        ),
        format!(
            "spin: {} rad/s about the {} axis, tilted by {} rad toward the next axis",
            significant(spin.rate, 6),
            spin.axis.name(),
            spin.perturbation
        ),
        linear,
    ]
}

/// The lines measured by a run: the flip period (predicted and simulated)
/// and the drift of the invariants.
pub fn result_lines(
    sim: &Simulation,
    prediction: &Prediction,
    spin: &Spin,
    method: &str,
    dt: f64,
) -> Vec<String> {
    let t = sim.time();
    let n = sim.flips.len();
    let flip = match (prediction.flip_period(), sim.measured_flip_period()) {
        (Some(x), Some(y)) => format!(
            "flip period: predicted {} s, simulated {} s (relative difference {}, {} flips in {} s, \
             the first at {} s)",
            significant(x, 10),
            significant(y, 10),
            relative((y - x).abs() / x),
            n,
            tidy(t),
            significant(sim.flips.first().copied().unwrap_or(f64::NAN), 10)
        ),
        (Some(x), None) => format!(
            "flip period: predicted {} s, simulated: {} flip{} in {} s, too few to time \
             (run at least {} s)",
            significant(x, 10),
            n,
            if n == 1 { "" } else { "s" },
            tidy(t),
            significant(sim.flips.first().copied().unwrap_or(0.5 * x) + 1.05 * x, 3)
        ),
        (None, _) => format!(
            "flip period: none predicted (spin about the {} axis is stable), {} flips simulated \
             in {} s",
            spin.axis.name(),
            n,
            tidy(t)
        ),
    };
    vec![
        flip,
        format!(
            "drift over {} s ({method}, dt = {dt} s): energy {}, |L| {}, L_world {} (relative, largest)",
            tidy(t),
            relative(sim.energy_drift),
            relative(sim.l_drift),
            relative(sim.l_world_drift)
        ),
    ]
}

/// `x` to 6 significant digits without trailing zeros; rounding noise
/// below 1e-12 shown as 0.
pub fn tidy(x: f64) -> String {
    if x.abs() < 1e-12 {
        return "0".to_owned();
    }
    let s = significant(x, 6);
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        s
    }
}

/// A relative difference in scientific notation (0 as `0`).
fn relative(x: f64) -> String {
    if x == 0.0 {
        "0".to_owned()
    } else {
        format!("{x:.1e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn significant_digits() {
        assert_eq!(significant(2.925549014329971, 10), "2.925549014");
        assert_eq!(significant(0.0033825, 3), "0.00338");
        assert_eq!(significant(123.456, 4), "123.5");
        assert_eq!(significant(-0.5, 2), "-0.50");
        assert_eq!(significant(0.0, 5), "0");
        assert_eq!(significant(0.01, 2), "0.010");
        assert_eq!(tidy(1.0), "1");
        assert_eq!(tidy(-0.0033825665), "-0.00338257");
        assert_eq!(tidy(10.0), "10");
        assert_eq!(tidy(1e-17), "0");
    }
}
