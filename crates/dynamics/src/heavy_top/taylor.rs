//! The heavy top by Taylor series: the whole motion (free body and gravity
//! together, no splitting) expanded to high order in `t` by the recurrences
//! of its quadratic equations (automatic differentiation).

use std::cell::RefCell;

use glam::{DQuat, DVec3};

use super::HeavyTop;
use crate::stepping::HeavyTopIntegrator;
use crate::{DynamicsError, PrincipalState};

/// The highest order a [`HeavyTopTaylor`] may have.
pub const TAYLOR_MAX_ORDER: usize = 28;

/// Taylor series of the heavy top in its principal frame, to a fixed
/// order `p`, every step cut into sub-steps short enough for the series.
///
/// ```text
/// ω = J⁻¹L,   γ = Rᵀ W  (the weight in principal axes)
/// L̇ = L × ω + c × γ,   γ̇ = γ × ω,   q̇ = ½ q ⊗ (0, ω)
/// x(t₀ + h) = Σₖ₌₀ᵖ xₖ hᵏ,   x_{k+1} = f_k / (k + 1)
/// (L × ω)ₖ = d ⊙ Σⱼ (L_j,y L_{k−j},z, L_j,z L_{k−j},x, L_j,x L_{k−j},y),   d = (1/J₃ − 1/J₂, 1/J₁ − 1/J₃, 1/J₂ − 1/J₁)
/// (γ × ω)ₖ = Σⱼ γⱼ × ω_{k−j},   (q ⊗ ω)ₖ = Σⱼ qⱼ ⊗ (0, ω_{k−j})
/// ```
/// The equations are quadratic, so the coefficient `k + 1` costs one
/// Cauchy product of length `k + 1` per quadratic term: 21 products, so a
/// series of order `p` costs about `10.5 p²` multiply–adds (Moore 1966;
/// Jorba & Zou, Exp. Math. 14:99, 2005), summed two terms at a time so
/// that they compile to two-wide vector operations, in a per-thread
/// scratch space (not cleared: clearing it was a fifth of the work). One
/// order-18 series takes ~1.1 µs on the project's VM: at `dt = 10⁻²` the
/// 150 rad/s reference tops take two per step, ~0.45 ms per 2 s
/// (BENCHMARKS.md, "Heavy top"). `γ` is an auxiliary variable
/// (`Rᵀ W` recomputed from `q` at every step); the free flow and gravity
/// are not split, so there is no splitting error, and the truncation error
/// falls like `(h |ω| / ρ)ᵖ⁺¹` for a radius `ρ` of order one.
///
/// Not symplectic: `|q|`, the energy and `L_v` drift by the rounding of
/// each step (a random walk of ~1e-16 per step), not bounded as the
/// splittings keep them.
///
/// Order: fixed ([`HeavyTopTaylor::new`]) or, for
/// [`HeavyTopTaylor::DEFAULT`], 18 at `h ω_max = 0.8` and lower for
/// shorter sub-steps ([`HeavyTopTaylor::order_for`], chosen before the
/// series from the same bound as the sub-steps; a test of the terms
/// inside the loop cost 20 % of the series' time).
///
/// Sub-steps: `n = ⌈h ω_max / reach⌉` with `ω_max` the bound of
/// [`HeavyTop::angular_speed_bound`] over the whole motion
/// ([`HeavyTopTaylor::try_substeps`]). The series converges for `h` below
/// the distance to the nearest complex-time singularity of the motion; on
/// the 150 rad/s asymmetric reference top order 18 at `h |ω| ≤ 0.8` gives
/// 8e-14 rad over 2 s, order 16 8e-13 rad, and at `h |ω| = 1.6` order 26
/// is needed for 1e-12 rad.
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{HeavyTop, HeavyTopIntegrator, HeavyTopTaylor, PrincipalState};
/// let top = HeavyTop::try_from_principal(DVec3::new(0.02, 0.03, 0.01), DVec3::new(0.01, 0.0, 0.1), 1.0, DVec3::new(0.0, 0.0, -9.81))?;
/// let start = PrincipalState { world_from_principal: DQuat::from_rotation_x(0.3), l_principal: DVec3::new(0.0, 0.0, 0.5) };
/// let mut s = start;
/// for _ in 0..100 {
///     HeavyTopTaylor::DEFAULT.step(&top, &mut s, 1e-2);
/// }
/// let e0 = top.energy(&start);
/// assert!((top.energy(&s) - e0).abs() < 1e-13 * e0);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct HeavyTopTaylor {
    order: usize,
    reach: f64,
    /// Lower the order for sub-steps shorter than `reach` (see
    /// [`HeavyTopTaylor::order_for`]).
    adaptive: bool,
}

