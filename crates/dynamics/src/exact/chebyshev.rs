//! Piecewise Chebyshev interpolants of four functions at once on `[0, end]`,
//! fitted adaptively to rounding level: how the exact solution tabulates
//! sn, cn, dn and the periodic part of the precession angle over a quarter
//! period once, so that each evaluation is a search and a Clenshaw sum.
//!
//! ```text
//! on a piece [a, b]:  x = (2τ − a − b)/(b − a),  f(τ) ≈ Σₖ cₖ Tₖ(x),  k < N
//! cₖ = (2 − δₖ₀)/N Σⱼ f(τⱼ) cos(πk(j + ½)/N),   xⱼ = cos(π(j + ½)/N)
//! a piece is split in two while its last two coefficients exceed TOLERANCE
//! ```
//!
//! Trefethen, *Approximation Theory and Approximation Practice* (SIAM 2013),
//! chapters 3, 8 and 19: on a piece of half-width w at distance d from the
//! nearest singularity the coefficients decay like ρ⁻ᵏ, ρ = d/w + √(d²/w² + 1).

use glam::DVec4;

/// Coefficients per piece (degree N − 1).
const N: usize = 16;

/// Largest trailing coefficient accepted, for values of magnitude ≤ 1 (sn,
/// cn, dn and the precession integrand). The rounding in the node values
/// and the sums puts a floor of ~7e-16 under the computed coefficients
/// (measured: it does not fall when a converged piece is halved), so the
/// test sits above it; a piece that passes has a true tail ≤ 1e-16, since
/// the coefficients of these analytic functions fall by ~10³ per halving.
const TOLERANCE: f64 = 2e-15;

/// Pieces are not split below this fraction of the interval (a safeguard
/// against rounding noise that never drops below the tolerance).
const MIN_FRACTION: f64 = 1.0 / 65536.0;

/// Four functions tabulated as piecewise Chebyshev series on `[0, end]`.
#[derive(Clone, Debug)]
pub(crate) struct PiecewiseChebyshev {
    /// Piece boundaries, ascending, from 0 to `end` (one more than pieces).
    breaks: Vec<f64>,
    /// Coefficients `c₀ … c_{N−1}` of each piece, one lane per function.
    coefficients: Vec<[DVec4; N]>,
    /// Centre and inverse half-width of each piece.
    centre: Vec<(f64, f64)>,
    /// The first piece of each cell of a uniform grid of the smallest piece
    /// width: a lookup and at most one comparison find a piece, with no
    /// search (the pieces are adaptive, the grid is not).
    grid: Vec<u32>,
    /// Cells per unit of τ.
    cells_per_unit: f64,
}

impl PiecewiseChebyshev {
    /// Fits `f` on `[0, end]` with pieces split until converged.
    pub(crate) fn fit(end: f64, f: impl Fn(f64) -> DVec4) -> PiecewiseChebyshev {
        let nodes: [f64; N] =
            std::array::from_fn(|j| (std::f64::consts::PI * (j as f64 + 0.5) / N as f64).cos());
        // cos(πk(j + ½)/N), scaled by 1/N (k = 0) or 2/N: the transform's matrix.
        let transform: [[f64; N]; N] = std::array::from_fn(|k| {
            let scale = if k == 0 { 1.0 } else { 2.0 } / N as f64;
            std::array::from_fn(|j| {
                scale * (std::f64::consts::PI * (k * (2 * j + 1)) as f64 / (2 * N) as f64).cos()
            })
        });
        let mut table = PiecewiseChebyshev {
            breaks: vec![0.0],
            coefficients: Vec::new(),
            centre: Vec::new(),
            grid: Vec::new(),
            cells_per_unit: 0.0,
        };
        // Depth-first over [a, b] keeps the pieces in ascending order.
        let mut stack = vec![(0.0, end)];
        while let Some((a, b)) = stack.pop() {
            let c = fit_piece(a, b, &nodes, &transform, &f);
            let tail = c[N - 1].abs().max(c[N - 2].abs()).max_element();
            if tail > TOLERANCE && b - a > end * MIN_FRACTION {
                let mid = 0.5 * (a + b);
                stack.push((mid, b));
                stack.push((a, mid));
            } else {
                table.breaks.push(b);
                table.coefficients.push(c);
                table.centre.push((0.5 * (a + b), 2.0 / (b - a)));
            }
        }
        table.index();
        table
    }

