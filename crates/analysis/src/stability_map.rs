//! [`StabilityMap`]: a steady motion's stability over a grid of one or two
//! parameters — the largest real part at every point — and the
//! boundaries between stable and unstable located by bisection to
//! rounding between grid points, not read off the grid.

use std::num::NonZeroUsize;

use crate::{AnalysisError, Linearisation, Verdict};

/// One swept parameter: `count` evenly spaced values from `from` to `to`
/// (both included).
///
/// ```text
/// p_k = from + (to − from) k/(count − 1),   k = 0 … count − 1
/// ```
///
/// ```
/// use kreisel_analysis::Sweep;
/// let s = Sweep::try_new("spin", 0.0, 10.0, 11)?;
/// assert_eq!(s.value(3), 3.0);
/// assert!(Sweep::try_new("spin", 0.0, 10.0, 1).is_err());
/// # Ok::<(), kreisel_analysis::AnalysisError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Sweep {
    /// The parameter's name (the family's key: `"spin"`, `"tilt"`, …).
    pub name: String,
    /// The first value.
    pub from: f64,
    /// The last value.
    pub to: f64,
    /// How many values (at least 2).
    pub count: usize,
}

impl Sweep {
    /// A sweep of `name` from `from` to `to` in `count` values.
    ///
    /// # Errors
    /// [`AnalysisError::Sweep`] for fewer than 2 values, an end that is not
    /// finite, or `from == to`.
    pub fn try_new(
        name: impl Into<String>,
        from: f64,
        to: f64,
        count: usize,
    ) -> Result<Self, AnalysisError> {
        let name = name.into();
        let why = if count < 2 {
            Some(format!("N = {count}: a sweep needs at least 2 values"))
        } else if !(from.is_finite() && to.is_finite()) {
            Some(format!("the range {from}:{to} is not finite"))
        } else if from == to {
            Some(format!("the range {from}:{to} is empty"))
        } else {
            None
        };
        match why {
            Some(why) => Err(AnalysisError::Sweep { name, why }),
            None => Ok(Self {
                name,
                from,
                to,
                count,
            }),
        }
    }

    /// The `k`-th value (exactly `to` at the end).
    pub fn value(&self, k: usize) -> f64 {
        if k + 1 == self.count {
            return self.to;
        }
        self.from + (self.to - self.from) * (k as f64 / (self.count - 1) as f64)
    }
}

/// What the grid holds at one point.
#[derive(Debug, Clone, PartialEq)]
pub enum GridPoint {
    /// A steady motion, linearised.
    Analysed {
        /// The largest real part of its eigenvalues, 1/s.
        max_real_part: f64,
        /// Its verdict.
        verdict: Verdict,
    },
    /// No steady motion of the family there (e.g. a precession too slow
    /// for its tilt), with the reason.
    Missing {
        /// The error, in words.
        reason: String,
    },
}

impl GridPoint {
    /// Whether the point is analysed and unstable.
    pub fn is_unstable(&self) -> bool {
        matches!(
            self,
            Self::Analysed {
                verdict: Verdict::Unstable { .. },
                ..
            }
        )
    }

    /// Its largest real part, `NaN` where there is no steady motion.
    pub fn max_real_part(&self) -> f64 {
        match self {
            Self::Analysed { max_real_part, .. } => *max_real_part,
            Self::Missing { .. } => f64::NAN,
        }
    }
}

/// A point of a stability boundary: on the segment between two grid
/// neighbours along `axis`, where the verdict turns from unstable to not.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoundaryPoint {
    /// The swept parameters' values there (one or two).
    pub at: [f64; 2],
    /// The axis it was bisected along.
    pub axis: usize,
    /// The bisection bracket's final width in that parameter.
    pub width: f64,
}

/// The stability of a family over a grid.
///
/// ```text
/// value[i + n₀ j] = max Re λ at (p₀ᵢ, p₁ⱼ)      (axis 0 fastest)
/// boundary: bisection on "unstable?" between grid neighbours that differ,
///           until the bracket is 4 ulp wide (or 200 halvings)
/// ```
///
/// Where two eigenvalues collide on the imaginary axis (a Krein collision,
/// the sleeping top) the growth rate rises like `√δ` from the boundary, so
/// "unstable" (`Re λ > 1e-7 |λ|`, [`crate::GROWTH_TOLERANCE`]) starts
/// `δ ≈ 1e-14` relative past it: the boundary's bias (measured 4.4e-14 for
/// the sleeping top below). A growth rate that crosses zero linearly (a
/// Hopf bifurcation of a dissipative body) is found to 1e-7 of its
/// slope's scale.
///
/// ```
/// use glam::DVec3;
/// use kreisel_analysis::{HeavyTopPivot, Linearisation, StabilityMap, Sweep};
/// // J = (2, 2, 1) about the pivot, l = 0.1 m, M g = 10 N: Ω_c = √8.
/// let top = HeavyTopPivot::try_new(DVec3::new(2.0, 2.0, 1.0), DVec3::new(0.0, 0.0, 0.1), 10.0)?;
/// let map = StabilityMap::try_new(&[Sweep::try_new("spin", 0.5, 5.0, 10)?], None, |p| {
///     Linearisation::try_new(&top, &top.sleeping(p[0])?)
/// })?;
/// assert_eq!(map.boundaries.len(), 1);
/// assert!((map.boundaries[0].at[0] / 8f64.sqrt() - 1.0).abs() < 1e-12);
/// # Ok::<(), kreisel_analysis::AnalysisError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct StabilityMap {
    /// The swept parameters (one or two).
    pub axes: Vec<Sweep>,
    /// Every grid point, axis 0 fastest.
    pub points: Vec<GridPoint>,
    /// The boundary points found between grid neighbours.
    pub boundaries: Vec<BoundaryPoint>,
}

