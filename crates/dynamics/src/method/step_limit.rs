//! The step-size limit of each stepping method for the torque-free body,
//! in terms of `h ω_max`: what `kreisel simulate --explain` prints and
//! warns about.

use glam::DVec3;

use super::FreeBodyMethod;

/// The relative energy error a run inside a method's step limit stays
/// below ([`FreeBodyMethod::step_limit`]).
pub const STEP_LIMIT_ENERGY_ERROR: f64 = 0.1;

impl FreeBodyMethod {
    /// The largest `h ω_max` (to 0.1) at which the method still follows a
    /// torque-free body, `ω_max = |L| / I₁` the fastest angular speed the
    /// body can reach (`I₁` the smallest moment): `None` for the exact
    /// solution (and `auto`), which has no limit.
    ///
    /// Measured, not assumed (`tests/free_body_step_limit.rs`): 6 bodies
    /// (moment ratios from 1 : 1 : 1.9 to 1 : 3 : 3) × 16 directions of
    /// `L` spread over the sphere, 2000 steps each, scanned in `h ω_max`
    /// (steps of 0.1, 0.02 near the dmv family's breakdown). Up to the
    /// limit every run keeps its state finite and its energy within
    /// [`STEP_LIMIT_ENERGY_ERROR`] (10 %) of the start (the test checks
    /// 0.5, 0.75, 0.9 and 1 times it); within 25 % beyond it some run does
    /// not:
    ///
    /// | method | limit | beyond it |
    /// |---|---|---|
    /// | `rk4` | 1.0 | energy drifts (decays) beyond 10 %, blows up past `2√2` |
    /// | `strang` | 1.8 | energy swings beyond 10 % (|L| stays exact) |
    /// | `splitting` | 3.3 | the same |
    /// | `splitting4` | 4.2 | the same |
    /// | `splitting6` | 6.5 | the same |
    /// | `splitting8` | 7.6 | the same |
    /// | `dmv` | 1.0 | the implicit step fails (no finite state) |
    /// | `pdmv4` | 2.8 | the same |
    /// | `pdmv6` | 1.4 | the same |
    /// | `pdmv8` | 2.0 | the same |
    /// | `pdmv10` | 1.5 | the same |
    ///
    /// The splittings move `L` by exact rotations, so they never blow up:
    /// past the limit the energy (and with it the motion) is simply no
    /// longer followed — at `h ω_max` = 30 (`I` = (1, 2, 3) kg m², `ω` =
    /// (1, 30, 0.5) rad/s, `h` = 0.5 s) `strang` swings the energy between
    /// 0.67 and 1.98 times its start. Below the limit each error
    /// falls as `(h ω_max)ᵖ` (order `p`), far below 10 % well inside it.
    /// `rk4`'s error grows with the run's length too (not geometric).
    ///
    /// ```
    /// use kreisel_dynamics::FreeBodyMethod;
    /// assert_eq!(FreeBodyMethod::Strang.step_limit(), Some(1.8));
    /// assert_eq!(FreeBodyMethod::Auto.step_limit(), None);
    /// ```
    pub const fn step_limit(self) -> Option<f64> {
        match self {
            Self::Auto | Self::Exact => None,
            Self::Rk4 | Self::Dmv => Some(1.0),
            Self::Strang => Some(1.8),
            Self::Splitting => Some(3.3),
            Self::Splitting4 => Some(4.2),
            Self::Splitting6 => Some(6.5),
            Self::Splitting8 => Some(7.6),
            Self::Pdmv4 => Some(2.8),
            Self::Pdmv6 => Some(1.4),
            Self::Pdmv8 => Some(2.0),
            Self::Pdmv10 => Some(1.5),
        }
    }

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
