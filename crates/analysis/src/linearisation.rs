//! [`Linearisation`]: the equations linearised at a steady motion with
//! exact derivatives, every zero eigenvalue accounted for (a conserved
//! quantity or a symmetry direction, named), and the verdict read off
//! what remains.

use nalgebra::{Complex, DMatrix, DVector};

use crate::eigen::eigen_pairs;
use crate::vector_field::{conserved_gradients, jacobian, rates_at};
use crate::{AnalysisError, Eigenvalue, Frame, Mode, VectorField, Verdict, ZeroMode};

/// A state whose relative residual `|f(x)| / (‖A‖ |x|)` is at most this
/// is a steady motion.
pub const STEADY_RESIDUAL: f64 = 1e-10;

/// The real part, relative to the largest `|λ|`, above which a mode
/// grows (a perturbed Jordan block's eigenvalues move by `O(√ε)` ≈
/// 1.5e-8, so this separates roundoff from growth).
pub const GROWTH_TOLERANCE: f64 = 1e-7;

/// Gradients or directions whose component outside the span of those
/// before them is smaller than this (relative) are dependent.
const DEPENDENT: f64 = 1e-9;

/// The linear stability of one steady motion.
///
/// ```text
/// A = ∂f/∂x (x*)                    exact (forward-mode dual numbers)
/// T = {v : ∇C_k · v = 0}            the common level of the conserved C_k
/// V = orthonormal basis of T ⊖ span{ξ_j}
/// B = Vᵀ A V                        eigenvalues of A without the accounted zeros
/// ```
///
/// `T` is invariant (`∇C_kᵀ A = 0`) and `span{ξ_j}` too (`A ξ_j = 0`),
/// so the spectrum of `B` is that of `A` less one zero per independent
/// gradient and per independent direction (Marsden & Ratiu, §1.7; the
/// notes' §2 for the eigenvalue method).
///
/// ```
/// use kreisel_analysis::{FreeBodyRotation, Linearisation, Verdict};
/// use glam::DVec3;
/// // Spin about the intermediate axis of moments (1, 2, 3) at 1 rad/s.
/// let family = FreeBodyRotation::try_new(DVec3::new(1.0, 2.0, 3.0))?;
/// let lin = Linearisation::try_new(&family, &family.about_axis(1, 1.0)?)?;
/// let growth = (1.0f64 * 1.0 / 3.0).sqrt();
/// assert!(matches!(lin.verdict, Verdict::Unstable { growth_rate } if (growth_rate - growth).abs() < 1e-14));
/// assert_eq!(lin.zero_modes.len(), 1); // |L|²: a steady spin at another rate
/// # Ok::<(), kreisel_analysis::AnalysisError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Linearisation {
    /// The steady motion `x*` in the reduced coordinates.
    pub state: Vec<f64>,
    /// What each coordinate is.
    pub state_names: Vec<String>,
    /// `|f(x*)| / (‖A‖ |x*|)`.
    pub residual: f64,
    /// The zero eigenvalues accounted for, one each.
    pub zero_modes: Vec<ZeroMode>,
    /// Conserved quantities whose gradient at `x*` depends on those
    /// before them: no zero eigenvalue of their own.
    pub dependent: Vec<ZeroMode>,
    /// The symmetries the coordinates removed before linearising.
    pub reduced_by: Vec<String>,
    /// The frame of the coordinates, which the eigenvalues' frequencies
    /// are seen in.
    pub frame: Frame,
    /// The other eigenvalues and their shapes, by real part then
    /// imaginary part, descending.
    pub modes: Vec<Mode>,
    /// Stable, unstable or neutral.
    pub verdict: Verdict,
}

