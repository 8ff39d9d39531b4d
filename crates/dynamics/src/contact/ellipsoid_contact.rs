//! The geometry of a body-fixed ellipsoid (a rattleback's hull) touching
//! the ground plane `z = 0`: its lowest point and that point's rate.

use glam::{DQuat, DVec3};

use crate::DynamicsError;

/// An ellipsoid fixed in the body: semi-axes `(a, b, c)` along the body
/// axes, centre `c` in body axes seen from the centre of mass.
///
/// With `A` the attitude's rotation and `E = diag(a, b, c)`, the point of
/// the surface whose outward normal is `−ẑ` is the lowest one. In body
/// axes that normal is `n_b = Aᵀ(−ẑ)`; the surface point `p_b` with
/// `p_bᵀ E⁻² p_b = 1` has outward normal `∝ E⁻² p_b`, so
///
/// ```text
/// s   = √(n_bᵀ E² n_b),       p_b = E² n_b / s
/// ρ   = A (c + p_b),          gap = z_G + (A c)_z − s
/// ```
///
/// (`(A p_b)_z = ẑ·A p_b = −n_b·p_b = −s`). Its rate: `Ȧ = [ω]× A` gives
/// `ṅ_b = Aᵀ(ω × ẑ) = n_b × ω_b` (`ω_b = Aᵀ ω`), and differentiating
/// `p_b(n_b)`,
///
/// ```text
/// ṗ_b = (E² ṅ_b − p_b (p_b·ṅ_b)) / s
/// ρ̇   = ω × ρ + A ṗ_b
/// ```
///
/// The contact point moves over the surface (`ρ̇ ≠ ω × ρ`), but
/// `n_b·ṗ_b = 0` (it moves in the tangent plane), so the gap's rate is the
/// vertical velocity of the material point, `(v_P)_z`, as the model needs.
/// For `a = b = c = R`, `p_b = R n_b`, `ρ = A c − R ẑ` and `ρ̇ = ω × A c`:
/// the [`crate::SphereContact`] of radius `R`.
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::EllipsoidContact;
/// // Kane & Levinson's rattleback: centre 1 cm above the centre of mass.
/// let e = EllipsoidContact::try_new(DVec3::new(0.2, 0.03, 0.02), DVec3::new(0.0, 0.0, 0.01))?;
/// // Resting: the contact is c − 0.01 = 1 cm straight below the centre of mass.
/// let rho = e.contact_from_com_world(DQuat::IDENTITY);
/// assert!((rho - DVec3::new(0.0, 0.0, -0.01)).length() < 1e-17);
/// // Pitched by 0.1 rad about y: the contact runs along x, far from the axis.
/// let rho = e.contact_from_com_world(DQuat::from_rotation_y(0.1));
/// assert!(rho.x > 0.1 && rho.y.abs() < 1e-18);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EllipsoidContact {
    semi_axes: DVec3,
    center_body: DVec3,
}

impl EllipsoidContact {
    /// An ellipsoid with `semi_axes` (m) along the body axes, centred at
    /// `center_body` (body axes, from the centre of mass).
    ///
    /// # Errors
    /// [`DynamicsError::InvalidContact`] for a semi-axis that is not
    /// positive and finite, or a non-finite centre.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::EllipsoidContact;
    /// assert!(EllipsoidContact::try_new(DVec3::new(0.2, 0.0, 0.02), DVec3::ZERO).is_err());
    /// assert!(EllipsoidContact::try_new(DVec3::new(0.2, 0.03, 0.02), DVec3::NAN).is_err());
    /// assert!(EllipsoidContact::try_new(DVec3::new(0.2, 0.03, 0.02), DVec3::ZERO).is_ok());
    /// ```
    pub fn try_new(semi_axes: DVec3, center_body: DVec3) -> Result<Self, DynamicsError> {
        if let Some(x) = semi_axes
            .to_array()
            .into_iter()
            .find(|x| !(x.is_finite() && *x > 0.0))
        {
            return Err(DynamicsError::InvalidContact {
                parameter: "semi_axes",
                value: x,
                reason: "every semi-axis must be positive and finite",
            });
        }
        super::sphere_contact::check_center(center_body)?;
        Ok(Self {
            semi_axes,
            center_body,
        })
    }

    /// The semi-axes `(a, b, c)` along the body axes, m.
    pub fn semi_axes(&self) -> DVec3 {
        self.semi_axes
    }

    /// The centre `c` in body axes from the centre of mass, m.
    pub fn center_body(&self) -> DVec3 {
        self.center_body
    }

    /// The lowest point of the surface seen from the centre of mass, world
    /// axes: `ρ = A (c + p_b)` (the attitude is normalised first).
    pub fn contact_from_com_world(&self, world_from_body: DQuat) -> DVec3 {
        let q = world_from_body.normalize();
        let (p, _) = self.lowest_point_body(q.conjugate() * -DVec3::Z);
        q * (self.center_body + p)
    }