/// The relative size of the first term left out, for which
/// [`HeavyTopTaylor::order_for`] picks the order: 2⁻⁵⁶, an eighth of the
/// rounding unit.
const NEGLIGIBLE: f64 = 1.0 / (1u64 << 56) as f64;

/// The Taylor coefficients of one step, one array per component: `L`,
/// `γ`, `ω`, `q` (see [`L`], [`G`], [`W`], [`Q`]).
struct Series {
    x: [[f64; M + 1]; 13],
    /// `L` and `ω` reversed (`rev[n][M − 1 − k]` = coefficient `k`), one
    /// zero past the end.
    rev: [[f64; M + 1]; 6],
}

thread_local! {
    /// One series' scratch space per thread, reused: clearing its 4 KB for
    /// every series cost a fifth of the series' instructions.
    static SCRATCH: RefCell<Series> = RefCell::new(Series::default());
}

/// Coefficients per component.
const M: usize = TAYLOR_MAX_ORDER + 1;

impl HeavyTopTaylor {
    /// The default series: order 18 at sub-steps of `h ω_max = 0.8` (on
    /// the 150 rad/s reference tops: 2 series per 0.01 s, ≤ 1e-13 rad over
    /// 2 s; `tests/heavy_top_taylor.rs`), lower for shorter sub-steps
    /// ([`HeavyTopTaylor::order_for`]: 12 at `h ω_max = 0.16`), so that
    /// short steps cost less.
    pub const DEFAULT: Self = Self {
        adaptive: true,
        ..Self::new(18, 0.8)
    };

    /// Order `order`, sub-steps of `h ω_max ≤ reach`.
    ///
    /// # Panics
    /// If `order` is 0 or above [`TAYLOR_MAX_ORDER`], or `reach` is not
    /// positive and finite (all constants: a panic is a typo).
    ///
    /// ```
    /// use kreisel_dynamics::{HeavyTopIntegrator, HeavyTopTaylor};
    /// assert_eq!(HeavyTopTaylor::new(8, 0.5).order(), 8);
    /// ```
    pub const fn new(order: usize, reach: f64) -> Self {
        assert!(
            order >= 1 && order <= TAYLOR_MAX_ORDER,
            "order out of range"
        );
        assert!(
            reach > 0.0 && reach < f64::INFINITY,
            "reach must be positive"
        );
        Self {
            order,
            reach,
            adaptive: false,
        }
    }

    /// The largest `h ω_max` of one series.
    pub fn reach(&self) -> f64 {
        self.reach
    }

    /// The number of equal sub-steps a step of `h` from `state` takes.
    ///
    /// ```text
    /// n = ⌈h ω_max / reach⌉,   ω_max² = 2 (E + |W||c|) / J_min
    /// ```
    ///
    /// # Errors
    /// [`DynamicsError::TooManySubsteps`] when `n` exceeds
    /// [`crate::MAX_SUBSTEPS`] or cannot be computed.
    pub fn try_substeps(
        &self,
        top: &HeavyTop,
        state: &PrincipalState,
        h: f64,
    ) -> Result<usize, DynamicsError> {
        self.substeps_for(h, top.angular_speed_bound(state))
    }

    /// [`HeavyTopTaylor::try_substeps`] for the speed bound `omega_max`.
    fn substeps_for(&self, h: f64, omega_max: f64) -> Result<usize, DynamicsError> {
        super::auto::substep_count("taylor", h, h.abs() * omega_max / self.reach)
    }

