//! The guard of a body on the ground ([`GroundCheck`]): the checks a
//! [`GroundTop`] run must pass after every step, so that a step far too
//! large for the motion (a game frame of 1/60 s for a top spinning at
//! 180 rad/s) or friction too stiff for an explicit step stops with a
//! typed error and its time instead of writing wrong numbers.
//!
//! This is a guard, not error control: it does not choose the step, it
//! only refuses a state that is wrong beyond [`GROUND_CHECK_TOLERANCE`]
//! (measured in `crates/dynamics/tests/contact_ground_check.rs`: the
//! tippe top and the rattleback pass at the steps that reproduce their
//! reference motions and fail at a game frame).

use super::{Friction, GroundTop, GroundTopState};
use crate::DynamicsError;

/// The relative size of a drift the guard refuses: `|q|` from its start,
/// the contact point's height over the plane per unit of the contact
/// shape's size `ℓ` ([`ContactShape::size`]), and the energy per unit of
/// its scale at the start, `|E₀| + m g ℓ`.
///
/// ```text
/// | |q| − |q₀| |          > 10⁻⁴ |q₀|
/// |g| = |z_G + ρ_z|       > 10⁻⁴ ℓ            (ℓ: the contact shape's size)
/// z_G                     < −10⁻⁴ ℓ           (the centre of mass below the plane)
/// E − min E(earlier)      > 10⁻⁴ (|E₀| + m g ℓ)   (viscous or sliding friction, no inputs)
/// |E − E₀|                > 10⁻⁴ (|E₀| + m g ℓ)   (no friction or rolling, no inputs)
/// ```
///
/// The classical RK4 the ground stepper uses changes these by `O(h⁴)` per
/// unit time; at the steps that reproduce the reference motions (the
/// tippe top at 1e-4 s and below: |g|/ℓ ≤ 2e-8, |q| drift ≤ 2e-10; the
/// rattleback at 1e-4 s: energy 4e-6) they stay two orders of magnitude
/// below this band, while a step of 1e-3 s turns the tippe top's final
/// tilt by 5° with |g|/ℓ = 6e-3, and a game frame puts its centre of mass
/// below the table. Friction only dissipates, and a frictionless or
/// rolling contact does no work, so a rise of the energy is the
/// integrator's, never the physics'. With applied loads ([`Inputs`]) the
/// energy is not checked (their work is not tracked).
///
/// [`Inputs`]: crate::Inputs
/// [`ContactShape::size`]: crate::ContactShape::size
pub const GROUND_CHECK_TOLERANCE: f64 = 1e-4;

/// Which check of a body on the ground failed ([`DynamicsError::GroundCheckFailed`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GroundViolation {
    /// The attitude quaternion's length left `|q₀|` by more than the tolerance.
    AttitudeNorm {
        /// `|q|` at the start.
        initial: f64,
        /// `|q|` now.
        current: f64,
    },
    /// The contact point left the plane: the constraint `g = 0` drifted.
    ContactOffPlane {
        /// The contact point's height `g`, m.
        gap: f64,
        /// The contact shape's size `ℓ` the drift is measured against, m.
        size: f64,
    },
    /// The centre of mass went below the plane.
    CentreBelowPlane {
        /// Its height `z_G`, m.
        height: f64,
    },
    /// The energy rose under a friction law that only dissipates.
    EnergyRose {
        /// The lowest energy of the earlier checks, J.
        lowest: f64,
        /// The energy now, J.
        current: f64,
    },
    /// The energy of a contact that does no work (no friction, rolling)
    /// drifted from its start.
    EnergyDrifted {
        /// The energy at the start, J.
        initial: f64,
        /// The energy now, J.
        current: f64,
    },
}

impl std::fmt::Display for GroundViolation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let tol = GROUND_CHECK_TOLERANCE;
        match *self {
            Self::AttitudeNorm { initial, current } => write!(
                f,
                "|q| went from {initial} to {current}, a drift beyond {tol:e} of it"
            ),
            Self::ContactOffPlane { gap, size } => write!(
                f,
                "the contact point is {gap:.3e} m off the plane, beyond {tol:e} of the contact's \
                 size {size} m"
            ),
            Self::CentreBelowPlane { height } => {
                write!(
                    f,
                    "the centre of mass is below the plane (z = {height:.3e} m)"
                )
            }
            Self::EnergyRose { lowest, current } => write!(
                f,
                "the energy rose from {lowest:.6e} J to {current:.6e} J, beyond {tol:e} of it, \
                 under friction that only dissipates"
            ),
            Self::EnergyDrifted { initial, current } => write!(
                f,
                "the energy, conserved by this contact, went from {initial:.6e} J to \
                 {current:.6e} J, beyond {tol:e} of it"
            ),
        }
    }
}

