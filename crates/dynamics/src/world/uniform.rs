//! The world's batch of uniform rotations ([`crate::Plan::Sphere`],
//! [`crate::Plan::PrincipalSpin`]), kept as a structure of arrays and
//! evaluated in one loop per move of the world:
//!
//! ```text
//! t = now − start (double-double),   q(t) = q₀ ⊗ exp(t ω),   L constant
//! ```
//!
//! bit for bit [`crate::ExactSolution::state_at`]'s uniform rotation. Only
//! the arrays the loop needs (`q₀`, `ω`, `start`, `q`, one flag) are read
//! and written; the bodies' entries are not touched.
//!
//! **Checks.** A uniform rotation cannot drift: `L` (so `|L|` and the
//! energy) is the same number at every `t`, and `|q(t)| = |q₀|·|exp(t ω)|`
//! stays within a few ulps of 1 (both factors are unit quaternions to
//! rounding). What the world's divergence check could still see is a
//! non-finite state, when `ω t` overflows (`|ω|` up to ~10²⁵⁴ rad/s is a
//! valid state). So each evaluation checks finiteness only, and a body
//! whose full check ([`crate::DivergenceCheck`]) fails or would depend on
//! more than that — its state when planned fails it, or the reference `|q|`
//! is far from 1 — is flagged and fully checked at every evaluation.

use glam::{DQuat, DVec3};

use super::clock::elapsed;
use crate::elliptic::dd::Dd;
use crate::exact::uniform_rotation;

/// Uniform rotations, one slot per body (slots are not in body order: a
/// removed slot is filled by the last one).
#[derive(Debug, Default)]
pub(crate) struct UniformBatch {
    /// The world's entry of each slot.
    entry: Vec<usize>,
    /// `q₀`, normalised.
    q0: Vec<DQuat>,
    /// `ω`, in the units of the exact solution.
    omega: Vec<DVec3>,
    /// The world time when the rotation started, double-double.
    start: Vec<Dd>,
    /// The attitude reported: the state given until the world moves, then
    /// `q(t)`.
    q: Vec<DQuat>,
    /// The angular momentum reported: the state's until the world moves,
    /// then the exact solution's (the same up to a power-of-two rescaling).
    l: Vec<DVec3>,
    /// The exact solution's angular momentum.
    l_exact: Vec<DVec3>,
    /// Whether finiteness is the whole check (see the module docs).
    finite_is_enough: Vec<bool>,
}

/// One uniform rotation to add to the batch.
pub(crate) struct Rotation {
    /// The world's entry.
    pub(crate) entry: usize,
    /// `(q₀, ω, L)` of [`crate::ExactSolution::uniform_parts`].
    pub(crate) parts: (DQuat, DVec3, DVec3),
    /// The world time it starts at.
    pub(crate) start: Dd,
    /// The state given (reported until the world moves).
    pub(crate) q: DQuat,
    /// Its angular momentum.
    pub(crate) l: DVec3,
    /// Whether finiteness is the whole check.
    pub(crate) finite_is_enough: bool,
}

impl UniformBatch {
    /// The number of rotations.
    pub(crate) fn len(&self) -> usize {
        self.entry.len()
    }

    /// Adds a rotation; its slot.
    pub(crate) fn push(&mut self, r: Rotation) -> usize {
        let (q0, omega, l_exact) = r.parts;
        self.entry.push(r.entry);
        self.q0.push(q0);
        self.omega.push(omega);
        self.start.push(r.start);
        self.q.push(r.q);
        self.l.push(r.l);
        self.l_exact.push(l_exact);
        self.finite_is_enough.push(r.finite_is_enough);
        self.entry.len() - 1
    }

    /// Removes slot `slot`; the last slot moves into it: `Some((entry, slot))`
    /// of the rotation that moved.
    pub(crate) fn swap_remove(&mut self, slot: usize) -> Option<(usize, usize)> {
        self.entry.swap_remove(slot);
        self.q0.swap_remove(slot);
        self.omega.swap_remove(slot);
        self.start.swap_remove(slot);
        self.q.swap_remove(slot);
        self.l.swap_remove(slot);
        self.l_exact.swap_remove(slot);
        self.finite_is_enough.swap_remove(slot);
        self.entry.get(slot).map(|&entry| (entry, slot))
    }

    /// The world's entry of slot `slot`.
    pub(crate) fn entry(&self, slot: usize) -> usize {
        self.entry[slot]
    }

    /// The state reported for slot `slot`: attitude and `L`, principal axes.
    pub(crate) fn state(&self, slot: usize) -> (DQuat, DVec3) {
        (self.q[slot], self.l[slot])
    }

    /// From the first move on, slot `slot` reports the exact solution's `L`.
    pub(crate) fn settle(&mut self, slot: usize) {
        self.l[slot] = self.l_exact[slot];
    }

    /// Evaluates every rotation at world time `now`; the slots to be fully
    /// checked (non-finite, or flagged), in slot order.
    pub(crate) fn evaluate(&mut self, now: Dd) -> Vec<usize> {
        let mut check = Vec::new();
        let n = self.q.len();
        let (q0, omega, start) = (&self.q0[..n], &self.omega[..n], &self.start[..n]);
        let (q, enough) = (&mut self.q[..n], &self.finite_is_enough[..n]);
        for i in 0..n {
            let t = elapsed(now, start[i]);
            let next = uniform_rotation(q0[i], omega[i], t.hi + t.lo);
            q[i] = next;
            if !(enough[i] && next.is_finite()) {
                check.push(i);
            }
        }
        check
    }
}
