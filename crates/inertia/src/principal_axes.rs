//! Principal moments and a right-handed principal frame of a symmetric
//! inertia tensor (cyclic Jacobi eigenvalue method).

use glam::{DMat3, DQuat, DVec3};
use kreisel_kinematics::quat_from_rotation_matrix;

use crate::MassPropertiesError;

/// Principal moments of inertia and the principal frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrincipalAxes {
    /// Principal moments `I₁ ≤ I₂ ≤ I₃`, kg·m².
    pub moments: DVec3,
    /// The principal axes as the columns of a rotation matrix
    /// (`body_from_principal`): column k is the unit axis of `moments[k]` in
    /// body coordinates; the frame is right-handed (`det = +1`).
    pub axes: DMat3,
    /// The same rotation as a unit quaternion (`body_from_principal`,
    /// canonical `w ≥ 0`).
    pub orientation: DQuat,
}

impl PrincipalAxes {
    /// Diagonalises a symmetric tensor, refusing a non-finite one (where
    /// [`PrincipalAxes::from_tensor`] gives NaN throughout).
    ///
    /// # Errors
    /// [`MassPropertiesError::TensorNotFinite`] if an element is NaN or
    /// infinite, [`MassPropertiesError::MomentsOverflow`] if the moments of
    /// a finite tensor overflow.
    ///
    /// ```
    /// use glam::{DMat3, DVec3};
    /// use kreisel_inertia::PrincipalAxes;
    /// let p = PrincipalAxes::try_from_tensor(DMat3::from_diagonal(DVec3::new(2.0, 1.0, 3.0)))?;
    /// assert_eq!(p.moments, DVec3::new(1.0, 2.0, 3.0));
    /// assert!(PrincipalAxes::try_from_tensor(DMat3::from_diagonal(DVec3::INFINITY)).is_err());
    /// # Ok::<(), kreisel_inertia::MassPropertiesError>(())
    /// ```
    pub fn try_from_tensor(tensor: DMat3) -> Result<Self, MassPropertiesError> {
        if !tensor.is_finite() {
            return Err(MassPropertiesError::TensorNotFinite);
        }
        let axes = Self::from_tensor(tensor);
        if !axes.moments.is_finite() {
            return Err(MassPropertiesError::MomentsOverflow {
                moments: axes.moments,
            });
        }
        Ok(axes)
    }

    /// Diagonalises a symmetric tensor: `I = R diag(moments) Rᵀ`.
    ///
    /// Cyclic Jacobi rotations (Jacobi 1846; Golub & Van Loan, *Matrix
    /// Computations*, §8.5): each eigenvalue comes out with an error of a
    /// few ulps of the largest one, and repeated or nearly repeated moments
    /// (spheres, symmetric tops) need no special case: the axes stay
    /// orthonormal however close the moments are.
    ///
    /// ```text
    /// I = R · diag(I₁, I₂, I₃) · Rᵀ,   I₁ ≤ I₂ ≤ I₃,   det R = +1
    /// ```
    ///
    /// Signs: the first two axes have their largest component positive, the
    /// third is their cross product. Only the symmetric part of `tensor` is
    /// used (the upper triangle). A non-finite tensor gives NaN throughout
    /// (see [`PrincipalAxes::try_from_tensor`]).
    ///
    /// ```
    /// use glam::{DMat3, DVec3};
    /// use kreisel_inertia::PrincipalAxes;
    /// let p = PrincipalAxes::from_tensor(DMat3::from_diagonal(DVec3::new(3.0, 1.0, 2.0)));
    /// assert_eq!(p.moments, DVec3::new(1.0, 2.0, 3.0));
    /// assert_eq!(p.axes.x_axis, DVec3::Y);
    /// assert!((p.axes.determinant() - 1.0).abs() < 1e-15);
    /// ```
    pub fn from_tensor(tensor: DMat3) -> Self {
        if !tensor.is_finite() {
            return Self {
                moments: DVec3::NAN,
                axes: DMat3::NAN,
                orientation: DQuat::NAN,
            };
        }
        // Diagonalise in the tensor's own power-of-two unit (exact), so that
        // squares inside the rotations neither overflow nor underflow for
        // any finite tensor; the moments are scaled back (to ±inf if they
        // exceed f64, which `try_from_tensor` refuses).
        let exponent = unit_exponent(tensor);
        let half = -exponent / 2;
        let unit = tensor * 2f64.powi(half) * 2f64.powi(-exponent - half);
        let (unit_values, vectors) = jacobi_eigen(unit);
        let half = exponent / 2;
        let values = unit_values.map(|x| x * 2f64.powi(half) * 2f64.powi(exponent - half));
        let mut order = [0usize, 1, 2];
        order.sort_by(|&i, &j| values[i].total_cmp(&values[j]));
        let moments = DVec3::new(values[order[0]], values[order[1]], values[order[2]]);
        let sign_fix = |v: DVec3| {
            let a = v.abs();
            let largest = if a.x >= a.y && a.x >= a.z {
                v.x
            } else if a.y >= a.z {
                v.y
            } else {
                v.z
            };
            if largest < 0.0 { -v } else { v }
        };
        // Re-orthonormalise (Gram–Schmidt) what the rotations left ~1e-15 off.
        let e1 = sign_fix(vectors[order[0]]).normalize();
        let e2 = sign_fix(vectors[order[1]]);
        let e2 = (e2 - e1 * e1.dot(e2)).normalize();
        let e3 = e1.cross(e2);
        let axes = DMat3::from_cols(e1, e2, e3);
        // Cannot panic: e1, e2 are finite orthonormal vectors (columns of
        // Jacobi's rotation product, re-orthonormalised) and e3 = e1 × e2, so
        // `axes` is finite with determinant |e1 × e2|² ≈ 1 > 0.
        let q = quat_from_rotation_matrix(axes);
        let orientation = if q.w < 0.0 { -q } else { q };
        Self {
            moments,
            axes,
            orientation,
        }
    }
}