    /// The order of one series over a sub-step with `h ω_max = x`: the
    /// fixed order, or for an adaptive series (the default) two more than
    /// the least order at which the first term left out falls below 2⁻⁵⁶,
    /// assuming the terms fall geometrically with a ratio proportional to
    /// `x` and that the full order is just enough at `x = reach`.
    ///
    /// ```text
    /// p(x) = min(p, ⌈ln ε / ln(x / ρ)⌉ + 1),   ρ = reach · ε^(−1/(p+1)),   ε = 2⁻⁵⁶
    /// ```
    /// (order 12 at `x = 0.16`, 9 at `x = 0.03` for the default).
    ///
    /// ```
    /// use kreisel_dynamics::HeavyTopTaylor;
    /// assert_eq!(HeavyTopTaylor::DEFAULT.order_for(0.8), 18);
    /// assert_eq!(HeavyTopTaylor::DEFAULT.order_for(0.156), 12);
    /// assert_eq!(HeavyTopTaylor::DEFAULT.order_for(0.03), 9);
    /// assert_eq!(HeavyTopTaylor::new(18, 0.8).order_for(0.156), 18);
    /// ```
    pub fn order_for(&self, x: f64) -> usize {
        if !self.adaptive || x.is_nan() {
            return self.order;
        }
        if x <= 0.0 {
            // No motion over the step (a top at rest at the bottom).
            return 1;
        }
        let p = self.order as f64;
        let ln_eps = NEGLIGIBLE.ln();
        let ln_rho = self.reach.ln() - ln_eps / (p + 1.0);
        let ratio = x.ln() - ln_rho;
        if ratio >= 0.0 {
            return self.order;
        }
        // Two orders above the estimate: measured on the four reference
        // tops at `x` ≈ 0.03, the estimate alone is one order short of
        // rounding level, and one more is 2× the rounding floor on the
        // asymmetric top (`tests/heavy_top_taylor.rs`).
        let needed = (ln_eps / ratio).ceil() + 1.0;
        needed.clamp(1.0, p) as usize
    }

    /// One series step of `h` and order `p` (no sub-steps).
    fn series_step(&self, top: &HeavyTop, state: &mut PrincipalState, h: f64, p: usize) {
        SCRATCH.with_borrow_mut(|s| series_in(s, top, state, h, p));
    }
}

/// [`HeavyTopTaylor::series_step`] in the scratch space `s`.
fn series_in(s: &mut Series, top: &HeavyTop, state: &mut PrincipalState, h: f64, p: usize) {
    let inverse = 1.0 / top.body().principal_moments();
    let d = DVec3::new(
        inverse.z - inverse.y,
        inverse.x - inverse.z,
        inverse.y - inverse.x,
    );
    let c = top.com_principal();
    let q0 = state.world_from_principal;
    let gamma0 = q0.normalize().conjugate() * top.weight_world();
    let x0 = [
        state.l_principal.x,
        state.l_principal.y,
        state.l_principal.z,
        gamma0.x,
        gamma0.y,
        gamma0.z,
        0.0,
        0.0,
        0.0,
        q0.w,
        q0.x,
        q0.y,
        q0.z,
    ];
    for (v, x) in s.x.iter_mut().zip(x0) {
        v[0] = x;
    }
    let inv = inverse.to_array();
    s.set_momentum(0, state.l_principal.to_array(), inv);
    for k in 0..p {
        // Coefficient k + 1 is read (times zero, in the second lane)
        // before it is set: clear what the last series left there.
        for v in s.x.iter_mut() {
            v[k + 1] = 0.0;
        }
        let acc = s.products(k);
        let r = 1.0 / (k + 1) as f64;
        let gk = [s.x[G][k], s.x[G + 1][k], s.x[G + 2][k]];
        let cg = c.cross(DVec3::from_array(gk));
        let lk = d * DVec3::new(acc[0], acc[1], acc[2]) + cg;
        s.set_momentum(k + 1, (lk * r).to_array(), inv);
        for n in 0..3 {
            s.x[G + n][k + 1] = acc[3 + n] * r;
        }
        for n in 0..4 {
            s.x[Q + n][k + 1] = acc[6 + n] * (0.5 * r);
        }
    }
    let horner = |v: &[f64; M + 1]| {
        let mut x = v[p];
        for k in (0..p).rev() {
            x = x * h + v[k];
        }
        x
    };
    state.l_principal = DVec3::new(horner(&s.x[L]), horner(&s.x[L + 1]), horner(&s.x[L + 2]));
    state.world_from_principal = DQuat::from_xyzw(
        horner(&s.x[Q + 1]),
        horner(&s.x[Q + 2]),
        horner(&s.x[Q + 3]),
        horner(&s.x[Q]),
    );
}