/// What the energy check compares with.
#[derive(Debug, Clone, Copy, PartialEq)]
enum EnergyCheck {
    /// Applied loads: their work is not tracked, the energy not checked.
    None,
    /// Friction dissipates: `E` may not rise above the lowest value seen.
    NoRise {
        /// The lowest energy of the earlier checks, J.
        lowest: f64,
    },
    /// The contact does no work: `E` stays at its start.
    Conserved,
}

/// The checks of one run of a [`GroundTop`] from its initial state (see
/// [`GROUND_CHECK_TOLERANCE`]); [`GroundCheck::check`] after each step.
///
/// ```
/// use glam::{DMat3, DQuat, DVec2, DVec3};
/// use kreisel_dynamics::{DynamicsError, Friction, GroundCheck, GroundTop, SphereContact};
/// let sphere = SphereContact::try_new(0.015, DVec3::new(0.0, 0.0, 0.003))?;
/// let inertia = DMat3::from_diagonal(DVec3::new(8e-7, 8e-7, 7e-7));
/// let top = GroundTop::try_new(0.006, inertia, sphere, Friction::try_sliding(0.3, 1e-3)?, 9.81)?;
/// let q = DQuat::from_rotation_x(0.1);
/// let s0 = top.try_state_on_ground(q, q * DVec3::new(0.0, 0.0, 180.0), DVec2::ZERO)?;
/// let mut check = GroundCheck::new(&top, &s0);
/// // a small step passes, a game frame does not
/// let mut s = s0;
/// top.try_step(&mut s, 0.0, 1e-4)?;
/// assert!(check.check(&top, &s, 1e-4, 1e-4).is_ok());
/// let mut s = s0;
/// let mut t = 0.0;
/// let failed = loop {
///     top.try_step(&mut s, t, 1.0 / 60.0)?;
///     t += 1.0 / 60.0;
///     if let Err(e) = check.check(&top, &s, t, 1.0 / 60.0) {
///         break e;
///     }
/// };
/// assert!(matches!(failed, DynamicsError::GroundCheckFailed { .. }));
/// # Ok::<(), DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GroundCheck {
    q_norm: f64,
    size: f64,
    energy0: f64,
    /// `|E₀| + m g ℓ`, J.
    energy_scale: f64,
    energy: EnergyCheck,
}

/// `value ≤ limit`; false where either is NaN, so a NaN fails a check.
fn within(value: f64, limit: f64) -> bool {
    value <= limit
}

impl GroundCheck {
    /// The checks of a run of `top` that starts at `initial`.
    pub fn new(top: &GroundTop, initial: &GroundTopState) -> Self {
        let energy0 = top.energy(initial);
        let energy = if top.inputs().is_some() {
            EnergyCheck::None
        } else {
            match top.friction() {
                Friction::None | Friction::Rolling => EnergyCheck::Conserved,
                Friction::Viscous { .. } | Friction::Sliding { .. } => {
                    EnergyCheck::NoRise { lowest: energy0 }
                }
            }
        };
        let size = top.shape().size();
        Self {
            q_norm: initial.world_from_body.length(),
            size,
            energy0,
            energy_scale: energy0.abs() + top.mass() * top.gravity() * size,
            energy,
        }
    }

