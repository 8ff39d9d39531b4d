//! The torque-free step for `f32` engines (bevy, avian, rapier): one frame
//! of a free rigid body on glam's `f32` `Quat`/`Vec3`, computed in `f64`
//! inside, so that the only error worth counting is the final rounding to
//! `f32`.
//!
//! See [`FreeBodyF32`] for the method, its accuracy and cost, and its use
//! from bevy and avian.

use glam::{DQuat, DVec3, Quat, Vec3};

use crate::{
    DynamicsError, ExactSolution, FreeBodyIntegrator, PreprocessedMoserVeselov, PrincipalState,
    RigidBody,
};

/// The largest `ω_max h` of one PDMV10 sub-step: 2e-14 rad from the exact
/// motion per sub-step there (see [`FreeBodyF32`]).
const SUBSTEP_ANGLE: f64 = 0.25;

/// The most PDMV10 sub-steps a step takes before the exact solution is
/// cheaper (~0.15 µs a sub-step against ~40 µs for the tables).
const MAX_PDMV_SUBSTEPS: f64 = 256.0;

/// A torque-free rigid body's inertia, prepared for `f32` frame steps:
/// principal moments and `body_from_principal`, widened to `f64` and
/// checked once.
///
/// ```text
/// I_body = R diag(I₁, I₂, I₃) Rᵀ,   R = body_from_principal
/// ```
///
/// ```
/// use glam::{Quat, Vec3};
/// use kreisel_dynamics::FreeBodyF32;
/// let body = FreeBodyF32::try_new(Vec3::new(1.0, 2.0, 3.0), Quat::IDENTITY)?;
/// // A spin about the largest axis (world z) is a uniform rotation: 1 rad in 1 s.
/// let (q, w) = body.try_step(Quat::IDENTITY, Vec3::new(0.0, 0.0, 1.0), 1.0)?;
/// assert!(q.angle_between(Quat::from_rotation_z(1.0)) < 2.0 * f32::EPSILON);
/// assert_eq!(w, Vec3::new(0.0, 0.0, 1.0));
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
///
/// Engines keep the attitude `world_from_body`, the angular velocity in
/// world axes and the inertia as principal moments plus the rotation of the
/// principal axes in the body (rapier: `MassProperties::
/// principal_inertia_local_frame`, with `inv_principal_inertia`; avian:
/// `AngularInertia::local_frame`, with `principal`);
/// both rotations map principal to body coordinates, `I_body = R diag(I) Rᵀ`.
/// rapier's own angular step is first order in `dt`
/// (`tests/rapier_cross_check.rs` at the workspace root); this step is the
/// exact motion to rounding.
///
/// ```text
/// q_wp = q̂_wb ⊗ q̂_bp,   L = I (q_wp⁻¹ ω_w)                    (f64, inputs widened exactly)
/// symmetric body (two moments equal):   (q_wp, L) ← ExactSolution(dt)       (closed form)
/// otherwise:  n = ⌈dt ω_max / 0.25⌉,  ω_max = √(2E / I_min)
///             n ≤ 256:  n steps of PDMV10 of dt/n  (Hairer & Vilmart 2006)
///             n > 256:  (q_wp, L) ← ExactSolution(dt)       (Jacobi elliptic functions)
/// q_wb' = round_f32(q_wp ⊗ q̂_bp⁻¹),   ω_w' = round_f32(q_wp (I⁻¹ L))
/// ```
///
/// `q̂` is `q` normalised in `f64`. The bound `ω_max` holds over the whole
/// motion (the energy `E = ½ I ω²` is conserved), so no sub-step turns the
/// body by more than 0.25 rad, where one step of PDMV10 is within 2e-14 rad
/// of the exact motion (`tests/free_body_f32.rs`, random bodies and states
/// against [`ExactSolution`]; 1.6e-13 at 0.3, 3.7e-12 at 0.4): far below
/// `f32`'s 1.2e-7. Beyond 256 sub-steps (`ω_max dt > 64 rad`) the
/// exact solution, ~40 µs with its tables, is cheaper.
///
/// The preprocessed discrete Moser–Veselov algorithm of order 10: E. Hairer
/// and G. Vilmart, *Preprocessed discrete Moser–Veselov algorithm for the
/// full dynamics of a rigid body*, J. Phys. A 39 (2006) 13225
/// ([`PreprocessedMoserVeselov`]).
///
/// # Accuracy and cost
/// Measured in `tests/free_body_f32.rs` against the exact motion of the
/// same `f32` input ([`ExactSolution`] in `f64`, and fine PDMV10
/// steps where the step itself uses the exact solution): over 24 000
/// random states — generic, near-symmetric (1e-6, 1e-3), symmetric, flat
/// and rod-like bodies, `|ω| dt` from 1e-3 to 8 rad — and 300 fast spins
/// (`|ω| dt` up to 400 rad), the returned attitude is within 0.80
/// `f32::EPSILON` (as a rotation angle, rad: 9.5e-8) of the exact
/// rotation, and `ω_w'` within 0.48 ε of the exact `ω`, relative to `|ω|`.
/// Steps of 0.5 s between the samples of the 60-digit reference
/// `tests/data/free_body/rapier.csv`, each sample rounded to `f32`: within
/// 1.13 ε (the rounding of the input, carried by the motion, included).
///
/// Frame after frame the `f32` state is rounded, and that accumulates: 6000
/// frames of 1/60 s of `I = (1, 2, 3)`, `ω₀ = (0.01, 1, 0)` (a Dzhanibekov
/// flip every 20.75 s, next to the separatrix) keep the energy and `|L|`
/// within 6.4e-6, and the flip period within 5.8e-5 of the exact one
/// (rapier at 1/60: 6e-3); the attitude is 1.2e-4 rad from the exact
/// motion of the same start at 100 s, and up to 9.2e-3 rad during a flip,
/// where the flip's timing is sensitive (the exact motion from `ω₂` one
/// `f32` ulp larger departs by 1.2e-5 rad). A body kept in `f64`
/// ([`crate::World`]) has no such drift.
///
/// One call costs ~0.25 µs for `ω_max dt ≤ 0.25` (an asymmetric body
/// turning at up to ~15 rad/s at 60 Hz), ~0.15 µs per further sub-step,
/// ~0.28 µs for a symmetric body at any `dt`, at most ~45 µs (the exact
/// solution); [`try_free_body_step_f32`], which prepares the body each
/// call, ~0.37 µs (`cargo run --release -p kreisel-dynamics --example
/// free_body_f32_cost`, 2-core shared machine).
///
/// # A game loop
/// On glam 0.34's `f32` types directly: a brick tumbling about its
/// intermediate axis for 15 s at 60 Hz keeps its angular momentum in
/// world axes, which the exact motion conserves, to the `f32` rounding of
/// the frames.
///
/// ```
/// use glam::{Quat, Vec3};
/// use kreisel_dynamics::FreeBodyF32;
/// let moments = Vec3::new(1.0, 2.0, 3.0);
/// let body = FreeBodyF32::try_new(moments, Quat::IDENTITY)?;
/// let l_world = |q: Quat, w: Vec3| q * (moments * (q.inverse() * w));
/// let (mut q, mut w) = (Quat::IDENTITY, Vec3::new(0.05, 1.0, 0.0));
/// let (l0, mut lowest) = (l_world(q, w), 1.0f32);
/// for _frame in 0..900 {
///     (q, w) = body.try_step(q, w, 1.0 / 60.0)?;
///     lowest = lowest.min((q.inverse() * w).y);
/// }
/// // The intermediate axis is unstable: ω₂ in body axes has flipped…
/// assert!(lowest < -0.99);
/// // …while L_world stayed put.
/// assert!((l_world(q, w) - l0).length() < 1e-5 * l0.length());
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
///
/// # From bevy, avian or rapier
/// bevy (bevy_math 0.20) and rapier 0.36 use glam 0.33's `Quat`/`Vec3`:
/// convert them exactly with `kreisel_kinematics::glam033_interop`
/// (feature `glam033`); an engine on glam 0.34 passes its values as they
/// are. A per-frame bevy system for avian bodies in free flight, as a
/// sketch (not compiled: kreisel does not depend on bevy or avian; the
/// avian names are those of its `AngularInertia` component, `principal`
/// and `local_frame`, and `AngularVelocity`):
///
/// ```ignore
/// use kreisel_dynamics::FreeBodyF32;
/// use kreisel_kinematics::glam033_interop::{dquat_from_quat, dvec3_from_vec3, quat_from_dquat, vec3_from_dvec3};
///
/// /// Turns torque-free bodies by their exact motion, gyroscopic term included.
/// fn free_rotation(
///     time: Res<Time>,
///     mut bodies: Query<(&mut Transform, &mut AngularVelocity, &AngularInertia), With<FreeFlight>>,
/// ) {
///     let dt = time.delta_secs();
///     if dt <= 0.0 {
///         return; // paused: nothing to do (a zero step is refused)
///     }
///     // glam 0.33 → 0.34 and back, exactly (f32 → f64 → f32).
///     let q34 = |q| dquat_from_quat(q).as_quat();
///     let v34 = |v| dvec3_from_vec3(v).as_vec3();
///     for (mut transform, mut omega, inertia) in &mut bodies {
///         // Cache this in a component when the inertia does not change.
///         let body = match FreeBodyF32::try_new(v34(inertia.principal), q34(inertia.local_frame)) {
///             Ok(body) => body,
///             Err(e) => { warn!("{e}"); continue } // e.g. a locked (infinite) inertia
///         };
///         match body.try_step(q34(transform.rotation), v34(omega.0), dt) {
///             Ok((q, w)) => {
///                 transform.rotation = quat_from_dquat(q.as_dquat());
///                 omega.0 = vec3_from_dvec3(w.as_dvec3());
///             }
///             Err(e) => warn!("{e}"),
///         }
///     }
/// }
/// ```
///
/// Run it in place of the engine's own angular integration for those
/// bodies (avian and rapier would otherwise turn them a second time). With
/// rapier, the moments are `1 / mass_properties.inv_principal_inertia` and
/// the frame `principal_inertia_local_frame`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FreeBodyF32 {
    moments: DVec3,
    body_from_principal: DQuat,
    symmetric: bool,
    pdmv10: PreprocessedMoserVeselov,
}

