//! When a run has diverged: a non-finite state, or a conserved quantity
//! that has left any band an accurate method could produce.

use glam::DVec3;

use crate::error::Divergence;
use crate::state::kinetic_energy;
use crate::{DynamicsError, HeavyTop, PrincipalState};

/// How far a conserved quantity may drift before a run is declared
/// diverged: an order of magnitude.
///
/// ```text
/// free body:  E/E₀, |L|/|L₀|, |q|/|q₀|  outside [1/10, 10]
/// heavy top:  |E − E₀| > 10 (T₀ + |W||c|),   |q|/|q₀| outside [1/10, 10]
/// ```
///
/// A method that stays within its accuracy changes these by far less
/// (the geometric ones conserve `|L|` and `|q|` to rounding and keep the
/// energy error bounded; RK4's drift is `O(h⁴ t)`); a drift of a factor
/// ten is a step far beyond the method's stability or a method without a
/// solution at this step, never a usable result. For the heavy top the
/// energy is compared against its own scale, the initial kinetic energy
/// `T₀` plus the largest potential `|W||c|`, since `E` itself may be zero.
/// Nothing is corrected: the check only reports.
///
/// A body under applied inputs has no conserved energy or `|L|` to hold
/// to this band (both change by the work and impulse done): its steps are
/// checked for a finite state and finite reported quantities (ω, `L_world`,
/// the mechanical energy) and `|q|` in the band
/// ([`crate::ForcedPropagator`] says why that suffices).
pub const DIVERGENCE_FACTOR: f64 = 10.0;

/// The checks of one run from its initial state (see [`DIVERGENCE_FACTOR`]).
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{DivergenceCheck, DynamicsError, PrincipalState};
/// let m = DVec3::new(1.0, 2.0, 3.0);
/// let s0 = PrincipalState { world_from_principal: DQuat::IDENTITY, l_principal: DVec3::new(0.0, 2.0, 0.1) };
/// let check = DivergenceCheck::free_body("rk4", m, &s0);
/// assert!(check.check(&s0, 0.0).is_ok());
/// let blown = PrincipalState { l_principal: s0.l_principal * 20.0, ..s0 };
/// assert!(matches!(check.check(&blown, 1.5), Err(DynamicsError::Diverged { method: "rk4", time: 1.5, .. })));
/// let nan = PrincipalState { l_principal: DVec3::NAN, ..s0 };
/// assert!(check.check(&nan, 2.0).is_err());
/// ```
#[derive(Debug, Clone)]
pub struct DivergenceCheck<'a> {
    method: &'static str,
    kind: Kind<'a>,
    q_norm: f64,
}

#[derive(Debug, Clone)]
enum Kind<'a> {
    Free {
        moments: DVec3,
        energy: f64,
        l_norm: f64,
    },
    Top {
        top: &'a HeavyTop,
        energy: f64,
        scale: f64,
    },
}

impl<'a> DivergenceCheck<'a> {
    /// The checks for a free body with principal `moments` started at `initial`.
    pub fn free_body(method: &'static str, moments: DVec3, initial: &PrincipalState) -> Self {
        let energy = kinetic_energy(moments, initial.l_principal);
        Self {
            method,
            kind: Kind::Free {
                moments,
                energy,
                l_norm: initial.l_principal.length(),
            },
            q_norm: initial.world_from_principal.length(),
        }
    }

    /// The checks for a heavy top started at `initial`.
    pub fn heavy_top(method: &'static str, top: &'a HeavyTop, initial: &PrincipalState) -> Self {
        let kinetic = initial.energy(top.body());
        let potential = top.weight_world().length() * top.com_principal().length();
        Self {
            method,
            kind: Kind::Top {
                top,
                energy: top.energy(initial),
                scale: kinetic + potential,
            },
            q_norm: initial.world_from_principal.length(),
        }
    }

    /// `Ok` unless `state`, reached at `time`, is non-finite or has drifted
    /// beyond [`DIVERGENCE_FACTOR`].
    ///
    /// # Errors
    /// [`DynamicsError::Diverged`] naming the method, `time` and what went wrong.
    pub fn check(&self, state: &PrincipalState, time: f64) -> Result<(), DynamicsError> {
        let fail = |reason| {
            Err(DynamicsError::Diverged {
                method: self.method,
                time,
                reason,
            })
        };
        if !(state.world_from_principal.is_finite() && state.l_principal.is_finite()) {
            return fail(Divergence::NonFinite);
        }
        let outside = |initial: f64, current: f64| {
            initial > 0.0
                && !(current <= initial * DIVERGENCE_FACTOR
                    && current >= initial / DIVERGENCE_FACTOR)
        };
        let drift = |quantity, initial, current| {
            fail(Divergence::Drift {
                quantity,
                initial,
                current,
            })
        };
        let q_norm = state.world_from_principal.length();
        if outside(self.q_norm, q_norm) {
            return drift("|q|", self.q_norm, q_norm);
        }
        match &self.kind {
            Kind::Free {
                moments,
                energy,
                l_norm,
            } => {
                let l = state.l_principal.length();
                if outside(*l_norm, l) {
                    return drift("|L|", *l_norm, l);
                }
                let e = kinetic_energy(*moments, state.l_principal);
                if outside(*energy, e) {
                    return drift("energy", *energy, e);
                }
            }
            Kind::Top { top, energy, scale } => {
                let e = top.energy(state);
                if (e - energy).abs() > DIVERGENCE_FACTOR * scale || e.is_nan() {
                    return drift("energy", *energy, e);
                }
            }
        }
        Ok(())
    }
}
