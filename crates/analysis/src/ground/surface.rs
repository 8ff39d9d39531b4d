//! [`Surface`]: where a body's convex contact surface touches the ground,
//! seen from its centre of mass, as a function of the up vector `γ` in
//! body axes — and how fast that point moves when `γ` turns. The same
//! geometry as `kreisel_dynamics::ContactShape` (sphere, disk rim,
//! ellipsoid), written for any [`Scalar`].

use glam::DVec3;
use kreisel_dynamics::ContactShape;

use super::algebra::{V3, dot, lift, norm, scale, sub};
use crate::Scalar;

/// A body-fixed convex surface: its centre `c` from the centre of mass
/// (body axes) and its shape.
///
/// ```text
/// x_P(γ) = c + p(γ)      the lowest point (outward normal −γ/|γ|)
/// sphere:     p = −R γ/|γ|
/// ellipsoid:  p = −E² γ/σ,        σ = √(γᵀ E² γ)
/// disk rim:   p = −a q/|q|,       q = γ − (γ·n) n
/// r(γ) = −x_P(γ)                  from the contact to the centre of mass
/// ṙ = −(∂p/∂γ) γ̇                  (γ · ṙ = 0: the point moves in the tangent plane)
/// ```
///
/// `p` is homogeneous of degree 0 in `γ`, so `|γ|` (a Casimir of `γ̇ =
/// γ × ω`) never changes the geometry; `γ · ṙ = 0` for every `γ`, which
/// makes the energy `½ m |v|² + ½ ω·Iω + m g γ·r` an exact integral
/// (module docs of [`super`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Surface {
    /// A sphere of radius `R`.
    Sphere {
        /// `R`, m.
        radius: f64,
        /// `c`, body axes, m.
        center: [f64; 3],
    },
    /// A circular rim of radius `a` and unit axis `n`.
    Disk {
        /// `a`, m.
        radius: f64,
        /// `c`, body axes, m.
        center: [f64; 3],
        /// `n`, body axes, unit.
        axis: [f64; 3],
    },
    /// An ellipsoid with semi-axes `E = diag(a, b, c)` along the body axes.
    Ellipsoid {
        /// `(a, b, c)`, m.
        semi_axes: [f64; 3],
        /// `c`, body axes, m.
        center: [f64; 3],
    },
}

impl Surface {
    /// The engine's shape, in the same body axes.
    pub(crate) fn of(shape: ContactShape) -> Self {
        match shape {
            ContactShape::Sphere(s) => Self::Sphere {
                radius: s.radius(),
                center: s.center_body().to_array(),
            },
            ContactShape::Disk(d) => Self::Disk {
                radius: d.radius(),
                center: d.center_body().to_array(),
                axis: d.normal_body().to_array(),
            },
            ContactShape::Ellipsoid(e) => Self::Ellipsoid {
                semi_axes: e.semi_axes().to_array(),
                center: e.center_body().to_array(),
            },
        }
    }

    /// The centre `c` from the centre of mass, body axes.
    pub(crate) fn center(&self) -> DVec3 {
        let c = match self {
            Self::Sphere { center, .. }
            | Self::Disk { center, .. }
            | Self::Ellipsoid { center, .. } => center,
        };
        DVec3::from_array(*c)
    }

