//! Closed-form mass properties of primitive solids, centred in their own
//! frame (symmetry axis along z).
//!
//! Formulas: Goldstein, *Classical Mechanics*, ch. 5; any table of moments of
//! inertia (e.g. Gere & Timoshenko). Each is checked in the tests against a
//! fine triangle mesh of the same solid, integrated exactly.

use core::f64::consts::PI;

use glam::{DMat3, DVec3};

use crate::mass_properties::{check_positive, representable};
use crate::{InertiaError, MassProperties};

/// A body symmetric about z with moments `i_perp` (x, y) and `i_axis` (z).
fn symmetric(mass: f64, center_of_mass: DVec3, i_perp: f64, i_axis: f64) -> MassProperties {
    MassProperties {
        mass,
        center_of_mass,
        inertia: DMat3::from_diagonal(DVec3::new(i_perp, i_perp, i_axis)),
    }
}

impl MassProperties {
    /// A solid sphere of uniform density, centred at the origin.
    ///
    /// ```text
    /// m = ρ 4/3 π r³,   I = 2/5 m r² E
    /// ```
    ///
    /// # Errors
    /// [`InertiaError::NonPositive`] for a density or radius that is not positive and finite.
    /// [`InertiaError::NotRepresentable`] when the mass or a moment overflows
    /// f64 (or the mass underflows to zero).
    ///
    /// ```
    /// use kreisel_inertia::MassProperties;
    /// let s = MassProperties::solid_sphere(1000.0, 0.1)?;
    /// assert!((s.mass - 4.18879020478639).abs() < 1e-13);
    /// assert!((s.inertia.x_axis.x - 0.4 * s.mass * 0.01).abs() < 1e-16);
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn solid_sphere(density: f64, radius: f64) -> Result<Self, InertiaError> {
        check_positive("density", density)?;
        check_positive("radius", radius)?;
        let m = density * 4.0 / 3.0 * PI * radius.powi(3);
        let i = 0.4 * m * radius * radius;
        representable(symmetric(m, DVec3::ZERO, i, i))
    }

    /// A hollow sphere (spherical shell of finite thickness) between radii
    /// `inner < outer`.
    ///
    /// ```text
    /// m = ρ 4/3 π (R³ − r³),   I = 2/5 m (R⁵ − r⁵)/(R³ − r³)
    ///   = 2/5 m (R⁴ + R³r + R²r² + Rr³ + r⁴)/(R² + Rr + r²)   (no cancellation)
    /// ```
    ///
    /// `inner = 0` is the solid sphere; as `inner → outer` the moment tends
    /// to the thin shell's `2/3 m R²`.
    ///
    /// # Errors
    /// [`InertiaError::NonPositive`] for a density or outer radius that is not
    /// positive, or an inner radius not in `[0, outer)`.
    /// [`InertiaError::NotRepresentable`] when the mass or a moment overflows
    /// f64 (or the mass underflows to zero).
    ///
    /// ```
    /// use kreisel_inertia::MassProperties;
    /// let thin = MassProperties::hollow_sphere(1.0, 1.0 - 1e-9, 1.0)?;
    /// assert!((thin.inertia.x_axis.x / thin.mass - 2.0 / 3.0).abs() < 1e-8);
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn hollow_sphere(density: f64, inner: f64, outer: f64) -> Result<Self, InertiaError> {
        check_positive("density", density)?;
        check_positive("outer radius", outer)?;
        if !(0.0..outer).contains(&inner) {
            return Err(InertiaError::NonPositive {
                quantity: "wall thickness (outer − inner radius)",
                value: outer - inner,
            });
        }
        let (a, b) = (outer, inner);
        let q = a * a + a * b + b * b;
        let m = density * 4.0 / 3.0 * PI * (a - b) * q;
        let ratio = (a.powi(4) + a.powi(3) * b + a * a * b * b + a * b.powi(3) + b.powi(4)) / q;
        let i = 0.4 * m * ratio;
        representable(symmetric(m, DVec3::ZERO, i, i))
    }

