//! A [`HeavyTop`] that is a Lagrange top, moved by the closed form: the
//! [`LagrangeTopMotion`] built from its 3-D state, read back as
//! [`PrincipalState`]s at any time.

use glam::{DMat3, DQuat, DVec3};
use kreisel_kinematics::{Axis, EulerSequence, Frame};

use super::{LagrangeTop, LagrangeTopInitial, LagrangeTopMotion};
use crate::{DynamicsError, HeavyTop, PrincipalState};

/// What [`HeavyTopClosedForm::try_new`] says of a top that is not a
/// Lagrange top.
const NOT_LAGRANGE: &str = "the closed form needs a Lagrange top: two equal principal moments \
     about the pivot and the centre of mass on the third principal axis";

/// A Lagrange top given as a [`HeavyTop`] and a [`PrincipalState`], in
/// closed form: the state at any time `t` after the start, without steps.
///
/// ```text
/// k: J_a = J_b (a, b ≠ k) and c ∥ e_k      (HeavyTop::symmetry_axis)
/// I₁ = J_a,  I₃ = J_k,  Mgl = |W| c_k,      up = −W/|W|  (world z without gravity)
/// q(t) = world_from_vertical · Rz(φ) Rx(θ) Rz(ψ) · top_from_principal,   L(t) = J ω(t)
/// ```
/// The top frame has its `e₃` on the symmetry axis (a cyclic relabelling of
/// the principal axes) and the vertical frame its `z` up; φ, θ, ψ are
/// [`LagrangeTopMotion`]'s Euler angles, from Jacobi's `sn` and elliptic
/// integrals of the third kind. Accuracy: 1.1e-13 rad over 2 s on the
/// Brüls top, 7e-14 rad over 10 s on a slow top with loops
/// (`tests/heavy_top_lagrange.rs`); the phase of a fast top's nutation
/// drifts by ~ε per period. Cost on the project's VM: ~5 µs to build,
/// ~0.6 µs per [`HeavyTopClosedForm::state_at`], at any `t`.
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{HeavyTop, HeavyTopClosedForm, PrincipalState};
/// // A symmetric top, 1 kg, centre of mass 0.1 m along e₃, tilted 0.3 rad.
/// let top = HeavyTop::try_from_principal(DVec3::new(0.02, 0.02, 0.01), DVec3::new(0.0, 0.0, 0.1), 1.0, DVec3::new(0.0, 0.0, -9.81))?;
/// let start = PrincipalState { world_from_principal: DQuat::from_rotation_x(0.3), l_principal: DVec3::new(0.0, 0.0, 0.5) };
/// let motion = HeavyTopClosedForm::try_new(&top, start)?;
/// let s = motion.state_at(1.7);
/// // Energy, p_φ and p_ψ are those of the start.
/// assert!((top.energy(&s) - top.energy(&start)).abs() < 1e-12 * top.energy(&start));
/// assert!((top.vertical_momentum(&s) - top.vertical_momentum(&start)).abs() < 1e-13);
/// assert!((s.l_principal.z - 0.5).abs() < 1e-13);
/// // An asymmetric top has no closed form here.
/// let asym = HeavyTop::try_from_principal(DVec3::new(0.02, 0.03, 0.01), DVec3::new(0.0, 0.0, 0.1), 1.0, DVec3::new(0.0, 0.0, -9.81))?;
/// assert!(HeavyTopClosedForm::try_new(&asym, start).is_err());
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone)]
pub struct HeavyTopClosedForm {
    motion: LagrangeTopMotion,
    world_from_vertical: DQuat,
    top_from_principal: DQuat,
    /// `e_k` of the top frame in principal axes is `e₃`: the permutation
    /// reads principal components as top components.
    principal_from_top_matrix: DMat3,
    moments: DVec3,
}

impl HeavyTopClosedForm {
    /// The closed-form motion of `top` from `state` (taken at `t = 0`).
    ///
    /// # Errors
    /// [`DynamicsError::InvalidTop`] when `top` is not a Lagrange top
    /// (parameter `"principal moments"` when no two moments are equal,
    /// `"centre of mass"` when it is off the symmetry axis, with its
    /// distance from the axis); [`DynamicsError::InvalidState`] for a state
    /// [`PrincipalState::validate`] refuses; the errors of
    /// [`LagrangeTop::try_new`] and [`LagrangeTop::try_solve`] for a top or
    /// a spin whose constants overflow f64.
    pub fn try_new(top: &HeavyTop, state: PrincipalState) -> Result<Self, DynamicsError> {
        let moments = top.body().principal_moments();
        state.validate(moments)?;
        let k = top.symmetry_axis().ok_or_else(|| not_lagrange(top))?;
        let (a, b) = ((k + 1) % 3, (k + 2) % 3);
        let j = moments.to_array();
        let c = top.com_principal()[k];
        let weight = top.weight_world();
        let lagrange = LagrangeTop::try_new(j[a], j[k], weight.length() * c)?;
        // Top axes (e₁, e₂, e₃) = principal (e_a, e_b, e_k): a rotation.
        let unit = |i: usize| DVec3::from_array(std::array::from_fn(|n| f64::from(n == i)));
        let principal_from_top_matrix = DMat3::from_cols(unit(a), unit(b), unit(k));
        let top_from_principal = DQuat::from_mat3(&principal_from_top_matrix).conjugate();
        let up = -weight.normalize_or(DVec3::NEG_Z);
        let world_from_vertical = DQuat::from_rotation_arc(DVec3::Z, up);
        let vertical_from_top = world_from_vertical.conjugate()
            * state.world_from_principal.normalize()
            * top_from_principal.conjugate();
        let omega_top = principal_from_top_matrix.transpose() * (state.l_principal / moments);
        let motion = lagrange.try_solve(initial(vertical_from_top, omega_top))?;
        Ok(Self {
            motion,
            world_from_vertical,
            top_from_principal,
            principal_from_top_matrix,
            moments,
        })
    }

