//! [`ContactBody`]: a rigid body touching the ground, its equations of
//! motion in body-fixed (or axially turned) axes for any [`Scalar`] —
//! rolling without slipping (the contact force a reaction) and the
//! friction laws (the normal force solved from the contact staying on
//! the plane) — as `kreisel_dynamics::GroundTop` has them in world axes.

use glam::{DMat3, DVec3};
use kreisel_dynamics::{Body, Friction, GroundTop, Support};

use super::algebra::{V3, add, cross, dot, mat_vec, norm, scale, solve3, sub};
use super::surface::Surface;
use crate::{AnalysisError, Scalar};

/// Mass, inertia, gravity, contact surface and friction of a body on the
/// plane `z = 0` (gravity `−g ẑ`), body axes.
///
/// ```text
/// rolling (frame turning at Ω; body axes: Ω = ω):
///   γ̇ = γ × Ω,   v_G = ω × r,   ṙ = (∂r/∂γ) γ̇
///   [I + m(|r|² 𝟙 − r rᵀ)] ω̇ = −Ω × Iω − m r × (ω × ṙ + Ω × (ω × r) + g γ)
/// friction law (body axes, v = v_G):
///   v_P = v − ω × r,   e = γ/|γ| + f(v_P − (γ̂·v_P) γ̂)     (f: F/N of the law)
///   I ω̇ = −ω × Iω − N r × e,    m (v̇ + ω × v) = N e − m g γ
///   N (|γ|/m + (r×γ)·I⁻¹(r×e)) = g|γ|² − (r×γ)·I⁻¹(ω×Iω) + ω·(ṙ×γ) + ω·(r×γ̇)
/// ```
///
/// `N` is what keeps `γ · v_P` (the contact point's vertical velocity)
/// constant, for every state: `d(γ·v_P)/dt = 0` exactly, so `γ · v_P` is
/// conserved (zero on the plane). Newton and Euler about the centre of
/// mass with the contact force `F` at `−r` (`I ω̇ + ω × Iω = −r × F`,
/// `F = m a_G + m g γ`), as in the derivation of `kreisel_dynamics`'s
/// contact module; the rolling form is the rattleback generator's
/// (`tests/data/gen/rattleback.py`, body axes, Poisson's variables) with
/// the frame's rate `Ω` in place of `ω` where the axes turn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ContactBody {
    pub(crate) mass: f64,
    /// Rows of `I` about the centre of mass, body axes.
    pub(crate) inertia: [[f64; 3]; 3],
    /// Rows of `I⁻¹`.
    pub(crate) inverse_inertia: [[f64; 3]; 3],
    pub(crate) gravity: f64,
    pub(crate) surface: Surface,
    pub(crate) friction: Friction,
}

/// `M` as rows.
fn rows(m: DMat3) -> [[f64; 3]; 3] {
    let t = m.transpose();
    [
        t.x_axis.to_array(),
        t.y_axis.to_array(),
        t.z_axis.to_array(),
    ]
}

impl ContactBody {
    /// The engine's body on the ground.
    ///
    /// # Errors
    /// [`AnalysisError::Parameter`] if the top has applied loads (the
    /// steady motions here are those of gravity and the contact alone).
    pub(crate) fn of(top: &GroundTop) -> Result<Self, AnalysisError> {
        if top.inputs().is_some() {
            return Err(AnalysisError::Parameter {
                name: "inputs",
                value: 1.0,
                must: "absent: the steady motions are those of gravity and the contact alone",
            });
        }
        let i = top.inertia_body();
        Ok(Self {
            mass: top.mass(),
            inertia: rows(i),
            inverse_inertia: rows(i.inverse()),
            gravity: top.gravity(),
            surface: Surface::of(top.shape()),
            friction: top.friction(),
        })
    }

    /// `I` (body axes).
    pub(crate) fn inertia_matrix(&self) -> DMat3 {
        DMat3::from_cols_array_2d(&self.inertia).transpose()
    }

    /// `ω̇` rolling without slipping, in axes turning at `frame_rate` `Ω`
    /// (the body's own axes: `Ω = ω`), with `γ` and `ω` in those axes.
    pub(crate) fn rolling_omega_rate<D: Scalar>(
        &self,
        gamma: V3<D>,
        omega: V3<D>,
        frame_rate: V3<D>,
    ) -> V3<D> {
        let m = self.mass;
        let gamma_rate = cross(gamma, frame_rate);
        let (r, r_rate) = self.surface.com_from_contact(gamma, gamma_rate);
        let l = mat_vec(&self.inertia, omega);
        let inner = add(
            add(cross(omega, r_rate), cross(frame_rate, cross(omega, r))),
            scale(gamma, D::from(self.gravity)),
        );
        let rhs = sub(
            scale(cross(frame_rate, l), D::from(-1.0)),
            scale(cross(r, inner), D::from(m)),
        );
        let r2 = dot(r, r);
        let matrix: [V3<D>; 3] = [0, 1, 2].map(|i| {
            [0, 1, 2].map(|k| {
                let delta = if i == k { r2 } else { D::from(0.0) };
                D::from(self.inertia[i][k]) + (delta - r[i] * r[k]) * m
            })
        });
        solve3(matrix, rhs)
    }