    /// A solid rectangular box with edge lengths `size` along x, y, z, centred at the origin.
    ///
    /// ```text
    /// m = ρ a b c,   I = m/12 diag(b² + c², a² + c², a² + b²)
    /// ```
    ///
    /// # Errors
    /// [`InertiaError::NonPositive`] for a density or edge that is not positive and finite.
    /// [`InertiaError::NotRepresentable`] when the mass or a moment overflows
    /// f64 (or the mass underflows to zero).
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::MassProperties;
    /// let b = MassProperties::solid_box(1.0, DVec3::new(1.0, 2.0, 3.0))?;
    /// assert_eq!(b.mass, 6.0);
    /// assert_eq!(b.inertia.x_axis.x, 6.5);
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn solid_box(density: f64, size: DVec3) -> Result<Self, InertiaError> {
        check_positive("density", density)?;
        for e in size.to_array() {
            check_positive("box edge", e)?;
        }
        let m = density * size.x * size.y * size.z;
        let s = size * size;
        representable(Self {
            mass: m,
            center_of_mass: DVec3::ZERO,
            inertia: DMat3::from_diagonal(DVec3::new(s.y + s.z, s.x + s.z, s.x + s.y) * (m / 12.0)),
        })
    }

    /// A solid circular cylinder of `radius` and `height` along z, centred at the origin.
    ///
    /// ```text
    /// m = ρ π r² h,   I_zz = m r²/2,   I_xx = I_yy = m (3r² + h²)/12
    /// ```
    ///
    /// # Errors
    /// [`InertiaError::NonPositive`] for a density or dimension that is not positive and finite.
    /// [`InertiaError::NotRepresentable`] when the mass or a moment overflows
    /// f64 (or the mass underflows to zero).
    ///
    /// ```
    /// use kreisel_inertia::MassProperties;
    /// let c = MassProperties::solid_cylinder(1.0, 1.0, 2.0)?;
    /// assert!((c.inertia.z_axis.z - c.mass / 2.0).abs() < 1e-15);
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn solid_cylinder(density: f64, radius: f64, height: f64) -> Result<Self, InertiaError> {
        check_positive("density", density)?;
        check_positive("radius", radius)?;
        check_positive("height", height)?;
        let m = density * PI * radius * radius * height;
        let r2 = radius * radius;
        representable(symmetric(
            m,
            DVec3::ZERO,
            m * (3.0 * r2 + height * height) / 12.0,
            m * r2 / 2.0,
        ))
    }

    /// A solid right circular cone: base of `radius` in the plane z = 0,
    /// apex at z = `height`. The centre of mass is at z = h/4.
    ///
    /// ```text
    /// m = ρ π r² h / 3,   c = (0, 0, h/4),   I_zz = 3/10 m r²,   I_xx = I_yy = m (3r²/20 + 3h²/80)
    /// ```
    ///
    /// # Errors
    /// [`InertiaError::NonPositive`] for a density or dimension that is not positive and finite.
    /// [`InertiaError::NotRepresentable`] when the mass or a moment overflows
    /// f64 (or the mass underflows to zero).
    ///
    /// ```
    /// use kreisel_inertia::MassProperties;
    /// let c = MassProperties::solid_cone(1.0, 1.0, 4.0)?;
    /// assert_eq!(c.center_of_mass.z, 1.0);
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn solid_cone(density: f64, radius: f64, height: f64) -> Result<Self, InertiaError> {
        check_positive("density", density)?;
        check_positive("radius", radius)?;
        check_positive("height", height)?;
        let m = density * PI * radius * radius * height / 3.0;
        let (r2, h2) = (radius * radius, height * height);
        representable(symmetric(
            m,
            DVec3::new(0.0, 0.0, height / 4.0),
            m * (3.0 * r2 / 20.0 + 3.0 * h2 / 80.0),
            0.3 * m * r2,
        ))
    }