impl FreeBodyF32 {
    /// The body with principal `moments` (kg·m²) along the axes that
    /// `body_from_principal` maps into the body (rapier's
    /// `principal_inertia_local_frame`, avian's local inertial frame),
    /// normalised in `f64`.
    ///
    /// ```text
    /// I = moments as f64,   R = body_from_principal as f64 / |·|
    /// ```
    ///
    /// # Errors
    /// [`DynamicsError::UnphysicalInertia`] for moments that
    /// [`RigidBody::try_from_principal_moments`] refuses (not positive and
    /// finite — an engine's infinite inertia of a locked body —, or
    /// breaking the triangle inequality by more than 4 `f32` ε relative —
    /// within that, an `f32` plate's rounding, the largest moment is taken
    /// as the sum of the other two);
    /// [`DynamicsError::InvalidBody`] for a zero or non-finite
    /// `body_from_principal`.
    ///
    /// ```
    /// use glam::{Quat, Vec3};
    /// use kreisel_dynamics::{DynamicsError, FreeBodyF32};
    /// let e = FreeBodyF32::try_new(Vec3::new(1.0, 1.0, 3.0), Quat::IDENTITY).unwrap_err();
    /// assert!(matches!(e, DynamicsError::UnphysicalInertia { .. }));
    /// // A plate in f32: 0.1 + 0.2 < 0.3 by 2.5e-8 relative after rounding.
    /// let plate = FreeBodyF32::try_new(Vec3::new(0.1, 0.2, 0.3), Quat::IDENTITY)?;
    /// assert!((plate.principal_moments() - Vec3::new(0.1, 0.2, 0.3)).abs().max_element() <= 3e-8);
    /// let e = FreeBodyF32::try_new(Vec3::ONE, Quat::from_xyzw(0.0, 0.0, 0.0, 0.0)).unwrap_err();
    /// assert!(matches!(e, DynamicsError::InvalidBody { field: "body_from_principal", .. }));
    /// # Ok::<(), DynamicsError>(())
    /// ```
    pub fn try_new(moments: Vec3, body_from_principal: Quat) -> Result<Self, DynamicsError> {
        let moments = flat_within_f32(moments.as_dvec3());
        RigidBody::try_from_principal_moments(moments)?;
        let body_from_principal = kreisel_kinematics::try_normalize_quat(
            body_from_principal.as_dquat(),
        )
        .map_err(|_| DynamicsError::InvalidBody {
            field: "body_from_principal",
            reason: "is zero or not finite",
        })?;
        let [a, b, c] = moments.to_array();
        Ok(Self {
            moments,
            body_from_principal,
            symmetric: a == b || b == c || a == c,
            pdmv10: PreprocessedMoserVeselov::ORDER_10.for_body(moments),
        })
    }