    /// The friction law's force per newton of normal force for the
    /// horizontal slip `slip` (body axes).
    fn friction_per_newton<D: Scalar>(&self, slip: V3<D>) -> V3<D> {
        match self.friction {
            Friction::None | Friction::Rolling => [D::from(0.0); 3],
            Friction::Viscous { mu } => scale(slip, D::from(-mu)),
            Friction::Sliding { mu, slip_velocity } => {
                let size = (dot(slip, slip) + slip_velocity * slip_velocity).sqrt();
                scale(slip, D::from(-mu) / size)
            }
        }
    }

    /// `(ω̇, v̇, N)` under a friction law, body axes (`v` the centre of
    /// mass's velocity).
    pub(crate) fn sliding_rates<D: Scalar>(
        &self,
        gamma: V3<D>,
        omega: V3<D>,
        v: V3<D>,
    ) -> (V3<D>, V3<D>, D) {
        let m = self.mass;
        let g = self.gravity;
        let gamma_rate = cross(gamma, omega);
        let (r, r_rate) = self.surface.com_from_contact(gamma, gamma_rate);
        let size = norm(gamma);
        let up = scale(gamma, size.recip());
        let slip = sub(v, cross(omega, r));
        let horizontal = sub(slip, scale(up, dot(up, slip)));
        let e = add(up, self.friction_per_newton(horizontal));
        let l = mat_vec(&self.inertia, omega);
        let free = scale(
            mat_vec(&self.inverse_inertia, cross(omega, l)),
            D::from(-1.0),
        );
        let per_newton = scale(mat_vec(&self.inverse_inertia, cross(r, e)), D::from(-1.0));
        let lever = cross(r, gamma);
        let compliance = size / m - dot(per_newton, lever);
        let drive = size * size * g
            + dot(free, lever)
            + dot(omega, cross(r_rate, gamma))
            + dot(omega, cross(r, gamma_rate));
        let normal = drive / compliance;
        let omega_rate = add(free, scale(per_newton, normal));
        let v_rate = sub(
            sub(scale(e, normal / m), cross(omega, v)),
            scale(gamma, D::from(g)),
        );
        (omega_rate, v_rate, normal)
    }

    /// The energy with the centre of mass's velocity `v` (body axes), zero
    /// potential with the centre of mass on the plane.
    ///
    /// ```text
    /// E = ½ m |v|² + ½ ω·Iω + m g γ·r(γ)
    /// ```
    pub(crate) fn energy<D: Scalar>(&self, gamma: V3<D>, omega: V3<D>, v: V3<D>) -> D {
        let (r, _) = self.surface.com_from_contact(gamma, [D::from(0.0); 3]);
        let l = mat_vec(&self.inertia, omega);
        (dot(v, v) * self.mass + dot(omega, l)) * 0.5 + dot(gamma, r) * (self.mass * self.gravity)
    }

    /// Jellett's integral `λ = Iω · r` (conserved for a sphere whose
    /// centre lies on an axis of symmetry of `I`).
    pub(crate) fn jellett<D: Scalar>(&self, gamma: V3<D>, omega: V3<D>) -> D {
        let (r, _) = self.surface.com_from_contact(gamma, [D::from(0.0); 3]);
        dot(mat_vec(&self.inertia, omega), r)
    }

    /// Whether `I` is symmetric about the unit body axis `axis` (it is an
    /// eigenvector, and the two moments across it are equal), to `1e-12`
    /// relative.
    pub(crate) fn symmetric_about(&self, axis: DVec3) -> bool {
        let i = self.inertia_matrix();
        let scale = i
            .x_axis
            .length()
            .max(i.y_axis.length())
            .max(i.z_axis.length());
        let along = axis.dot(i * axis);
        let across = axis.any_orthonormal_vector();
        let other = axis.cross(across);
        let m1 = across.dot(i * across);
        (i * axis - along * axis).length() <= 1e-12 * scale
            && (m1 - other.dot(i * other)).abs() <= 1e-12 * scale
            && across.dot(i * other).abs() <= 1e-12 * scale
    }
}