    /// Builds the uniform grid over the pieces.
    fn index(&mut self) {
        let end = self.breaks[self.breaks.len() - 1];
        let smallest = self
            .breaks
            .windows(2)
            .map(|ab| ab[1] - ab[0])
            .fold(f64::INFINITY, f64::min);
        // Bisection makes every width end·2⁻ʲ: `end/smallest` cells of the
        // smallest width tile [0, end] (at most 1/MIN_FRACTION of them).
        let cells = (end / smallest).round().max(1.0) as usize;
        self.cells_per_unit = cells as f64 / end;
        let mut piece = 0;
        self.grid = (0..cells)
            .map(|cell| {
                let start = cell as f64 / self.cells_per_unit;
                while piece + 1 < self.coefficients.len() && self.breaks[piece + 1] <= start {
                    piece += 1;
                }
                piece as u32
            })
            .collect();
    }

    /// The number of pieces.
    pub(crate) fn pieces(&self) -> usize {
        self.coefficients.len()
    }

    /// Replaces lane `lane` by the periodic part of its antiderivative and
    /// returns the mean of the original function over `[0, end]`.
    ///
    /// ```text
    /// f̄ = (1/end) ∫₀^end f,   P(τ) = ∫₀^τ (f − f̄),   P(0) = P(end) = 0
    /// on a piece: ∫ Σ cₖ Tₖ dx = Σ Cₖ Tₖ,  Cₖ = (c′ₖ₋₁ − cₖ₊₁)/(2k),  c′₀ = 2c₀
    /// ```
    pub(crate) fn integrate_lane(&mut self, lane: usize) -> f64 {
        let end = *self.breaks.last().unwrap_or(&0.0);
        // ∫₋₁¹ Tₖ = 2/(1 − k²) for even k, 0 for odd k.
        let piece_integral = |c: &[DVec4; N], half_width: f64| {
            half_width
                * (0..N)
                    .step_by(2)
                    .map(|k| c[k][lane] * 2.0 / (1.0 - (k * k) as f64))
                    .sum::<f64>()
        };
        let total: f64 = self
            .coefficients
            .iter()
            .zip(self.breaks.windows(2))
            .map(|(c, ab)| piece_integral(c, 0.5 * (ab[1] - ab[0])))
            .sum();
        let mean = if end > 0.0 { total / end } else { 0.0 };
        let mut offset = 0.0;
        for (c, ab) in self.coefficients.iter_mut().zip(self.breaks.windows(2)) {
            let half_width = 0.5 * (ab[1] - ab[0]);
            let f: [f64; N] = std::array::from_fn(|k| c[k][lane] - if k == 0 { mean } else { 0.0 });
            let coefficient = |k: usize| match k {
                0 => 2.0 * f[0],
                k if k < N => f[k],
                _ => 0.0,
            };
            let mut integral = [0.0; N];
            for (k, value) in integral.iter_mut().enumerate().skip(1) {
                *value = half_width * (coefficient(k - 1) - coefficient(k + 1)) / (2 * k) as f64;
            }
            // The antiderivative is `offset` at the piece's left end (x = −1).
            let at_left: f64 = (1..N)
                .map(|k| {
                    if k % 2 == 0 {
                        integral[k]
                    } else {
                        -integral[k]
                    }
                })
                .sum();
            integral[0] = offset - at_left;
            offset = integral[0] + integral[1..].iter().sum::<f64>();
            for (k, value) in integral.iter().enumerate() {
                c[k][lane] = *value;
            }
        }
        mean
    }

