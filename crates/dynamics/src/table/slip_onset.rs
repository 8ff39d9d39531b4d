//! The slip a closed contact starts when the force that would keep it
//! sticking lies outside the friction cone: Newton's method on the slip
//! direction.
//!
//! For one contact's block (Delassus block `G`, free rates `y⁰`, friction
//! `μ`, `n_T` friction components) slipping along the unit vector `d`:
//!
//! ```text
//! κ(d)   = G_NN − μ G_NT d                      (the normal coefficient; > 0)
//! x_N(d) = −y⁰_N / κ(d),   x_T = −μ x_N d        (y_N = 0, the friction on the cone)
//! y_T(d) = y⁰_T + x_N (G_TN − μ G_TT d)
//! solve   r(d) = y_T − (y_T·d) d = 0,   λ = y_T·d ≥ 0   (the slip accelerates along d)
//! ```
//!
//! On the sphere `|d| = 1`, in an orthonormal basis `B` of `d⊥`, the
//! Newton step `d ← (d + B u)/|d + B u|` solves
//!
//! ```text
//! (Bᵀ J B − λ 𝟙) u = −Bᵀ y_T,   J = ∂y_T/∂d = (G_TN − μ G_TT d) ⊗ (μ x_N G_NT / κ) − μ x_N G_TT
//! ```
//!
//! with a backtracking line search on `|r|`. It stops when `|r|` is at
//! the rounding of the sums that make `y_T` (a few ulps of their
//! magnitude): where a slip starts out of sticking at an event located to
//! rounding, the force that would stick lies on the cone's edge, the
//! slip's acceleration `λ` is itself at rounding and its direction
//! `y_T/|y_T|` is noise — a fixed point `d ← y_T/|y_T|` then wanders off
//! the solution it started on (measured: the thrown ellipsoid at
//! μ = 1000, `λ = 2·10⁻¹⁴` m/s² on a sum of 7 m/s², the run unsolved on
//! one grid and solved on another).

use glam::DVec3;

/// The residual `|r|`, relative to the magnitude of the sums that make
/// `y_T`, at which the direction is solved (a few ulps).
const ROUNDING: f64 = 64.0 * f64::EPSILON;

/// The residual, relative as [`ROUNDING`], accepted when Newton's steps no
/// longer decrease it (the sticking check's relative tolerance).
const STAGNATION: f64 = 1e-12;

/// The most Newton steps (quadratic convergence takes a handful).
const MAX_NEWTON: usize = 60;

/// The most halvings of a Newton step in the line search.
const MAX_HALVINGS: usize = 40;

/// A block slipping along one direction: the unknowns and the rates.
#[derive(Debug, Clone, Copy)]
struct Along {
    d: DVec3,
    kappa: f64,
    x_n: f64,
    /// `y_T(d)`.
    y_t: DVec3,
    /// The magnitude of the sums that make `y_T` (their largest
    /// component-wise sum of absolute terms).
    scale: f64,
}

impl Along {
    /// `λ = y_T·d`.
    fn lambda(&self) -> f64 {
        self.y_t.dot(self.d)
    }

    /// `|r| = |y_T − λ d|`.
    fn residual(&self) -> f64 {
        (self.y_t - self.lambda() * self.d).length()
    }
}

/// The block slipping along `d` (unit, `nf` components): `None` when
/// `κ(d)` is not positive (no normal force holds that slip: Painlevé).
fn along(g: &[[f64; 4]; 4], y0: &[f64; 4], nf: usize, mu: f64, d: DVec3) -> Option<Along> {
    let mut kappa = g[0][0];
    for c in 0..nf {
        kappa -= mu * g[0][1 + c] * d[c];
    }
    if kappa.is_nan() || kappa <= 0.0 {
        return None;
    }
    let x_n = -y0[0] / kappa;
    let mut y_t = DVec3::ZERO;
    let mut scale: f64 = 0.0;
    for c in 0..nf {
        let mut v = y0[1 + c] + g[1 + c][0] * x_n;
        let mut size = y0[1 + c].abs() + (g[1 + c][0] * x_n).abs();
        for k in 0..nf {
            let term = mu * x_n * g[1 + c][1 + k] * d[k];
            v -= term;
            size += term.abs();
        }
        y_t[c] = v;
        scale = scale.max(size);
    }
    Some(Along {
        d,
        kappa,
        x_n,
        y_t,
        scale,
    })
}

/// An orthonormal basis of the directions tangent to the unit sphere of
/// `nf` components at `d` (`nf − 1` vectors; the third component stays 0
/// for `nf = 2`).
fn tangent_basis(d: DVec3, nf: usize) -> [DVec3; 2] {
    if nf == 2 {
        [DVec3::new(-d.y, d.x, 0.0), DVec3::ZERO]
    } else {
        let (a, b) = d.any_orthonormal_pair();
        [a, b]
    }
}