    /// The height of the lowest point above the plane:
    /// `z_G + (A c)_z − √(n_bᵀ E² n_b)` (zero while touching).
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_dynamics::EllipsoidContact;
    /// let e = EllipsoidContact::try_new(DVec3::new(0.2, 0.03, 0.02), DVec3::new(0.0, 0.0, 0.01))?;
    /// // Rolled by 90° about x it lies on its side: centre of mass at height b.
    /// let q = DQuat::from_rotation_x(std::f64::consts::FRAC_PI_2);
    /// assert!(e.gap(DVec3::new(0.0, 0.0, 0.03), q).abs() < 1e-17);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn gap(&self, com_world: DVec3, world_from_body: DQuat) -> f64 {
        let q = world_from_body.normalize();
        let (_, s) = self.lowest_point_body(q.conjugate() * -DVec3::Z);
        com_world.z + (q * self.center_body).z - s
    }

    /// `p_b = E² n_b / s` and `s = √(n_bᵀ E² n_b)` for the unit outward
    /// normal `n_b` (body axes).
    fn lowest_point_body(&self, normal_body: DVec3) -> (DVec3, f64) {
        let e2n = self.semi_axes * self.semi_axes * normal_body;
        let s = normal_body.dot(e2n).sqrt();
        (e2n / s, s)
    }

    /// `ρ` and its rate `ρ̇` for the angular velocity `omega_world` at the
    /// unit attitude `q` (the formulas above).
    pub(crate) fn offset_and_rate(&self, q: DQuat, omega_world: DVec3) -> (DVec3, DVec3) {
        let to_body = q.conjugate();
        let n = to_body * -DVec3::Z;
        let (p, s) = self.lowest_point_body(n);
        let rho = q * (self.center_body + p);
        let dn = n.cross(to_body * omega_world);
        let dp = (self.semi_axes * self.semi_axes * dn - p * p.dot(dn)) / s;
        (rho, omega_world.cross(rho) + q * dp)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::SphereContact;

    fn rattleback() -> EllipsoidContact {
        EllipsoidContact::try_new(DVec3::new(0.2, 0.03, 0.02), DVec3::new(0.001, -0.002, 0.01))
            .unwrap()
    }

    #[test]
    fn the_contact_rate_is_the_derivative_of_the_contact_offset() {
        let e = rattleback();
        for (q, omega) in [
            (
                DQuat::from_euler(glam::EulerRot::ZXZ, 0.3, 0.8, -0.4),
                DVec3::new(1.5, -2.0, 3.0),
            ),
            (
                DQuat::from_euler(glam::EulerRot::ZXY, 2.0, 0.05, -0.03),
                DVec3::new(0.2, 4.0, -5.0),
            ),
        ] {
            let (rho, rate) = e.offset_and_rate(q, omega);
            assert_eq!(rho, e.contact_from_com_world(q));
            // Central difference along the rotation q(t) = exp(ω t) q: its
            // error is O(h²) ρ''' ~ 1e-12 · 100 m/s³, rounding 1e-17/1e-6.
            let h = 1e-6;
            let at = |t: f64| {
                e.offset_and_rate(DQuat::from_scaled_axis(omega * t) * q, omega)
                    .0
            };
            let numeric = (at(h) - at(-h)) / (2.0 * h);
            assert!((numeric - rate).length() < 1e-9, "{numeric} vs {rate}");
        }
    }

    #[test]
    fn the_contact_is_the_lowest_point_of_the_surface() {
        let e = rattleback();
        let q = DQuat::from_euler(glam::EulerRot::ZXZ, 0.3, 0.8, -0.4);
        let rho = e.contact_from_com_world(q);
        // It lies on the surface …
        let p = q.conjugate() * rho - e.center_body();
        let on = (p / e.semi_axes()).length_squared() - 1.0;
        assert!(on.abs() < 1e-15, "{on}");
        // … and 200 × 100 surface points (c + E u, u on the unit sphere)
        // lie no lower.
        let mut lowest = f64::INFINITY;
        for i in 0..200 {
            let phi = i as f64 * std::f64::consts::TAU / 200.0;
            for j in 0..=100 {
                let theta = j as f64 * std::f64::consts::PI / 100.0;
                let u = DVec3::new(
                    theta.sin() * phi.cos(),
                    theta.sin() * phi.sin(),
                    theta.cos(),
                );
                let z = (q * (e.center_body() + e.semi_axes() * u)).z;
                assert!(z >= rho.z - 1e-17, "{z} < {}", rho.z);
                lowest = lowest.min(z);
            }
        }
        // The grid's lowest point is close above it (grid spacing 0.03 rad).
        assert!(lowest - rho.z < 1e-4 * 0.2, "{}", lowest - rho.z);
        // The gap formula.
        let com = DVec3::new(0.3, -0.1, 0.05);
        assert!((e.gap(com, q) - (com.z + rho.z)).abs() < 1e-17);
    }

    #[test]
    fn equal_semi_axes_are_the_sphere() {
        let (r, c) = (0.015, DVec3::new(0.001, -0.002, 0.003));
        let e = EllipsoidContact::try_new(DVec3::splat(r), c).unwrap();
        let s = SphereContact::try_new(r, c).unwrap();
        let q = DQuat::from_euler(glam::EulerRot::ZXZ, 0.3, 2.5, -0.4);
        let omega = DVec3::new(1.5, -20.0, 180.0);
        let (rho_e, rate_e) = e.offset_and_rate(q, omega);
        let (rho_s, rate_s) = s.offset_and_rate(q, omega);
        // A few ulps of 0.015 m and of |ω| R ≈ 3 m/s.
        assert!((rho_e - rho_s).length() < 1e-17, "{}", rho_e - rho_s);
        assert!((rate_e - rate_s).length() < 4e-15, "{}", rate_e - rate_s);
    }

    #[test]
    fn bad_geometry_is_a_typed_error() {
        for (axes, c) in [
            (DVec3::new(-0.2, 0.03, 0.02), DVec3::ZERO),
            (DVec3::new(0.2, f64::NAN, 0.02), DVec3::ZERO),
            (DVec3::new(0.2, 0.03, f64::INFINITY), DVec3::ZERO),
            (
                DVec3::new(0.2, 0.03, 0.02),
                DVec3::new(0.0, f64::INFINITY, 0.0),
            ),
        ] {
            assert!(matches!(
                EllipsoidContact::try_new(axes, c),
                Err(DynamicsError::InvalidContact { .. })
            ));
        }
    }
}
