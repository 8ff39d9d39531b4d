//! The eigenvalues of a real matrix by the Francis double-shift QR
//! iteration on its Hessenberg form, with the exceptional shifts of
//! EISPACK's `hqr` (Martin, Peters & Wilkinson, *Numer. Math.* 14:219
//! (1970); Wilkinson & Reinsch, *Handbook for Automatic Computation II*,
//! contribution II/14).
//!
//! Why not nalgebra's `Schur`: measured, nalgebra 0.35's real Schur form
//! does not converge on the sleeping top's reduced 4×4 Jacobian below its
//! threshold (`Schur::try_new(B, ε, 10 000)` returns `None`; `Schur::new`
//! never returns): its iteration has no exceptional shift, and the
//! Hamiltonian spectrum `±σ ± iω` makes the standard double shift stall.
//! nalgebra still does the Hessenberg reduction.

use nalgebra::{Complex, DMatrix};

/// Iterations per eigenvalue before giving up (EISPACK uses 30 per
/// eigenvalue; the exceptional shifts come at 10 and 20).
const MAX_ITERATIONS: usize = 60;

/// `|a|` with the sign of `b`.
fn sign(a: f64, b: f64) -> f64 {
    if b >= 0.0 { a.abs() } else { -a.abs() }
}

/// The eigenvalues of the square matrix `m` (any order), or `None` if the
/// iteration does not converge (never seen; the caller reports it).
///
/// ```text
/// M ← D⁻¹ M D (balancing),  H = Qᵀ M Q (Householder),  then H ← double-shift QR steps until H is
/// quasi-triangular; each 1×1 block is a real eigenvalue, each 2×2 a pair
/// ```
pub(crate) fn eigenvalues(m: &DMatrix<f64>) -> Option<Vec<Complex<f64>>> {
    let n = m.nrows();
    if n == 0 {
        return Some(Vec::new());
    }
    // Balanced first (Parlett & Reinsch): rows and columns of mixed units
    // (γ and ω) scaled to comparable norms, by powers of two (exact).
    let mut balanced = m.clone();
    nalgebra::linalg::balancing::balance_parlett_reinsch(&mut balanced);
    let mut a = nalgebra::Hessenberg::new(balanced).h();
    let anorm: f64 = (0..n)
        .flat_map(|i| (i.saturating_sub(1)..n).map(move |j| (i, j)))
        .map(|(i, j)| a[(i, j)].abs())
        .sum();
    let mut roots = vec![Complex::new(0.0, 0.0); n];
    let mut nn = n as isize - 1;
    let mut t = 0.0;
    let mut its = 0;
    let at = |i: isize, j: isize| (i as usize, j as usize);
    while nn >= 0 {
        // The lowest l with a negligible subdiagonal a[l][l-1].
        let mut l = nn;
        while l >= 1 {
            let mut s = a[at(l - 1, l - 1)].abs() + a[at(l, l)].abs();
            if s == 0.0 {
                s = anorm;
            }
            if a[at(l, l - 1)].abs() + s == s {
                a[at(l, l - 1)] = 0.0;
                break;
            }
            l -= 1;
        }
        let mut x = a[at(nn, nn)];
        if l == nn {
            roots[nn as usize] = Complex::new(x + t, 0.0);
            nn -= 1;
            its = 0;
            continue;
        }
        let mut y = a[at(nn - 1, nn - 1)];
        let mut w = a[at(nn, nn - 1)] * a[at(nn - 1, nn)];
        if l == nn - 1 {
            let p = 0.5 * (y - x);
            let q = p * p + w;
            let z = q.abs().sqrt();
            x += t;
            if q >= 0.0 {
                let z = p + sign(z, p);
                let lower = if z != 0.0 { x - w / z } else { x + z };
                roots[(nn - 1) as usize] = Complex::new(x + z, 0.0);
                roots[nn as usize] = Complex::new(lower, 0.0);
            } else {
                roots[(nn - 1) as usize] = Complex::new(x + p, z);
                roots[nn as usize] = Complex::new(x + p, -z);
            }
            nn -= 2;
            its = 0;
            continue;
        }
        if its == MAX_ITERATIONS {
            return None;
        }
        if its == 10 || its == 20 {
            // Exceptional shift.
            t += x;
            for i in 0..=nn {
                a[at(i, i)] -= x;
            }
            let s = a[at(nn, nn - 1)].abs() + a[at(nn - 1, nn - 2)].abs();
            x = 0.75 * s;
            y = x;
            w = -0.4375 * s * s;
        }
        its += 1;
        double_shift_step(&mut a, l, nn, x, y, w);
    }
    Some(roots)
}