    /// A solid capsule: a cylinder of `radius` and `length` along z capped by
    /// two hemispheres, centred at the origin (total length `length + 2r`).
    ///
    /// ```text
    /// m_c = ρ π r² L,   m_s = ρ 4/3 π r³   (both caps)
    /// I_zz = m_c r²/2 + 2/5 m_s r²
    /// I_xx = I_yy = m_c (L²/12 + r²/4) + m_s (2r²/5 + L²/4 + 3Lr/8)
    /// ```
    ///
    /// # Errors
    /// [`InertiaError::NonPositive`] for a density or radius that is not
    /// positive, or a negative length (0 is a sphere).
    /// [`InertiaError::NotRepresentable`] when the mass or a moment overflows
    /// f64 (or the mass underflows to zero).
    ///
    /// ```
    /// use kreisel_inertia::MassProperties;
    /// let ball = MassProperties::solid_capsule(1.0, 0.5, 0.0)?;
    /// let sphere = MassProperties::solid_sphere(1.0, 0.5)?;
    /// assert!((ball.inertia.x_axis.x - sphere.inertia.x_axis.x).abs() < 1e-16);
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn solid_capsule(density: f64, radius: f64, length: f64) -> Result<Self, InertiaError> {
        check_positive("density", density)?;
        check_positive("radius", radius)?;
        if !(length >= 0.0 && length.is_finite()) {
            return Err(InertiaError::NonPositive {
                quantity: "capsule length",
                value: length,
            });
        }
        let (r, l) = (radius, length);
        let mc = density * PI * r * r * l;
        let ms = density * 4.0 / 3.0 * PI * r.powi(3);
        let i_axis = mc * r * r / 2.0 + 0.4 * ms * r * r;
        let i_perp = mc * (l * l / 12.0 + r * r / 4.0)
            + ms * (0.4 * r * r + l * l / 4.0 + 3.0 * l * r / 8.0);
        representable(symmetric(mc + ms, DVec3::ZERO, i_perp, i_axis))
    }

    /// A solid ellipsoid with semi-axes `semi_axes` along x, y, z, centred at the origin.
    ///
    /// ```text
    /// m = ρ 4/3 π a b c,   I = m/5 diag(b² + c², a² + c², a² + b²)
    /// ```
    ///
    /// # Errors
    /// [`InertiaError::NonPositive`] for a density or semi-axis that is not positive and finite.
    /// [`InertiaError::NotRepresentable`] when the mass or a moment overflows
    /// f64 (or the mass underflows to zero).
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::MassProperties;
    /// let e = MassProperties::solid_ellipsoid(1.0, DVec3::ONE)?;
    /// let s = MassProperties::solid_sphere(1.0, 1.0)?;
    /// assert!((e.inertia.x_axis.x - s.inertia.x_axis.x).abs() < 1e-15);
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn solid_ellipsoid(density: f64, semi_axes: DVec3) -> Result<Self, InertiaError> {
        check_positive("density", density)?;
        for e in semi_axes.to_array() {
            check_positive("semi-axis", e)?;
        }
        let m = density * 4.0 / 3.0 * PI * semi_axes.x * semi_axes.y * semi_axes.z;
        let s = semi_axes * semi_axes;
        representable(Self {
            mass: m,
            center_of_mass: DVec3::ZERO,
            inertia: DMat3::from_diagonal(DVec3::new(s.y + s.z, s.x + s.z, s.x + s.y) * (m / 5.0)),
        })
    }

