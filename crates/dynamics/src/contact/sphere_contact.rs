//! The geometry of a body-fixed sphere touching the ground plane `z = 0`.

use glam::{DQuat, DVec3};

use crate::DynamicsError;

/// A sphere fixed in the body: radius `R`, centre `c` in body axes seen
/// from the centre of mass.
///
/// With `r_G` the centre of mass and `A` the rotation of `world_from_body`,
/// the sphere's centre, its lowest point (the contact point when it
/// touches) and its gap to the plane are
///
/// ```text
/// r_C = r_G + A c,   r_P = r_C − R ẑ,   gap = z_G + (A c)_z − R
/// ```
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::SphereContact;
/// let s = SphereContact::try_new(0.015, DVec3::new(0.0, 0.0, 0.003))?;
/// // Upright, centre of mass at R − a = 12 mm: touching.
/// let gap = s.gap(DVec3::new(0.0, 0.0, 0.012), DQuat::IDENTITY);
/// assert!(gap.abs() < 1e-18);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SphereContact {
    radius: f64,
    center_body: DVec3,
}

impl SphereContact {
    /// A sphere of `radius` m centred at `center_body` (body axes, from the
    /// centre of mass).
    ///
    /// # Errors
    /// [`DynamicsError::InvalidContact`] for a radius that is not positive
    /// and finite, or a non-finite centre.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::SphereContact;
    /// assert!(SphereContact::try_new(0.0, DVec3::ZERO).is_err());
    /// assert!(SphereContact::try_new(0.01, DVec3::ZERO).is_ok());
    /// ```
    pub fn try_new(radius: f64, center_body: DVec3) -> Result<Self, DynamicsError> {
        if !(radius.is_finite() && radius > 0.0) {
            return Err(DynamicsError::InvalidContact {
                parameter: "radius",
                value: radius,
                reason: "must be positive and finite",
            });
        }
        check_center(center_body)?;
        Ok(Self {
            radius,
            center_body,
        })
    }

    /// The radius `R`, m.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The centre `c` in body axes from the centre of mass, m.
    pub fn center_body(&self) -> DVec3 {
        self.center_body
    }

    /// The sphere's centre seen from the centre of mass, world axes:
    /// `A c` (the attitude is normalised first, so any non-zero multiple of
    /// a unit quaternion gives the same answer).
    pub fn center_from_com_world(&self, world_from_body: DQuat) -> DVec3 {
        world_from_body.normalize() * self.center_body
    }

    /// The lowest point of the sphere seen from the centre of mass, world
    /// axes: `ρ = A c − R ẑ`.
    pub fn contact_from_com_world(&self, world_from_body: DQuat) -> DVec3 {
        self.center_from_com_world(world_from_body) - self.radius * DVec3::Z
    }

    /// The height of the sphere's lowest point above the plane:
    /// `z_G + (A c)_z − R` (zero while touching, the constraint's residual).
    pub fn gap(&self, com_world: DVec3, world_from_body: DQuat) -> f64 {
        com_world.z + self.center_from_com_world(world_from_body).z - self.radius
    }

    /// `ρ = A c − R ẑ` and its rate `ρ̇ = ω × A c` at the unit attitude `q`.
    pub(crate) fn offset_and_rate(&self, q: DQuat, omega_world: DVec3) -> (DVec3, DVec3) {
        let c = q * self.center_body;
        (c - self.radius * DVec3::Z, omega_world.cross(c))
    }
}

/// [`DynamicsError::InvalidContact`] for a shape's centre that is not
/// finite.
pub(super) fn check_center(center_body: DVec3) -> Result<(), DynamicsError> {
    match center_body.to_array().into_iter().find(|x| !x.is_finite()) {
        Some(x) => Err(DynamicsError::InvalidContact {
            parameter: "center",
            value: x,
            reason: "must be finite",
        }),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tilted_sphere_touches_below_its_centre() {
        let s = SphereContact::try_new(0.015, DVec3::new(0.0, 0.0, 0.003)).unwrap();
        let q = DQuat::from_rotation_x(0.7);
        let rho = s.contact_from_com_world(q);
        // The lowest point is straight below the centre, R under it.
        let c = s.center_from_com_world(q);
        assert_eq!((c - rho).x, 0.0);
        assert!(((c - rho).z - 0.015).abs() < 1e-18);
        // The centre is at a from the centre of mass, along the tilted axis.
        assert!((c.length() - 0.003).abs() < 1e-18);
        assert!((c.z - 0.003 * 0.7f64.cos()).abs() < 1e-18);
        // Scale invariance of the attitude, up to a few ulps of 0.015 m.
        assert!((s.contact_from_com_world(q * 3.0) - rho).length() < 1e-17);
    }

    #[test]
    fn bad_geometry_is_a_typed_error() {
        for (r, c) in [
            (-1.0, DVec3::ZERO),
            (f64::NAN, DVec3::ZERO),
            (0.01, DVec3::new(0.0, f64::INFINITY, 0.0)),
        ] {
            assert!(matches!(
                SphereContact::try_new(r, c),
                Err(DynamicsError::InvalidContact { .. })
            ));
        }
    }
}