/// Where the components live in [`Series::x`]: `L`, `γ`, `ω`, `q` (w, x, y, z).
const L: usize = 0;
const G: usize = 3;
const W: usize = 6;
const Q: usize = 9;

impl Default for Series {
    fn default() -> Self {
        Self {
            x: [[0.0; M + 1]; 13],
            rev: [[0.0; M + 1]; 6],
        }
    }
}

impl Series {
    /// Stores the `k`-th coefficients of `L` and `ω`, forward and reversed.
    #[inline]
    fn set_momentum(&mut self, k: usize, l: [f64; 3], inverse: [f64; 3]) {
        for n in 0..3 {
            self.x[L + n][k] = l[n];
            self.x[W + n][k] = l[n] * inverse[n];
            self.rev[n][M - 1 - k] = l[n];
            self.rev[3 + n][M - 1 - k] = l[n] * inverse[n];
        }
    }

    /// The `k`-th coefficients of the ten quadratic terms: the Euler
    /// products `(L_y L_z, L_z L_x, L_x L_y)`, `γ × ω` and `q ⊗ (0, ω)`.
    ///
    /// ```text
    /// Σⱼ₌₀ᵏ aⱼ b_{k−j} = Σⱼ aⱼ b̃_{M−1−k+j},   b̃ = b reversed
    /// ```
    /// Both factors are read forward, two `j` at a time into two lanes
    /// (the compiler packs them into two-wide vector operations); the term
    /// `j = k + 1` that rounds the count up is zero (`a_{k+1}` not yet
    /// set, `b̃_M` = 0).
    #[inline]
    fn products(&self, k: usize) -> [f64; 10] {
        // Two lanes: terms j and j + 1 side by side, over k/2 + 1 pairs.
        let n = 2 * (k / 2 + 1);
        let o = M - 1 - k;
        let fwd = |c: usize| self.x[c][..n].chunks_exact(2);
        let rev = |c: usize| self.rev[c][o..o + n].chunks_exact(2);
        let pair = |a: &[f64]| [a[0], a[1]];
        // Three passes (Euler, γ × ω, q ⊗ ω), each with few enough
        // registers for its two lanes.
        let mut euler = [[0.0f64; 2]; 3];
        for (((((a, b), c), lx), ly), lz) in fwd(L)
            .zip(fwd(L + 1))
            .zip(fwd(L + 2))
            .zip(rev(0))
            .zip(rev(1))
            .zip(rev(2))
        {
            let (a, b, c) = (pair(a), pair(b), pair(c));
            let (lx, ly, lz) = (pair(lx), pair(ly), pair(lz));
            for lane in 0..2 {
                euler[0][lane] += b[lane] * lz[lane];
                euler[1][lane] += c[lane] * lx[lane];
                euler[2][lane] += a[lane] * ly[lane];
            }
        }
        let mut turn = [[0.0f64; 2]; 3];
        for (((((gx, gy), gz), wx), wy), wz) in fwd(G)
            .zip(fwd(G + 1))
            .zip(fwd(G + 2))
            .zip(rev(3))
            .zip(rev(4))
            .zip(rev(5))
        {
            let (gx, gy, gz) = (pair(gx), pair(gy), pair(gz));
            let (wx, wy, wz) = (pair(wx), pair(wy), pair(wz));
            for lane in 0..2 {
                turn[0][lane] += gy[lane] * wz[lane] - gz[lane] * wy[lane];
                turn[1][lane] += gz[lane] * wx[lane] - gx[lane] * wz[lane];
                turn[2][lane] += gx[lane] * wy[lane] - gy[lane] * wx[lane];
            }
        }
        let mut quat = [[0.0f64; 2]; 4];
        for ((((((qw, qx), qy), qz), wx), wy), wz) in fwd(Q)
            .zip(fwd(Q + 1))
            .zip(fwd(Q + 2))
            .zip(fwd(Q + 3))
            .zip(rev(3))
            .zip(rev(4))
            .zip(rev(5))
        {
            let (qw, qx, qy, qz) = (pair(qw), pair(qx), pair(qy), pair(qz));
            let (wx, wy, wz) = (pair(wx), pair(wy), pair(wz));
            for lane in 0..2 {
                quat[0][lane] -= qx[lane] * wx[lane] + qy[lane] * wy[lane] + qz[lane] * wz[lane];
                quat[1][lane] += qw[lane] * wx[lane] + qy[lane] * wz[lane] - qz[lane] * wy[lane];
                quat[2][lane] += qw[lane] * wy[lane] + qz[lane] * wx[lane] - qx[lane] * wz[lane];
                quat[3][lane] += qw[lane] * wz[lane] + qx[lane] * wy[lane] - qy[lane] * wx[lane];
            }
        }
        let sum = |a: [f64; 2]| a[0] + a[1];
        [
            sum(euler[0]),
            sum(euler[1]),
            sum(euler[2]),
            sum(turn[0]),
            sum(turn[1]),
            sum(turn[2]),
            sum(quat[0]),
            sum(quat[1]),
            sum(quat[2]),
            sum(quat[3]),
        ]
    }
}

