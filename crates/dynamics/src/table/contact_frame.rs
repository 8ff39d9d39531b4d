//! The contact quantities of one state of a [`TableBody`]: for every
//! shape its gap, the directions along which the table can push and rub
//! (generalized force directions `w`), the matching relative velocities
//! `γ = wᵀ u` and the parts `ŵ` of their rates that do not depend on the
//! accelerations; the Delassus products `w_aᵀ M⁻¹ w_b` between them.
//!
//! ```text
//! u = (v_G, ω),   M⁻¹ (F, τ) = (F/m, I_w⁻¹ τ)
//! normal:    w_N = (ẑ, ρ × ẑ)         γ_N = ġ = (v_P)_z       ŵ_N = (ω × ρ̇)_z
//! tangent:   w_x = (x̂, ρ × x̂)         γ_x = (v_P)_x           ŵ_x = (ω × ρ̇)_x
//!            w_y = (ŷ, ρ × ŷ)         γ_y = (v_P)_y           ŵ_y = (ω × ρ̇)_y
//! drilling:  w_d = (0, ε ẑ)           γ_d = ε ω_z             ŵ_d = 0
//! rolling:   w_r = (0, δ x̂), (0, δ ŷ) γ_r = δ (ω_x, ω_y)      ŵ_r = 0
//! rate of γ:  γ̇ = wᵀ u̇ + ŵ            (v_P = v_G + ω × ρ, d v_P/dt = v̇_G + ω̇ × ρ + ω × ρ̇)
//! ```
//!
//! `ρ` is the shape's lowest point seen from the centre of mass and `ρ̇`
//! its rate as the point moves over the surface (the formulas at
//! [`crate::DiskContact`] and [`crate::EllipsoidContact`]; `ω × A c` for a
//! sphere).

use glam::{DMat3, DQuat, DVec3};

use super::TableBody;
use crate::GroundTopState;

/// A generalized force direction (a force through the centre of mass and
/// a torque about it, world axes), also read as the velocity functional
/// `wᵀ u = F·v_G + τ·ω`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct Wrench {
    pub(crate) force: DVec3,
    pub(crate) torque: DVec3,
}

impl Wrench {
    /// `self · s`.
    pub(crate) fn scaled(self, s: f64) -> Self {
        Self {
            force: self.force * s,
            torque: self.torque * s,
        }
    }

    /// `self + other`.
    pub(crate) fn plus(self, other: Self) -> Self {
        Self {
            force: self.force + other.force,
            torque: self.torque + other.torque,
        }
    }

    /// `wᵀ u` for `u = (v, ω)`.
    pub(crate) fn dot_motion(&self, velocity: DVec3, omega: DVec3) -> f64 {
        self.force.dot(velocity) + self.torque.dot(omega)
    }
}

/// The contact quantities of one shape: index 0 the normal, then the
/// friction directions (0, 2 or 3 of them, [`super::ContactLaw`]), and at
/// [`ROLLING`] the two rolling directions when the law has a rolling
/// resistance.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ContactRow {
    /// The gap `g = z_G + ρ_z`, m.
    pub(crate) gap: f64,
    /// How many friction directions (0, 2, 3).
    pub(crate) friction_dimensions: usize,
    /// Whether the law has a rolling resistance (components
    /// [`ROLLING`]).
    pub(crate) rolls: bool,
    /// `μ`.
    pub(crate) mu: f64,
    /// Directions `w_N, w_x, w_y, w_d, w_rx, w_ry`.
    pub(crate) directions: [Wrench; 6],
    /// Relative velocities `γ = wᵀ u`.
    pub(crate) velocity: [f64; 6],
    /// The acceleration-free parts of their rates, `ŵ`.
    pub(crate) bias: [f64; 6],
}

/// The components of a row's rolling directions.
pub(crate) const ROLLING: [usize; 2] = [4, 5];

impl ContactRow {
    /// The slip `γ_T` (friction components), zero-padded to 3.
    pub(crate) fn slip(&self) -> DVec3 {
        let n = self.friction_dimensions;
        DVec3::new(
            if n > 0 { self.velocity[1] } else { 0.0 },
            if n > 1 { self.velocity[2] } else { 0.0 },
            if n > 2 { self.velocity[3] } else { 0.0 },
        )
    }

    /// The rolling rate `γ_R = δ ω_h` (zero without rolling resistance),
    /// its third component zero.
    pub(crate) fn roll(&self) -> DVec3 {
        if self.rolls {
            DVec3::new(self.velocity[ROLLING[0]], self.velocity[ROLLING[1]], 0.0)
        } else {
            DVec3::ZERO
        }
    }
}

/// Everything the contact problems need at one state.
#[derive(Debug, Clone)]
pub(crate) struct ContactFrame {
    pub(crate) omega: DVec3,
    pub(crate) inverse_mass: f64,
    pub(crate) inverse_inertia_world: DMat3,
    /// `v̇_G` without contact forces: gravity and the applied force,
    /// `−g ẑ + F/m`.
    pub(crate) free_velocity_rate: DVec3,
    /// `ω̇` without contact torques: `I_w⁻¹ (L × ω + τ)`.
    pub(crate) free_omega_rate: DVec3,
    /// The applied torque `τ` (part of `L̇`).
    pub(crate) applied_torque: DVec3,
    pub(crate) rows: Vec<ContactRow>,
}

