//! The turning points of the nutation: the roots of the cubic `f(u)`,
//! found relative to the initial `u₀ = cos θ₀` without cancellation.
//!
//! With `w = u − u₀` the cubic of notes §3.10 reads
//!
//! ```text
//! f(u₀ + w) = β w³ + c₂ w² + c₁ w + c₀
//! c₀ = sin²θ₀ θ̇₀²  (= u̇₀², exactly: no cancellation of α − βu₀ against (b − au₀)²)
//! c₁ = −β sin²θ₀ − 2u₀ A₀ + 2a B₀,   c₂ = 2u₀ β − A₀ − a²
//! A₀ = θ̇₀² + sin²θ₀ φ̇₀² (= α − βu₀),  B₀ = sin²θ₀ φ̇₀ (= b − a u₀)
//! ```
//!
//! When `c₀ = 0` (released with θ̇₀ = 0, or at the vertical) `w = 0` is an
//! exact root; it is divided out and the remaining quadratic
//! `β w² + c₂ w + c₁` is solved by the cancellation-free formula. Otherwise
//! the two turning points are bracketed, `w₁ ∈ [−1 − u₀, 0)` and
//! `w₂ ∈ (0, 1 − u₀]` (since `f(u₀) = u̇₀² > 0` and `f(±1) = −(b ∓ a)² ≤ 0`),
//! and found by safeguarded Newton iteration; the third root follows from
//! Vieta, `β w₃ = −c₀ / (w₁ w₂)`. Either way the factorisation
//!
//! ```text
//! f(u₀ + w) = (w − w₁)(w − w₂)(β w − g),   g = β w₃  (g = −c₂ when β = 0)
//! ```
//!
//! is known with `w₁ ≤ 0 ≤ w₂`, `g` finite also for `β → 0`, and
//! `u₂ − u₁ = w₂ − w₁` formed without cancellation.

/// The roots of `f` relative to `u₀`, see the module docs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct TurningPoints {
    /// `u₁ − u₀ ≤ 0` (lower turning point, largest θ).
    pub w1: f64,
    /// `u₂ − u₀ ≥ 0` (upper turning point, smallest θ).
    pub w2: f64,
    /// `β u₃ − β u₀` (finite for β → 0; `−c₂` for β = 0).
    pub g: f64,
}

/// Coefficients of `f(u₀ + w)` in powers of `w` (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ShiftedCubic {
    pub beta: f64,
    pub c2: f64,
    pub c1: f64,
    pub c0: f64,
}

impl ShiftedCubic {
    /// `f(u₀ + w)` and its derivative (Horner).
    pub fn eval(&self, w: f64) -> (f64, f64) {
        let f = ((self.beta * w + self.c2) * w + self.c1) * w + self.c0;
        let d = (3.0 * self.beta * w + 2.0 * self.c2) * w + self.c1;
        (f, d)
    }

    /// The turning points and the third root (module docs).
    pub fn turning_points(&self, one_plus_u0: f64, one_minus_u0: f64) -> TurningPoints {
        if self.c0 > 0.0 {
            let w1 = bracketed_root(self, -one_plus_u0, 0.0, true);
            let w2 = bracketed_root(self, 0.0, one_minus_u0, false);
            let g = -self.c0 / (w1 * w2);
            return TurningPoints { w1, w2, g };
        }
        // w = 0 is a root: divide it out, β w² + c₂ w + c₁ = 0.
        let (beta, c2, c1) = (self.beta, self.c2, self.c1);
        if beta == 0.0 {
            let r = if c2 == 0.0 { 0.0 } else { -c1 / c2 };
            let (w1, w2) = if r < 0.0 { (r, 0.0) } else { (0.0, r) };
            return TurningPoints {
                w1: w1.max(-one_plus_u0),
                w2: w2.min(one_minus_u0),
                g: -c2,
            };
        }
        // Scaled by a power of two near the largest coefficient (exact), so
        // that c₂² and β c₁ neither overflow nor underflow for any scale of
        // the top (β up to ~1e308).
        let scale = 2f64.powi(beta.abs().max(c2.abs()).max(c1.abs()).log2().floor() as i32);
        let (sb, s2, s1) = (beta / scale, c2 / scale, c1 / scale);
        let disc = (s2 * s2 - 4.0 * sb * s1).max(0.0);
        let q = -0.5 * (s2 + s2.signum() * disc.sqrt());
        if q == 0.0 {
            return TurningPoints {
                w1: 0.0,
                w2: 0.0,
                g: 0.0,
            };
        }
        // (root, β·root) pairs, β·root formed without dividing by a small β.
        let big = (q / sb, q * scale);
        let small = (s1 / q, beta * (s1 / q));
        let zero = (0.0, 0.0);
        let mut all = [big, small, zero];
        all.sort_by(|x, y| x.0.total_cmp(&y.0));
        let (w1, w2, w3) = if beta > 0.0 {
            (all[0], all[1], all[2])
        } else {
            (all[1], all[2], all[0])
        };
        TurningPoints {
            w1: w1.0.max(-one_plus_u0),
            w2: w2.0.min(one_minus_u0),
            g: w3.1,
        }
    }
}