    /// [`FreeBodyF32::try_new`], panicking on bad input.
    ///
    /// # Panics
    /// Where [`FreeBodyF32::try_new`] returns an error.
    ///
    /// ```
    /// use glam::{Quat, Vec3};
    /// let body = kreisel_dynamics::FreeBodyF32::new(Vec3::new(1.0, 2.0, 2.5), Quat::IDENTITY);
    /// assert_eq!(body.principal_moments(), Vec3::new(1.0, 2.0, 2.5));
    /// ```
    pub fn new(moments: Vec3, body_from_principal: Quat) -> Self {
        Self::try_new(moments, body_from_principal).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The principal moments, kg·m² (the `f32` values given; a plate's
    /// largest moment may differ by one `f32` ulp, see [`FreeBodyF32::try_new`]).
    pub fn principal_moments(&self) -> Vec3 {
        self.moments.as_vec3()
    }

    /// Advances the attitude `world_from_body` and the world-axes angular
    /// velocity `omega_world` (rad/s) by `dt` seconds of torque-free
    /// motion; returns the new `(world_from_body, omega_world)`.
    ///
    /// ```text
    /// (q_wb', ω_w') = round_f32(Φ_dt(q̂_wb, ω_w))   (see [`FreeBodyF32`])
    /// ```
    ///
    /// The attitude need not be unit (it is normalised in `f64`); the
    /// result is unit to `f32` rounding.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidStep`] for `dt` that is not positive and
    /// finite; [`DynamicsError::InvalidState`] for a zero or non-finite
    /// attitude or a non-finite angular velocity.
    ///
    /// ```
    /// use glam::{Quat, Vec3};
    /// use kreisel_dynamics::{DynamicsError, FreeBodyF32};
    /// // A brick tumbling near its intermediate axis, one frame at 60 Hz.
    /// let body = FreeBodyF32::try_new(Vec3::new(1.0, 2.0, 3.0), Quat::IDENTITY)?;
    /// let (q0, w0) = (Quat::from_rotation_x(0.3), Quat::from_rotation_x(0.3) * Vec3::new(0.01, 1.0, 0.0));
    /// let (q, w) = body.try_step(q0, w0, 1.0 / 60.0)?;
    /// // L_world = q I q⁻¹ ω is conserved by the exact motion: here to f32 rounding.
    /// let l_world = |q: Quat, w: Vec3| q * (Vec3::new(1.0, 2.0, 3.0) * (q.inverse() * w));
    /// assert!((l_world(q, w) - l_world(q0, w0)).length() < 4.0 * f32::EPSILON * 2.0);
    /// assert!(q.angle_between(q0) > 0.016);
    /// let e = body.try_step(q0, w0, 0.0).unwrap_err();
    /// assert!(matches!(e, DynamicsError::InvalidStep { .. }));
    /// # Ok::<(), DynamicsError>(())
    /// ```
    pub fn try_step(
        &self,
        world_from_body: Quat,
        omega_world: Vec3,
        dt: f32,
    ) -> Result<(Quat, Vec3), DynamicsError> {
        let h = f64::from(dt);
        if !(h.is_finite() && h > 0.0) {
            return Err(DynamicsError::InvalidStep { h });
        }
        let q_wb =
            kreisel_kinematics::try_normalize_quat(world_from_body.as_dquat()).map_err(|_| {
                DynamicsError::InvalidState {
                    reason: "attitude quaternion is zero or not finite",
                }
            })?;
        if !omega_world.is_finite() {
            return Err(DynamicsError::InvalidState {
                reason: "angular velocity is not finite",
            });
        }
        let world_from_principal = q_wb * self.body_from_principal;
        let omega_principal = world_from_principal.conjugate() * omega_world.as_dvec3();
        let start = PrincipalState {
            world_from_principal,
            l_principal: self.moments * omega_principal,
        };
        // f32 inputs cannot overflow f64 here (|L|² ≤ 1e309 only for ω, I
        // near f32::MAX); the check keeps the promise anyway.
        start.validate(self.moments)?;
        let end = self.advance(start, h)?;
        let world_from_principal = end.world_from_principal.normalize();
        let omega_world = world_from_principal * (end.l_principal / self.moments);
        let world_from_body = world_from_principal * self.body_from_principal.conjugate();
        Ok((world_from_body.as_quat(), omega_world.as_vec3()))
    }

    /// [`FreeBodyF32::try_step`], panicking on bad input.
    ///
    /// # Panics
    /// Where [`FreeBodyF32::try_step`] returns an error.
    ///
    /// ```
    /// use glam::{Quat, Vec3};
    /// use kreisel_dynamics::FreeBodyF32;
    /// // A sphere turns uniformly about ω.
    /// let (q, _) = FreeBodyF32::new(Vec3::splat(0.4), Quat::IDENTITY).step(Quat::IDENTITY, Vec3::new(0.0, 2.0, 0.0), 0.25);
    /// assert!(q.angle_between(Quat::from_rotation_y(0.5)) < 2.0 * f32::EPSILON);
    /// ```
    pub fn step(&self, world_from_body: Quat, omega_world: Vec3, dt: f32) -> (Quat, Vec3) {
        self.try_step(world_from_body, omega_world, dt)
            .unwrap_or_else(|e| panic!("{e}"))
    }

    /// The `f64` motion over `h`: closed form for a symmetric body or a
    /// long step, PDMV10 sub-steps otherwise (see [`FreeBodyF32`]).
    fn advance(&self, start: PrincipalState, h: f64) -> Result<PrincipalState, DynamicsError> {
        // ω_max² = 2E / I_min bounds |ω| over the whole motion.
        let energy = crate::state::kinetic_energy(self.moments, start.l_principal);
        let omega_max = (2.0 * energy / self.moments.min_element()).sqrt();
        let substeps = (h * omega_max / SUBSTEP_ANGLE).ceil().max(1.0);
        if self.symmetric || substeps > MAX_PDMV_SUBSTEPS {
            return Ok(ExactSolution::try_new(self.moments, start)?.state_at(h));
        }
        let mut state = start;
        let n = substeps as u32;
        let sub = h / f64::from(n);
        for _ in 0..n {
            self.pdmv10.step(self.moments, &mut state, sub);
        }
        Ok(state)
    }
}

/// One frame of torque-free motion on `f32` types without keeping a
/// [`FreeBodyF32`]: [`FreeBodyF32::try_new`] then
/// [`FreeBodyF32::try_step`] (the body's set-up, ~0.1 µs, is paid per call).
///
/// ```text
/// (q_wb', ω_w') = round_f32(Φ_dt(q̂_wb, ω_w))   for I_body = R diag(I) Rᵀ
/// ```
///
/// # Errors
/// Those of [`FreeBodyF32::try_new`] and [`FreeBodyF32::try_step`].
///
/// ```
/// use glam::{Quat, Vec3};
/// use kreisel_dynamics::try_free_body_step_f32;
/// // A rod whose principal axes are the body axes turned 90° about z.
/// let frame = Quat::from_rotation_z(core::f32::consts::FRAC_PI_2);
/// let (q, w) = try_free_body_step_f32(Vec3::new(1.0, 1.0, 0.1), frame, Quat::IDENTITY, Vec3::new(0.0, 0.0, 3.0), 0.5)?;
/// // Spinning about the symmetry axis: a uniform rotation of 1.5 rad.
/// assert!(q.angle_between(Quat::from_rotation_z(1.5)) < 2.0 * f32::EPSILON);
/// assert!((w - Vec3::new(0.0, 0.0, 3.0)).length() < 3.0 * f32::EPSILON);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
pub fn try_free_body_step_f32(
    principal_moments: Vec3,
    body_from_principal: Quat,
    world_from_body: Quat,
    omega_world: Vec3,
    dt: f32,
) -> Result<(Quat, Vec3), DynamicsError> {
    FreeBodyF32::try_new(principal_moments, body_from_principal)?.try_step(
        world_from_body,
        omega_world,
        dt,
    )
}

/// A flat body's moments rounded to `f32` can break the triangle
/// inequality by a few `f32` ulps (`I₃ = I₁ + I₂` exactly in real numbers,
/// measured for 41% of random zero-thickness plates): the largest moment
/// is then taken as the sum of the other two, a change within the input's
/// own precision. Larger breaches are left for
/// [`RigidBody::try_from_principal_moments`] to refuse.
///
/// ```text
/// I_max ← I_a + I_b   when   0 < I_max − (I_a + I_b) ≤ 4 ε_f32 I_max
/// ```
fn flat_within_f32(moments: DVec3) -> DVec3 {
    let k = moments.max_position();
    let rest = moments.element_sum() - moments[k];
    let breach = moments[k] - rest;
    let mut out = moments;
    if breach > 0.0 && breach <= 4.0 * f64::from(f32::EPSILON) * moments[k] {
        out[k] = rest;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_input_is_refused_not_panicked() {
        let body = FreeBodyF32::new(Vec3::new(1.0, 2.0, 3.0), Quat::IDENTITY);
        let (q, w) = (Quat::IDENTITY, Vec3::X);
        for dt in [0.0, -1.0, f32::NAN, f32::INFINITY] {
            assert!(matches!(
                body.try_step(q, w, dt),
                Err(DynamicsError::InvalidStep { .. })
            ));
        }
        for bad_q in [Quat::from_xyzw(0.0, 0.0, 0.0, 0.0), Quat::NAN] {
            assert!(matches!(
                body.try_step(bad_q, w, 0.1),
                Err(DynamicsError::InvalidState { .. })
            ));
        }
        assert!(matches!(
            body.try_step(q, Vec3::new(f32::INFINITY, 0.0, 0.0), 0.1),
            Err(DynamicsError::InvalidState { .. })
        ));
        for m in [
            Vec3::new(0.0, 1.0, 1.0),
            Vec3::new(-1.0, 1.0, 1.0),
            Vec3::new(f32::INFINITY, 1.0, 1.0),
            Vec3::new(f32::NAN, 1.0, 1.0),
            Vec3::new(1.0, 1.0, 2.001),
        ] {
            assert!(matches!(
                FreeBodyF32::try_new(m, Quat::IDENTITY),
                Err(DynamicsError::UnphysicalInertia { .. })
            ));
        }
        assert!(matches!(
            FreeBodyF32::try_new(Vec3::ONE, Quat::from_xyzw(f32::NAN, 0.0, 0.0, 1.0)),
            Err(DynamicsError::InvalidBody { .. })
        ));
    }

    #[test]
    fn extreme_but_finite_inputs_give_finite_results() {
        let body = FreeBodyF32::new(Vec3::new(1e-30, 2e-30, 2.5e-30), Quat::IDENTITY);
        for w in [Vec3::ZERO, Vec3::new(1e-30, 0.0, 0.0), Vec3::splat(1e30)] {
            let (q, w2) = body.try_step(Quat::IDENTITY, w, 1.0 / 60.0).unwrap();
            assert!(q.is_finite() && w2.is_finite(), "{w}: {q} {w2}");
            // |ω| is conserved to f32 rounding... up to the orbit's spread:
            // |ω| changes along the motion, bounded by ω_max.
            assert!(w2.length() <= 1.01 * w.length() * (2.5f32 / 1.0).sqrt());
        }
        let big = FreeBodyF32::new(Vec3::new(f32::MAX, f32::MAX, f32::MAX), Quat::IDENTITY);
        let (q, w) = big
            .try_step(Quat::IDENTITY, Vec3::splat(f32::MAX), f32::MAX)
            .unwrap();
        assert!(q.is_finite() && w.is_finite());
    }
}
