//! [`VectorField`]: the reduced equations of motion of one family of
//! steady motions, written once for any scalar, so that their Jacobian and
//! the gradients of their conserved quantities are exact (forward-mode
//! dual numbers, [`num_dual`]), never finite differences.

use nalgebra::DMatrix;
use num_dual::{Dual64, DualNum};

use crate::{Eigenvalue, Frame, ZeroMode};

/// A scalar the equations can be evaluated in: `f64` for values, dual
/// numbers for exact derivatives.
pub trait Scalar: DualNum<Primitive = f64> + Copy {}

impl<D: DualNum<Primitive = f64> + Copy> Scalar for D {}

/// The reduced equations `ẋ = f(x)` of a body whose steady motion is an
/// equilibrium `f(x*) = 0` in these coordinates (a relative equilibrium of
/// the full motion: the symmetries it was reduced by are named by
/// [`VectorField::reduced_by`]).
///
/// ```text
/// ẋ = f(x),   x ∈ ℝⁿ,   conserved C_k(x) (∇C_k · f = 0),   symmetry directions ξ_j (f(x* + s ξ_j) = 0)
/// ```
///
/// At an equilibrium each conserved quantity's gradient is a left null
/// vector of the Jacobian `A = ∂f/∂x` (differentiate `∇C·f = 0` at `x*`),
/// and each symmetry direction a right null vector: these are the zero
/// eigenvalues [`crate::Linearisation`] accounts for (Marsden & Ratiu,
/// *Introduction to Mechanics and Symmetry*, §1.7).
pub trait VectorField {
    /// The state's dimension `n`.
    fn dim(&self) -> usize;

    /// What each state component is, with its unit (`"ω_x (rad/s)"`), in
    /// order; `dim()` names.
    fn state_names(&self) -> Vec<String>;

    /// `f(x)` into `dx` (both of length `dim()`).
    fn rates<D: Scalar>(&self, x: &[D], dx: &mut [D]);

    /// The conserved quantities `C_k(x)`, each with what it is. Those whose
    /// gradients are dependent at a steady motion account for one zero
    /// eigenvalue between them.
    fn conserved<D: Scalar>(&self, x: &[D]) -> Vec<(ZeroMode, D)>;

    /// Directions `ξ_j` at `x` along which the equilibria continue at the
    /// same values of every conserved quantity (an unreduced symmetry),
    /// each with what it is. None by default.
    fn symmetry_directions(&self, _x: &[f64]) -> Vec<(ZeroMode, Vec<f64>)> {
        Vec::new()
    }

    /// The symmetries the coordinates already removed, in words (`"rotation
    /// about the vertical"`): each took its zero eigenvalues with it.
    fn reduced_by(&self) -> Vec<String>;

    /// Whether the equations conserve energy (their spectrum is then
    /// symmetric under `λ → −λ`, and stability is at best neutral: all
    /// eigenvalues on the imaginary axis).
    fn is_conservative(&self) -> bool;

    /// The size of each component near `x`, in its unit: how far counts as
    /// near ([`crate::NEARBY`] of it). By default `|x|` for every one; a
    /// family mixing units (an angle and momenta) says more.
    fn state_scales(&self, x: &[f64]) -> Vec<f64> {
        let size = x.iter().map(|v| v * v).sum::<f64>().sqrt();
        vec![size; x.len()]
    }

    /// The frame the coordinates are in ([`Frame::Body`] by default).
    fn frame(&self) -> Frame {
        Frame::Body
    }

    /// The frequency in space of the mode `shape` with eigenvalue
    /// `eigenvalue` at the steady motion `x`, where the coordinates' frame
    /// turns steadily and the mode is circular; `None` (the default)
    /// otherwise.
    fn space_frequency(
        &self,
        _x: &[f64],
        _eigenvalue: Eigenvalue,
        _shape: &[Eigenvalue],
    ) -> Option<f64> {
        None
    }
}

/// `f(x)` in plain numbers.
pub(crate) fn rates_at<F: VectorField>(field: &F, x: &[f64]) -> Vec<f64> {
    let mut dx = vec![0.0; field.dim()];
    field.rates(x, &mut dx);
    dx
}

/// The state with its `k`-th component seeded: `x + ε e_k`.
fn seeded(x: &[f64], k: usize) -> Vec<Dual64> {
    x.iter()
        .enumerate()
        .map(|(i, &v)| Dual64::new(v, if i == k { 1.0 } else { 0.0 }))
        .collect()
}

/// The Jacobian `A = ∂f/∂x` at `x`, exact to rounding: one forward-mode
/// pass per column.
///
/// ```text
/// A_ik = ∂f_i/∂x_k = ε-part of f_i(x + ε e_k),   ε² = 0
/// ```
pub(crate) fn jacobian<F: VectorField>(field: &F, x: &[f64]) -> DMatrix<f64> {
    let n = field.dim();
    let mut a = DMatrix::zeros(n, n);
    let mut dx = vec![Dual64::from(0.0); n];
    for k in 0..n {
        field.rates(&seeded(x, k), &mut dx);
        for (i, d) in dx.iter().enumerate() {
            a[(i, k)] = d.eps;
        }
    }
    a
}

/// The conserved quantities' values and gradients at `x`, exact to
/// rounding.
pub(crate) fn conserved_gradients<F: VectorField>(
    field: &F,
    x: &[f64],
) -> Vec<(ZeroMode, f64, Vec<f64>)> {
    let n = field.dim();
    let mut out: Vec<(ZeroMode, f64, Vec<f64>)> = Vec::new();
    for k in 0..n {
        for (j, (mode, c)) in field.conserved(&seeded(x, k)).into_iter().enumerate() {
            if k == 0 {
                out.push((mode, c.re, vec![0.0; n]));
            }
            out[j].2[k] = c.eps;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ZeroModeKind;

    /// `ẋ = (x₁ x₂, sin x₀)`, conserving `C = cos x₀ + ½x₂²·…`: only the
    /// derivatives are under test here.
    struct Toy;

    impl VectorField for Toy {
        fn dim(&self) -> usize {
            2
        }
        fn state_names(&self) -> Vec<String> {
            vec!["a".into(), "b".into()]
        }
        fn rates<D: Scalar>(&self, x: &[D], dx: &mut [D]) {
            dx[0] = x[0] * x[1];
            dx[1] = x[0].sin() / x[1];
        }
        fn conserved<D: Scalar>(&self, x: &[D]) -> Vec<(ZeroMode, D)> {
            vec![(
                ZeroMode::new(ZeroModeKind::Casimir, "x₀ x₁²"),
                x[0] * x[1] * x[1],
            )]
        }
        fn reduced_by(&self) -> Vec<String> {
            Vec::new()
        }
        fn is_conservative(&self) -> bool {
            false
        }
    }

    #[test]
    fn the_jacobian_is_the_hand_derivative() {
        let (a, b) = (0.7_f64, 1.3_f64);
        let j = jacobian(&Toy, &[a, b]);
        let expected = [[b, a], [a.cos() / b, -a.sin() / (b * b)]];
        for (i, row) in expected.iter().enumerate() {
            for (k, e) in row.iter().enumerate() {
                assert!((j[(i, k)] - e).abs() <= 1e-16 * e.abs().max(1.0), "{i}{k}");
            }
        }
        let g = conserved_gradients(&Toy, &[a, b]);
        assert_eq!(g.len(), 1);
        assert_eq!(g[0].1, a * b * b);
        assert_eq!(g[0].2, vec![b * b, 2.0 * a * b]);
    }
}
