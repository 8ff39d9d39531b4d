//! The exact solution of the free rigid body, attitude included: uniform
//! rotation for a sphere or a spin about a principal axis, two commuting
//! rotations for a symmetric body, Jacobi elliptic functions for an
//! asymmetric one (accurate next to the separatrix and on it).

mod asymmetric;
mod chebyshev;

use glam::{DQuat, DVec3};

use self::asymmetric::Asymmetric;
use crate::elliptic::dd::Dd;
use crate::rigid_body::moment_scale;
use crate::splitting::{axis_flow, casimir_flow};
use crate::stepping::Propagator;
use crate::{DynamicsError, FreeBodyIntegrator, PrincipalState, RigidBody};

/// The exact torque-free motion from an initial state, evaluated at any time.
///
/// ```text
/// sphere / spin about a principal axis:  L const,  q(t) = q₀ ⊗ exp(t I⁻¹L)
/// symmetric (I_p = I_q ≠ I_k):  q(t) = q₀ ⊗ exp(t L₀/I_p) ⊗ exp(t (1/I_k − 1/I_p) L_k eₖ),  L(t) = Rₖ(−θ) L₀
/// asymmetric:  L in sn, cn, dn;  q(t) = C R_e(ψ(t)) M(l(t))   (see the module docs of `exact`)
/// ```
///
/// Everything that does not depend on `t` is computed once by
/// [`ExactSolution::try_new`] (for an asymmetric body: the quarter period,
/// the initial phase, and sn, cn, dn and the precession integral tabulated
/// over a quarter period to rounding), so that [`ExactSolution::state_at`]
/// costs about as much as one Strang splitting step. The state at `t` is
/// computed from the initial state, never by stepping, so its error does not
/// grow with the number of evaluations.
///
/// References: Landau & Lifshitz, *Mechanics*, §37; E. Celledoni, F. Fassò,
/// N. Säfström, A. Zanna, SIAM J. Sci. Comput. 30:2084–2112 (2008);
/// R. van Zon, J. Schofield, J. Comput. Phys. 225:145–164 (2007).
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{ExactSolution, PrincipalState, elliptic_motion};
/// let moments = DVec3::new(1.0, 2.0, 3.0);
/// let s0 = PrincipalState { world_from_principal: DQuat::IDENTITY, l_principal: DVec3::new(0.01, 2.0, 0.0) };
/// let exact = ExactSolution::try_new(moments, s0)?;
/// // After one period of ω the body-frame L is back where it started.
/// let period = elliptic_motion(moments, s0.l_principal).unwrap().period;
/// let s = exact.state_at(period);
/// assert!((s.l_principal - s0.l_principal).length() < 1e-13);
/// // L_world is conserved.
/// assert!((s.l_world() - s0.l_world()).length() < 1e-14);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Clone, Debug)]
pub struct ExactSolution {
    motion: Motion,
    /// The body's unit of inertia (a power of two, see
    /// `rigid_body::moment_scale`): the motion is prepared for `I / unit`
    /// and `L / unit`, and `L` is multiplied back.
    unit: f64,
}

/// The closed form an [`ExactSolution`] uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ExactKind {
    /// One uniform rotation (a sphere, or a spin about a principal axis).
    Uniform,
    /// Two commuting rotations; `axis` is the symmetry axis.
    Symmetric { axis: usize },
    /// Jacobi elliptic functions.
    Asymmetric,
}

#[derive(Clone, Debug)]
enum Motion {
    /// `q(t) = q₀ ⊗ exp(t ω)`, L constant.
    Uniform {
        q0: DQuat,
        l: DVec3,
        omega: DVec3,
    },
    /// The Casimir rotation about L₀ (moment I_p), then the rotation about
    /// `axis` of `H = c L_axis²/2`: the splitting's two exact flows, which
    /// commute here.
    Symmetric {
        start: PrincipalState,
        perpendicular: f64,
        axis: usize,
        c: f64,
    },
    Asymmetric(Box<Asymmetric>),
}

