//! The geometry of a body-fixed circular rim (a coin, Euler's disk)
//! touching the ground plane `z = 0`.

use glam::{DQuat, DVec3};

use super::SphereContact;
use crate::DynamicsError;

/// A circular rim fixed in the body: radius `r`, centre `c` in body axes
/// seen from the centre of mass, unit axis `n` (body axes).
///
/// With `A` the attitude's rotation and `n_w = A n`, the rim's lowest
/// point lies `r` from the centre along the steepest downward direction
/// in the rim's plane:
///
/// ```text
/// s = |ẑ × n_w| = √(1 − n_wz²),   û = (n_wz n_w − ẑ)/s
/// ρ = A c + r û,   gap = z_G + (A c)_z − r s
/// ρ̇ = ω × A c + r û̇,   ṅ_w = ω × n_w,   ṡ = −n_wz ṅ_wz / s
/// û̇ = (ṅ_wz n_w + n_wz ṅ_w)/s − û ṡ/s
/// ```
///
/// The contact point moves over the rim (`ρ̇ ≠ ω × ρ`). A flat disk
/// (`s = 0`, axis vertical) touches along the whole rim: no contact point,
/// and a step there is reported as [`crate::DynamicsError::Diverged`].
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::DiskContact;
/// let d = DiskContact::try_new(0.02, DVec3::ZERO, DVec3::Z)?;
/// // Standing on its edge (axis horizontal): the contact is r straight below.
/// let rho = d.contact_from_com_world(DQuat::from_rotation_x(std::f64::consts::FRAC_PI_2));
/// assert!((rho - DVec3::new(0.0, 0.0, -0.02)).length() < 1e-17);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DiskContact {
    radius: f64,
    center_body: DVec3,
    normal_body: DVec3,
}

impl DiskContact {
    /// A rim of `radius` m centred at `center_body`, axis `normal_body`
    /// (body axes; normalised here).
    ///
    /// # Errors
    /// [`DynamicsError::InvalidContact`] for a radius that is not positive
    /// and finite, a non-finite centre, or an axis that is not finite and
    /// non-zero.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::DiskContact;
    /// assert!(DiskContact::try_new(0.02, DVec3::ZERO, DVec3::ZERO).is_err());
    /// assert_eq!(DiskContact::try_new(0.02, DVec3::ZERO, 3.0 * DVec3::Z)?.normal_body(), DVec3::Z);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_new(
        radius: f64,
        center_body: DVec3,
        normal_body: DVec3,
    ) -> Result<Self, DynamicsError> {
        SphereContact::try_new(radius, center_body)?;
        let length = normal_body.length();
        if !(length.is_finite() && length > 0.0) {
            return Err(DynamicsError::InvalidContact {
                parameter: "normal",
                value: length,
                reason: "the disk's axis must be finite and non-zero",
            });
        }
        Ok(Self {
            radius,
            center_body,
            normal_body: normal_body / length,
        })
    }

    /// The radius `r`, m.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The centre `c` in body axes from the centre of mass, m.
    pub fn center_body(&self) -> DVec3 {
        self.center_body
    }

    /// The unit axis `n`, body axes.
    pub fn normal_body(&self) -> DVec3 {
        self.normal_body
    }

    /// The rim's lowest point seen from the centre of mass, world axes:
    /// `ρ = A c + r û` (NaN for a flat disk).
    pub fn contact_from_com_world(&self, world_from_body: DQuat) -> DVec3 {
        let q = world_from_body.normalize();
        q * self.center_body + self.radius * down_in_plane(q * self.normal_body)
    }

    /// `ρ` and its rate `ρ̇` for the angular velocity `omega_world` at the
    /// unit attitude `q` (the formulas above).
    pub(crate) fn offset_and_rate(&self, q: DQuat, omega_world: DVec3) -> (DVec3, DVec3) {
        let c = q * self.center_body;
        let n = q * self.normal_body;
        let s = DVec3::Z.cross(n).length();
        let u = (n.z * n - DVec3::Z) / s;
        let dn = omega_world.cross(n);
        let ds = -n.z * dn.z / s;
        let du = (dn.z * n + n.z * dn) / s - u * (ds / s);
        (c + self.radius * u, omega_world.cross(c) + self.radius * du)
    }
}

/// `û = (n_z n − ẑ)/|ẑ × n|`, the steepest downward unit vector in the
/// plane normal to the unit vector `n`.
fn down_in_plane(n: DVec3) -> DVec3 {
    (n.z * n - DVec3::Z) / DVec3::Z.cross(n).length()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_contact_rate_is_the_derivative_of_the_contact_offset() {
        let d = DiskContact::try_new(
            0.03,
            DVec3::new(0.001, -0.002, 0.004),
            DVec3::new(0.2, 0.1, 1.0),
        )
        .unwrap();
        let shape = d;
        let q = DQuat::from_euler(glam::EulerRot::ZXZ, 0.3, 0.8, -0.4);
        let omega = DVec3::new(1.5, -2.0, 3.0);
        let (rho, rate) = shape.offset_and_rate(q, omega);
        // Central difference along the rotation q(t) = exp(ω t) q.
        let h = 1e-6;
        let at = |t: f64| {
            let turn = DQuat::from_scaled_axis(omega * t);
            shape.offset_and_rate(turn * q, omega).0
        };
        let numeric = (at(h) - at(-h)) / (2.0 * h);
        assert!((numeric - rate).length() < 1e-9, "{numeric} vs {rate}");
        // The lowest point of the rim: 64 points on it lie no lower.
        let n = q * d.normal_body();
        let e1 = n.any_orthonormal_vector();
        let e2 = n.cross(e1);
        let centre = q * d.center_body();
        for k in 0..64 {
            let a = k as f64 * std::f64::consts::TAU / 64.0;
            let p = centre + d.radius() * (a.cos() * e1 + a.sin() * e2);
            assert!(p.z >= rho.z - 1e-15);
        }
        // The gap formula, to a few ulps of 0.03 m.
        let dz = rho.z - (centre.z - 0.03 * DVec3::Z.cross(n).length());
        assert!(dz.abs() < 1e-16, "{dz}");
    }
}