/// One Francis double-shift QR step on rows and columns `l..=nn` of the
/// Hessenberg `a`, with shifts the roots of `λ² − (x + y) λ + (x y − w)`.
fn double_shift_step(a: &mut DMatrix<f64>, l: isize, nn: isize, x: f64, y: f64, w: f64) {
    let at = |i: isize, j: isize| (i as usize, j as usize);
    // Two consecutive small subdiagonal elements: the step starts at m.
    let (mut p, mut q, mut r) = (0.0, 0.0, 0.0);
    let mut m = nn - 2;
    while m >= l {
        let z = a[at(m, m)];
        let rr = x - z;
        let s = y - z;
        p = (rr * s - w) / a[at(m + 1, m)] + a[at(m, m + 1)];
        q = a[at(m + 1, m + 1)] - z - rr - s;
        r = a[at(m + 2, m + 1)];
        let scale = p.abs() + q.abs() + r.abs();
        p /= scale;
        q /= scale;
        r /= scale;
        if m == l {
            break;
        }
        let u = a[at(m, m - 1)].abs() * (q.abs() + r.abs());
        let v = p.abs() * (a[at(m - 1, m - 1)].abs() + z.abs() + a[at(m + 1, m + 1)].abs());
        if u + v == v {
            break;
        }
        m -= 1;
    }
    for i in (m + 2)..=nn {
        a[at(i, i - 2)] = 0.0;
        if i != m + 2 {
            a[at(i, i - 3)] = 0.0;
        }
    }
    let mut k = m;
    while k < nn {
        let mut scale = 1.0;
        if k != m {
            p = a[at(k, k - 1)];
            q = a[at(k + 1, k - 1)];
            r = if k != nn - 1 {
                a[at(k + 2, k - 1)]
            } else {
                0.0
            };
            scale = p.abs() + q.abs() + r.abs();
            if scale != 0.0 {
                p /= scale;
                q /= scale;
                r /= scale;
            }
        }
        let s = sign((p * p + q * q + r * r).sqrt(), p);
        if s != 0.0 {
            if k == m {
                if l != m {
                    a[at(k, k - 1)] = -a[at(k, k - 1)];
                }
            } else {
                a[at(k, k - 1)] = -s * scale;
            }
            p += s;
            let (hx, hy, hz) = (p / s, q / s, r / s);
            q /= p;
            r /= p;
            for j in k..=nn {
                let mut pj = a[at(k, j)] + q * a[at(k + 1, j)];
                if k != nn - 1 {
                    pj += r * a[at(k + 2, j)];
                    a[at(k + 2, j)] -= pj * hz;
                }
                a[at(k + 1, j)] -= pj * hy;
                a[at(k, j)] -= pj * hx;
            }
            let last = nn.min(k + 3);
            for i in l..=last {
                let mut pi = hx * a[at(i, k)] + hy * a[at(i, k + 1)];
                if k != nn - 1 {
                    pi += hz * a[at(i, k + 2)];
                    a[at(i, k + 2)] -= pi * r;
                }
                a[at(i, k + 1)] -= pi * q;
                a[at(i, k)] -= pi;
            }
        }
        k += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Sorted by real then imaginary part.
    fn sorted(mut v: Vec<Complex<f64>>) -> Vec<Complex<f64>> {
        v.sort_by(|a, b| a.re.total_cmp(&b.re).then(a.im.total_cmp(&b.im)));
        v
    }

    #[test]
    fn the_sleeping_top_below_threshold_converges() {
        // The matrix nalgebra's Schur never finishes: ±0.5 ± 1.25 i·…
        let b = DMatrix::from_row_slice(
            4,
            4,
            &[
                0.0, 2.5, 0.0, -1.0, -2.5, 0.0, 1.0, 0.0, 0.0, 0.5, 0.0, 1.25, -0.5, 0.0, -1.25,
                0.0,
            ],
        );
        let roots = eigenvalues(&b).expect("converges");
        // Characteristic polynomial by hand: the block is z ↦ (rotation by
        // 2.5, coupling): λ = ±i 1.25 ± σ with σ² = 2.5·… — check instead
        // the invariants: Σλ = trace = 0, Πλ = det.
        let sum: Complex<f64> = roots.iter().sum();
        let product: Complex<f64> = roots.iter().product();
        assert!(sum.norm() < 1e-14);
        assert!((product.re - b.determinant()).abs() < 1e-13 * b.determinant().abs());
        for r in &roots {
            // Each is a root of det(B − λ) = 0.
            let shifted = b.map(|v| Complex::new(v, 0.0)) - DMatrix::identity(4, 4) * *r;
            assert!(shifted.determinant().norm() < 1e-12, "{r}");
        }
    }

    #[test]
    fn a_companion_matrix_gives_its_polynomial_s_roots() {
        // (λ − 1)(λ − 2)(λ² + 1)(λ + 3) = λ⁵ − λ³ + 6λ² ... built from roots.
        let roots = [
            Complex::new(1.0, 0.0),
            Complex::new(2.0, 0.0),
            Complex::new(0.0, 1.0),
            Complex::new(0.0, -1.0),
            Complex::new(-3.0, 0.0),
        ];
        let mut coefficients = vec![Complex::new(1.0, 0.0)];
        for r in roots {
            let mut next = vec![Complex::new(0.0, 0.0); coefficients.len() + 1];
            for (k, c) in coefficients.iter().enumerate() {
                next[k] += c;
                next[k + 1] -= c * r;
            }
            coefficients = next;
        }
        let n = roots.len();
        let companion = DMatrix::from_fn(n, n, |i, j| {
            if i == 0 {
                -coefficients[j + 1].re
            } else {
                f64::from(i == j + 1)
            }
        });
        let found = sorted(eigenvalues(&companion).expect("converges"));
        for (f, e) in found.iter().zip(sorted(roots.to_vec())) {
            assert!((f - e).norm() < 1e-12, "{f} vs {e}");
        }
    }

    #[test]
    fn triangular_and_empty_matrices() {
        assert_eq!(eigenvalues(&DMatrix::zeros(0, 0)), Some(Vec::new()));
        let t = DMatrix::from_row_slice(3, 3, &[1.0, 5.0, 7.0, 0.0, -2.0, 3.0, 0.0, 0.0, 4.0]);
        let found = sorted(eigenvalues(&t).expect("converges"));
        assert_eq!(
            found.iter().map(|c| c.re).collect::<Vec<_>>(),
            vec![-2.0, 1.0, 4.0]
        );
    }
}