/// Eigenvalues and unit eigenvectors of the symmetric part of `a`.
/// The exponent `e` of the power of two nearest below the tensor's largest
/// element (0 for the zero tensor): `tensor · 2⁻ᵉ` has elements of order 1.
/// The scaling is applied in two halves, since `2⁻ᵉ` alone overflows for a
/// subnormal tensor.
fn unit_exponent(tensor: DMat3) -> i32 {
    let largest = tensor
        .to_cols_array()
        .iter()
        .fold(0.0_f64, |m, x| m.max(x.abs()));
    if largest > 0.0 {
        // Exact for every finite positive f64 (subnormals included).
        largest.log2().floor() as i32
    } else {
        0
    }
}

fn jacobi_eigen(a: DMat3) -> ([f64; 3], [DVec3; 3]) {
    // m[r][c], symmetric: take the upper triangle.
    let e = |r: usize, c: usize| a.col(c)[r];
    let mut m = [
        [e(0, 0), e(0, 1), e(0, 2)],
        [e(0, 1), e(1, 1), e(1, 2)],
        [e(0, 2), e(1, 2), e(2, 2)],
    ];
    let mut v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    // Quadratic convergence: 3×3 matrices need ≤ 6 sweeps; 50 bounds the
    // loop for any input, NaN included.
    for _ in 0..50 {
        let off = m[0][1].abs() + m[0][2].abs() + m[1][2].abs();
        if off == 0.0 || off.is_nan() {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            let apq = m[p][q];
            if apq == 0.0 {
                continue;
            }
            // An off-diagonal at the rounding level of the diagonal is noise
            // (a backward error of a few ulps): drop it rather than let it
            // turn a symmetric top's axes by 45°.
            let scale = m[p][p].abs() + m[q][q].abs();
            if apq.abs() <= 2.0 * f64::EPSILON * scale {
                m[p][q] = 0.0;
                m[q][p] = 0.0;
                continue;
            }
            // Rotation angle that annihilates m[p][q] (Golub & Van Loan, Alg. 8.5.1).
            let theta = (m[q][q] - m[p][p]) / (2.0 * apq);
            let t = if theta.abs() > 1e150 {
                0.5 / theta
            } else {
                theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt())
            };
            let t = if theta == 0.0 { 1.0 } else { t };
            let c = 1.0 / (t * t + 1.0).sqrt();
            let s = t * c;
            // m ← Jᵀ m J, with J the rotation in the (p, q) plane.
            for row in &mut m {
                let (mkp, mkq) = (row[p], row[q]);
                row[p] = c * mkp - s * mkq;
                row[q] = s * mkp + c * mkq;
            }
            let (row_p, row_q) = (m[p], m[q]);
            for k in 0..3 {
                m[p][k] = c * row_p[k] - s * row_q[k];
                m[q][k] = s * row_p[k] + c * row_q[k];
            }
            m[p][q] = 0.0;
            m[q][p] = 0.0;
            for row in &mut v {
                let (vp, vq) = (row[p], row[q]);
                row[p] = c * vp - s * vq;
                row[q] = s * vp + c * vq;
            }
        }
    }
    let col = |k: usize| DVec3::new(v[0][k], v[1][k], v[2][k]);
    ([m[0][0], m[1][1], m[2][2]], [col(0), col(1), col(2)])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn reconstruct(p: &PrincipalAxes) -> DMat3 {
        p.axes * DMat3::from_diagonal(p.moments) * p.axes.transpose()
    }

    fn max_abs(m: DMat3) -> f64 {
        m.to_cols_array()
            .iter()
            .fold(0.0_f64, |a, v| a.max(v.abs()))
    }

    #[test]
    fn rotated_diagonal_tensor_is_recovered() {
        let r = DMat3::from_quat(DQuat::from_euler(glam::EulerRot::ZXZ, 0.3, 1.1, -0.7));
        let d = DVec3::new(1.0, 2.5, 3.0);
        let tensor = r * DMat3::from_diagonal(d) * r.transpose();
        let p = PrincipalAxes::from_tensor(tensor);
        assert!((p.moments - d).abs().max_element() < 1e-15);
        // Backward stable: a few ulps of the largest moment.
        let err = max_abs(reconstruct(&p) - tensor);
        assert!(err < 8.0 * f64::EPSILON * 3.0, "{err:e} {p:?}");
        assert!((p.axes.determinant() - 1.0).abs() < 1e-15);
        let q = DMat3::from_quat(p.orientation);
        assert!(max_abs(q - p.axes) < 1e-15);
    }

    #[test]
    fn repeated_and_nearly_repeated_moments() {
        let r = DMat3::from_quat(DQuat::from_euler(glam::EulerRot::XYZ, 0.4, -0.2, 0.9));
        for split in [0.0, 1e-14, 1e-10, 1e-6] {
            let d = DVec3::new(2.0, 2.0 + split, 5.0);
            let tensor = r * DMat3::from_diagonal(d) * r.transpose();
            let p = PrincipalAxes::from_tensor(tensor);
            // Backward stable: a few ulps of the largest moment.
            let tol = 8.0 * f64::EPSILON * 5.0;
            assert!(
                (p.moments - d).abs().max_element() < tol,
                "{split}: {}",
                p.moments
            );
            assert!(max_abs(reconstruct(&p) - tensor) < tol);
            let orth = p.axes.transpose() * p.axes - DMat3::IDENTITY;
            assert!(max_abs(orth) < 4.0 * f64::EPSILON);
            // The unique axis (largest moment) is found exactly.
            assert!((p.axes.z_axis.dot(r.z_axis).abs() - 1.0).abs() < 1e-14);
        }
        // A sphere: identity frame.
        let p = PrincipalAxes::from_tensor(DMat3::IDENTITY * 0.4);
        assert_eq!(p.axes, DMat3::IDENTITY);
        assert_eq!(p.orientation, DQuat::IDENTITY);
    }

    /// Regression: the mesh of a symmetric top has off-diagonals of ~1e-17
    /// relative (rounding); they must not turn the axes by 45°.
    #[test]
    fn rounding_noise_keeps_a_symmetric_top_axis_aligned() {
        let mut t = DMat3::from_diagonal(DVec3::new(7.8e-6, 7.8e-6, 1.26e-5));
        t.x_axis.y = 1.05e-22;
        t.y_axis.x = 1.05e-22;
        t.y_axis.z = 4.0e-22;
        t.z_axis.y = 4.0e-22;
        let p = PrincipalAxes::from_tensor(t);
        assert_eq!(p.axes, DMat3::IDENTITY);
    }

    #[test]
    fn nan_input_terminates() {
        let mut m = DMat3::IDENTITY;
        m.x_axis.y = f64::NAN;
        m.y_axis.x = f64::NAN;
        let p = PrincipalAxes::from_tensor(m);
        assert!(p.moments.is_nan() && p.axes.is_nan());
    }

    #[test]
    fn non_finite_tensors_are_refused_by_the_try_form() {
        let mut t = DMat3::IDENTITY;
        t.y_axis.x = f64::NAN;
        assert!(PrincipalAxes::try_from_tensor(t).is_err());
        assert!(PrincipalAxes::from_tensor(t).moments.is_nan());
    }

    #[test]
    fn scale_free_and_overflow_refused() {
        // Regression: at 1e308 the rotations' squares overflowed and Jacobi
        // stopped with every moment 1e308 (true: 1e307, 1e308, 1.9e308, the
        // last beyond f64), silently.
        let base = DMat3::from_cols(
            DVec3::new(1.0, 0.9, 0.0),
            DVec3::new(0.9, 1.0, 0.0),
            DVec3::new(0.0, 0.0, 1.0),
        );
        // Closed form: eigenvalues 1 − 0.9, 1, 1 + 0.9.
        let exact = DVec3::new(0.1, 1.0, 1.9);
        for k in [1e-300, 1e-100, 1.0, 1e100, 1e300] {
            let p = PrincipalAxes::try_from_tensor(base * k).unwrap();
            let rel = (p.moments / k - exact).abs().max_element();
            assert!(rel < 1e-15, "scale {k}: {:?}", p.moments);
            assert!((p.axes.determinant() - 1.0).abs() < 1e-15, "scale {k}");
        }
        let huge = PrincipalAxes::from_tensor(base * 1e308);
        assert!((huge.moments.x / 1e307 - 1.0).abs() < 1e-14, "{huge:?}");
        assert_eq!(huge.moments.z, f64::INFINITY);
        assert!(PrincipalAxes::try_from_tensor(base * 1e308).is_err());
    }
}
