//! The mesh's own power-of-two unit of length, so that welding, checking
//! and integrating do not depend on the units the mesh is given in.
//!
//! A mesh `2^k` across is worked on in units of `2^k` (its extent becomes
//! about 1), and lengths, areas, volumes and moments are scaled back by
//! `2^k`, `2^{2k}`, `2^{3k}`, `2^{5k}`. Multiplying by a power of two is
//! exact in f64 unless the result leaves the normal range, so a mesh that
//! needs no rescaling (extent between `2^-64` and `2^64`, every ordinary
//! part in metres or millimetres) is left as it is and gives the same bits
//! as without this step, and a mesh scaled by `2^j` gives the unscaled
//! results times exact powers of two, whatever `j`. Only the results
//! themselves can leave f64 (a 1e120 m cube's volume, 8e360 m³), and that
//! is reported as such ([`crate::InertiaError::MeshOutOfRange`]).

use glam::DVec3;

use crate::InertiaError;

/// Meshes whose extent has a binary exponent within `±FREE` are worked on
/// in their own units: up to `2^64` across, their fifth moments and squared
/// tolerances stay far inside f64 (`2^±320` and more).
const FREE: i32 = 64;

/// `2^e` for `e` in `-1022..=1023`.
fn pow2(e: i32) -> f64 {
    debug_assert!((-1022..=1023).contains(&e));
    f64::from_bits(((e + 1023) as u64) << 52)
}

/// `x · 2^e`, exact whenever the result (and so every step towards it) is
/// a normal number; overflows to ±∞ and underflows towards 0 otherwise.
///
/// ```text
/// ldexp(x, e) = x · 2^e
/// ```
pub(crate) fn ldexp(mut x: f64, mut e: i32) -> f64 {
    while e != 0 && x != 0.0 && x.is_finite() {
        let step = e.clamp(-1000, 1000);
        x *= pow2(step);
        e -= step;
    }
    x
}

/// `⌊log2 |x|⌋` for a finite non-zero `x` (subnormals included).
pub(crate) fn exponent(x: f64) -> i32 {
    let biased = ((x.abs().to_bits() >> 52) & 0x7ff) as i32;
    if biased == 0 {
        exponent(x * pow2(64)) - 64
    } else {
        biased - 1023
    }
}

/// The unit of length `2^k` a mesh is worked on in, and the point its
/// coordinates are taken from.
///
/// ```text
/// v = offset + 2^k · v_unit
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct MeshUnit {
    /// The binary exponent of the unit (0: the mesh's own units).
    pub(crate) k: i32,
    /// Subtracted before scaling (zero unless scaling a small mesh far from
    /// the origin up would overflow its coordinates).
    pub(crate) offset: DVec3,
}

impl MeshUnit {
    /// The unit for these vertices: `2^k` with the largest axis-aligned
    /// extent in `[2^k, 2^(k+1))`, or 1 when that is within `2^±64`.
    pub(crate) fn of(vertices: &[DVec3]) -> Self {
        let k = extent_exponent(vertices).map_or(0, |e| if e.abs() <= FREE { 0 } else { e });
        let mut unit = Self {
            k,
            offset: DVec3::ZERO,
        };
        if k < 0 {
            // Scaling up: a small mesh far from the origin would overflow.
            let largest = vertices
                .iter()
                .fold(0.0_f64, |a, v| a.max(v.abs().max_element()));
            if exponent_or_min(largest) - k >= 1000 {
                unit.offset = vertices[0];
            }
        }
        unit
    }

    /// Whether the mesh is worked on as it is.
    pub(crate) fn is_identity(&self) -> bool {
        self.k == 0 && self.offset == DVec3::ZERO
    }

    /// A point in units of `2^k` relative to the offset.
    pub(crate) fn point_in_unit(&self, v: DVec3) -> DVec3 {
        (v - self.offset)
            .to_array()
            .map(|x| ldexp(x, -self.k))
            .into()
    }

    /// A point back in the mesh's units.
    pub(crate) fn point_back(&self, v: DVec3) -> DVec3 {
        let v = DVec3::from(v.to_array().map(|x| ldexp(x, self.k)));
        // Not `+ 0.0`, which would turn −0.0 into +0.0.
        if self.offset == DVec3::ZERO {
            v
        } else {
            v + self.offset
        }
    }

    /// A quantity of dimension `length^power` back in the mesh's units.
    pub(crate) fn scale_back(&self, x: f64, power: i32) -> f64 {
        ldexp(x, power * self.k)
    }

    /// `log10` of a quantity of dimension `length^power` given in units of
    /// `2^k` (finite where the quantity itself is not).
    pub(crate) fn log10_back(&self, x: f64, power: i32) -> f64 {
        x.abs().log10() + f64::from(power * self.k) * core::f64::consts::LOG10_2
    }
}

