//! Small dense linear systems (at most 32 unknowns: 8 contacts × 4
//! directions), Gaussian elimination with partial pivoting.
//!
//! Hand-written rather than nalgebra: the systems are tiny, built fresh in
//! every right-hand side of the integrator, and the engine keeps nalgebra
//! out of `kreisel-dynamics` (its boundary is the kinematics crate's
//! optional feature).

/// Solves `a x = b` in place (`a` row-major `n × n`, `b` becomes `x`).
/// Returns `false` when a pivot is zero or not finite relative to the
/// largest entry of its column (the matrix is singular to rounding).
pub(crate) fn solve_in_place(a: &mut [f64], b: &mut [f64], n: usize) -> bool {
    debug_assert!(a.len() >= n * n && b.len() >= n);
    let scale = a[..n * n].iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    if !(scale.is_finite() && scale > 0.0) {
        return n == 0;
    }
    for col in 0..n {
        let pivot_row = (col..n)
            .max_by(|&r, &s| a[r * n + col].abs().total_cmp(&a[s * n + col].abs()))
            .unwrap_or(col);
        let pivot = a[pivot_row * n + col];
        if pivot.is_nan() || pivot.abs() <= 1e-14 * scale {
            return false;
        }
        if pivot_row != col {
            for k in 0..n {
                a.swap(col * n + k, pivot_row * n + k);
            }
            b.swap(col, pivot_row);
        }
        for r in col + 1..n {
            let f = a[r * n + col] / pivot;
            if f != 0.0 {
                for k in col..n {
                    a[r * n + k] -= f * a[col * n + k];
                }
                b[r] -= f * b[col];
            }
        }
    }
    for col in (0..n).rev() {
        let mut s = b[col];
        for k in col + 1..n {
            s -= a[col * n + k] * b[k];
        }
        b[col] = s / a[col * n + col];
    }
    b[..n].iter().all(|x| x.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_system_that_needs_pivoting() {
        // x = (1, 2, 3): the first pivot is zero without row exchange.
        let mut a = [0.0, 2.0, 1.0, 1.0, 1.0, 1.0, 2.0, 0.0, 3.0];
        let mut b = [7.0, 6.0, 11.0];
        assert!(solve_in_place(&mut a, &mut b, 3));
        for (x, want) in b.iter().zip([1.0, 2.0, 3.0]) {
            assert!((x - want).abs() < 1e-15, "{x} vs {want}");
        }
    }

    #[test]
    fn a_singular_system_is_refused() {
        let mut a = [1.0, 2.0, 2.0, 4.0];
        let mut b = [1.0, 2.0];
        assert!(!solve_in_place(&mut a, &mut b, 2));
    }
}