    /// `r(γ)` (from the contact to the centre of mass) and its rate `ṙ`
    /// for the up vector's rate `γ̇`, both body axes.
    pub(crate) fn com_from_contact<D: Scalar>(
        &self,
        gamma: V3<D>,
        gamma_rate: V3<D>,
    ) -> (V3<D>, V3<D>) {
        let c: V3<D> = lift(self.center().to_array());
        let (minus_p, minus_p_rate) = match *self {
            Self::Sphere { radius, .. } => unit_and_rate(gamma, gamma_rate, radius),
            Self::Disk { radius, axis, .. } => {
                let n: V3<D> = lift(axis);
                let q = sub(gamma, scale(n, dot(gamma, n)));
                let q_rate = sub(gamma_rate, scale(n, dot(gamma_rate, n)));
                unit_and_rate(q, q_rate, radius)
            }
            Self::Ellipsoid { semi_axes, .. } => {
                let e2 = semi_axes.map(|s| s * s);
                let e2g: V3<D> = [0, 1, 2].map(|k| gamma[k] * e2[k]);
                let e2g_rate: V3<D> = [0, 1, 2].map(|k| gamma_rate[k] * e2[k]);
                let sigma = dot(gamma, e2g).sqrt();
                let sigma_rate = dot(gamma_rate, e2g) / sigma;
                let p = scale(e2g, sigma.recip());
                let rate = scale(sub(e2g_rate, scale(p, sigma_rate)), sigma.recip());
                (p, rate)
            }
        };
        (sub(minus_p, c), minus_p_rate)
    }
}

/// `R u/|u|` and its rate `R (u̇/|u| − u (u·u̇)/|u|³)`.
fn unit_and_rate<D: Scalar>(u: V3<D>, u_rate: V3<D>, radius: f64) -> (V3<D>, V3<D>) {
    let length = norm(u);
    let along = dot(u, u_rate) / (length * length);
    let k = D::from(radius) / length;
    (scale(u, k), scale(sub(u_rate, scale(u, along)), k))
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DQuat;
    use kreisel_dynamics::{DiskContact, EllipsoidContact, SphereContact};
    use num_dual::Dual64;

    /// `r(γ)` is the engine's `−ρ` seen in body axes, and `ṙ` the
    /// derivative of `r` along `γ̇` (dual numbers: exact).
    #[test]
    fn the_geometry_is_the_engines_and_the_rate_its_derivative() {
        let shapes = [
            ContactShape::Sphere(
                SphereContact::try_new(0.015, DVec3::new(0.0, 0.0, 0.003)).unwrap(),
            ),
            ContactShape::Disk(
                DiskContact::try_new(0.03, DVec3::new(0.0, 0.0, 0.004), DVec3::new(0.2, 0.1, 1.0))
                    .unwrap(),
            ),
            ContactShape::Ellipsoid(
                EllipsoidContact::try_new(
                    DVec3::new(0.2, 0.03, 0.02),
                    DVec3::new(0.001, -0.002, 0.01),
                )
                .unwrap(),
            ),
        ];
        let q = DQuat::from_euler(glam::EulerRot::ZXZ, 0.3, 0.8, -0.4);
        let gamma = (q.conjugate() * DVec3::Z).to_array();
        let gamma_rate = [0.3, -0.7, 0.2];
        for shape in shapes {
            let surface = Surface::of(shape);
            let (r, _) = surface.com_from_contact(gamma, gamma_rate);
            let rho_body = q.conjugate() * shape.contact_from_com_world(q);
            // A few ulps of the largest size (0.2 m: ulp 2.8e-17).
            let off = (DVec3::from_array(r) + rho_body).length();
            assert!(off < 1e-16, "{shape:?}: {off:e}");
            // Scaled γ: the same point.
            let (r2, _) = surface.com_from_contact(gamma.map(|g| 3.0 * g), gamma_rate);
            let scaled = (DVec3::from_array(r2) - DVec3::from_array(r)).length();
            assert!(scaled < 1e-16, "{shape:?}: {scaled:e}");
            // The rate: d/ds r(γ + s γ̇) at s = 0.
            let g: V3<Dual64> = [0, 1, 2].map(|k| Dual64::new(gamma[k], gamma_rate[k]));
            let (rd, _) = surface.com_from_contact(g, [Dual64::from(0.0); 3]);
            let (_, rate) = surface.com_from_contact(gamma, gamma_rate);
            for k in 0..3 {
                assert!((rd[k].eps - rate[k]).abs() < 1e-16, "{shape:?}");
            }
            // Rounding of a rate of size |γ̇| ℓ ≈ 0.2 m/s.
            let along = dot(gamma, rate);
            assert!(along.abs() < 1e-16, "{shape:?}: {along:e}");
        }
    }
}
