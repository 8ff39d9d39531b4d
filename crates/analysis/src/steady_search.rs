//! [`find_steady_motion`]: the steady motion nearest a given state, by
//! Newton's method with minimum-norm steps (the Jacobian is singular
//! there: each conserved quantity and symmetry makes a family).

use nalgebra::{DMatrix, DVector};

use crate::linearisation::{check_state, relative_residual};
use crate::vector_field::{conserved_gradients, jacobian, rates_at};
use crate::{AnalysisError, STEADY_RESIDUAL, VectorField, ZeroMode, ZeroModeKind};

/// Newton steps before giving up.
const MAX_ITERATIONS: usize = 40;

/// Singular values of the scaled Jacobian below this fraction of the
/// largest are dropped from a step (a family of steady motions).
const CUT: f64 = 1e-7;

/// A steady motion is near a state if no component differs from the
/// state's by more than this fraction of its size
/// ([`crate::VectorField::state_scales`]: `|x₀|` unless the family says).
pub const NEARBY: f64 = 0.05;

/// A steady motion found from a start.
#[derive(Debug, Clone, PartialEq)]
pub struct SteadyMotion {
    /// The steady state `x*`.
    pub state: Vec<f64>,
    /// The start's relative residual `|f(x₀)| / (‖A‖ |x₀|)`.
    pub start_residual: f64,
    /// The found state's.
    pub residual: f64,
    /// `|x* − x₀|`, in the state's units.
    pub distance: f64,
    /// Newton steps taken.
    pub iterations: usize,
}

/// The steady motion (`f(x*) = 0`) near `start` with the start's values of
/// every Casimir and momentum: Gauss–Newton on the equations and those
/// levels together, with minimum-norm steps (the energy–momentum picture:
/// a relative equilibrium on the start's momentum level).
///
/// ```text
/// g(x) = [f(x); C_k(x) − C_k(x₀)],   x_{j+1} = x_j − J⁺ g(x_j),   J = [A; ∇C_k]
/// J's columns scaled by each component's size, J⁺ from the SVD with
/// singular values below 1e-7 σ_max dropped (directions along a family)
/// ```
///
/// # Errors
/// [`AnalysisError::NoSteadyMotionNearby`] (with the residuals) if the
/// relative residual does not reach [`STEADY_RESIDUAL`] within
/// [`NEARBY`] of the start; the state's own
/// errors as [`crate::Linearisation::try_new`].
///
/// ```
/// use glam::DVec3;
/// use kreisel_analysis::{FreeBodyRotation, find_steady_motion};
/// let family = FreeBodyRotation::try_new(DVec3::new(1.0, 2.0, 3.0))?;
/// // Nearly about the largest axis: the search lands on it.
/// let found = find_steady_motion(&family, &[1e-3, -2e-3, 5.0])?;
/// assert!(found.state[0].abs() < 1e-12 && found.state[1].abs() < 1e-12);
/// # Ok::<(), kreisel_analysis::AnalysisError>(())
/// ```
pub fn find_steady_motion<F: VectorField>(
    field: &F,
    start: &[f64],
) -> Result<SteadyMotion, AnalysisError> {
    check_state(field, start)?;
    let mut x = DVector::from_column_slice(start);
    // The Jacobian at x, carried from one step to the next.
    let mut a = jacobian(field, start);
    let start_residual = relative_residual(field, start, &a);
    let (mut best, mut best_x, mut iterations) = (start_residual, x.clone(), 0);
    // The levels the search keeps: each Casimir and momentum of the start.
    let kept =
        |mode: &ZeroMode| matches!(mode.kind, ZeroModeKind::Casimir | ZeroModeKind::Momentum);
    let levels: Vec<f64> = conserved_gradients(field, start)
        .into_iter()
        .filter(|(mode, _, _)| kept(mode))
        .map(|(_, value, _)| value)
        .collect();
    let n = field.dim();
    let scales = DVector::from_iterator(
        n,
        field
            .state_scales(start)
            .into_iter()
            .map(|s| if s > 0.0 { s } else { 1.0 }),
    );
    while iterations < MAX_ITERATIONS && best > f64::EPSILON {
        let levels_here: Vec<(ZeroMode, f64, Vec<f64>)> = conserved_gradients(field, x.as_slice())
            .into_iter()
            .filter(|(mode, _, _)| kept(mode))
            .collect();
        let rows = n + levels_here.len();
        let f = rates_at(field, x.as_slice());
        let mut j = DMatrix::zeros(rows, n);
        j.view_mut((0, 0), (n, n)).copy_from(&a);
        let mut g = DVector::zeros(rows);
        g.rows_mut(0, n).copy_from_slice(&f);
        for (k, ((_, value, gradient), level)) in levels_here.iter().zip(&levels).enumerate() {
            g[n + k] = value - level;
            for (i, d) in gradient.iter().enumerate() {
                j[(n + k, i)] = *d;
            }
        }
        // Columns in units of each component's size; directions whose
        // singular value is below 1e-7 of the largest run along a family
        // of steady motions (to that accuracy) and are not taken.
        for (k, scale) in scales.iter().enumerate() {
            j.column_mut(k).scale_mut(*scale);
        }
        let svd = j.svd(true, true);
        let cut = CUT * svd.singular_values.max();
        let Ok(step) = svd.solve(&g, cut) else { break };
        x -= step.component_mul(&scales);
        iterations += 1;
        if !x.iter().all(|v| v.is_finite()) {
            break;
        }
        a = jacobian(field, x.as_slice());
        let r = relative_residual(field, x.as_slice(), &a);
        if r < best {
            (best, best_x) = (r, x.clone());
        } else if best <= STEADY_RESIDUAL {
            break;
        }
    }
    let distance = (&best_x - DVector::from_column_slice(start)).norm();
    // The largest change of a component in units of its size.
    let relative_distance = scales
        .iter()
        .zip(best_x.iter().zip(start))
        .map(|(scale, (a, b))| (a - b).abs() / scale)
        .fold(0.0, f64::max);
    if best > STEADY_RESIDUAL || best.is_nan() || relative_distance > NEARBY {
        return Err(AnalysisError::NoSteadyMotionNearby {
            start: start_residual,
            best,
            iterations,
            relative_distance,
            limit: NEARBY,
        });
    }
    Ok(SteadyMotion {
        distance,
        state: best_x.as_slice().to_vec(),
        start_residual,
        residual: best,
        iterations,
    })
}
