//! Eigenvalues and eigenvectors of a real nonsymmetric matrix: the
//! eigenvalues from nalgebra's real Schur form, each mode shape as the
//! null vector of `B − λ𝟙` (complex SVD), and how many independent modes a
//! repeated eigenvalue has (fewer than its multiplicity: a Jordan block,
//! secular growth).

use nalgebra::{Complex, DMatrix};

use crate::Eigenvalue;

/// One eigenvalue with its eigenvector (unit length, largest component
/// real and positive) and the geometric multiplicity of its cluster.
#[derive(Debug, Clone)]
pub(crate) struct EigenPair {
    pub(crate) value: Eigenvalue,
    pub(crate) vector: Vec<Complex<f64>>,
    /// Eigenvalues within the cluster tolerance of this one (itself
    /// included).
    pub(crate) multiplicity: usize,
    /// Independent eigenvectors of that cluster.
    pub(crate) modes_in_cluster: usize,
}

/// Eigenvalues closer than this (relative to the spectrum's scale) form a
/// cluster; a perturbed Jordan block splits by `O(√ε_machine)`.
const CLUSTER: f64 = 1e-6;

/// The eigenpairs of `b`, sorted by real part (descending), then by
/// imaginary part (descending). `scale > 0` is the spectrum's size.
pub(crate) fn eigen_pairs(b: &DMatrix<f64>, scale: f64) -> Option<Vec<EigenPair>> {
    let n = b.nrows();
    if n == 0 {
        return Some(Vec::new());
    }
    let mut values = crate::hessenberg_qr::eigenvalues(b)?;
    values.sort_by(|x, y| y.re.total_cmp(&x.re).then(y.im.total_cmp(&x.im)));
    let bc: DMatrix<Complex<f64>> = b.map(|v| Complex::new(v, 0.0));
    let mut pairs: Vec<EigenPair> = Vec::with_capacity(n);
    for &lambda in &values {
        // A real matrix: the mode of λ̄ is the conjugate of λ's (the QR
        // iteration gives the pair exactly conjugate, λ first).
        let partner = pairs
            .iter()
            .find(|p| lambda.im < 0.0 && Complex::new(p.value.re, -p.value.im) == lambda);
        let vector = match partner {
            Some(p) => p.vector.iter().map(|c| c.conj()).collect(),
            None => null_vector(&bc, lambda)?,
        };
        let cluster: Vec<Complex<f64>> = values
            .iter()
            .copied()
            .filter(|v| (v - lambda).norm() <= CLUSTER * scale)
            .collect();
        let modes_in_cluster = if cluster.len() > 1 {
            let centre = cluster.iter().sum::<Complex<f64>>() / cluster.len() as f64;
            let at_centre = &bc - DMatrix::<Complex<f64>>::identity(n, n) * centre;
            at_centre
                .singular_values()
                .iter()
                .filter(|&&s| s <= CLUSTER.sqrt() * 1e-1 * scale)
                .count()
                .max(1)
        } else {
            1
        };
        pairs.push(EigenPair {
            value: Eigenvalue::new(lambda.re, lambda.im),
            vector,
            multiplicity: cluster.len(),
            modes_in_cluster,
        });
    }
    Some(pairs)
}

/// The mode of `lambda`: the right singular vector of `B − λ𝟙` for its
/// smallest singular value (unit length, largest component real and
/// positive); `None` only if the SVD gives no `Vᴴ` (never: it is asked for).
fn null_vector(bc: &DMatrix<Complex<f64>>, lambda: Complex<f64>) -> Option<Vec<Complex<f64>>> {
    let n = bc.nrows();
    let shifted = bc - DMatrix::<Complex<f64>>::identity(n, n) * lambda;
    let svd = shifted.svd(false, true);
    let v_t = svd.v_t?;
    let (k, _) =
        svd.singular_values
            .iter()
            .enumerate()
            .fold(
                (0, f64::INFINITY),
                |(kb, sb), (k, &s)| if s < sb { (k, s) } else { (kb, sb) },
            );
    let mut vector: Vec<Complex<f64>> = v_t.row(k).iter().map(|c| c.conj()).collect();
    normalise_phase(&mut vector);
    Some(vector)
}

/// Unit length, and the largest component made real and positive.
fn normalise_phase(v: &mut [Complex<f64>]) {
    let norm = v.iter().map(|c| c.norm_sqr()).sum::<f64>().sqrt();
    let biggest = v.iter().copied().fold(Complex::new(0.0, 0.0), |b, c| {
        if c.norm() > b.norm() { c } else { b }
    });
    if norm > 0.0 && biggest.norm() > 0.0 {
        let phase = biggest.conj() / biggest.norm();
        for c in v.iter_mut() {
            *c = *c * phase / norm;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_rotation_generator_has_plus_minus_i_omega() {
        let w = 3.0;
        let b = DMatrix::from_row_slice(2, 2, &[0.0, -w, w, 0.0]);
        let pairs = eigen_pairs(&b, w).unwrap();
        assert_eq!(pairs.len(), 2);
        assert!(pairs[0].value.re.abs() < 1e-15 && (pairs[0].value.im - w).abs() < 1e-15);
        assert!((pairs[1].value.im + w).abs() < 1e-15);
        // B v = λ v.
        for p in &pairs {
            let l = Complex::new(p.value.re, p.value.im);
            for i in 0..2 {
                let bv: Complex<f64> = (0..2).map(|k| p.vector[k] * b[(i, k)]).sum();
                assert!((bv - l * p.vector[i]).norm() < 1e-14);
            }
        }
    }

    #[test]
    fn a_jordan_block_has_one_mode_and_a_double_eigenvalue_two() {
        let jordan = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, 0.0, 0.0]);
        let pairs = eigen_pairs(&jordan, 1.0).unwrap();
        assert_eq!((pairs[0].multiplicity, pairs[0].modes_in_cluster), (2, 1));
        let zero = DMatrix::<f64>::zeros(2, 2);
        let pairs = eigen_pairs(&zero, 1.0).unwrap();
        assert_eq!((pairs[0].multiplicity, pairs[0].modes_in_cluster), (2, 2));
    }
}
