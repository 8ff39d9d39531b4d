//! [`TableRun`]: a body on the table as the world moves it — its
//! [`TableMotion`] from a start in world time, its events in world time
//! (kept across restarts) and what the world reads of it (how the world
//! adds, restarts and reads such a body, and why: `table`).

use glam::{DQuat, DVec3};

use super::ground_motion::gravity_down;
use super::{Body, BodyState};
use crate::{
    AdaptiveTolerance, ContactMode, DynamicsError, GroundTopState, PrincipalState, TableBody,
    TableEvent, TableEventKind, TableMotion,
};

/// A body on the table as the world moves it: its run, the world time at
/// which the run's clock reads 0, its events in world time (those of the
/// runs before a setter too), and the rotation from principal to body
/// axes (to report the rotational state the other plans report).
#[derive(Debug)]
pub(crate) struct TableRun {
    pub(crate) run: TableMotion,
    /// The run's tolerance.
    pub(super) tolerance: AdaptiveTolerance,
    start: f64,
    events: Vec<TableEvent>,
    /// How many of the run's events are in `events`.
    seen: usize,
    body_from_principal: DQuat,
}

impl TableRun {
    /// The run of `body` (on the table, in a world of gravity `gravity`)
    /// from `state` at world time `start`, after the `earlier` events.
    pub(super) fn try_new(
        body: &Body,
        gravity: DVec3,
        tolerance: AdaptiveTolerance,
        state: GroundTopState,
        start: f64,
        earlier: Vec<TableEvent>,
    ) -> Result<Self, DynamicsError> {
        let g = gravity_down(gravity)?;
        let props = body.mass_properties();
        let table =
            TableBody::try_new(props.mass, props.inertia, body.table_contacts().to_vec(), g)?;
        let run = TableMotion::try_new(table, state, tolerance)?;
        let mut made = Self {
            run,
            tolerance,
            start,
            events: earlier,
            seen: 0,
            body_from_principal: body.rigid_body().body_from_principal(),
        };
        made.take_events();
        Ok(made)
    }

    /// The same body from `state` now (world time `now`), with tolerance
    /// `tolerance`; its events so far kept. A contact that was closed and
    /// stays closed does not touch down again: the new run's touchdown of
    /// it at the start is not an event of the body.
    pub(super) fn restarted(
        &self,
        body: &Body,
        gravity: DVec3,
        tolerance: AdaptiveTolerance,
        state: GroundTopState,
        now: f64,
    ) -> Result<Self, DynamicsError> {
        let closed = self.run.modes();
        let kept = self.events.len();
        let mut next = Self::try_new(body, gravity, tolerance, state, now, self.events.clone())?;
        let mut index = 0;
        next.events.retain(|e| {
            index += 1;
            let again = index > kept
                && e.kind == TableEventKind::Touchdown
                && e.contact
                    .is_some_and(|i| closed.get(i).is_some_and(|m| *m != ContactMode::Open));
            !again
        });
        Ok(next)
    }

    /// Copies the run's new events, in world time.
    fn take_events(&mut self) {
        let start = self.start;
        let new = &self.run.events()[self.seen..];
        self.events.extend(new.iter().map(|e| TableEvent {
            time: e.time + start,
            ..*e
        }));
        self.seen = self.run.events().len();
    }

    /// Advances the run to world time `t`; its events recorded (up to a
    /// failure too).
    ///
    /// # Errors
    /// The errors of [`TableMotion::try_advance_to`].
    pub(crate) fn advance_to(&mut self, t: f64) -> Result<(), DynamicsError> {
        let target = (t - self.start).max(self.run.time());
        let advanced = self.run.try_advance_to(target);
        self.take_events();
        advanced
    }

    /// A copy of the run advanced until its next event before world time
    /// `t` ([`TableMotion::try_advance_until_event`]): the copy, and the
    /// event's world time (`None` when it reached `t` first).
    ///
    /// # Errors
    /// Those of [`TableMotion::try_advance_until_event`].
    pub(crate) fn until_event(&self, t: f64) -> Result<(TableMotion, Option<f64>), DynamicsError> {
        let mut run = self.run.clone();
        let target = (t - self.start).max(run.time());
        let stopped = run.try_advance_until_event(target)?;
        let event = stopped.then(|| self.start + run.time());
        Ok((run, event))
    }

    /// Takes `run`, a copy of this run advanced further
    /// ([`TableRun::until_event`]), as its own; its new events recorded.
    pub(crate) fn take_run(&mut self, run: TableMotion) {
        self.run = run;
        self.take_events();
    }

    /// The world time the run has reached, s.
    pub(crate) fn time(&self) -> f64 {
        self.start + self.run.time()
    }

    /// The events so far, world time.
    pub(crate) fn events(&self) -> &[TableEvent] {
        &self.events
    }

    /// The rotational state as the other plans hold it: principal axes,
    /// `L` about the centre of mass.
    pub(crate) fn principal_state(&self) -> PrincipalState {
        let state = self.run.state();
        let world_from_principal = state.world_from_body.normalize() * self.body_from_principal;
        PrincipalState {
            world_from_principal,
            l_principal: world_from_principal.conjugate() * state.l_world,
        }
    }

    /// The attitude as integrated (not renormalised).
    pub(crate) fn attitude(&self) -> DQuat {
        self.run.state().world_from_body
    }

    /// What the world reports at `time`.
    pub(crate) fn body_state(&self, time: f64) -> BodyState {
        let state = self.run.state();
        let body = self.run.body();
        let q = state.world_from_body;
        BodyState {
            time,
            world_from_body: q,
            omega_body: q.normalize().conjugate() * body.omega_world(state),
            l_world: state.l_world,
            energy: body.energy(state),
            position: state.com_world,
            velocity: state.velocity_world,
        }
    }
}
