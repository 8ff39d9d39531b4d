//! The step-size limit of the stepping methods for the torque-free body,
//! in terms of `h ω_max` (each method's own limit is its integrator's,
//! [`FreeBodyMethod::step_limit`]): what `kreisel simulate --explain`
//! prints and warns about.

use glam::DVec3;

use super::FreeBodyMethod;

/// The relative energy error a run inside a method's step limit stays
/// below ([`FreeBodyMethod::step_limit`]).
pub const STEP_LIMIT_ENERGY_ERROR: f64 = 0.1;

impl FreeBodyMethod {
    /// `h ω_max` of a torque-free body with principal `moments` and angular
    /// momentum `l` (any frame: only `|L|` enters) for steps of `h`: the
    /// number [`FreeBodyMethod::step_limit`] bounds.
    ///
    /// ```text
    /// h ω_max = h |L| / min(I₁, I₂, I₃)
    /// ```
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::FreeBodyMethod;
    /// // ω = (1, 30, 0.5) rad/s, I = (1, 2, 3): |L| = |(1, 60, 1.5)|, ω_max ≈ 60.03 rad/s.
    /// let x = FreeBodyMethod::step_ratio(DVec3::new(1.0, 2.0, 3.0), DVec3::new(1.0, 60.0, 1.5), 0.5);
    /// assert!((x - 30.01354).abs() < 1e-5, "{x}");
    /// assert!(x > FreeBodyMethod::Strang.step_limit().unwrap());
    /// // The same body at any unit scale.
    /// let huge = FreeBodyMethod::step_ratio(DVec3::new(1.0, 2.0, 3.0) * 1e200, DVec3::new(1.0, 60.0, 1.5) * 1e200, 0.5);
    /// assert!((huge - x).abs() < 1e-12 * x, "{huge}");
    /// ```
    pub fn step_ratio(moments: DVec3, l: DVec3, h: f64) -> f64 {
        // Divided first: |L| of a body of 1e200 kg m² overflows, |L|/I₁ not.
        h * (l / moments.min_element()).length()
    }
}
