//! Where a [`World`] moves each body, kept apart by kind so that a move
//! touches only what changes:
//!
//! ```text
//! resting (Plan::Resting)                 nowhere: settled once, at the first move after its plan
//! uniform (Plan::Sphere, PrincipalSpin)   the structure-of-arrays batch (`uniform.rs`)
//! every other plan                        `moving`, the ascending list of entries a move visits
//! ```
//!
//! A plan made or remade puts its body in its place ([`World::place`]),
//! after taking it out of the old one ([`World::unplace`]); bodies planned
//! since the last move are `fresh` until the next one settles them.

use super::World;
use super::motion::Motion;
use super::uniform::Rotation;
use crate::PrincipalState;

impl World {
    /// Puts entry `index` (its motion just made) where the world moves it:
    /// a uniform rotation into the batch, a resting body nowhere (both
    /// into `fresh`), any other into `moving`.
    pub(super) fn place(&mut self, index: usize) {
        let entry = &mut self.entries[index];
        if let Motion::Exact {
            solution,
            start,
            state,
        } = &entry.motion
            && let Some(parts) = solution.uniform_parts()
        {
            let (q0, _, l) = parts;
            let at_start = PrincipalState {
                world_from_principal: q0,
                l_principal: l,
            };
            let q_norm = entry.baseline.world_from_principal.length();
            let finite_is_enough = (0.5..=2.0).contains(&q_norm)
                && entry
                    .check
                    .as_ref()
                    .is_some_and(|c| c.check(&at_start, 0.0).is_ok());
            let slot = self.uniform.push(Rotation {
                entry: index,
                parts,
                start: *start,
                q: state.world_from_principal,
                l: state.l_principal,
                finite_is_enough,
            });
            entry.motion = Motion::Uniform { slot };
        } else if entry.motion.is_moving() {
            if let Err(at) = self.moving.binary_search(&index) {
                self.moving.insert(at, index);
            }
            self.refresh_reading(index);
            return;
        }
        if self.fresh.last() != Some(&index) {
            self.fresh.push(index);
        }
        self.refresh_reading(index);
    }

    /// Takes entry `index` out of the batch or of `moving` (before its
    /// motion is replaced).
    pub(super) fn unplace(&mut self, index: usize) {
        match self.entries[index].motion {
            Motion::Uniform { slot } => {
                if let Some((moved, slot)) = self.uniform.swap_remove(slot) {
                    self.entries[moved].motion = Motion::Uniform { slot };
                    self.refresh_reading(moved);
                }
            }
            Motion::Resting { .. } => {}
            _ => {
                // Ascending: found by bisection.
                if let Ok(at) = self.moving.binary_search(&index) {
                    self.moving.remove(at);
                }
            }
        }
    }

    /// The rotational state of entry `index` now.
    pub(super) fn rotation(&self, index: usize) -> PrincipalState {
        self.entries[index].motion.state(&self.uniform)
    }

    /// From this move on, the bodies planned since the last one report the
    /// exact solution's state (a resting body's normalised attitude, a
    /// uniform rotation's `L` in its own unit).
    pub(super) fn settle_fresh(&mut self) {
        let mut fresh = std::mem::take(&mut self.fresh);
        for &index in &fresh {
            match &mut self.entries[index].motion {
                Motion::Resting { state, settled } => *state = *settled,
                Motion::Uniform { slot } => self.uniform.settle(*slot),
                _ => {}
            }
            self.refresh_reading(index);
        }
        fresh.clear();
        self.fresh = fresh;
    }
}