/// The engine's `GroundTop` for a body with [`Support::Ground`] in a world
/// of gravity `gravity`.
pub(crate) fn ground_top_of(body: &Body, gravity: DVec3) -> Result<GroundTop, AnalysisError> {
    let Support::Ground {
        shape, friction, ..
    } = body.support()
    else {
        return Err(AnalysisError::Parameter {
            name: "support",
            value: f64::NAN,
            must: "the ground (Support::Ground)",
        });
    };
    if !(gravity.x == 0.0 && gravity.y == 0.0 && gravity.z < 0.0 && gravity.z.is_finite()) {
        return Err(AnalysisError::Parameter {
            name: "gravity",
            value: gravity.length(),
            must: "along −z (0, 0, −g), g > 0",
        });
    }
    let props = body.mass_properties();
    Ok(GroundTop::try_with_shape(
        props.mass,
        props.inertia,
        shape,
        friction,
        -gravity.z,
    )?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DQuat, DVec2};
    use kreisel_dynamics::{ContactShape, DiskContact, EllipsoidContact, SphereContact};

    fn shapes() -> [ContactShape; 3] {
        [
            ContactShape::Sphere(
                SphereContact::try_new(0.015, DVec3::new(0.0005, -0.001, 0.003)).unwrap(),
            ),
            ContactShape::Disk(
                DiskContact::try_new(
                    0.03,
                    DVec3::new(0.0, 0.001, 0.004),
                    DVec3::new(0.2, 0.1, 1.0),
                )
                .unwrap(),
            ),
            ContactShape::Ellipsoid(
                EllipsoidContact::try_new(
                    DVec3::new(0.2, 0.03, 0.02),
                    DVec3::new(0.001, -0.002, 0.01),
                )
                .unwrap(),
            ),
        ]
    }

    /// A full inertia tensor (no symmetry), kg m².
    fn inertia() -> DMat3 {
        DMat3::from_cols(
            DVec3::new(2e-4, 2e-5, -1e-5),
            DVec3::new(2e-5, 16e-4, 3e-5),
            DVec3::new(-1e-5, 3e-5, 17e-4),
        )
    }

    /// The normal force of each friction law and the rolling reaction, in
    /// body axes here, are the engine's (world axes, its own solve) at
    /// tilted, spinning, slipping states: to 1e-13 relative.
    #[test]
    fn the_contact_force_is_the_engines() {
        let q = DQuat::from_euler(glam::EulerRot::ZXZ, 0.3, 0.7, -0.4);
        let omega_world = DVec3::new(3.0, -2.0, 15.0);
        let mut worst: f64 = 0.0;
        for shape in shapes() {
            for friction in [
                Friction::None,
                Friction::try_viscous(0.3).unwrap(),
                Friction::try_sliding(0.3, 1e-3).unwrap(),
                Friction::Rolling,
            ] {
                let top = GroundTop::try_with_shape(1.0, inertia(), shape, friction, 9.81).unwrap();
                let s = if friction == Friction::Rolling {
                    top.try_rolling_state_on_ground(q, omega_world).unwrap()
                } else {
                    top.try_state_on_ground(q, omega_world, DVec2::new(0.05, -0.02))
                        .unwrap()
                };
                let body = ContactBody::of(&top).unwrap();
                let to_body = q.conjugate();
                let gamma = (to_body * DVec3::Z).to_array();
                let omega = (to_body * omega_world).to_array();
                let v = (to_body * s.velocity_world).to_array();
                let engine = top.contact_force(&s).unwrap();
                let ours = if friction == Friction::Rolling {
                    let w_dot = body.rolling_omega_rate(gamma, omega, omega);
                    let gamma_rate = cross(gamma, omega);
                    let (r, r_rate) = body.surface.com_from_contact(gamma, gamma_rate);
                    let accel = add(
                        add(cross(w_dot, r), cross(omega, r_rate)),
                        cross(omega, cross(omega, r)),
                    );
                    let f = add(
                        scale(accel, body.mass),
                        scale(gamma, body.mass * body.gravity),
                    );
                    q * DVec3::from_array(f)
                } else {
                    let (_, _, n) = body.sliding_rates(gamma, omega, v);
                    DVec3::Z * n
                };
                let error = if friction == Friction::Rolling {
                    (ours - engine).length() / engine.length()
                } else {
                    (ours.z - engine.z).abs() / engine.z.abs()
                };
                worst = worst.max(error);
                assert!(error <= 1e-13, "{shape:?} {friction:?}: {ours} vs {engine}");
            }
        }
        eprintln!("largest relative difference from the engine: {worst:.1e}");
    }

    #[test]
    fn applied_loads_are_refused() {
        let top = GroundTop::try_with_shape(1.0, inertia(), shapes()[0], Friction::None, 9.81)
            .unwrap()
            .try_with_inputs(
                kreisel_dynamics::Inputs::default()
                    .with_load(|_, _| (DVec3::ZERO, DVec3::new(0.0, 0.0, 1.0))),
            )
            .unwrap();
        assert!(matches!(
            ContactBody::of(&top),
            Err(AnalysisError::Parameter { name: "inputs", .. })
        ));
    }
}
