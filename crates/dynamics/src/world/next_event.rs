//! Moving a [`World`] to the next event of a body on the table, or to a
//! time, whichever comes first: for a client that reads the state at the
//! instants of impacts, lift-offs, stick and slip (the tippe-top demo
//! does). [`World::advance_to`] moves through the events without stopping.
//!
//! ```text
//! each body on the table: a copy of its run advanced until its next event before t
//!                         (TableMotion::try_advance_until_event)
//! the earliest, at t_e:   the bodies whose copy stopped there take it (their runs as if
//!                         they had stopped there themselves); the world advances to t_e,
//!                         the others from where they were, as through World::advance_to
//! none before t:          every body on the table takes its copy (at t); the world
//!                         advances to t
//! ```
//!
//! A run that fails on the way is left to [`World::advance_to`], which
//! reports it as the world's failure with its time. The cost: a body
//! whose copy is taken advances once; one whose copy went past another's
//! earlier event advances again from where it was.

use super::World;
use super::motion::Motion;
use crate::DynamicsError;

impl World {
    /// Advances to time `t`, or to the first event before it of a body on
    /// the table ([`crate::Support::Table`]: an impact, a touchdown, a
    /// lift-off, stick or slip, rest), whichever comes first: `true` when
    /// it stopped at an event (the world's time is the event's, and
    /// [`World::events`] of that body ends with it). The bodies' runs are
    /// the same as through [`World::advance_to`] with stops at these
    /// instants; a world without bodies on the table just advances to `t`.
    ///
    /// # Errors
    /// As [`World::advance_to`].
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::{Body, ContactLaw, ContactShape, SphereContact, TableContact, TableEventKind, World};
    /// // A ball dropped from 1 m (centre), e = 0.9: it stops at the first impact.
    /// let ball = ContactShape::Sphere(SphereContact::try_new(0.1, DVec3::ZERO)?);
    /// let law = ContactLaw::try_new(0.0)?.try_with_restitution(0.9)?;
    /// let body = Body::from_principal_moments(1.0, DVec3::splat(0.004))
    ///     .on_table(DVec3::new(0.0, 0.0, 1.0), DVec3::ZERO, &[TableContact { shape: ball, law }])
    ///     .try_build()?;
    /// let mut world = World::try_new(DVec3::new(0.0, 0.0, -9.81), 1.0 / 60.0)?;
    /// let id = world.add(body)?;
    /// assert!(world.advance_until_event(2.0)?);
    /// let impact = world.events(id).unwrap()[0];
    /// assert!(matches!(impact.kind, TableEventKind::Impact { .. }));
    /// assert_eq!(world.time(), impact.time);
    /// assert!((impact.time - (2.0 * 0.9 / 9.81f64).sqrt()).abs() < 1e-12);
    /// // Just after it: rebounding.
    /// assert!(world.state(id).unwrap().velocity.z > 0.0);
    /// // Without bodies on the table: to `t`.
    /// let mut empty = World::try_new(DVec3::new(0.0, 0.0, -9.81), 0.1)?;
    /// assert!(!empty.advance_until_event(0.25)?);
    /// assert_eq!(empty.time(), 0.25);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn advance_until_event(&mut self, t: f64) -> Result<bool, DynamicsError> {
        if let Some(error) = &self.failed {
            return Err(error.clone());
        }
        // Refuses a `t` before now or not finite before any run moves.
        self.clock.route_to(t)?;
        let mut copies = Vec::new();
        for (index, entry) in self.entries.iter().enumerate() {
            if let Motion::Table(table) = &entry.motion
                && let Ok((run, event)) = table.until_event(t)
            {
                copies.push((index, run, event));
            }
        }
        let first = copies
            .iter()
            .filter_map(|(_, _, event)| *event)
            .min_by(f64::total_cmp);
        for (index, run, event) in copies {
            if event == first
                && let Motion::Table(table) = &mut self.entries[index].motion
            {
                table.take_run(run);
            }
        }
        self.advance_to(first.unwrap_or(t))?;
        Ok(first.is_some())
    }
}