impl ContactFrame {
    /// The frame of `state` at time `t` (attitude read through `q/|q|`;
    /// `t` only where applied inputs depend on it).
    pub(crate) fn of(body: &TableBody, state: &GroundTopState, t: f64) -> Self {
        let q: DQuat = state.world_from_body.normalize();
        let inverse_inertia_world = body.inverse_inertia_world(q);
        let omega = inverse_inertia_world * state.l_world;
        let rows = body
            .contacts()
            .iter()
            .map(|c| {
                let (rho, rho_dot) = super::face::offset_and_rate(&c.shape, q, omega);
                let v_p = state.velocity_world + omega.cross(rho);
                let spin = omega.cross(rho_dot);
                let along = |axis: DVec3| Wrench {
                    force: axis,
                    torque: rho.cross(axis),
                };
                let turning = |axis: DVec3, arm: f64| Wrench {
                    force: DVec3::ZERO,
                    torque: axis * arm,
                };
                let arm = c.law.drilling_arm();
                let delta = c.law.rolling_resistance();
                ContactRow {
                    gap: state.com_world.z + rho.z,
                    friction_dimensions: c.law.friction_dimensions(),
                    rolls: delta > 0.0,
                    mu: c.law.mu(),
                    directions: [
                        along(DVec3::Z),
                        along(DVec3::X),
                        along(DVec3::Y),
                        turning(DVec3::Z, arm),
                        turning(DVec3::X, delta),
                        turning(DVec3::Y, delta),
                    ],
                    velocity: [
                        v_p.z,
                        v_p.x,
                        v_p.y,
                        arm * omega.z,
                        delta * omega.x,
                        delta * omega.y,
                    ],
                    bias: [spin.z, spin.x, spin.y, 0.0, 0.0, 0.0],
                }
            })
            .collect();
        let (torque, force) = body.applied_world(t, state);
        Self {
            omega,
            inverse_mass: 1.0 / body.mass(),
            inverse_inertia_world,
            free_velocity_rate: force / body.mass() - body.gravity() * DVec3::Z,
            free_omega_rate: inverse_inertia_world * (state.l_world.cross(omega) + torque),
            applied_torque: torque,
            rows,
        }
    }

    /// `M⁻¹ w`: the change of `(v̇_G, ω̇)` per unit of `w`.
    pub(crate) fn response(&self, w: &Wrench) -> (DVec3, DVec3) {
        (
            w.force * self.inverse_mass,
            self.inverse_inertia_world * w.torque,
        )
    }

    /// The Delassus product `aᵀ M⁻¹ b`.
    pub(crate) fn delassus(&self, a: &Wrench, b: &Wrench) -> f64 {
        let (dv, dw) = self.response(b);
        a.dot_motion(dv, dw)
    }

    /// The rate `γ̇ = wᵀ u̇ + ŵ` of component `k` of contact `i` under the
    /// accelerations `(v̇_G, ω̇)`.
    pub(crate) fn rate(&self, i: usize, k: usize, accel: (DVec3, DVec3)) -> f64 {
        let row = &self.rows[i];
        row.directions[k].dot_motion(accel.0, accel.1) + row.bias[k]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::table::{ContactLaw, TableContact};
    use crate::{ContactShape, SphereContact};

    /// The rates `γ̇` the frame predicts match finite differences of `γ`
    /// along the motion (the check that `ŵ` is the right bias).
    #[test]
    fn rates_match_finite_differences_of_the_relative_velocities() {
        let sphere = SphereContact::try_new(0.015, DVec3::new(0.0, 0.0, 0.003)).unwrap();
        let law = ContactLaw::new(0.3)
            .try_with_contensou_radius(5e-4)
            .and_then(|l| l.try_with_rolling_resistance(1e-3))
            .unwrap();
        let body = TableBody::try_new(
            0.006,
            DMat3::from_diagonal(DVec3::new(8e-7, 8e-7, 7e-7)),
            vec![TableContact {
                shape: ContactShape::Sphere(sphere),
                law,
            }],
            9.81,
        )
        .unwrap();
        let state = GroundTopState {
            com_world: DVec3::new(0.0, 0.0, 0.02),
            velocity_world: DVec3::new(0.1, -0.2, 0.05),
            world_from_body: DQuat::from_rotation_x(0.7) * DQuat::from_rotation_z(0.2),
            l_world: DVec3::new(1e-5, -3e-5, 1.2e-4),
        };
        // Any accelerations: move the state along them to second order.
        let accel = (DVec3::new(0.3, -1.0, 2.0), DVec3::new(40.0, -25.0, 10.0));
        let at = |h: f64| {
            let f = ContactFrame::of(&body, &state, 0.0);
            let omega = f.omega + accel.1 * h;
            let q = DQuat::from_scaled_axis(f.omega * h + 0.5 * accel.1 * h * h)
                * state.world_from_body;
            let q = if h == 0.0 { state.world_from_body } else { q };
            // L from ω at the new attitude.
            let a = DMat3::from_quat(q.normalize());
            let l = a * body.inertia_body() * a.transpose() * omega;
            let s = GroundTopState {
                com_world: state.com_world + state.velocity_world * h + 0.5 * accel.0 * h * h,
                velocity_world: state.velocity_world + accel.0 * h,
                world_from_body: q,
                l_world: l,
            };
            ContactFrame::of(&body, &s, 0.0)
        };
        let f0 = ContactFrame::of(&body, &state, 0.0);
        let h = 1e-6;
        let (fp, fm) = (at(h), at(-h));
        for k in 0..6 {
            let fd = (fp.rows[0].velocity[k] - fm.rows[0].velocity[k]) / (2.0 * h);
            let predicted = f0.rate(0, k, accel);
            assert!(
                (fd - predicted).abs() < 1e-6 * (1.0 + predicted.abs()),
                "component {k}: {fd} vs {predicted}"
            );
        }
    }
}