/// The Newton step `B u` at `s` (`None` where its system is singular).
fn newton_step(g: &[[f64; 4]; 4], nf: usize, mu: f64, s: &Along) -> Option<DVec3> {
    // J = a ⊗ b − μ x_N G_TT.
    let mut a = DVec3::ZERO;
    let mut b = DVec3::ZERO;
    for c in 0..nf {
        a[c] = g[1 + c][0];
        for k in 0..nf {
            a[c] -= mu * g[1 + c][1 + k] * s.d[k];
        }
        b[c] = mu * s.x_n * g[0][1 + c] / s.kappa;
    }
    let j = |v: DVec3| {
        let mut out = a * b.dot(v);
        for c in 0..nf {
            for k in 0..nf {
                out[c] -= mu * s.x_n * g[1 + c][1 + k] * v[k];
            }
        }
        out
    };
    let basis = tangent_basis(s.d, nf);
    let lambda = s.lambda();
    let m = nf - 1;
    // M = Bᵀ J B − λ 𝟙, rhs = −Bᵀ y_T (at most 2 × 2).
    let mut mat = [[0.0; 2]; 2];
    let mut rhs = [0.0; 2];
    for (p, bp) in basis.iter().enumerate().take(m) {
        for (q, bq) in basis.iter().enumerate().take(m) {
            mat[p][q] = bp.dot(j(*bq)) - if p == q { lambda } else { 0.0 };
        }
        rhs[p] = -bp.dot(s.y_t);
    }
    let u = if m == 1 {
        [rhs[0] / mat[0][0], 0.0]
    } else {
        let det = mat[0][0] * mat[1][1] - mat[0][1] * mat[1][0];
        [
            (rhs[0] * mat[1][1] - mat[0][1] * rhs[1]) / det,
            (mat[0][0] * rhs[1] - mat[1][0] * rhs[0]) / det,
        ]
    };
    let step = basis[0] * u[0] + basis[1] * u[1];
    step.is_finite().then_some(step)
}