    /// `Ok` unless `state`, reached at `time` by steps of `h`, fails a check.
    /// Remembers the lowest energy seen for the next call.
    ///
    /// # Errors
    /// [`DynamicsError::GroundCheckFailed`] with `time`, `h` and the first
    /// check that failed, in the order of [`GroundViolation`]'s variants.
    pub fn check(
        &mut self,
        top: &GroundTop,
        state: &GroundTopState,
        time: f64,
        h: f64,
    ) -> Result<(), DynamicsError> {
        let tol = GROUND_CHECK_TOLERANCE;
        let fail = |violation| {
            Err(DynamicsError::GroundCheckFailed {
                time,
                step: h,
                violation,
            })
        };
        let q_norm = state.world_from_body.length();
        if !within((q_norm - self.q_norm).abs(), tol * self.q_norm) {
            return fail(GroundViolation::AttitudeNorm {
                initial: self.q_norm,
                current: q_norm,
            });
        }
        let gap = top.gap(state);
        if !within(gap.abs(), tol * self.size) {
            return fail(GroundViolation::ContactOffPlane {
                gap,
                size: self.size,
            });
        }
        let height = state.com_world.z;
        if !within(-height, tol * self.size) {
            return fail(GroundViolation::CentreBelowPlane { height });
        }
        let band = tol * self.energy_scale;
        match &mut self.energy {
            EnergyCheck::None => {}
            EnergyCheck::NoRise { lowest } => {
                let current = top.energy(state);
                if !within(current - *lowest, band) {
                    return fail(GroundViolation::EnergyRose {
                        lowest: *lowest,
                        current,
                    });
                }
                *lowest = lowest.min(current);
            }
            EnergyCheck::Conserved => {
                let current = top.energy(state);
                if !within((current - self.energy0).abs(), band) {
                    return fail(GroundViolation::EnergyDrifted {
                        initial: self.energy0,
                        current,
                    });
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::SphereContact;
    use glam::{DMat3, DQuat, DVec2, DVec3};

    /// The tippe top of Leine & Glocker spinning at 180 rad/s, tilted 0.1 rad.
    fn tippe(friction: Friction) -> (GroundTop, GroundTopState) {
        let sphere = SphereContact::try_new(0.015, DVec3::new(0.0, 0.0, 0.003)).unwrap();
        let inertia = DMat3::from_diagonal(DVec3::new(8e-7, 8e-7, 7e-7));
        let top = GroundTop::try_new(0.006, inertia, sphere, friction, 9.81).unwrap();
        let q = DQuat::from_rotation_x(0.1);
        let s = top
            .try_state_on_ground(q, q * DVec3::new(0.0, 0.0, 180.0), DVec2::ZERO)
            .unwrap();
        (top, s)
    }

    fn violation(
        top: &GroundTop,
        s0: &GroundTopState,
        s: &GroundTopState,
    ) -> Option<GroundViolation> {
        match GroundCheck::new(top, s0).check(top, s, 1.0, 0.1) {
            Ok(()) => None,
            Err(DynamicsError::GroundCheckFailed {
                time: 1.0,
                step: 0.1,
                violation,
            }) => Some(violation),
            Err(e) => panic!("{e}"),
        }
    }

    #[test]
    fn the_start_passes_and_each_drift_is_named() {
        let (top, s0) = tippe(Friction::None);
        assert_eq!(violation(&top, &s0, &s0), None);
        let tol = GROUND_CHECK_TOLERANCE;
        // |q| scaled just inside and just beyond the band
        let scaled = |k: f64| GroundTopState {
            world_from_body: s0.world_from_body * k,
            ..s0
        };
        assert_eq!(violation(&top, &s0, &scaled(1.0 + 0.5 * tol)), None);
        assert!(matches!(
            violation(&top, &s0, &scaled(1.0 + 2.0 * tol)),
            Some(GroundViolation::AttitudeNorm { .. })
        ));
        // the contact point lifted by 2e-4 of the radius
        let lifted = GroundTopState {
            com_world: s0.com_world + DVec3::Z * (2.0 * tol * 0.015),
            ..s0
        };
        assert!(matches!(
            violation(&top, &s0, &lifted),
            Some(GroundViolation::ContactOffPlane { size: 0.015, .. })
        ));
        // a NaN anywhere fails
        let nan = GroundTopState {
            l_world: DVec3::NAN,
            ..s0
        };
        assert!(violation(&top, &s0, &nan).is_some());
    }

    #[test]
    fn the_energy_may_not_rise_under_friction_nor_drift_without_it() {
        let spin_up = |s0: &GroundTopState, k: f64| GroundTopState {
            l_world: s0.l_world * k,
            ..*s0
        };
        let (top, s0) = tippe(Friction::None);
        assert!(matches!(
            violation(&top, &s0, &spin_up(&s0, 0.99)),
            Some(GroundViolation::EnergyDrifted { .. })
        ));
        let (top, s0) = tippe(Friction::try_sliding(0.3, 1e-3).unwrap());
        // losing energy is what friction does
        assert_eq!(violation(&top, &s0, &spin_up(&s0, 0.99)), None);
        assert!(matches!(
            violation(&top, &s0, &spin_up(&s0, 1.01)),
            Some(GroundViolation::EnergyRose { .. })
        ));
        // the lowest energy seen is the reference: down, then back up fails
        let mut check = GroundCheck::new(&top, &s0);
        assert!(check.check(&top, &spin_up(&s0, 0.9), 1.0, 0.1).is_ok());
        assert!(check.check(&top, &s0, 2.0, 0.1).is_err());
    }

    #[test]
    fn a_centre_of_mass_below_the_plane_fails() {
        // a sphere whose centre is far above the centre of mass: touching,
        // the centre of mass is below the plane
        let sphere = SphereContact::try_new(0.01, DVec3::new(0.0, 0.0, 0.05)).unwrap();
        let inertia = DMat3::from_diagonal(DVec3::new(1e-5, 1e-5, 1e-5));
        let top = GroundTop::try_new(0.1, inertia, sphere, Friction::None, 9.81).unwrap();
        let s0 = top
            .try_state_on_ground(DQuat::IDENTITY, DVec3::ZERO, DVec2::ZERO)
            .unwrap();
        assert!(matches!(
            GroundCheck::new(&top, &s0).check(&top, &s0, 0.0, 0.1),
            Err(DynamicsError::GroundCheckFailed {
                violation: GroundViolation::CentreBelowPlane { .. },
                ..
            })
        ));
    }
}
