//! [`ContactShape`]: the surfaces a [`crate::GroundTop`] can touch the
//! ground with, their contact point seen from the centre of mass and its
//! rate.

use glam::{DQuat, DVec3};

use super::{DiskContact, EllipsoidContact, SphereContact};

/// The surface near the contact: a sphere, a circular rim or an ellipsoid.
///
/// ```
/// use glam::DVec3;
/// use kreisel_dynamics::{ContactShape, SphereContact};
/// let s = ContactShape::Sphere(SphereContact::try_new(0.015, DVec3::ZERO)?);
/// assert!(matches!(s, ContactShape::Sphere(_)));
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ContactShape {
    /// A body-fixed sphere (ball-ended top, tippe top).
    Sphere(SphereContact),
    /// A body-fixed circular rim (coin, Euler's disk).
    Disk(DiskContact),
    /// A body-fixed ellipsoid (the rattleback).
    Ellipsoid(EllipsoidContact),
}

impl ContactShape {
    /// The contact point seen from the centre of mass, world axes: `ρ`.
    pub fn contact_from_com_world(&self, world_from_body: DQuat) -> DVec3 {
        match self {
            Self::Sphere(s) => s.contact_from_com_world(world_from_body),
            Self::Disk(d) => d.contact_from_com_world(world_from_body),
            Self::Ellipsoid(e) => e.contact_from_com_world(world_from_body),
        }
    }

    /// The shape's size `ℓ`, m: a sphere's or a rim's radius, an
    /// ellipsoid's smallest semi-axis (the scale of the guard's contact
    /// check, [`crate::GROUND_CHECK_TOLERANCE`]).
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::{ContactShape, EllipsoidContact};
    /// let e = EllipsoidContact::try_new(DVec3::new(0.2, 0.03, 0.02), DVec3::ZERO)?;
    /// assert_eq!(ContactShape::Ellipsoid(e).size(), 0.02);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn size(&self) -> f64 {
        match self {
            Self::Sphere(s) => s.radius(),
            Self::Disk(d) => d.radius(),
            Self::Ellipsoid(e) => e.semi_axes().min_element(),
        }
    }

    /// The shape's centre seen from the centre of mass, world axes: `A c`.
    pub fn center_from_com_world(&self, world_from_body: DQuat) -> DVec3 {
        let c = match self {
            Self::Sphere(s) => s.center_body(),
            Self::Disk(d) => d.center_body(),
            Self::Ellipsoid(e) => e.center_body(),
        };
        world_from_body.normalize() * c
    }

    /// `ρ` and its rate `ρ̇` for the angular velocity `omega_world`, at
    /// the unit attitude `q` (formulas at [`DiskContact`] and
    /// [`EllipsoidContact`]; for a sphere `ρ̇ = ω × A c`).
    pub(crate) fn offset_and_rate(&self, q: DQuat, omega_world: DVec3) -> (DVec3, DVec3) {
        match self {
            Self::Sphere(s) => s.offset_and_rate(q, omega_world),
            Self::Disk(d) => d.offset_and_rate(q, omega_world),
            Self::Ellipsoid(e) => e.offset_and_rate(q, omega_world),
        }
    }
}