/// The slip a sticking block starts: the unknowns `x = (x_N, −μ x_N d)`
/// of the direction `d` solved from `start` (the direction opposite the
/// force that would stick), or `None` when Newton's method does not reach
/// a slip with `x_N > 0` and `λ ≥ 0` (the caller falls back on slower
/// iterations).
///
/// `g` is the block's Delassus matrix, `y0` its free rates with
/// `y⁰_N < 0` (the contact pressed), `n = 1 + n_T` its size.
pub(crate) fn slip_onset(
    g: &[[f64; 4]; 4],
    y0: &[f64; 4],
    n: usize,
    mu: f64,
    start: DVec3,
) -> Option<[f64; 4]> {
    let nf = n - 1;
    if !(y0[0] < 0.0 && (2..=3).contains(&nf) && mu > 0.0) {
        return None;
    }
    let mut s = along(g, y0, nf, mu, start.normalize_or_zero())?;
    let mut solved = false;
    for _ in 0..MAX_NEWTON {
        let r = s.residual();
        if r <= ROUNDING * s.scale {
            solved = true;
            break;
        }
        let step = newton_step(g, nf, mu, &s)?;
        let mut t = 1.0;
        let mut next = None;
        for _ in 0..MAX_HALVINGS {
            let d = (s.d + step * t).normalize_or_zero();
            if let Some(trial) = along(g, y0, nf, mu, d)
                && trial.residual() < r
            {
                next = Some(trial);
                break;
            }
            t *= 0.5;
        }
        match next {
            Some(trial) => s = trial,
            None => {
                // No step decreases the residual: rounding, if it is small.
                solved = r <= STAGNATION * s.scale;
                break;
            }
        }
    }
    let valid = solved && s.x_n > 0.0 && s.lambda() >= -STAGNATION * s.scale;
    if !valid {
        return None;
    }
    let mut x = [0.0; 4];
    x[0] = s.x_n;
    for c in 0..nf {
        x[1 + c] = -mu * s.x_n * s.d[c];
    }
    Some(x)
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// The block of the thrown ellipsoid (semi-axes 6, 4, 1.5 cm, 0.3 kg,
    /// μ = 1000) at the event where its sticking force reaches the cone
    /// (t = 0.14518 s; dumped from the run): the force that would stick
    /// lies outside the cone by 3.7·10⁻¹² of `μ N`.
    pub(crate) fn ellipsoid_at_the_cone() -> ([[f64; 4]; 4], [f64; 4]) {
        let g = [
            [
                6.5872222260761095,
                5.5230587472126915,
                -2.3770112563911394,
                0.0,
            ],
            [
                5.5230587472126915,
                13.358759403744909,
                -1.374510163028987,
                0.0,
            ],
            [
                -2.3770112563911403,
                -1.3745101630289887,
                15.94420614773313,
                0.0,
            ],
            [0.0; 4],
        ];
        let y0 = [
            -2.3670111847511457,
            -6.226417129013562,
            -1.1876331412243117,
            0.0,
        ];
        (g, y0)
    }

    /// `y = y0 + G x` of a 3-component block.
    fn rates(g: &[[f64; 4]; 4], y0: &[f64; 4], x: &[f64; 4]) -> [f64; 3] {
        let mut y = [0.0; 3];
        for (r, v) in y.iter_mut().enumerate() {
            *v = y0[r] + (0..3).map(|k| g[r][k] * x[k]).sum::<f64>();
        }
        y
    }

    #[test]
    fn a_slip_starting_on_the_cone_edge_keeps_the_direction_it_starts_along() {
        // The slip's acceleration is at rounding there (λ ≈ 2e-14 m/s²):
        // the force is the sticking one, on the cone's edge. An
        // independent check: the sticking force by Cramer's rule.
        let (g, y0) = ellipsoid_at_the_cone();
        let m = |r: usize, c: usize| g[r][c];
        let det = m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1))
            - m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0))
            + m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
        let cramer = |col: usize| {
            let a = |r: usize, c: usize| if c == col { -y0[r] } else { g[r][c] };
            (a(0, 0) * (a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1))
                - a(0, 1) * (a(1, 0) * a(2, 2) - a(1, 2) * a(2, 0))
                + a(0, 2) * (a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0)))
                / det
        };
        let stick = [cramer(0), cramer(1), cramer(2)];
        let t = DVec3::new(stick[1], stick[2], 0.0);
        assert!((t.length() / (1000.0 * stick[0]) - 1.0).abs() < 1e-10);
        let x = slip_onset(&g, &y0, 3, 1000.0, -t.normalize()).unwrap();
        for k in 0..3 {
            assert!(
                (x[k] - stick[k]).abs() < 1e-9 * stick[k].abs(),
                "{x:?} vs {stick:?}"
            );
        }
        // On the cone, y_N = 0, the slip's acceleration at rounding.
        let y = rates(&g, &y0, &x);
        assert!(y[0].abs() < 1e-13 && y[1].hypot(y[2]) < 1e-12, "{y:?}");
    }

    #[test]
    fn a_start_off_the_slip_reaches_it() {
        // From starts 0.6 rad either side (κ > 0 there), Newton's steps
        // reach the same slip: the block has one valid slip among the four
        // roots of its direction equation (a trigonometric polynomial of
        // degree 2; the roots found by a scan of 200 000 angles and
        // bisection: 0.2373, 1.2927, 3.3793, 4.4355 rad, the others with
        // x_N < 0 or λ < 0).
        let (g, y0) = ellipsoid_at_the_cone();
        for off in [-0.6, 0.6] {
            let theta: f64 = 3.379_270_257_524 + off;
            let start = DVec3::new(theta.cos(), theta.sin(), 0.0);
            let x = slip_onset(&g, &y0, 3, 1000.0, start).unwrap();
            let d = DVec3::new(-x[1], -x[2], 0.0).normalize();
            let angle = d.y.atan2(d.x).rem_euclid(std::f64::consts::TAU);
            assert!((angle - 3.379_270_257_524).abs() < 1e-9, "{angle}");
        }
    }

    #[test]
    fn a_point_mass_slips_against_its_pull() {
        // G = 𝟙/m (m = 0.5 kg): pressed at 10 m/s², pulled at (3, 4) m/s²
        // with μ = 0.2: N = 5 N, the friction μ N = 1 N against the pull,
        // the slip accelerating at 5 − 2 · 1 = 3 m/s².
        let mut g = [[0.0; 4]; 4];
        for (k, row) in g.iter_mut().enumerate().take(3) {
            row[k] = 2.0;
        }
        let y0 = [-10.0, 3.0, 4.0, 0.0];
        let x = slip_onset(&g, &y0, 3, 0.2, DVec3::new(0.0, 1.0, 0.0)).unwrap();
        assert!((x[0] - 5.0).abs() < 1e-14);
        assert!(
            (x[1] + 0.6).abs() < 1e-14 && (x[2] + 0.8).abs() < 1e-14,
            "{x:?}"
        );
        let y = rates(&g, &y0, &x);
        assert!((y[1] - 1.8).abs() < 1e-14 && (y[2] - 2.4).abs() < 1e-14);
    }
}