impl MeshUnit {
    /// An error of the mesh checks with its places back in the mesh's units.
    pub(crate) fn error_back(&self, error: InertiaError) -> InertiaError {
        match error {
            InertiaError::OpenMesh {
                boundary_edges,
                at,
                weld_gap,
            } => InertiaError::OpenMesh {
                boundary_edges,
                at: self.point_back(at),
                weld_gap: weld_gap.map(|g| self.scale_back(g, 1)),
            },
            InertiaError::NonManifold { edges, at } => InertiaError::NonManifold {
                edges,
                at: self.point_back(at),
            },
            other => other,
        }
    }
}

/// `⌊log2 |x|⌋`, or the smallest exponent for 0.
fn exponent_or_min(x: f64) -> i32 {
    if x == 0.0 { -1074 } else { exponent(x) }
}

/// `⌊log2⌋` of the largest axis-aligned extent, `None` for a single point
/// (or no vertices).
pub(crate) fn extent_exponent(vertices: &[DVec3]) -> Option<i32> {
    let (lo, hi) = bounds(vertices)?;
    // Halved first, so that an extent beyond f64::MAX does not overflow.
    let half = (hi * 0.5 - lo * 0.5).max_element();
    (half > 0.0).then(|| exponent(half) + 1)
}

/// The axis-aligned bounding box, `None` without vertices.
pub(crate) fn bounds(vertices: &[DVec3]) -> Option<(DVec3, DVec3)> {
    let first = *vertices.first()?;
    Some(
        vertices
            .iter()
            .fold((first, first), |(lo, hi), &v| (lo.min(v), hi.max(v))),
    )
}

/// The diagonal of the axis-aligned bounding box in units of `unit`.
pub(crate) fn diagonal_in(vertices: &[DVec3], unit: &MeshUnit) -> f64 {
    bounds(vertices).map_or(0.0, |(lo, hi)| {
        (unit.point_in_unit(hi) - unit.point_in_unit(lo)).length()
    })
}

/// The diagonal of the axis-aligned bounding box (∞ beyond `f64::MAX`,
/// but never ∞ from an intermediate overflow, nor 0 from an underflow).
pub(crate) fn bounding_diagonal(vertices: &[DVec3]) -> f64 {
    let unit = MeshUnit::of(vertices);
    unit.scale_back(diagonal_in(vertices, &unit), 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ldexp_is_exact_across_the_whole_range() {
        for e in [-1074, -1030, -1023] {
            assert_eq!(ldexp(1.0, e), f64::from_bits(1 << (e + 1074)), "{e}");
        }
        for e in [-1022, -600, -1, 0, 1, 600, 1023] {
            assert_eq!(ldexp(1.0, e), 2f64.powi(e), "{e}");
        }
        assert_eq!(ldexp(1.5, 2000), f64::INFINITY);
        assert_eq!(ldexp(1.5, -2000), 0.0);
        assert_eq!(ldexp(ldexp(3.0, 1020), -2040), ldexp(3.0, -1020));
        assert_eq!(ldexp(ldexp(0.3, -900), 900), 0.3);
    }

    #[test]
    fn exponent_of_normals_and_subnormals() {
        assert_eq!(exponent(1.0), 0);
        assert_eq!(exponent(-3.0), 1);
        assert_eq!(exponent(0.75), -1);
        assert_eq!(exponent(f64::MAX), 1023);
        assert_eq!(exponent(f64::MIN_POSITIVE), -1022);
        assert_eq!(exponent(5e-324), -1074);
    }

    #[test]
    fn units_of_ordinary_tiny_huge_and_far_meshes() {
        let cube = |s: f64, at: f64| vec![DVec3::splat(at - s), DVec3::splat(at + s)];
        assert!(MeshUnit::of(&cube(0.5, 0.0)).is_identity());
        assert!(MeshUnit::of(&cube(1e15, 3e17)).is_identity());
        let huge = MeshUnit::of(&cube(1e200, 0.0));
        assert_eq!((huge.k, huge.offset), (665, DVec3::ZERO));
        let tiny = MeshUnit::of(&cube(1e-200, 0.0));
        assert_eq!((tiny.k, tiny.offset), (-664, DVec3::ZERO));
        // Flat in x at 1e300, 1e-200 across in y: scaled up only about a vertex.
        let flat = [DVec3::new(1e300, 0.0, 0.0), DVec3::new(1e300, 1e-200, 0.0)];
        let far = MeshUnit::of(&flat);
        assert_eq!((far.k, far.offset), (-665, flat[0]));
        let v = far.point_in_unit(flat[1]);
        assert!(v.x == 0.0 && (1.0..2.0).contains(&v.y), "{v}");
        assert_eq!(far.point_back(v), flat[1]);
        assert!(MeshUnit::of(&[DVec3::ONE]).is_identity());
        assert_eq!(MeshUnit::of(&cube(f64::MAX, 0.0)).k, 1024);
    }
}
