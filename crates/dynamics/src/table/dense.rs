//! Small dense linear systems (at most 48 unknowns: 8 contacts × 6
//! directions): Gaussian elimination with partial pivoting, and with
//! complete pivoting for the singular systems of contacts that
//! overconstrain the body (a particular solution and the null space).
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

/// The pivot, relative to the largest entry, below which
/// [`solve_with_null_space`] calls a matrix rank-deficient.
pub(crate) const RANK_TOLERANCE: f64 = 1e-11;

/// The solutions of a possibly singular `a x = b` (`a` row-major `n × n`,
/// overwritten): the particular solution of least norm `x₀` and an
/// orthonormal basis of the null space, so that every solution is
/// `x₀ + Σ z_k n_k`.
///
/// ```text
/// P a Q = L U   (complete pivoting; rank r: the pivots above RANK_TOLERANCE · max |a|)
/// x₀ ⟂ null(a),   a n_k = 0,   n_j · n_k = δ_jk
/// ```
///
/// Equations dependent on the others to rounding are dropped (a least
/// residual in their direction, not a refusal). `None` when an entry is
/// not finite.
pub(crate) fn solve_with_null_space(
    a: &mut [f64],
    b: &[f64],
    n: usize,
) -> Option<(Vec<f64>, Vec<Vec<f64>>)> {
    let scale = a[..n * n].iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    if !scale.is_finite() || b[..n].iter().any(|x| !x.is_finite()) {
        return None;
    }
    let mut rhs = b[..n].to_vec();
    let mut cols: Vec<usize> = (0..n).collect();
    let mut rank = 0;
    while rank < n {
        let (mut pr, mut pc, mut best) = (rank, rank, 0.0);
        for r in rank..n {
            for c in rank..n {
                let v = a[r * n + cols[c]].abs();
                if v > best {
                    (pr, pc, best) = (r, c, v);
                }
            }
        }
        if best <= RANK_TOLERANCE * scale {
            break;
        }
        for k in 0..n {
            a.swap(rank * n + k, pr * n + k);
        }
        rhs.swap(rank, pr);
        cols.swap(rank, pc);
        let pivot = a[rank * n + cols[rank]];
        for r in rank + 1..n {
            let f = a[r * n + cols[rank]] / pivot;
            if f != 0.0 {
                for &c in &cols[rank..] {
                    a[r * n + c] -= f * a[rank * n + c];
                }
                rhs[r] -= f * rhs[rank];
            }
        }
        rank += 1;
    }
    // Back substitution of the pivot rows for the pivot columns, the free
    // columns at `free` (right-hand side `rhs`, or zero for a null vector).
    let back = |rhs: &[f64], free: &[f64]| {
        let mut x = vec![0.0; n];
        for (k, &c) in cols[rank..].iter().enumerate() {
            x[c] = free[k];
        }
        for p in (0..rank).rev() {
            let mut s = rhs[p];
            for &c in &cols[p + 1..] {
                s -= a[p * n + c] * x[c];
            }
            x[cols[p]] = s / a[p * n + cols[p]];
        }
        x
    };
    let zero = vec![0.0; n];
    let mut basis: Vec<Vec<f64>> = Vec::with_capacity(n - rank);
    for k in 0..n - rank {
        let mut unit = vec![0.0; n - rank];
        unit[k] = 1.0;
        let mut v = back(&zero, &unit);
        // Modified Gram–Schmidt, twice for orthogonality to rounding.
        for _ in 0..2 {
            for u in &basis {
                let d = dot(&v, u);
                v.iter_mut().zip(u).for_each(|(x, y)| *x -= d * y);
            }
        }
        let norm = dot(&v, &v).sqrt();
        v.iter_mut().for_each(|x| *x /= norm);
        basis.push(v);
    }
    let mut x = back(&rhs, &vec![0.0; n - rank]);
    for u in &basis {
        let d = dot(&x, u);
        x.iter_mut().zip(u).for_each(|(x, y)| *x -= d * y);
    }
    x.iter().all(|v| v.is_finite()).then_some((x, basis))
}

/// `a · b`.
pub(crate) fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
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
    fn a_singular_consistent_system_gives_its_least_norm_solution_and_null_space() {
        // x + y + z = 3, 2x + 2y + 2z = 6, x − y = 0: the solutions are
        // (1, 1, 1) + t (1, 1, −2)/√6, the least-norm one (1, 1, 1).
        let mut a = [1.0, 1.0, 1.0, 2.0, 2.0, 2.0, 1.0, -1.0, 0.0];
        let (x, null) = solve_with_null_space(&mut a, &[3.0, 6.0, 0.0], 3).unwrap();
        for v in &x {
            assert!((v - 1.0).abs() < 1e-15, "{x:?}");
        }
        assert_eq!(null.len(), 1);
        let want = [1.0, 1.0, -2.0].map(|v: f64| v / 6.0_f64.sqrt());
        let sign = null[0][0].signum();
        for (v, w) in null[0].iter().zip(want) {
            assert!((v * sign - w).abs() < 1e-15, "{null:?}");
        }
        // A regular system: the solution, no null space.
        let mut a = [0.0, 2.0, 1.0, 1.0, 1.0, 1.0, 2.0, 0.0, 3.0];
        let (x, null) = solve_with_null_space(&mut a, &[7.0, 6.0, 11.0], 3).unwrap();
        assert!(null.is_empty());
        for (v, w) in x.iter().zip([1.0, 2.0, 3.0]) {
            assert!((v - w).abs() < 1e-14, "{x:?}");
        }
    }

    #[test]
    fn a_singular_system_is_refused() {
        let mut a = [1.0, 2.0, 2.0, 4.0];
        let mut b = [1.0, 2.0];
        assert!(!solve_in_place(&mut a, &mut b, 2));
    }
}
