//! Further contact shapes of a [`GroundTop`] that do not touch — the
//! stem's ball of a tippe top — watched after every step: their gaps,
//! and the touchdown instant located inside the step where one reaches
//! the plane (reported, not followed).

use glam::{DQuat, DVec3};

use super::{ContactShape, GroundTop, GroundTopState};
use crate::DynamicsError;

/// The most further contact shapes a [`GroundTop`] watches
/// ([`GroundTop::try_with_other_contacts`]); a fixed capacity keeps the
/// gap checks after each step free of allocation.
pub const MAX_OTHER_CONTACTS: usize = 4;

/// The lowest point of `shape` seen from the centre of mass, world axes,
/// at the unit attitude `q`; for a disk lying flat (no single lowest
/// point) its centre, at the height of the whole rim.
fn lowest_offset(shape: &ContactShape, q: DQuat) -> DVec3 {
    let rho = shape.contact_from_com_world(q);
    if rho.is_finite() {
        rho
    } else {
        shape.center_from_com_world(q)
    }
}

impl GroundTop {
    /// This body with further body-fixed contact shapes that do not touch
    /// the plane at the start — the stem's ball of a tippe top — watched
    /// for touchdown (replacing any given before).
    ///
    /// The model follows the main shape's contact only. After every step
    /// ([`GroundTop::try_step`], [`GroundTop::try_advance_adaptive`]) each
    /// further shape's gap, the height of its lowest point,
    ///
    /// ```text
    /// gᵢ = z_G + (ρᵢ)_z,   ġᵢ = ż_G + (ω × ρᵢ)_z
    /// (a sphere: ρᵢ = A cᵢ − Rᵢ ẑ)
    /// ```
    ///
    /// is checked; where one reaches zero inside the step the instant is
    /// located and reported as [`DynamicsError::ContactTouchdown`] with the
    /// state left there. The impact and the two-contact motion after it
    /// are not modelled: the run stops and reports.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidContact`] for more than
    /// [`MAX_OTHER_CONTACTS`] shapes.
    ///
    /// ```
    /// use glam::{DMat3, DQuat, DVec2, DVec3};
    /// use kreisel_dynamics::{ContactShape, Friction, GroundTop, SphereContact};
    /// // Leine & Glocker's tippe top with its stem's ball (5 mm, 16 mm up the axis).
    /// let ball = SphereContact::try_new(0.015, DVec3::new(0.0, 0.0, 0.003))?;
    /// let stem = SphereContact::try_new(0.005, DVec3::new(0.0, 0.0, 0.016))?;
    /// let i = DMat3::from_diagonal(DVec3::new(8e-7, 8e-7, 7e-7));
    /// let top = GroundTop::try_new(0.006, i, ball, Friction::None, 9.81)?
    ///     .try_with_other_contacts(&[ContactShape::Sphere(stem)])?;
    /// let s = top.try_state_on_ground(DQuat::IDENTITY, DVec3::ZERO, DVec2::ZERO)?;
    /// // Upright: the stem ball's bottom at 12 + 16 − 5 = 23 mm.
    /// assert!((top.other_gap(&s, 0).unwrap() - 0.023).abs() < 1e-15);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_with_other_contacts(
        mut self,
        others: &[ContactShape],
    ) -> Result<Self, DynamicsError> {
        if others.len() > MAX_OTHER_CONTACTS {
            return Err(DynamicsError::InvalidContact {
                parameter: "other_contacts",
                value: others.len() as f64,
                reason: "too many further contact shapes (at most MAX_OTHER_CONTACTS = 4)",
            });
        }
        self.others = others.to_vec();
        Ok(self)
    }

    /// The further contact shapes watched for touchdown
    /// ([`GroundTop::try_with_other_contacts`]; empty by default).
    pub fn other_contacts(&self) -> &[ContactShape] {
        &self.others
    }

    /// The gap of further contact `contact`, the height of its lowest
    /// point above the plane, m (`None` for an index out of range).
    ///
    /// ```text
    /// gᵢ = z_G + (ρᵢ)_z     (a sphere: z_G + (A cᵢ)_z − Rᵢ)
    /// ```
    pub fn other_gap(&self, state: &GroundTopState, contact: usize) -> Option<f64> {
        let shape = self.other_contacts().get(contact)?;
        let q = state.world_from_body.normalize();
        Some(state.com_world.z + lowest_offset(shape, q).z)
    }

    /// The rate of [`GroundTop::other_gap`], the vertical velocity of the
    /// body's material point at that lowest point, m/s (`None` for an
    /// index out of range); negative while it approaches the plane.
    ///
    /// ```text
    /// ġᵢ = ż_G + (ω × ρᵢ)_z
    /// ```
    pub fn other_gap_rate(&self, state: &GroundTopState, contact: usize) -> Option<f64> {
        let shape = self.other_contacts().get(contact)?;
        let q = state.world_from_body.normalize();
        let omega = self.omega_world(state);
        Some(state.velocity_world.z + omega.cross(lowest_offset(shape, q)).z)
    }

    /// The further contact with the smallest gap, and that gap (`None`
    /// without further contacts).
    fn lowest_other(&self, state: &GroundTopState) -> Option<(usize, f64)> {
        (0..self.others.len())
            .filter_map(|i| Some((i, self.other_gap(state, i)?)))
            .min_by(|a, b| a.1.total_cmp(&b.1))
    }

    /// Whether every further contact is above the plane (gap > 0).
    pub(super) fn others_clear(&self, state: &GroundTopState) -> bool {
        self.lowest_other(state).is_none_or(|(_, gap)| gap > 0.0)
    }

    /// [`DynamicsError::OtherContactTouching`] for a start state where a
    /// further contact is at or below the plane.
    pub(super) fn check_others_clear(&self, state: &GroundTopState) -> Result<(), DynamicsError> {
        match self.lowest_other(state) {
            Some((contact, gap)) if gap.is_nan() || gap <= 0.0 => {
                Err(DynamicsError::OtherContactTouching { contact, gap })
            }
            _ => Ok(()),
        }
    }

    /// [`DynamicsError::ContactTouchdown`] at `time` for `state`, the
    /// further contact with the smallest gap the one touching.
    pub(super) fn touchdown_at(&self, state: &GroundTopState, time: f64) -> DynamicsError {
        let (contact, _) = self.lowest_other(state).unwrap_or((0, f64::NAN));
        DynamicsError::ContactTouchdown {
            time,
            contact,
            approach_speed: -self.other_gap_rate(state, contact).unwrap_or(f64::NAN),
        }
    }

    /// A step size `τ ∈ (0, h]` from `start` at which the step `redo(τ)`
    /// ends with a further contact at or below the plane, or `None` when
    /// the step `start → next` (of `h`) keeps them all above it;
    /// [`DynamicsError::ContactTouchdown`] at `time` when `start` already
    /// has one at or below the plane.
    ///
    /// `h` when a gap is not positive at `next`. Otherwise a graze — a gap
    /// that dips below zero and comes back within the step — is looked
    /// for: the cubic Hermite interpolant of each gap from its values and
    /// rates at both ends (`Δ = g₁ − g₀`, `dₖ = h ġₖ`),
    ///
    /// ```text
    /// p(s) = g₀ + Δ s + s (1 − s) [(1 − s)(d₀ − Δ) − s (d₁ − Δ)]
    ///      ≥ min(g₀, g₁) − ¼ max(|d₀ − Δ|, |d₁ − Δ|)
    /// ```
    ///
    /// has its interior minima `s*` checked; where `p(s*) ≤ 0` the step is
    /// redone to `τ = s* h` and its true gaps tested. A graze shallower
    /// than the interpolant's error (`O(h⁴)` of the gap's fourth
    /// derivative) can pass unseen. The rates are computed only where the
    /// bound above, with `|dₖ| ≤ h (|ż_G| + |L| ‖I⁻¹‖∞ |ρᵢ|)`, cannot
    /// exclude a dip.
    pub(super) fn touchdown_bound(
        &self,
        start: &GroundTopState,
        next: &GroundTopState,
        time: f64,
        h: f64,
        redo: impl Fn(f64) -> GroundTopState,
    ) -> Result<Option<f64>, DynamicsError> {
        let n = self.others.len();
        let begin = self.other_gaps(start);
        if begin.0[..n].iter().any(|&g| g.is_nan() || g <= 0.0) {
            return Err(self.touchdown_at(start, time));
        }
        let end = self.other_gaps(next);
        if end.0[..n].iter().any(|&g| g.is_nan() || g <= 0.0) {
            return Ok(Some(h));
        }
        let inverse = self.inverse_inertia_body;
        let row_sums =
            (inverse.x_axis.abs() + inverse.y_axis.abs() + inverse.z_axis.abs()).max_element();
        let omega_max = start.l_world.length().max(next.l_world.length()) * row_sums;
        let vz_max = start
            .velocity_world
            .z
            .abs()
            .max(next.velocity_world.z.abs());
        let mut rates: Option<([f64; MAX_OTHER_CONTACTS], [f64; MAX_OTHER_CONTACTS])> = None;
        let mut first: Option<f64> = None;
        for i in 0..n {
            let (g0, g1) = (begin.0[i], end.0[i]);
            let d_max = h * (vz_max + omega_max * begin.1[i].max(end.1[i]));
            if g0.min(g1) > 0.25 * (d_max + (g1 - g0).abs()) {
                continue;
            }
            let (r0, r1) = *rates
                .get_or_insert_with(|| (self.other_gap_rates(start), self.other_gap_rates(next)));
            let Some(s_min) = hermite_dip((g0, r0[i] * h), (g1, r1[i] * h)) else {
                continue;
            };
            let tau = s_min * h;
            if first.is_some_and(|t| t <= tau) {
                continue;
            }
            if !self.others_clear(&redo(tau)) {
                first = Some(tau);
            }
        }
        Ok(first)
    }

    /// The gaps of every further contact and the lengths `|ρᵢ|` of their
    /// lowest points from the centre of mass (unused slots zero).
    fn other_gaps(
        &self,
        state: &GroundTopState,
    ) -> ([f64; MAX_OTHER_CONTACTS], [f64; MAX_OTHER_CONTACTS]) {
        let q = state.world_from_body.normalize();
        let mut out = ([0.0; MAX_OTHER_CONTACTS], [0.0; MAX_OTHER_CONTACTS]);
        for (i, shape) in self.other_contacts().iter().enumerate() {
            let rho = lowest_offset(shape, q);
            out.0[i] = state.com_world.z + rho.z;
            out.1[i] = rho.length();
        }
        out
    }

    /// The gap rates of every further contact ([`GroundTop::other_gap_rate`];
    /// unused slots zero), `ω` computed once.
    fn other_gap_rates(&self, state: &GroundTopState) -> [f64; MAX_OTHER_CONTACTS] {
        let q = state.world_from_body.normalize();
        let omega = self.omega_world(state);
        let mut out = [0.0; MAX_OTHER_CONTACTS];
        for (slot, shape) in out.iter_mut().zip(self.other_contacts()) {
            *slot = state.velocity_world.z + omega.cross(lowest_offset(shape, q)).z;
        }
        out
    }
}