    /// A solid torus around the z axis: tube of radius `minor` whose centre
    /// circle has radius `major > minor`, centred at the origin.
    ///
    /// ```text
    /// m = ρ 2π² R r²,   I_zz = m (R² + 3/4 r²),   I_xx = I_yy = m (R²/2 + 5/8 r²)
    /// ```
    ///
    /// # Errors
    /// [`InertiaError::NonPositive`] for a density or radius that is not
    /// positive, or `minor ≥ major` (a self-intersecting torus).
    /// [`InertiaError::NotRepresentable`] when the mass or a moment overflows
    /// f64 (or the mass underflows to zero).
    ///
    /// ```
    /// use kreisel_inertia::MassProperties;
    /// let t = MassProperties::solid_torus(1.0, 2.0, 0.5)?;
    /// assert!((t.inertia.z_axis.z - t.mass * (4.0 + 0.1875)).abs() < 1e-13);
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn solid_torus(density: f64, major: f64, minor: f64) -> Result<Self, InertiaError> {
        check_positive("density", density)?;
        check_positive("minor radius", minor)?;
        check_positive("major − minor radius", major - minor)?;
        let (rr, r) = (major, minor);
        let m = density * 2.0 * PI * PI * rr * r * r;
        representable(symmetric(
            m,
            DVec3::ZERO,
            m * (rr * rr / 2.0 + 5.0 / 8.0 * r * r),
            m * (rr * rr + 0.75 * r * r),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_bad_dimensions() {
        assert!(MassProperties::solid_sphere(0.0, 1.0).is_err());
        assert!(MassProperties::solid_sphere(1.0, f64::NAN).is_err());
        assert!(MassProperties::hollow_sphere(1.0, 1.0, 1.0).is_err());
        assert!(MassProperties::hollow_sphere(1.0, -0.1, 1.0).is_err());
        assert!(MassProperties::solid_box(1.0, DVec3::new(1.0, 0.0, 1.0)).is_err());
        assert!(MassProperties::solid_torus(1.0, 1.0, 1.0).is_err());
        assert!(MassProperties::solid_capsule(1.0, 1.0, -1.0).is_err());
    }

    #[test]
    fn overflowing_primitives_are_errors_not_infinities() {
        // Regression: solid_sphere(1000, 1e200) was Ok with mass = inf.
        let huge = [
            MassProperties::solid_sphere(1000.0, 1e200),
            MassProperties::hollow_sphere(1000.0, 0.0, 1e200),
            MassProperties::solid_box(1000.0, DVec3::splat(1e200)),
            MassProperties::solid_cylinder(1000.0, 1e200, 1.0),
            MassProperties::solid_cone(1000.0, 1.0, 1e200),
            MassProperties::solid_capsule(1000.0, 1e110, 1.0),
            MassProperties::solid_ellipsoid(1e300, DVec3::new(1e10, 1.0, 1.0)),
            MassProperties::solid_torus(1000.0, 1e200, 1.0),
            // Underflow: a mass of zero is no body either.
            MassProperties::solid_sphere(1e-300, 1e-100),
        ];
        for (k, p) in huge.into_iter().enumerate() {
            assert!(
                matches!(p, Err(InertiaError::NotRepresentable { .. })),
                "{k}: {p:?}"
            );
        }
    }

    #[test]
    fn hollow_sphere_is_solid_minus_core() {
        let outer = MassProperties::solid_sphere(2.0, 1.5).unwrap();
        let core = MassProperties::solid_sphere(2.0, 0.7).unwrap();
        let shell = MassProperties::hollow_sphere(2.0, 0.7, 1.5).unwrap();
        assert!((shell.mass - (outer.mass - core.mass)).abs() < 1e-14 * outer.mass);
        let di = outer.inertia.x_axis.x - core.inertia.x_axis.x;
        assert!((shell.inertia.x_axis.x - di).abs() < 1e-14 * outer.inertia.x_axis.x);
    }

    #[test]
    fn all_primitives_are_physical() {
        let all = [
            MassProperties::solid_sphere(1.0, 1.0),
            MassProperties::hollow_sphere(1.0, 0.5, 1.0),
            MassProperties::solid_box(1.0, DVec3::new(1.0, 2.0, 3.0)),
            MassProperties::solid_cylinder(1.0, 1.0, 0.01),
            MassProperties::solid_cone(1.0, 1.0, 2.0),
            MassProperties::solid_capsule(1.0, 1.0, 3.0),
            MassProperties::solid_ellipsoid(1.0, DVec3::new(1.0, 2.0, 3.0)),
            MassProperties::solid_torus(1.0, 2.0, 1.0),
        ];
        for p in all {
            assert!(p.unwrap().validate().is_ok());
        }
    }
}