    /// The four functions at `tau` (clamped into `[0, end]`).
    #[inline]
    pub(crate) fn eval(&self, tau: f64) -> DVec4 {
        let last = self.coefficients.len() - 1;
        let cell = ((tau * self.cells_per_unit) as usize).min(self.grid.len() - 1);
        let mut piece = self.grid[cell] as usize;
        if piece < last && self.breaks[piece + 1] <= tau {
            piece += 1;
        }
        let (centre, inverse_half_width) = self.centre[piece];
        let x = ((tau - centre) * inverse_half_width).clamp(-1.0, 1.0);
        clenshaw(&self.coefficients[piece], x)
    }
}

/// Chebyshev coefficients of `f` on `[a, b]` from its values at the nodes.
fn fit_piece(
    a: f64,
    b: f64,
    nodes: &[f64; N],
    transform: &[[f64; N]; N],
    f: &impl Fn(f64) -> DVec4,
) -> [DVec4; N] {
    let values: [DVec4; N] = std::array::from_fn(|j| f(0.5 * (a + b) + 0.5 * (b - a) * nodes[j]));
    std::array::from_fn(|k| {
        values
            .iter()
            .zip(&transform[k])
            .fold(DVec4::ZERO, |acc, (v, w)| acc + *v * *w)
    })
}

/// Clenshaw's recurrence for `Σ cₖ Tₖ(x)`.
///
/// ```text
/// bₖ = cₖ + 2x bₖ₊₁ − bₖ₊₂,   f = c₀ + x b₁ − b₂
/// ```
#[inline]
fn clenshaw(c: &[DVec4; N], x: f64) -> DVec4 {
    let two_x = DVec4::splat(2.0 * x);
    let (mut b1, mut b2) = (DVec4::ZERO, DVec4::ZERO);
    for ck in c[1..].iter().rev() {
        let b0 = two_x * b1 + (*ck - b2);
        b2 = b1;
        b1 = b0;
    }
    DVec4::splat(x) * b1 + (c[0] - b2)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// sin, cos, exp, 1/(2 + cos) on [0, 5]: the fit reproduces them to rounding,
    /// and the antiderivative's periodic part matches the closed form.
    #[test]
    fn fits_and_integrates_to_rounding() {
        let f = |t: f64| DVec4::new(t.sin(), t.cos(), (-t).exp(), 1.0 / (2.0 + t.cos()));
        let mut table = PiecewiseChebyshev::fit(5.0, f);
        assert!(
            table.pieces() >= 2 && table.pieces() <= 16,
            "{}",
            table.pieces()
        );
        for k in 0..=1000 {
            let t = 5.0 * f64::from(k) / 1000.0;
            let err = (table.eval(t) - f(t)).abs().max_element();
            // Accepted pieces have trailing coefficients ≤ 2e-15; the
            // dropped tail of a geometric series adds about as much again.
            assert!(err < 5e-15, "t = {t}: {err:e}");
        }
        // ∫₀^τ cos = sin τ; mean over [0, 5] is sin 5 / 5.
        let mean = table.integrate_lane(1);
        assert!((mean - 5.0f64.sin() / 5.0).abs() < 1e-16);
        for k in 0..=100 {
            let t = 5.0 * f64::from(k) / 100.0;
            let p = t.sin() - mean * t;
            assert!((table.eval(t).y - p).abs() < 3e-15, "t = {t}");
        }
        // The other lanes are untouched.
        assert!((table.eval(1.0).x - 1.0f64.sin()).abs() < 5e-15);
    }

    /// A periodic integrand over whole periods: the mean is the closed form
    /// 1/√3 of 1/(2 + cos) and P returns to 0 at the end.
    #[test]
    fn mean_of_a_periodic_integrand() {
        let two_pi = 2.0 * std::f64::consts::PI;
        let mut table = PiecewiseChebyshev::fit(two_pi, |t| DVec4::splat(1.0 / (2.0 + t.cos())));
        let mean = table.integrate_lane(3);
        assert!((mean - 1.0 / 3.0f64.sqrt()).abs() < 2.5e-16, "{mean}");
        assert!(table.eval(two_pi).w.abs() < 1e-15);
    }
}
