//! Close passes of a vertical: a turning point closer to a pole than f64
//! resolves, on a band that is not itself that small.
//!
//! A top released off the vertical with a vanishing spin (a pendulum that
//! swings almost through the bottom) turns back at `1 + u₁ ≈ (b + a)²/(2(α + β))`:
//! at ψ̇₀ = 10⁻³⁰⁰ rad/s about 10⁻⁶⁰⁰, which underflows. Where the axis passes
//! the pole, φ̇ ≈ (b + a)/(2(1 + u)) turns φ by π (sign of b + a) within a
//! time ~√((1 + u₁)/Δ)/ν, and ψ with it (ψ̇ has the same term); apart from
//! those instants the motion is that through the pole (`b + a = 0`) to
//! within √((1 + u₁)/Δ). So below `1 ± u = 10⁻²⁹⁰` with `(1 ± u)/Δ < 10⁻⁴⁰`
//! the motion is evaluated as passing through the pole, and φ, ψ step by
//! ±π at each pass instead of the through-form's `(φ + π, −θ, ψ − π)`:
//!
//! ```text
//! bottom (u₁ = −1⁺, s = sign(b + a)):  φ += sπ, ψ += sπ at each pass
//! top    (u₂ = +1⁻, s = sign(b − a)):  φ += sπ, ψ −= sπ at each pass
//! ⟨φ̇⟩ = (through-form mean) + Σ sπ/T       (one pass of each such pole per period T)
//! ```
//!
//! `Rz(φ + sπ)·Rx(−θ)·Rz(ψ ± sπ)` is the attitude `Rz(φ)·Rx(θ)·Rz(ψ)`, so the
//! attitude is the through-form's (continuous in t).

use super::EulerAnglesAndRates;
use super::motion::LagrangeTopMotion;

/// Pole distances below this are not resolved (`(b ∓ a)²` that forms
/// them is near or in the subnormal range).
pub(super) const UNRESOLVED: f64 = 1e-290;

/// A pole passed closer than f64 resolves, on a band of width `width`:
/// the step of φ then differs from a jump by less than √(distance/width).
pub(super) fn close_pass(distance: f64, b_pole: f64, through: bool, width: f64) -> bool {
    !through && b_pole != 0.0 && distance < UNRESOLVED && distance < 1e-40 * width
}

impl LagrangeTopMotion {
    /// The phase offsets (in τ) of the bottom and top turning points:
    /// `u = u_b + σΔ sn²` is `u_b` at `τ ≡ 0`, the other at `τ ≡ K (mod 2K)`.
    fn pass_offsets(&self) -> (f64, f64) {
        if self.sigma > 0.0 {
            (0.0, self.k)
        } else {
            (self.k, 0.0)
        }
    }

    /// The passes of the turning point at phase offset `off` after the
    /// start up to `t` (negative before it), and how close `τ` is to the
    /// next or last pass (in periods).
    fn passes(&self, t: f64, off: f64) -> (f64, f64) {
        let period = 2.0 * self.k;
        let x = (self.tau0 + self.nu * t - off) / period;
        let x0 = (self.tau0 - off) / period;
        let f = x - x.floor();
        (x.floor() - x0.floor(), f.min(1.0 - f))
    }

    /// The rate the passes add to the mean precession: Σ sπ/T.
    pub(super) fn pass_rate(&self) -> f64 {
        let steps = self.pass_bottom + self.pass_top;
        if steps == 0.0 {
            0.0
        } else {
            steps * std::f64::consts::PI * self.nu / (2.0 * self.k)
        }
    }

    /// φ and ψ of `e` (converted from the signed form, `flipped` when θ was
    /// mirrored back into [0, π] with `(φ + π, ψ − π)`) with the steps of
    /// the close passes up to `t` instead (module docs).
    pub(super) fn apply_passes(&self, e: &mut EulerAnglesAndRates, t: f64, flipped: bool) {
        if self.pass_bottom == 0.0 && self.pass_top == 0.0 {
            return;
        }
        let (off_b, off_t) = self.pass_offsets();
        let (mut nb, near_b) = self.passes(t, off_b);
        let (mut nt, near_t) = self.passes(t, off_t);
        if self.pass_bottom == 0.0 {
            nb = 0.0;
        }
        if self.pass_top == 0.0 {
            nt = 0.0;
        }
        // Each pass mirrors θ once: the count's parity is `flipped`, up to
        // rounding right at a pass (then the nearer pass is the one).
        if ((nb + nt).rem_euclid(2.0) == 1.0) != flipped {
            let bottom = self.pass_top == 0.0 || (self.pass_bottom != 0.0 && near_b <= near_t);
            let (n, x) = if bottom {
                (&mut nb, off_b)
            } else {
                (&mut nt, off_t)
            };
            let ahead = (self.tau0 + self.nu * t - x) / (2.0 * self.k);
            *n += if ahead - ahead.floor() > 0.5 {
                1.0
            } else {
                -1.0
            };
        }
        let pi = std::f64::consts::PI;
        let f = if flipped { 1.0 } else { 0.0 };
        let (b, tp) = (self.pass_bottom * nb, self.pass_top * nt);
        e.phi += pi * (b + tp - f);
        e.psi += pi * (b - tp + f);
    }
}
