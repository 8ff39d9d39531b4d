//! The polhode of a free rigid body: the path of its angular momentum on
//! the momentum sphere in principal axes, and the separatrices that divide
//! the sphere into the regions of rotation about the smallest and the
//! largest axis (notes §2, Euler's equations and the two integrals).
//!
//! With principal moments I₁ < I₂ < I₃ and m = L / |L| in principal axes,
//! the motion keeps both
//!
//! ```text
//! |m|² = m₁² + m₂² + m₃² = 1                       (momentum sphere)
//! m₁²/I₁ + m₂²/I₂ + m₃²/I₃ = 2E / L²               (energy ellipsoid)
//! ```
//!
//! The separatrix is the level 2E = L²/I₂ (the unstable rotation about the
//! middle axis). Subtracting the sphere divided by I₂ leaves
//! `m₁² (1/I₁ − 1/I₂) = m₃² (1/I₂ − 1/I₃)`, two planes through the middle
//! axis:
//!
//! ```text
//! m₁ / m₃ = ± k,   k = √( I₁ (I₃ − I₂) / (I₃ (I₂ − I₁)) )
//! ```
//!
//! whose intersections with the sphere are two great circles through ±e₂.
//! (`kreisel simulate --plot` draws them dashed.)

use glam::DVec3;

/// Relative gap below which two principal moments count as equal (the
/// body is symmetric: the separatrices degenerate).
const EQUAL_MOMENTS: f64 = 1e-9;

/// The slope `k = m₁/m₃` of the separatrix planes for ascending principal
/// moments `I₁ ≤ I₂ ≤ I₃`; `None` when two moments are equal within
/// a relative 1e-9 (a symmetric body or a sphere has no separatrix).
///
/// ```text
/// k = √( I₁ (I₃ − I₂) / (I₃ (I₂ − I₁)) )
/// ```
///
/// ```
/// use glam::DVec3;
/// use kreisel_dynamics::polhode::separatrix_slope;
/// // I = (1, 2, 3): k² = 1·1 / (3·1).
/// let k = separatrix_slope(DVec3::new(1.0, 2.0, 3.0)).unwrap();
/// assert!((k * k - 1.0 / 3.0).abs() < 1e-15);
/// assert_eq!(separatrix_slope(DVec3::new(1.0, 1.0, 3.0)), None);
/// ```
pub fn separatrix_slope(moments: DVec3) -> Option<f64> {
    let [i1, i2, i3] = moments.to_array();
    let scale = i3.abs().max(f64::MIN_POSITIVE);
    if (i2 - i1) <= EQUAL_MOMENTS * scale || (i3 - i2) <= EQUAL_MOMENTS * scale {
        return None;
    }
    Some((i1 * (i3 - i2) / (i3 * (i2 - i1))).sqrt())
}

/// The two separatrices on the unit sphere in principal axes, `n` + 1
/// points each (closed great circles through ±e₂ in the planes
/// m₁ = ±k m₃); `None` as for [`separatrix_slope`].
///
/// ```text
/// m(s) = cos s · (±k, 0, 1)/√(1 + k²) + sin s · e₂,   s = 2π j / n
/// ```
///
/// ```
/// use glam::DVec3;
/// use kreisel_dynamics::polhode::separatrices;
/// let moments = DVec3::new(1.0, 2.0, 3.0);
/// let [a, b] = separatrices(moments, 8).unwrap();
/// // On the sphere and on the energy ellipsoid 2E = L²/I₂ (|L| = 1).
/// for m in a.iter().chain(&b) {
///     assert!((m.length() - 1.0).abs() < 1e-15);
///     let two_e = (*m * *m / moments).element_sum();
///     assert!((two_e - 0.5).abs() < 1e-15);
/// }
/// ```
pub fn separatrices(moments: DVec3, n: usize) -> Option<[Vec<DVec3>; 2]> {
    let k = separatrix_slope(moments)?;
    let circle = |sign: f64| {
        // In-plane unit vectors: the middle axis and (±k, 0, 1)/√(1 + k²).
        let u = DVec3::new(sign * k, 0.0, 1.0).normalize();
        (0..=n)
            .map(|j| {
                let s = std::f64::consts::TAU * j as f64 / n.max(1) as f64;
                u * s.cos() + DVec3::Y * s.sin()
            })
            .collect()
    };
    Some([circle(1.0), circle(-1.0)])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every point of both curves, scaled to |L|, lies on the momentum sphere
    /// and on the energy ellipsoid of 2E = L²/I₂.
    #[test]
    fn separatrix_points_lie_on_the_sphere_and_the_middle_ellipsoid() {
        for moments in [
            DVec3::new(1.0, 2.0, 3.0),
            DVec3::new(0.02, 0.021, 0.5),
            DVec3::new(1e-3, 7.0, 7.5),
            DVec3::new(3.0, 5.0, 5.0 + 1e-6),
        ] {
            let [a, b] = separatrices(moments, 720).expect("distinct moments");
            let l = 3.7;
            for m in a.iter().chain(&b) {
                let big_l = *m * l;
                let sphere = big_l.length_squared() / (l * l);
                let energy2 = big_l.x * big_l.x / moments.x
                    + big_l.y * big_l.y / moments.y
                    + big_l.z * big_l.z / moments.z;
                assert!((sphere - 1.0).abs() < 1e-14, "{moments} {m}");
                let middle = l * l / moments.y;
                assert!(
                    (energy2 - middle).abs() < 1e-13 * (l * l / moments.x),
                    "{moments} {m}: 2E {energy2} vs L²/I₂ {middle}"
                );
            }
            // Through the middle axis, and symmetric about the 1–2 and 2–3 planes.
            assert!((a[180] - DVec3::Y).length() < 1e-15);
            assert_eq!(b[0], DVec3::new(-a[0].x, a[0].y, a[0].z));
        }
    }

    #[test]
    fn symmetric_bodies_have_no_separatrix() {
        assert!(separatrix_slope(DVec3::new(1.0, 1.0, 2.0)).is_none());
        assert!(separatrix_slope(DVec3::new(1.0, 2.0, 2.0)).is_none());
        assert!(separatrix_slope(DVec3::splat(1.0)).is_none());
        // 1, 2, 3: k² = 1·1 / (3·1).
        let k = separatrix_slope(DVec3::new(1.0, 2.0, 3.0)).unwrap();
        assert!((k * k - 1.0 / 3.0).abs() < 1e-16);
    }
}