impl HeavyTopIntegrator for HeavyTopTaylor {
    fn name(&self) -> &'static str {
        "taylor"
    }

    fn order(&self) -> u32 {
        self.order as u32
    }

    fn description(&self) -> &'static str {
        "Taylor series of the whole heavy top, sub-stepped within its reach"
    }

    /// As [`HeavyTopIntegrator::try_step`]; a step it refuses leaves a NaN
    /// state (which [`crate::DivergenceCheck`] reports).
    fn step(&self, top: &HeavyTop, state: &mut PrincipalState, h: f64) {
        if self.try_step(top, state, h).is_err() {
            *state = PrincipalState {
                world_from_principal: DQuat::NAN,
                l_principal: DVec3::NAN,
            };
        }
    }

    fn try_step(
        &self,
        top: &HeavyTop,
        state: &mut PrincipalState,
        h: f64,
    ) -> Result<(), DynamicsError> {
        let omega_max = top.angular_speed_bound(state);
        let n = self.substeps_for(h, omega_max)?;
        let sub = h / n as f64;
        let p = self.order_for(sub.abs() * omega_max);
        for _ in 0..n {
            self.series_step(top, state, sub, p);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use glam::{DQuat, DVec3};

    use super::*;
    use crate::ExactSolution;

    /// Without gravity the heavy top is a free body: the series against
    /// the exact elliptic solution (an independent closed form), at steps
    /// from a sub-step of `h |ω| = 0.8` (full order) to `0.008` (order 8 for
    /// the default), fixed-order and adaptive.
    #[test]
    fn free_body_matches_the_exact_solution() {
        let moments = DVec3::new(1.0, 1.7, 2.3);
        let top =
            HeavyTop::try_from_principal(moments, DVec3::new(0.1, 0.2, 0.3), 1.0, DVec3::ZERO)
                .unwrap();
        let start = PrincipalState {
            world_from_principal: DQuat::from_rotation_y(0.4),
            l_principal: DVec3::new(3.0, -20.0, 25.0),
        };
        let exact = ExactSolution::try_new(moments, start).unwrap();
        let omega = (start.l_principal / moments).length();
        for method in [HeavyTopTaylor::DEFAULT, HeavyTopTaylor::new(18, 0.8)] {
            for h in [0.8 / omega, 0.08 / omega, 0.008 / omega] {
                let mut s = start;
                let steps = (1.0 / h).round() as usize;
                for _ in 0..steps {
                    method.step(&top, &mut s, h);
                }
                let reference = exact.state_at(steps as f64 * h);
                let angle = kreisel_kinematics::rotation_angle_between(
                    s.world_from_principal,
                    reference.world_from_principal,
                );
                let dl = (s.l_principal - reference.l_principal).length();
                assert!(angle < 1e-12, "h {h:e}: {angle:e} rad");
                assert!(dl < 1e-12 * start.l_principal.length(), "h {h:e}: L {dl:e}");
            }
        }
    }
}