/// The distance `v ≥ 0` of a turning point from the pole `u = ±1`, polished
/// by Newton's method on `f` written about that pole, so that `v` keeps
/// its relative accuracy when the axis comes close to the vertical:
///
/// ```text
/// f(±(1 − v)) = v (2 − v) (α ∓ β ± β v) − ((b ∓ a) ± a v)²
/// ```
///
/// `alpha_pole = α ∓ β` and `b_pole = b ∓ a` must be formed without
/// cancellation by the caller; `a_signed = ±a`, `beta_signed = ±β`. Starts
/// from `v0` (the value from the roots about `u₀`) and keeps it unless
/// Newton converges nearby.
pub(crate) fn polish_pole_distance(
    v0: f64,
    alpha_pole: f64,
    beta_signed: f64,
    b_pole: f64,
    a_signed: f64,
) -> f64 {
    if !(v0 > 0.0 && v0 < 0.25) {
        return v0;
    }
    let eval = |v: f64| {
        let q = alpha_pole + beta_signed * v;
        let r = b_pole + a_signed * v;
        let f = v * (2.0 - v) * q - r * r;
        let d = (2.0 - 2.0 * v) * q + v * (2.0 - v) * beta_signed - 2.0 * a_signed * r;
        (f, d)
    };
    let mut v = v0;
    for _ in 0..8 {
        let (f, d) = eval(v);
        if d == 0.0 || !f.is_finite() {
            return v0;
        }
        let next = v - f / d;
        if next.is_nan() || next <= 0.0 || (next - v0).abs() > 1e-3 * v0 {
            return v0;
        }
        if next == v {
            break;
        }
        v = next;
    }
    v
}

/// The turning point in `[lo, hi]`, where `f(lo) ≤ 0 < f(hi)` (`rising`,
/// the end `hi = 0` is `u₀`) or `f(lo) > 0 ≥ f(hi)`: Newton steps kept
/// inside the shrinking bracket, bisection when a step leaves it, until the
/// iterate stops moving.
///
/// The other end is a pole `u = ±1`, where `f = −(b ∓ a)²` may be 0 (or
/// rounded to ≥ 0). The pole is the turning point itself only if `f` has
/// the sign of the motion next to it; if `f` dips below 0 there (the pole
/// is the third root, e.g. `b = a = 0` with too little energy to reach the
/// top), the turning point is inside and the bisection finds it.
fn bracketed_root(cubic: &ShiftedCubic, lo: f64, hi: f64, rising: bool) -> f64 {
    if rising {
        let (flo, dlo) = cubic.eval(lo);
        if flo >= 0.0 && dlo >= 0.0 {
            return lo;
        }
    } else {
        let (fhi, dhi) = cubic.eval(hi);
        if fhi >= 0.0 && dhi <= 0.0 {
            return hi;
        }
    }
    let (mut a, mut b) = (lo, hi);
    let mut x = 0.5 * (lo + hi);
    for _ in 0..200 {
        let (f, d) = cubic.eval(x);
        if f == 0.0 {
            return x;
        }
        if (f < 0.0) == rising {
            a = x;
        } else {
            b = x;
        }
        let newton = x - f / d;
        let next = if d != 0.0 && newton > a.min(b) && newton < a.max(b) {
            newton
        } else {
            0.5 * (a + b)
        };
        if next == x || (b - a).abs() <= f64::EPSILON * x.abs() {
            return next;
        }
        x = next;
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roots_of_a_known_cubic() {
        // f = 2 (w + 0.5)(w − 0.25)(w − 3): c₀ = 0.75 > 0.
        let cubic = ShiftedCubic {
            beta: 2.0,
            c2: -2.0 * 2.75,
            c1: 2.0 * (-0.125 - 1.5 + 0.75),
            c0: 2.0 * 0.375,
        };
        let tp = cubic.turning_points(0.8, 0.4);
        assert!((tp.w1 + 0.5).abs() < 1e-16);
        assert!((tp.w2 - 0.25).abs() < 1e-16);
        assert!((tp.g - 6.0).abs() < 1e-14);
    }

    #[test]
    fn exact_root_divided_out() {
        // f = w (w + 0.5)(w − 3) = w³ − 2.5 w² − 1.5 w, β = 1.
        let cubic = ShiftedCubic {
            beta: 1.0,
            c2: -2.5,
            c1: -1.5,
            c0: 0.0,
        };
        let tp = cubic.turning_points(0.8, 0.4);
        assert_eq!((tp.w1, tp.w2), (-0.5, 0.0));
        assert!((tp.g - 3.0).abs() < 1e-15);
        // β < 0: f = −w (w − 0.2)(w + 3): turning points 0, 0.2; β w₃ = 3.
        let cubic = ShiftedCubic {
            beta: -1.0,
            c2: -2.8,
            c1: 0.6,
            c0: 0.0,
        };
        let tp = cubic.turning_points(0.8, 0.4);
        assert_eq!(tp.w1, 0.0);
        assert!((tp.w2 - 0.2).abs() < 1e-16);
        assert!((tp.g - 3.0).abs() < 1e-15);
    }
}