    /// As [`HeavyTopClosedForm::try_new`].
    ///
    /// # Panics
    /// Where [`HeavyTopClosedForm::try_new`] returns an error.
    pub fn new(top: &HeavyTop, state: PrincipalState) -> Self {
        match Self::try_new(top, state) {
            Ok(motion) => motion,
            Err(e) => panic!("{e}"),
        }
    }

    /// The state at time `t` (s) after the start.
    ///
    /// ```text
    /// q(t) = world_from_vertical · Rz(φ) Rx(θ) Rz(ψ) · top_from_principal,   L(t) = J ω(t)
    /// ```
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_dynamics::{HeavyTop, HeavyTopClosedForm, PrincipalState};
    /// // Gravity along −x, symmetry axis on principal x: the frames are relabelled.
    /// let top = HeavyTop::try_from_principal(DVec3::new(0.01, 0.02, 0.02), DVec3::new(0.1, 0.0, 0.0), 1.0, DVec3::new(-9.81, 0.0, 0.0))?;
    /// let start = PrincipalState { world_from_principal: DQuat::from_rotation_z(0.5), l_principal: DVec3::new(0.3, 0.01, -0.02) };
    /// let s = HeavyTopClosedForm::new(&top, start).state_at(0.0);
    /// assert!(kreisel_kinematics::rotation_angle_between(s.world_from_principal, start.world_from_principal) < 1e-14);
    /// assert!((s.l_principal - start.l_principal).length() < 1e-14);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn state_at(&self, t: f64) -> PrincipalState {
        let (vertical_from_top, omega_top) = self.motion.world_from_body_and_omega_at(t);
        PrincipalState {
            world_from_principal: self.world_from_vertical
                * vertical_from_top
                * self.top_from_principal,
            l_principal: self.moments * (self.principal_from_top_matrix * omega_top),
        }
    }

    /// The Lagrange-top motion in the vertical and top frames (Euler
    /// angles, turning points, nutation period).
    pub fn motion(&self) -> &LagrangeTopMotion {
        &self.motion
    }
}

/// The error for a top with no symmetry axis carrying its centre of mass.
fn not_lagrange(top: &HeavyTop) -> DynamicsError {
    let j = top.body().principal_moments().to_array();
    let c = top.com_principal().to_array();
    // A symmetric top whose centre of mass is off the axis, or no symmetry.
    let symmetric = (0..3).find(|&k| j[(k + 1) % 3] == j[(k + 2) % 3]);
    match symmetric {
        Some(k) => DynamicsError::InvalidTop {
            parameter: "centre of mass",
            value: c[(k + 1) % 3].hypot(c[(k + 2) % 3]),
            reason: NOT_LAGRANGE,
        },
        None => DynamicsError::InvalidTop {
            parameter: "principal moments",
            value: (0..3)
                .map(|k| (j[(k + 1) % 3] - j[(k + 2) % 3]).abs())
                .fold(f64::INFINITY, f64::min),
            reason: NOT_LAGRANGE,
        },
    }
}

/// ZXZ Euler angles and rates of an attitude `vertical_from_top` turning at
/// `omega_top` (top axes).
///
/// ```text
/// θ̇ = ω₁ cos ψ − ω₂ sin ψ,  φ̇ sin θ = ω₁ sin ψ + ω₂ cos ψ,  ψ̇ = ω₃ − φ̇ cos θ
/// ```
/// Within 1e-14 rad of a pole (θ = 0 or π, where only φ ± ψ is defined and
/// [`LagrangeTop::try_solve`] puts the axis on the pole) ψ is chosen so
/// that `ω₁ sin ψ + ω₂ cos ψ = 0`: the axis leaves the pole along θ with
/// `θ̇ = |ω⊥|`, and `φ̇ = 0`.
fn initial(vertical_from_top: DQuat, omega_top: DVec3) -> LagrangeTopInitial {
    let zxz = EulerSequence::new([Axis::Z, Axis::X, Axis::Z], Frame::Intrinsic);
    let angles = zxz.from_quat(vertical_from_top).angles;
    let (mut phi, theta, mut psi) = (angles.x, angles.y, angles.z);
    let pole = theta.min(std::f64::consts::PI - theta) <= 1e-14;
    if pole {
        // Rz(φ) Rx(0) Rz(ψ) depends on φ + ψ only, Rz(φ) Rx(π) Rz(ψ) on φ − ψ.
        let sign = if theta < 1.0 { 1.0 } else { -1.0 };
        let turn = (-omega_top.y).atan2(omega_top.x);
        phi += sign * (psi - turn);
        psi = turn;
    }
    let (sp, cp) = psi.sin_cos();
    let (st, ct) = theta.sin_cos();
    let theta_dot = omega_top.x * cp - omega_top.y * sp;
    let phi_dot = if pole {
        0.0
    } else {
        (omega_top.x * sp + omega_top.y * cp) / st
    };
    LagrangeTopInitial {
        phi,
        theta,
        psi,
        phi_dot,
        theta_dot,
        psi_dot: omega_top.z - phi_dot * ct,
    }
}