/// Bisection steps at most (a bracket of any width reaches 4 ulp in fewer).
const MAX_HALVINGS: usize = 200;

/// Two grid neighbours whose verdicts differ: a boundary lies between.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BoundaryEdge {
    /// The first point's index (axis 0 fastest).
    pub from: usize,
    /// Its neighbour's, one step along `axis`.
    pub to: usize,
    /// The axis between them.
    pub axis: usize,
    /// Whether the first point is unstable (the second is not, or the
    /// other way round).
    pub from_unstable: bool,
}

/// The parameters' values at grid point `index` of `axes` (axis 0
/// fastest).
///
/// ```
/// use kreisel_analysis::{Sweep, grid_point};
/// let axes = [Sweep::try_new("spin", 0.0, 2.0, 3)?, Sweep::try_new("tilt", 0.0, 1.0, 2)?];
/// assert_eq!(grid_point(&axes, 4), vec![1.0, 1.0]);
/// # Ok::<(), kreisel_analysis::AnalysisError>(())
/// ```
pub fn grid_point(axes: &[Sweep], index: usize) -> Vec<f64> {
    let n0 = axes.first().map_or(1, |a| a.count);
    let (i, j) = (index % n0, index / n0);
    let mut p = vec![axes[0].value(i)];
    if let Some(a) = axes.get(1) {
        p.push(a.value(j));
    }
    p
}

/// Every pair of grid neighbours where "unstable?" changes; `None` (no
/// steady motion there) takes part in none.
///
/// ```text
/// (k, k + 1) along axis 0,  (k, k + n₀) along axis 1,  unstable[k] ≠ unstable[next]
/// ```
pub fn boundary_edges(axes: &[Sweep], unstable: &[Option<bool>]) -> Vec<BoundaryEdge> {
    let shape = [axes[0].count, axes.get(1).map_or(1, |a| a.count)];
    let mut found = Vec::new();
    for index in 0..(shape[0] * shape[1]).min(unstable.len()) {
        let (i, j) = (index % shape[0], index / shape[0]);
        for (axis, next) in [
            (0, (i + 1 < shape[0]).then_some(index + 1)),
            (1, (j + 1 < shape[1]).then_some(index + shape[0])),
        ] {
            let Some(next) = next else { continue };
            if let (Some(Some(a)), Some(Some(b))) = (unstable.get(index), unstable.get(next))
                && a != b
            {
                found.push(BoundaryEdge {
                    from: index,
                    to: next,
                    axis,
                    from_unstable: *a,
                });
            }
        }
    }
    found
}

/// The boundary on `edge` by bisection on `unstable` (which returns
/// `None` where no steady motion exists: then no boundary).
///
/// ```text
/// halve [p_from, p_to] along the edge's axis until 4 ulp wide (or 200 halvings)
/// ```
pub fn bisect_boundary(
    axes: &[Sweep],
    edge: BoundaryEdge,
    unstable: impl Fn(&[f64]) -> Option<bool>,
) -> Option<BoundaryPoint> {
    bisect(
        &grid_point(axes, edge.from),
        &grid_point(axes, edge.to),
        edge.axis,
        edge.from_unstable,
        &unstable,
    )
}

impl StabilityMap {
    /// The map of `analyse` (the linearisation at the parameters' values,
    /// in the order of `axes`) over the grid of `axes`, on `threads`
    /// threads (default: the machine's).
    ///
    /// # Errors
    /// [`AnalysisError::Sweep`] for no axis or more than two. A grid point
    /// whose `analyse` fails is [`GridPoint::Missing`], not an error.
    pub fn try_new<F>(
        axes: &[Sweep],
        threads: Option<NonZeroUsize>,
        analyse: F,
    ) -> Result<Self, AnalysisError>
    where
        F: Fn(&[f64]) -> Result<Linearisation, AnalysisError> + Sync,
    {
        if axes.is_empty() || axes.len() > 2 {
            return Err(AnalysisError::Sweep {
                name: axes
                    .iter()
                    .map(|a| a.name.as_str())
                    .collect::<Vec<_>>()
                    .join(", "),
                why: format!("{} parameters: a map sweeps one or two", axes.len()),
            });
        }
        let shape = [axes[0].count, axes.get(1).map_or(1, |a| a.count)];
        let point = |index: usize| match analyse(&grid_point(axes, index)) {
            Ok(lin) => GridPoint::Analysed {
                max_real_part: lin.max_real_part(),
                verdict: lin.verdict,
            },
            Err(e) => GridPoint::Missing {
                reason: e.to_string(),
            },
        };
        let points = in_parallel(shape[0] * shape[1], threads, point);
        let flags: Vec<Option<bool>> = points
            .iter()
            .map(|p| match p {
                GridPoint::Missing { .. } => None,
                analysed => Some(analysed.is_unstable()),
            })
            .collect();
        let edges = boundary_edges(axes, &flags);
        let unstable = |p: &[f64]| {
            analyse(p)
                .ok()
                .map(|lin| matches!(lin.verdict, Verdict::Unstable { .. }))
        };
        let boundaries = in_parallel(edges.len(), threads, |k| {
            bisect_boundary(axes, edges[k], unstable)
        })
        .into_iter()
        .flatten()
        .collect();
        Ok(Self {
            axes: axes.to_vec(),
            points,
            boundaries,
        })
    }

