//! Splitting methods built from exact rotations: the kinetic energy split
//! into pieces whose flows are rotations about fixed axes (McLachlan 1993;
//! Touma & Wisdom 1994; Reich 1994; Dullweber, Leimkuhler & McLachlan 1997),
//! composed symmetrically (Strang). Every piece preserves `|L|`, `L_world`
//! and `|q|` exactly up to rounding.

use glam::{DQuat, DVec3};

use crate::{FreeBodyIntegrator, PrincipalState};

/// Exact flow for time `h` of `H = c Lₖ²/2`: a rotation about principal axis `k`.
///
/// ```text
/// ω = c Lₖ eₖ,   θ = h c Lₖ:   L ← Rₖ(−θ) L,   q ← q ⊗ (cos θ/2, sin θ/2 eₖ)
/// ```
#[inline]
pub(crate) fn axis_flow(k: usize, c: f64, state: &mut PrincipalState, h: f64) {
    let l = state.l_principal.to_array();
    let theta = h * c * l[k];
    // sin θ and cos θ directly: deriving them from the half angle (2sc,
    // c² − s²) saves a sin_cos but makes the rotation's norm err the same
    // way every step, and |L| and the energy then drift (measured over 10⁶
    // steps in tests/free_body_reference.rs).
    let (s, co) = theta.sin_cos();
    let (j, m) = ((k + 1) % 3, (k + 2) % 3);
    let mut out = l;
    out[j] = co * l[j] + s * l[m];
    out[m] = -s * l[j] + co * l[m];
    state.l_principal = DVec3::from_array(out);
    let (sh, ch) = (0.5 * theta).sin_cos();
    let mut v = [0.0; 3];
    v[k] = sh;
    state.world_from_principal *= DQuat::from_xyzw(v[0], v[1], v[2], ch);
}

/// Exact flow for time `h` of the Casimir part `|L|²/(2 I)`: a rotation of the
/// attitude about `L` itself (`L` does not change).
///
/// ```text
/// ω = L / I:   q ← q ⊗ exp(h L / I)
/// ```
#[inline]
pub(crate) fn casimir_flow(inertia: f64, state: &mut PrincipalState, h: f64) {
    state.world_from_principal *=
        kreisel_kinematics::quat_from_rotation_vector(state.l_principal * (h / inertia));
}

/// The classical five-rotation Strang splitting `R₁(h/2) R₂(h/2) R₃(h) R₂(h/2) R₁(h/2)`,
/// order 2 (McLachlan 1993; Touma & Wisdom 1994).
///
/// ```text
/// H = L₁²/2I₁ + L₂²/2I₂ + L₃²/2I₃
/// ```
///
/// Kept as the textbook baseline: its error constant is up to 230× larger
/// than [`SymmetricTopSplitting`]'s at equal cost (Fassò 2003).
#[derive(Debug, Clone, Copy, Default)]
pub struct AxisStrang;

impl FreeBodyIntegrator for AxisStrang {
    fn name(&self) -> &'static str {
        "strang"
    }

    fn order(&self) -> u32 {
        2
    }

    fn description(&self) -> &'static str {
        "five exact rotations about the principal axes, Strang-composed"
    }

    /// 1.8: beyond it the energy swings beyond 10 % (|L| stays exact).
    fn step_limit(&self) -> Option<f64> {
        Some(1.8)
    }

    fn step(&self, moments: DVec3, state: &mut PrincipalState, h: f64) {
        let c = DVec3::ONE / moments;
        axis_flow(0, c.x, state, 0.5 * h);
        axis_flow(1, c.y, state, 0.5 * h);
        axis_flow(2, c.z, state, h);
        axis_flow(1, c.y, state, 0.5 * h);
        axis_flow(0, c.x, state, 0.5 * h);
    }
}

/// The splitting into an exactly solvable symmetric top and one rotation,
/// order 2 (Dullweber, Leimkuhler & McLachlan 1997; ordering after Fassò,
/// J. Comput. Phys. 189:527 (2003)).
///
/// ```text
/// H = |L|²/2I_a + L_b²/2 (1/I_b − 1/I_a)  +  L_c²/2 (1/I_c − 1/I_a)
///     └──── symmetric top, exact ─────┘     └── rotation about c ──┘
/// step: R_c(h/2) · [Casimir_a(h) · R_b(h)] · R_c(h/2)
/// ```
///
/// with `a` the axis of the middle moment, `b` the largest and `c` the
/// smallest: of the six orderings, it measured best on three of four test
/// cases and 5.5 % behind the best on the fourth, where the worst ordering
/// was 16× worse (`tests/splitting_order.rs`; Fassò 2003 measured 230×). The two parts of the
/// symmetric top commute, so their exact flows compose in either order.
#[derive(Debug, Clone, Copy, Default)]
pub struct SymmetricTopSplitting;

/// The default axes `(a, b, c)`: middle, largest and smallest moment.
#[inline]
pub fn default_axes(moments: DVec3) -> (usize, usize, usize) {
    let m = moments.to_array();
    let mut idx = [0, 1, 2];
    idx.sort_by(|&i, &j| m[i].total_cmp(&m[j]));
    (idx[1], idx[2], idx[0])
}

impl SymmetricTopSplitting {
    /// One step with an explicit choice of axes (reference `a`, paired `b`,
    /// split `c`), for comparing orderings.
    pub fn step_with_axes(
        moments: DVec3,
        axes: (usize, usize, usize),
        state: &mut PrincipalState,
        h: f64,
    ) {
        let m = moments.to_array();
        let (a, b, c) = axes;
        let cb = 1.0 / m[b] - 1.0 / m[a];
        let cc = 1.0 / m[c] - 1.0 / m[a];
        axis_flow(c, cc, state, 0.5 * h);
        axis_flow(b, cb, state, h);
        casimir_flow(m[a], state, h);
        axis_flow(c, cc, state, 0.5 * h);
    }
}

impl FreeBodyIntegrator for SymmetricTopSplitting {
    fn name(&self) -> &'static str {
        "splitting"
    }

    fn order(&self) -> u32 {
        2
    }

    fn description(&self) -> &'static str {
        "exact symmetric top plus one exact axis rotation (Dullweber, Leimkuhler, McLachlan)"
    }

    /// 3.3: beyond it the energy swings beyond 10 % (|L| stays exact).
    fn step_limit(&self) -> Option<f64> {
        Some(3.3)
    }

    fn step(&self, moments: DVec3, state: &mut PrincipalState, h: f64) {
        Self::step_with_axes(moments, default_axes(moments), state, h);
    }
}