impl Linearisation {
    /// Linearises `field` at the steady motion `x`.
    ///
    /// # Errors
    /// [`AnalysisError::StateLength`] if `x` has the wrong length,
    /// [`AnalysisError::NotFinite`] if it is not finite,
    /// [`AnalysisError::NotSteady`] if its relative residual exceeds
    /// [`STEADY_RESIDUAL`] (search first: [`crate::find_steady_motion`]);
    /// [`AnalysisError::EigenvaluesDidNotConverge`] if the QR iteration
    /// fails (never seen).
    pub fn try_new<F: VectorField>(field: &F, x: &[f64]) -> Result<Self, AnalysisError> {
        check_state(field, x)?;
        let n = field.dim();
        let a = jacobian(field, x);
        let residual = relative_residual(field, x, &a);
        if residual > STEADY_RESIDUAL || !residual.is_finite() {
            return Err(AnalysisError::NotSteady {
                residual,
                limit: STEADY_RESIDUAL,
            });
        }
        // One orthonormal basis: the independent gradients (their
        // complement is the level set's tangent space T), then the
        // symmetry directions inside T.
        let mut taken: Vec<DVector<f64>> = Vec::new();
        let (mut zero_modes, mut dependent) = (Vec::new(), Vec::new());
        for (mode, _, gradient) in conserved_gradients(field, x) {
            if push_independent(&mut taken, DVector::from_vec(gradient)) {
                zero_modes.push(mode);
            } else {
                dependent.push(mode);
            }
        }
        let normals = taken.len();
        for (mode, direction) in field.symmetry_directions(x) {
            // Its part in T is what counts.
            let mut d = DVector::from_vec(direction);
            for g in &taken[..normals] {
                d -= g * g.dot(&d);
            }
            if push_independent(&mut taken, d) {
                zero_modes.push(mode);
            } else {
                dependent.push(mode);
            }
        }
        let kept = taken.len();
        for i in 0..n {
            if taken.len() == n {
                break;
            }
            push_independent(&mut taken, DVector::from_fn(n, |k, _| f64::from(k == i)));
        }
        let v = DMatrix::from_columns(&taken[kept..]);
        let b = v.transpose() * &a * &v;
        let modes_and_verdict = spectrum(field, x, &a, &b, &v)
            .ok_or(AnalysisError::EigenvaluesDidNotConverge { dim: b.nrows() })?;
        Ok(Self {
            state: x.to_vec(),
            state_names: field.state_names(),
            residual,
            zero_modes,
            dependent,
            reduced_by: field.reduced_by(),
            frame: field.frame(),
            modes: modes_and_verdict.0,
            verdict: modes_and_verdict.1,
        })
    }

    /// Every eigenvalue of [`Linearisation::modes`].
    pub fn eigenvalues(&self) -> Vec<Eigenvalue> {
        self.modes.iter().map(|m| m.eigenvalue).collect()
    }

    /// The largest real part of the remaining eigenvalues, 1/s (`0` if
    /// none remains).
    ///
    /// ```text
    /// max_k Re λ_k
    /// ```
    pub fn max_real_part(&self) -> f64 {
        if self.modes.is_empty() {
            return 0.0;
        }
        self.modes
            .iter()
            .map(|m| m.eigenvalue.re)
            .fold(f64::NEG_INFINITY, f64::max)
    }
}

/// The length and finiteness checks of a state.
pub(crate) fn check_state<F: VectorField>(field: &F, x: &[f64]) -> Result<(), AnalysisError> {
    if x.len() != field.dim() {
        return Err(AnalysisError::StateLength {
            expected: field.dim(),
            got: x.len(),
        });
    }
    if let Some(index) = x.iter().position(|v| !v.is_finite()) {
        return Err(AnalysisError::NotFinite {
            name: field.state_names()[index].clone(),
            value: x[index],
        });
    }
    Ok(())
}

/// `|f(x)| / (‖A‖ |x|)`, `|f(x)|` itself where the denominator vanishes.
pub(crate) fn relative_residual<F: VectorField>(field: &F, x: &[f64], a: &DMatrix<f64>) -> f64 {
    let f = DVector::from_vec(rates_at(field, x));
    let scale = a.norm() * DVector::from_column_slice(x).norm();
    if scale > 0.0 {
        f.norm() / scale
    } else {
        f.norm()
    }
}

