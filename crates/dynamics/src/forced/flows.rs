//! The two sub-flows of the forced splittings: the free drift (exact
//! rotation, uniform translation, time advancing) and the kick of the
//! applied loads with the attitude, the position and the time frozen.

use glam::DVec3;

use super::{ForcedBody, ForcedState};

/// Iterations allowed for the implicit midpoint kick of a velocity law
/// before the step is declared failed (a non-finite state).
const MAX_ITERATIONS: usize = 100;

/// `φ(z) = (eᶻ − 1)/z`, `φ(0) = 1`: the exact weight of a constant torque
/// under linear damping.
#[inline]
fn phi(z: f64) -> f64 {
    if z == 0.0 { 1.0 } else { z.exp_m1() / z }
}

impl ForcedBody {
    /// The drift `A` for time `h`: the torque-free rotation (exact for two
    /// equal moments, PDMV10 otherwise) and the uniform motion of the centre
    /// of mass.
    ///
    /// ```text
    /// (q, L) ← free flow(h),   x ← x + h v
    /// ```
    #[inline]
    pub(super) fn drift(&self, state: &mut ForcedState, h: f64) {
        self.free
            .apply(self.body().principal_moments(), &mut state.rotation, h);
        // On a pivot the centre of mass follows the attitude: brought up
        // to date where it is read (a load's kick, the end of a step).
        if !self.is_anchored() {
            state.position_world += state.velocity_world * h;
        }
    }

    /// The exact kick `B` for time `h` of every load that reads no velocity
    /// and of the damping, at time `t`: `q`, `x`, `t` stand still, so the
    /// torque is constant in principal axes and the damping linear.
    ///
    /// ```text
    /// τ = configuration torque (principal axes),   kᵢ = c / Iᵢ
    /// Lᵢ ← Lᵢ e^{−kᵢh} + h τᵢ φ(−kᵢh),   φ(z) = (eᶻ − 1)/z
    /// v ← v + h (F/m + g)
    /// ```
    #[inline]
    pub(super) fn exact_kick(&self, state: &mut ForcedState, t: f64, h: f64) {
        if self.is_anchored() && self.inputs().load.is_some() {
            // A law may read where the centre of mass is.
            self.follow_pivot(state);
        }
        if self.is_anchored() || self.inputs().has_rotational_part() {
            let tau = self.configuration_torque_principal(t, state);
            let z = -self.decay() * h;
            let l = &mut state.rotation.l_principal;
            if z == DVec3::ZERO {
                *l += tau * h;
            } else {
                let decay = DVec3::new(z.x.exp(), z.y.exp(), z.z.exp());
                let weight = DVec3::new(phi(z.x), phi(z.y), phi(z.z));
                *l = *l * decay + tau * weight * h;
            }
        }
        if !self.is_anchored() {
            let force = self.configuration_force_world(t, state);
            state.velocity_world += (force / self.mass() + self.gravity_world()) * h;
        }
    }

    /// The kick for time `h` at time `t`: [`ForcedBody::exact_kick`], or,
    /// when a law reads the velocity, the symmetric order-2 approximation
    /// of its flow
    ///
    /// ```text
    /// B̃(h) = E(h/2) ∘ M(h) ∘ E(h/2)
    /// E: the exact kick above;   M: implicit midpoint for the law alone,
    /// y = (L, v):  y₁ = y₀ + h f(t, q, x, (y₀ + y₁)/2),   f = (Rᵀ τ_law, F_law / m)
    /// ```
    /// solved by fixed-point iteration to rounding (contracting while
    /// `h/2 ‖∂f/∂y‖ < 1`; stopped when the relative change is ≤ 4ε, or
    /// ≤ 1e-10 and no longer shrinking); a step where it does not converge
    /// in 100 iterations leaves a NaN state.
    pub(super) fn kick(&self, state: &mut ForcedState, t: f64, h: f64) {
        match self.inputs().load.as_ref().filter(|l| l.reads_velocity()) {
            None => self.exact_kick(state, t, h),
            Some(load) => {
                self.exact_kick(state, t, 0.5 * h);
                let (l0, v0) = (state.rotation.l_principal, state.velocity_world);
                let principal_from_world =
                    state.rotation.world_from_principal.normalize().conjugate();
                let f = |s: &ForcedState| {
                    let (tau, force) = load.eval(t, s);
                    let arm = self.pivot_torque_principal(principal_from_world * force);
                    (principal_from_world * tau + arm, force / self.mass())
                };
                let (dl, dv) = f(state);
                let (mut l1, mut v1) = (l0 + dl * h, v0 + dv * h);
                let mut converged = false;
                let mut previous = f64::INFINITY;
                for _ in 0..MAX_ITERATIONS {
                    let mut mid = ForcedState {
                        rotation: crate::PrincipalState {
                            l_principal: 0.5 * (l0 + l1),
                            ..state.rotation
                        },
                        velocity_world: 0.5 * (v0 + v1),
                        ..*state
                    };
                    // On a pivot the velocity is the midpoint L's.
                    self.follow_pivot(&mut mid);
                    let (dl, dv) = f(&mid);
                    let (l2, v2) = (l0 + dl * h, v0 + dv * h);
                    let change = relative(l2 - l1, l0, l2).max(relative(v2 - v1, v0, v2));
                    (l1, v1) = (l2, v2);
                    // Converged: at rounding, or no longer shrinking once
                    // below 1e-10 (the iterates then wander within a few
                    // ulps, e.g. with subnormal L at rest).
                    if change <= 4.0 * f64::EPSILON || (change <= 1e-10 && change >= previous) {
                        converged = true;
                        break;
                    }
                    previous = change;
                }
                if !converged {
                    l1 = DVec3::NAN;
                }
                state.rotation.l_principal = l1;
                state.velocity_world = v1;
                self.follow_pivot(state);
                self.exact_kick(state, t, 0.5 * h);
            }
        }
    }
}