/// The interior minimum `s* ∈ (0, 1)` of the cubic Hermite interpolant
/// from `(g₀, h ġ₀)` to `(g₁, h ġ₁)` where it is not positive, if any.
pub(super) fn hermite_dip((g0, d0): (f64, f64), (g1, d1): (f64, f64)) -> Option<f64> {
    // p(s) = g0 + d0 s + c2 s² + c3 s³.
    let c2 = 3.0 * (g1 - g0) - 2.0 * d0 - d1;
    let c3 = 2.0 * (g0 - g1) + d0 + d1;
    let p = |s: f64| g0 + s * (d0 + s * (c2 + s * c3));
    // p'(s) = d0 + 2 c2 s + 3 c3 s² = 0, minima where p'' = 2 c2 + 6 c3 s > 0.
    let (a, b, c) = (3.0 * c3, 2.0 * c2, d0);
    let roots = if a.abs() <= 1e-14 * (b.abs() + c.abs()) {
        [-c / b, f64::NAN]
    } else {
        let disc = b * b - 4.0 * a * c;
        if disc < 0.0 {
            return None;
        }
        let q = -0.5 * (b + b.signum() * disc.sqrt());
        [q / a, c / q]
    };
    roots
        .into_iter()
        .filter(|&s| s > 0.0 && s < 1.0 && b + 2.0 * a * s > 0.0 && p(s) <= 0.0)
        .min_by(f64::total_cmp)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hermite_dip_finds_an_interior_minimum_below_zero() {
        // g(s) = (s − ½)² − 0.01: ends 0.24, rates ∓1, minimum −0.01 at ½.
        let s = hermite_dip((0.24, -1.0), (0.24, 1.0)).unwrap();
        assert!((s - 0.5).abs() < 1e-15, "{s}");
        // Minimum +0.01: no dip.
        assert!(hermite_dip((0.26, -1.0), (0.26, 1.0)).is_none());
        // Monotone: none.
        assert!(hermite_dip((1.0, -0.5), (0.5, -0.5)).is_none());
        // A true cubic, g = 0.1 − s + s³ (min at 1/√3, −0.2849): exact.
        let s = hermite_dip((0.1, -1.0), (0.1, 2.0)).unwrap();
        assert!((s - 3f64.sqrt().recip()).abs() < 1e-15, "{s}");
    }
}