/// Appends `v` made orthonormal to `basis` if what is left of it is not
/// negligible; whether it was.
fn push_independent(basis: &mut Vec<DVector<f64>>, v: DVector<f64>) -> bool {
    let size = v.norm();
    if size == 0.0 || !size.is_finite() {
        return false;
    }
    let mut w = v / size;
    // Twice is enough (Kahan's "twice is enough" for Gram–Schmidt).
    for _ in 0..2 {
        for b in basis.iter() {
            w -= b * b.dot(&w);
        }
    }
    let left = w.norm();
    if left <= DEPENDENT {
        return false;
    }
    basis.push(w / left);
    true
}

/// The modes of `B` (shapes mapped back through `V`) and the verdict.
fn spectrum<F: VectorField>(
    field: &F,
    x: &[f64],
    a: &DMatrix<f64>,
    b: &DMatrix<f64>,
    v: &DMatrix<f64>,
) -> Option<(Vec<Mode>, Verdict)> {
    if b.nrows() == 0 {
        let reason = "every eigenvalue is a zero accounted for: nothing is left to decide".into();
        return Some((Vec::new(), Verdict::Neutral { reason }));
    }
    let size = b.norm().max(a.norm());
    let pairs = eigen_pairs(b, size)?;
    let largest = pairs.iter().map(|p| p.value.norm()).fold(0.0, f64::max);
    if largest <= f64::EPSILON * size || largest == 0.0 {
        let reason = "every eigenvalue is zero: no spin and no restoring force".into();
        let modes = pairs.iter().map(|p| mode_of(field, x, p, v)).collect();
        return Some((modes, Verdict::Neutral { reason }));
    }
    let tolerance = GROWTH_TOLERANCE * largest;
    let modes: Vec<Mode> = pairs.iter().map(|p| mode_of(field, x, p, v)).collect();
    let growth = pairs
        .iter()
        .map(|p| p.value.re)
        .fold(f64::NEG_INFINITY, f64::max);
    let verdict = if growth > tolerance {
        Verdict::Unstable {
            growth_rate: growth,
        }
    } else if let Some(p) = pairs.iter().find(|p| p.value.norm() <= tolerance) {
        Verdict::Neutral {
            reason: format!(
                "an eigenvalue {} is zero and no conserved quantity or symmetry accounts for it (a family of steady motions, or a degenerate body)",
                p.value
            ),
        }
    } else if let Some(p) = pairs
        .iter()
        .find(|p| p.value.re.abs() <= tolerance && p.modes_in_cluster < p.multiplicity)
    {
        Verdict::Neutral {
            reason: format!(
                "the eigenvalue {} is {}-fold with {} mode: perturbations grow linearly in time (a stability boundary)",
                p.value, p.multiplicity, p.modes_in_cluster
            ),
        }
    } else {
        Verdict::Stable {
            asymptotic: pairs.iter().all(|p| p.value.re < -tolerance),
        }
    };
    Some((modes, verdict))
}

/// One eigenpair of `B` as a [`Mode`] of the reduced state.
fn mode_of<F: VectorField>(
    field: &F,
    x: &[f64],
    pair: &crate::eigen::EigenPair,
    v: &DMatrix<f64>,
) -> Mode {
    let w = DVector::from_vec(pair.vector.clone());
    let vc: DMatrix<Complex<f64>> = v.map(|e| Complex::new(e, 0.0));
    let shape: Vec<Eigenvalue> = (vc * w)
        .iter()
        .map(|c| Eigenvalue::new(c.re, c.im))
        .collect();
    let space_frequency = field.space_frequency(x, pair.value, &shape);
    Mode {
        eigenvalue: pair.value,
        shape,
        space_frequency,
    }
}