    /// The grid's shape `[n₀, n₁]` (`n₁ = 1` for one axis).
    pub fn shape(&self) -> [usize; 2] {
        [self.axes[0].count, self.axes.get(1).map_or(1, |a| a.count)]
    }

    /// The largest real parts, axis 0 fastest (`NaN` where no steady
    /// motion exists).
    pub fn max_real_parts(&self) -> Vec<f64> {
        self.points.iter().map(GridPoint::max_real_part).collect()
    }
}

/// Bisects between `lo` (unstable: `lo_unstable`) and `hi` along `axis`.
fn bisect(
    lo: &[f64],
    hi: &[f64],
    axis: usize,
    lo_unstable: bool,
    unstable: &impl Fn(&[f64]) -> Option<bool>,
) -> Option<BoundaryPoint> {
    let (mut a, mut b) = (lo[axis], hi[axis]);
    let mut p = lo.to_vec();
    for _ in 0..MAX_HALVINGS {
        let mid = 0.5 * (a + b);
        if (b - a).abs() <= 4.0 * f64::EPSILON * a.abs().max(b.abs()) || mid == a || mid == b {
            break;
        }
        p[axis] = mid;
        if unstable(&p)? == lo_unstable {
            a = mid;
        } else {
            b = mid;
        }
    }
    p[axis] = 0.5 * (a + b);
    let mut at = [p[0], f64::NAN];
    if p.len() > 1 {
        at[1] = p[1];
    }
    Some(BoundaryPoint {
        at,
        axis,
        width: (b - a).abs(),
    })
}

/// `f(0), …, f(n − 1)` on `threads` scoped threads, in order.
fn in_parallel<T: Send>(
    n: usize,
    threads: Option<NonZeroUsize>,
    f: impl Fn(usize) -> T + Sync,
) -> Vec<T> {
    let threads = threads
        .or_else(|| std::thread::available_parallelism().ok())
        .map_or(1, NonZeroUsize::get)
        .min(n.max(1));
    if threads == 1 {
        return (0..n).map(f).collect();
    }
    let chunk = n.div_ceil(threads);
    std::thread::scope(|scope| {
        let handles: Vec<_> = (0..threads)
            .map(|t| {
                let f = &f;
                scope.spawn(move || {
                    (t * chunk..((t + 1) * chunk).min(n))
                        .map(f)
                        .collect::<Vec<T>>()
                })
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)))
            .collect()
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::FreeBodyRotation;
    use glam::DVec3;

    #[test]
    fn sweeps_refuse_bad_ranges_and_maps_bad_axes() {
        for (from, to, n) in [(0.0, 1.0, 1), (0.0, f64::INFINITY, 5), (1.0, 1.0, 5)] {
            assert!(matches!(
                Sweep::try_new("spin", from, to, n),
                Err(AnalysisError::Sweep { .. })
            ));
        }
        let s = Sweep::try_new("spin", 0.0, 1.0, 3).unwrap();
        let f = FreeBodyRotation::try_new(DVec3::new(1.0, 2.0, 3.0)).unwrap();
        let analyse = |p: &[f64]| Linearisation::try_new(&f, &f.about_axis(1, p[0])?);
        assert!(StabilityMap::try_new(&[], None, analyse).is_err());
        assert!(StabilityMap::try_new(&[s.clone(), s.clone(), s], None, analyse).is_err());
    }

    #[test]
    fn threads_do_not_change_the_map() {
        let f = FreeBodyRotation::try_new(DVec3::new(1.0, 2.0, 3.0)).unwrap();
        let axes = [Sweep::try_new("spin", -2.0, 3.0, 17).unwrap()];
        let analyse = |p: &[f64]| Linearisation::try_new(&f, &f.about_axis(1, p[0])?);
        let one = StabilityMap::try_new(&axes, NonZeroUsize::new(1), analyse).unwrap();
        let three = StabilityMap::try_new(&axes, NonZeroUsize::new(3), analyse).unwrap();
        assert_eq!(one, three);
        // σ = |Ω|/√3 > 0 at every grid point (Ω = 0 is not on it).
        assert!(one.boundaries.is_empty() && one.points.iter().all(GridPoint::is_unstable));
    }
}