/// `|d|∞ / max(|a|∞, |b|∞, 2⁻⁹⁷⁰)`, zero when `d` is: the floor keeps
/// changes among subnormal numbers (a body come to rest) from counting as
/// large.
#[inline]
fn relative(d: DVec3, a: DVec3, b: DVec3) -> f64 {
    let d = d.abs().max_element();
    if d == 0.0 {
        0.0
    } else {
        d / a
            .abs()
            .max_element()
            .max(b.abs().max_element())
            .max(f64::MIN_POSITIVE / f64::EPSILON)
    }
}

#[cfg(test)]
mod tests {
    use glam::DQuat;

    use super::*;
    use crate::{Inputs, PrincipalState, RigidBody};

    fn state() -> ForcedState {
        ForcedState::at_origin(PrincipalState {
            world_from_principal: DQuat::from_rotation_y(0.7),
            l_principal: DVec3::new(0.3, -0.2, 1.5),
        })
    }

    /// The damped kick solves `L̇ = τ − c I⁻¹ L` exactly: two half kicks
    /// are one whole kick, and the closed form of one axis.
    #[test]
    fn damped_kick_is_a_flow() {
        let body = RigidBody::try_from_principal_moments(DVec3::new(1.0, 2.0, 3.0)).unwrap();
        let inputs = Inputs::default()
            .with_torque_body(DVec3::new(0.4, 0.1, -0.3))
            .with_angular_damping(0.7);
        let forced = ForcedBody::try_new(body, 1.0, DVec3::ZERO, inputs).unwrap();
        let (mut a, mut b) = (state(), state());
        forced.exact_kick(&mut a, 0.0, 0.3);
        forced.exact_kick(&mut b, 0.0, 0.1);
        forced.exact_kick(&mut b, 0.0, 0.2);
        assert!((a.rotation.l_principal - b.rotation.l_principal).length() < 1e-15);
        // Axis 1: k = 0.7, τ = 0.4: L = τ/k + (L₀ − τ/k) e^{−k h}.
        let (k, tau, l0) = (0.7, 0.4, 0.3);
        let l = tau / k + (l0 - tau / k) * (-k * 0.3f64).exp();
        assert!((a.rotation.l_principal.x - l).abs() < 1e-15);
    }

    /// Regression: a PD-controlled body come to rest (`L` and the attitude
    /// error subnormal) kept iterating among subnormal values and the step
    /// gave NaN (after ~3 h of simulated time at dt = 1/60).
    #[test]
    fn velocity_kick_at_rest_stays_finite() {
        let body = RigidBody::try_from_principal_moments(DVec3::new(1.0, 2.0, 3.0)).unwrap();
        let moments = body.principal_moments();
        let inputs = Inputs::default().with_velocity_load(move |_, s: &ForcedState| {
            let rotvec =
                kreisel_kinematics::rotation_vector_from_quat(s.rotation.world_from_principal);
            (-2.0 * rotvec - 1.5 * s.omega_world(moments), DVec3::ZERO)
        });
        let gravity = DVec3::new(0.0, 0.0, -9.81);
        let forced = ForcedBody::try_new(body, 1.0, gravity, inputs).unwrap();
        // The state before the failed step (170 634 at dt = 1/60).
        let mut s = ForcedState {
            rotation: PrincipalState {
                world_from_principal: DQuat::from_xyzw(
                    4.74e-322,
                    -4.74e-322,
                    -1.203668112026713e-309,
                    0.9999999999988656,
                ),
                l_principal: DVec3::new(-7.56e-322, 1.507e-321, 4.17884015471668e-309),
            },
            position_world: DVec3::new(0.0, 0.0, -39670498.16463863),
            velocity_world: DVec3::new(0.0, 0.0, -27898.658998837742),
        };
        for k in 170_634..170_734 {
            crate::ForcedSplitting::ORDER_6.step(&forced, &mut s, k as f64 / 60.0, 1.0 / 60.0);
            assert!(s.is_finite(), "step {k}: {s:?}");
        }
    }

    /// The implicit midpoint kick of a linear law `τ = −c ω` against its
    /// closed form (the Cayley map of the exact decay), on a sphere.
    #[test]
    fn implicit_midpoint_kick() {
        let body = RigidBody::try_from_principal_moments(DVec3::splat(2.0)).unwrap();
        let c = 0.6;
        let inputs = Inputs::default().with_velocity_load(move |_, s: &ForcedState| {
            (-c * s.omega_world(DVec3::splat(2.0)), DVec3::ZERO)
        });
        let forced = ForcedBody::try_new(body, 1.0, DVec3::ZERO, inputs).unwrap();
        let mut s = state();
        let h = 0.25;
        forced.kick(&mut s, 0.0, h);
        let z = c * h / 2.0;
        let cayley = (1.0 - 0.5 * z) / (1.0 + 0.5 * z);
        let expected = state().rotation.l_principal * cayley;
        assert!((s.rotation.l_principal - expected).length() < 1e-15);
    }
}
