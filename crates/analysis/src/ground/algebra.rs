//! Three-vectors and 3×3 solves in any [`Scalar`], for the equations of a
//! body on the ground (written once for `f64` and for dual numbers).

use crate::Scalar;

/// A vector of three scalars, body axes unless its name says otherwise.
pub(crate) type V3<D> = [D; 3];

/// `[x, y, z]` lifted into `D`.
pub(crate) fn lift<D: Scalar>(v: [f64; 3]) -> V3<D> {
    v.map(D::from)
}

/// `a · b`.
pub(crate) fn dot<D: Scalar>(a: V3<D>, b: V3<D>) -> D {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `a × b`.
pub(crate) fn cross<D: Scalar>(a: V3<D>, b: V3<D>) -> V3<D> {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `a + b`.
pub(crate) fn add<D: Scalar>(a: V3<D>, b: V3<D>) -> V3<D> {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// `a − b`.
pub(crate) fn sub<D: Scalar>(a: V3<D>, b: V3<D>) -> V3<D> {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `s a`.
pub(crate) fn scale<D: Scalar>(a: V3<D>, s: D) -> V3<D> {
    [a[0] * s, a[1] * s, a[2] * s]
}

/// `M v` for a constant matrix (rows).
pub(crate) fn mat_vec<D: Scalar>(m: &[[f64; 3]; 3], v: V3<D>) -> V3<D> {
    [0, 1, 2].map(|i| v[0] * m[i][0] + v[1] * m[i][1] + v[2] * m[i][2])
}

/// `|a|`.
pub(crate) fn norm<D: Scalar>(a: V3<D>) -> D {
    dot(a, a).sqrt()
}

/// The solution `x` of `M x = b` for a 3×3 matrix `M` (rows), by the
/// adjugate: `x = adj(M) b / det M` (the matrices here are symmetric
/// positive definite, `det M > 0`).
///
/// ```text
/// adj(M) rows = (M₁ × M₂, M₂ × M₀, M₀ × M₁) as columns,   det M = M₀ · (M₁ × M₂)
/// ```
pub(crate) fn solve3<D: Scalar>(m: [V3<D>; 3], b: V3<D>) -> V3<D> {
    // Columns of the inverse times det: the cross products of the rows.
    let c0 = cross(m[1], m[2]);
    let c1 = cross(m[2], m[0]);
    let c2 = cross(m[0], m[1]);
    let det = dot(m[0], c0);
    // x = (c0 b₀ + c1 b₁ + c2 b₂) / det.
    let x = add(add(scale(c0, b[0]), scale(c1, b[1])), scale(c2, b[2]));
    scale(x, det.recip())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_solve_inverts_a_matrix() {
        let m = [[4.0, 1.0, 0.5], [1.0, 3.0, -0.2], [0.5, -0.2, 2.0]];
        let x = [0.3, -1.2, 2.5];
        let b = mat_vec(&m, x);
        let y = solve3(m, b);
        for k in 0..3 {
            assert!((y[k] - x[k]).abs() < 1e-15, "{y:?}");
        }
        let a = [1.0, 2.0, 3.0];
        let c = cross(a, [-2.0, 0.5, 1.0]);
        assert_eq!(dot(a, c), 0.0);
    }
}