impl ExactSolution {
    /// Prepares the exact motion of a body with principal `moments` from `state`.
    ///
    /// ```text
    /// two of I₁, I₂, I₃ equal: symmetric;  all equal or L ∥ eₖ: uniform;  else elliptic
    /// ```
    ///
    /// The motion is prepared in the body's own unit of inertia (the largest
    /// moment in `[1, 2)`, an exact power-of-two rescaling of `I` and `L`),
    /// so it is the same in every unit system.
    ///
    /// # Errors
    /// [`DynamicsError::UnphysicalInertia`] for moments that
    /// [`RigidBody::try_from_principal_moments`] refuses;
    /// [`DynamicsError::InvalidState`] for a state that
    /// [`PrincipalState::validate`] refuses (the attitude is normalised).
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_dynamics::{ExactSolution, PrincipalState};
    /// let s0 = PrincipalState { world_from_principal: DQuat::IDENTITY, l_principal: DVec3::new(0.0, 0.0, 3.0) };
    /// // A sphere of moment 3 with L = 3 e₃ turns at 1 rad/s.
    /// let s = ExactSolution::try_new(DVec3::splat(3.0), s0)?.state_at(0.5);
    /// assert!(kreisel_kinematics::rotation_angle_between(s.world_from_principal, DQuat::from_rotation_z(0.5)) < 1e-15);
    /// assert!(ExactSolution::try_new(DVec3::new(1.0, -1.0, 1.0), s0).is_err());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_new(moments: DVec3, state: PrincipalState) -> Result<ExactSolution, DynamicsError> {
        RigidBody::try_from_principal_moments(moments)?;
        state.validate(moments)?;
        let unit = moment_scale(moments);
        let (moments, l) = (moments / unit, state.l_principal / unit);
        let q0 =
            kreisel_kinematics::try_normalize_quat(state.world_from_principal).map_err(|_| {
                DynamicsError::InvalidState {
                    reason: "attitude quaternion is zero or not finite",
                }
            })?;
        let [i1, i2, i3] = moments.to_array();
        let zeros = l.to_array().iter().filter(|&&x| x == 0.0).count();
        let uniform = Motion::Uniform {
            q0,
            l,
            omega: l / moments,
        };
        let motion = if zeros >= 2 || (i1 == i2 && i2 == i3) {
            uniform
        } else if i1 == i2 || i2 == i3 || i1 == i3 {
            let axis = if i1 == i2 {
                2
            } else if i2 == i3 {
                0
            } else {
                1
            };
            let perpendicular = moments[(axis + 1) % 3];
            Motion::Symmetric {
                start: PrincipalState {
                    world_from_principal: q0,
                    l_principal: l,
                },
                perpendicular,
                axis,
                c: 1.0 / moments[axis] - 1.0 / perpendicular,
            }
        } else {
            match Asymmetric::new(moments, q0, l) {
                Some(a) => Motion::Asymmetric(Box::new(a)),
                None => uniform,
            }
        };
        Ok(ExactSolution { motion, unit })
    }

    /// The state `t` seconds after the initial state (`t` may be negative).
    ///
    /// ```text
    /// (q(t), L(t)),  evaluated from (q₀, L₀) directly
    /// ```
    pub fn state_at(&self, t: f64) -> PrincipalState {
        self.state_at_split(t, 0.0)
    }

    /// The state at `t_hi + t_lo` (an unevaluated sum, for times accumulated
    /// in double-double by [`ExactPropagator`]).
    pub(crate) fn state_at_split(&self, t_hi: f64, t_lo: f64) -> PrincipalState {
        let t = t_hi + t_lo;
        let (world_from_principal, l_principal) = match &self.motion {
            Motion::Uniform { q0, l, omega } => (uniform_rotation(*q0, *omega, t), *l),
            Motion::Symmetric {
                start,
                perpendicular,
                axis,
                c,
            } => {
                let mut s = *start;
                casimir_flow(*perpendicular, &mut s, t);
                axis_flow(*axis, *c, &mut s, t);
                (s.world_from_principal, s.l_principal)
            }
            Motion::Asymmetric(a) => a.eval(t_hi, t_lo),
        };
        PrincipalState {
            world_from_principal,
            l_principal: l_principal * self.unit,
        }
    }

    /// For a uniform rotation: `(q₀, ω, L)` with `q(t) = uniform_rotation(q₀, ω, t)`
    /// and `L` constant, bit for bit what [`ExactSolution::state_at`]
    /// gives (the world evaluates these in a batch); `None` otherwise.
    pub(crate) fn uniform_parts(&self) -> Option<(DQuat, DVec3, DVec3)> {
        match &self.motion {
            Motion::Uniform { q0, l, omega } => Some((*q0, *omega, *l * self.unit)),
            _ => None,
        }
    }

    /// Which closed form this motion uses (for the world's plans).
    pub(crate) fn kind(&self) -> ExactKind {
        match &self.motion {
            Motion::Uniform { .. } => ExactKind::Uniform,
            Motion::Symmetric { axis, .. } => ExactKind::Symmetric { axis: *axis },
            Motion::Asymmetric(_) => ExactKind::Asymmetric,
        }
    }

    /// Time between successive sign changes of the components of ω that
    /// change sign (the flips of the Dzhanibekov effect), `2K/λ`; `None`
    /// unless the body is asymmetric and off its steady rotations (infinite
    /// on the separatrix).
    ///
    /// ```text
    /// T½ = 2K(m)/λ
    /// ```
    pub fn half_period(&self) -> Option<f64> {
        match &self.motion {
            Motion::Asymmetric(a) => Some(a.half_period()),
            _ => None,
        }
    }

    /// The mean rate of rotation about L_world, rad/s, for an asymmetric
    /// body (`None` otherwise).
    ///
    /// ```text
    /// ω̄ = 2E/|L| − κ h̄,   h̄ = mean of g/(1 + g),   g = l·e_a,   κ = (2E I_a − L²)/(|L| I_a)
    /// ```
    pub fn mean_precession_rate(&self) -> Option<f64> {
        match &self.motion {
            Motion::Asymmetric(a) => Some(a.mean_precession_rate()),
            _ => None,
        }
    }

    /// How many Chebyshev pieces tabulate the quarter period (0 unless the
    /// body is asymmetric and off the separatrix): the size of the table.
    pub fn table_pieces(&self) -> usize {
        match &self.motion {
            Motion::Asymmetric(a) => a.pieces(),
            _ => 0,
        }
    }
}

/// The uniform rotation at `t`, the exact motion of a sphere or of a spin
/// about a principal axis (ω in the units of the motion).
///
/// ```text
/// q(t) = q₀ ⊗ exp(t ω)
/// ```
#[inline]
pub(crate) fn uniform_rotation(q0: DQuat, omega: DVec3, t: f64) -> DQuat {
    q0 * kreisel_kinematics::quat_from_rotation_vector(omega * t)
}

/// The exact flow as an integrator (registry name `"exact"`): no truncation
/// error at any step size.
///
/// ```text
/// Φₕ = the exact flow of Euler's equations and q̇ = ½ q ⊗ (0, ω)
/// ```
///
/// [`FreeBodyIntegrator::step`] prepares an [`ExactSolution`] from the state
/// each time (tens of microseconds); [`FreeBodyIntegrator::propagator`] (used
/// by [`crate::integrate`]) prepares it once and evaluates it at the
/// accumulated time, so a step costs about as much as one Strang step.
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{integrate, ExactFlow, PrincipalState, ExactSolution};
/// let moments = DVec3::new(1.0, 2.0, 3.0);
/// let s0 = PrincipalState { world_from_principal: DQuat::IDENTITY, l_principal: DVec3::new(0.3, 2.0, 0.4) };
/// let mut s = s0;
/// integrate(&ExactFlow, moments, &mut s, 0.25, 40)?;
/// let direct = ExactSolution::try_new(moments, s0)?.state_at(10.0);
/// assert!(kreisel_kinematics::rotation_angle_between(s.world_from_principal, direct.world_from_principal) < 1e-14);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, Default)]
pub struct ExactFlow;

impl FreeBodyIntegrator for ExactFlow {
    fn name(&self) -> &'static str {
        "exact"
    }

    /// `u32::MAX`: no truncation error.
    fn order(&self) -> u32 {
        u32::MAX
    }

    fn description(&self) -> &'static str {
        "the exact solution: uniform rotation, symmetric-top closed form, \
         or Jacobi elliptic functions"
    }

    fn step(&self, moments: DVec3, state: &mut PrincipalState, h: f64) {
        *state = match ExactSolution::try_new(moments, *state) {
            Ok(exact) => exact.state_at(h),
            Err(_) => PrincipalState {
                world_from_principal: DQuat::NAN,
                l_principal: DVec3::NAN,
            },
        };
    }

    fn propagator<'a>(&'a self, moments: DVec3, state: PrincipalState) -> Box<dyn Propagator + 'a> {
        match ExactSolution::try_new(moments, state) {
            Ok(exact) => Box::new(ExactPropagator {
                exact,
                time: Dd::from_f64(0.0),
                state,
            }),
            Err(_) => Box::new(ExactPropagator {
                exact: ExactSolution {
                    motion: Motion::Uniform {
                        q0: DQuat::NAN,
                        l: DVec3::NAN,
                        omega: DVec3::NAN,
                    },
                    unit: 1.0,
                },
                time: Dd::from_f64(0.0),
                state,
            }),
        }
    }
}

/// An [`ExactSolution`] advanced step by step: the time is accumulated in
/// double-double, so `n` steps of `h` land on `t = n h` to ~10⁻³² relative.
#[derive(Clone, Debug)]
pub struct ExactPropagator {
    exact: ExactSolution,
    time: Dd,
    state: PrincipalState,
}

impl Propagator for ExactPropagator {
    fn advance(&mut self, h: f64) {
        self.time = self.time.add(Dd::from_f64(h));
        self.state = self.exact.state_at_split(self.time.hi, self.time.lo);
    }

    fn state(&self) -> PrincipalState {
        self.state
    }
}
