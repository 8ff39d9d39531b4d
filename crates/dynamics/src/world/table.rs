//! Bodies on the table in a [`World`] ([`Support::Table`],
//! [`crate::Plan::OnTable`]): the world's gravity must point along −z;
//! each body is a [`TableMotion`] — nonsmooth contact with every shape,
//! events recorded while the run goes on.
//!
//! ```text
//! add:       TableBody(mass, inertia about the centre of mass (body axes), contacts, g = −gravity_z)
//!            state: r_G, v_G as given, q, L = q (I ω_body)     (above or touching the table)
//! move to t: TableMotion::try_advance_to(t − t_start): its own error-controlled steps and events;
//!            the world's dt is only the grid the states are read on
//! read:      q, ω_body = qᵀ ω, L about the centre of mass (world axes), r_G, v_G,
//!            E = ½ m |v_G|² + ½ L·ω + m g z_G           (TableBody::energy)
//! events:    World::events, world times (t_start + the run's), kept across setters
//! accuracy:  rtol = atol = DEFAULT_TABLE_TOLERANCE, or with a Tolerance of attitude ε:
//!            clamp(ε/1000, 1e-12, 1e-4)
//! setters:   attitude / ω / angular impulse / centre of mass: the run starts again from
//!            the new state now (a shape put below the table: BodyInsideTable, nothing changes)
//! ```
//!
//! The user's `dt` does not enter the motion: [`World::step`],
//! [`World::advance_steps`] and [`World::advance_to`] each advance the
//! body's run to the end of the move, which takes its own steps (the
//! last one shortened to land there). States read on grids of 1/60 s and
//! of 10⁻⁵ s agree to the tolerance. A failure of the run (Painlevé's
//! indeterminacy, an impact that would gain energy, modes that chatter,
//! a step below the smallest) is the world's
//! [`DynamicsError::BodyFailed`] with the run's time; the body holds the
//! last state reached.

use glam::{DQuat, DVec3};

use super::ground::gravity_down;
use super::plan::Motion;
use super::state::Reading;
use super::{Body, BodyId, BodyState, Entry, Plan, Support, World};
use crate::{
    AdaptiveTolerance, ContactMode, DynamicsError, GroundTopState, PrincipalState, TableBody,
    TableEvent, TableEventKind, TableMotion, Tolerance,
};

/// The error tolerance (`rtol = atol`) of a body on the table in a world
/// without a [`Tolerance`]. Measured on Leine & Glocker's tippe top with
/// its stem (the example scene `tippe_top_coulomb.toml`) stepped at
/// 1/60 s: its stem strikes the table 1.0e-9 s from the time of a run at
/// 10⁻¹² (1.0e-8 s at 10⁻⁹, 1.0e-7 s at 10⁻⁸, 1.2e-6 s at 10⁻⁷), for
/// 5639 steps over the first 3 s (a real-time factor of 50 to 110 in a
/// release build on a shared 2-core machine).
pub const DEFAULT_TABLE_TOLERANCE: f64 = 1e-10;

/// The error tolerance of a body on the table under the world's
/// `tolerance` (module docs): `rtol = atol = ε/1000` for an attitude
/// tolerance `ε`, within `[10⁻¹², 10⁻⁴]`; [`DEFAULT_TABLE_TOLERANCE`]
/// without one. The control is per step, the factor measured: the
/// attitude error of Leine & Glocker's tippe top after 1.5 s (through its
/// first turn) against a run at 10⁻¹² was 280 `rtol` for `rtol` from
/// 10⁻¹⁰ to 10⁻⁷, 680 at 10⁻⁶ — 0.3 ε to 0.7 ε for ε from 10⁻⁷ to
/// 10⁻³. Longer runs gather more: the horizon is not used.
///
/// ```
/// use kreisel_dynamics::{DEFAULT_TABLE_TOLERANCE, Tolerance, table_tolerance};
/// assert_eq!(table_tolerance(None).rtol(), DEFAULT_TABLE_TOLERANCE);
/// assert!((table_tolerance(Some(Tolerance::new(1e-6, 10.0))).atol() - 1e-9).abs() < 1e-24);
/// assert_eq!(table_tolerance(Some(Tolerance::new(1e-20, 10.0))).rtol(), 1e-12);
/// ```
pub fn table_tolerance(tolerance: Option<Tolerance>) -> AdaptiveTolerance {
    let tol = tolerance.map_or(DEFAULT_TABLE_TOLERANCE, |t| {
        (t.attitude() / 1000.0).clamp(1e-12, 1e-4)
    });
    AdaptiveTolerance::new(tol, tol)
}

/// A body on the table as the world moves it: its run, the world time at
/// which the run's clock reads 0, its events in world time (those of the
/// runs before a setter too), and the rotation from principal to body
/// axes (to report the rotational state the other plans report).
#[derive(Debug)]
pub(crate) struct TableRun {
    pub(crate) run: TableMotion,
    /// The run's tolerance.
    tolerance: AdaptiveTolerance,
    start: f64,
    events: Vec<TableEvent>,
    /// How many of the run's events are in `events`.
    seen: usize,
    body_from_principal: DQuat,
}

impl TableRun {
    /// The run of `body` (on the table, in a world of gravity `gravity`)
    /// from `state` at world time `start`, after the `earlier` events.
    fn try_new(
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
    fn restarted(
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

/// The state of a body with attitude `q` (normalised here), angular
/// velocity `omega_body` and inertia `inertia_body`, its centre of mass at
/// `position` moving at `velocity`.
fn table_state(
    q: DQuat,
    omega_body: DVec3,
    inertia_body: glam::DMat3,
    position: DVec3,
    velocity: DVec3,
) -> Result<GroundTopState, DynamicsError> {
    if !(q.is_finite() && q.length_squared() > 0.0) {
        return Err(DynamicsError::InvalidState {
            reason: "the attitude must be a finite, non-zero quaternion",
        });
    }
    let q = q.normalize();
    Ok(GroundTopState {
        com_world: position,
        velocity_world: velocity,
        world_from_body: q,
        l_world: q * (inertia_body * omega_body),
    })
}

impl World {
    /// Adds `body`, on the table, now (the part of [`World::add`] for
    /// [`Support::Table`]).
    pub(super) fn add_on_table(&mut self, body: Body) -> Result<BodyId, DynamicsError> {
        let Support::Table { position, velocity } = body.support() else {
            return Err(DynamicsError::InvalidBody {
                field: "support",
                reason: "is not the table",
            });
        };
        super::body::check_table_inputs(body.support(), body.inputs())?;
        let inertia = body.mass_properties().inertia;
        let state = table_state(
            body.world_from_body(),
            body.omega_body(),
            inertia,
            position,
            velocity,
        )?;
        let tolerance = table_tolerance(self.tolerance);
        let now = self.time();
        let table = TableRun::try_new(&body, self.gravity, tolerance, state, now, Vec::new())?;
        let plan = Plan::OnTable {
            contacts: body.table_contacts().len(),
        };
        let baseline = table.principal_state();
        let mass = body.mass();
        self.entries.push(Entry {
            rigid: *body.rigid_body(),
            body,
            top: None,
            plan,
            motion: Motion::Table(Box::new(table)),
            baseline,
            check: None,
            choice: None,
        });
        self.reads
            .push(Reading::new(mass, (position, velocity, now)));
        let index = self.entries.len() - 1;
        self.place(index);
        Ok(BodyId(index))
    }

    /// Starts body `index`'s run on the table again now from `state`
    /// (nothing changes on an error).
    fn restart_table(
        &mut self,
        index: usize,
        state: impl FnOnce(&GroundTopState) -> Result<GroundTopState, DynamicsError>,
    ) -> Result<(), DynamicsError> {
        let tolerance = table_tolerance(self.tolerance);
        let (gravity, now) = (self.gravity, self.time());
        let entry = &mut self.entries[index];
        let Motion::Table(table) = &mut entry.motion else {
            return Ok(());
        };
        let next = state(table.run.state())?;
        **table = table.restarted(&entry.body, gravity, tolerance, next, now)?;
        entry.baseline = table.principal_state();
        self.refresh_reading(index);
        Ok(())
    }

    /// Gives body `index`, on the table, the rotational state `state` now:
    /// its run starts again there, the centre of mass and its velocity
    /// kept.
    pub(super) fn replan_table(
        &mut self,
        index: usize,
        state: PrincipalState,
    ) -> Result<(), DynamicsError> {
        let rigid = self.entries[index].rigid;
        state.validate(rigid.principal_moments())?;
        let inertia = self.entries[index].body.mass_properties().inertia;
        let q = state.world_from_body(&rigid);
        let omega_body = state.omega_body(&rigid);
        self.restart_table(index, |now| {
            table_state(q, omega_body, inertia, now.com_world, now.velocity_world)
        })
    }

    /// Puts body `index`'s centre of mass, on the table, at `position`
    /// moving at `velocity` now: its run starts again there.
    pub(super) fn move_on_table(
        &mut self,
        index: usize,
        position: DVec3,
        velocity: DVec3,
    ) -> Result<(), DynamicsError> {
        self.restart_table(index, |now| {
            Ok(GroundTopState {
                com_world: position,
                velocity_world: velocity,
                ..*now
            })
        })?;
        self.reads[index].ballistic = (position, velocity, self.time());
        Ok(())
    }

    /// Starts the run of every body on the table again from its state now
    /// under the world's tolerance (those whose tolerance it changes).
    pub(super) fn retune_tables(&mut self) -> Result<(), DynamicsError> {
        let tolerance = table_tolerance(self.tolerance);
        for index in 0..self.entries.len() {
            let Motion::Table(table) = &self.entries[index].motion else {
                continue;
            };
            if table.tolerance != tolerance {
                self.restart_table(index, |now| Ok(*now))?;
            }
        }
        Ok(())
    }

    /// The events of body `id` on the table so far (impacts, touchdowns,
    /// lift-offs, sticking, slipping, rest), in time order, world time;
    /// empty for a body not on the table, `None` for an id of another
    /// world. A setter does not clear them.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::{Body, ContactLaw, ContactShape, SphereContact, TableContact, TableEventKind, World};
    /// let ball = ContactShape::Sphere(SphereContact::try_new(0.1, DVec3::ZERO)?);
    /// let law = ContactLaw::try_new(0.0)?.try_with_restitution(0.5)?;
    /// let body = Body::from_principal_moments(1.0, DVec3::splat(0.004))
    ///     .on_table(DVec3::new(0.0, 0.0, 0.1), DVec3::new(0.0, 0.0, -1.0), &[TableContact { shape: ball, law }])
    ///     .try_build()?;
    /// let mut world = World::try_new(DVec3::new(0.0, 0.0, -9.81), 0.01)?;
    /// let id = world.add(body)?;
    /// // Thrown down while touching: it strikes the table at once, rebounds at e v.
    /// let first = world.events(id).unwrap()[0];
    /// assert_eq!(first.time, 0.0);
    /// assert!(matches!(first.kind, TableEventKind::Impact { rebound_speed, .. } if (rebound_speed - 0.5).abs() < 1e-12));
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn events(&self, id: BodyId) -> Option<&[TableEvent]> {
        let entry = self.entries.get(id.0)?;
        Some(match &entry.motion {
            Motion::Table(table) => table.events(),
            _ => &[],
        })
    }

    /// The run of body `id` on the table (its contact modes, normal
    /// forces, whether it rests, its steps): `None` for a body not on the
    /// table or an unknown id. Its clock starts when the body was added or
    /// last changed by a setter (its events are in that clock; the
    /// world's are [`World::events`]).
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_dynamics::{Body, ContactLaw, ContactMode, ContactShape, SphereContact, TableContact, World};
    /// let ball = ContactShape::Sphere(SphereContact::try_new(0.1, DVec3::ZERO)?);
    /// let body = Body::from_principal_moments(1.0, DVec3::splat(0.004))
    ///     .on_table(DVec3::new(0.0, 0.0, 0.1), DVec3::ZERO, &[TableContact { shape: ball, law: ContactLaw::try_new(0.5)? }])
    ///     .try_build()?;
    /// let mut world = World::try_new(DVec3::new(0.0, 0.0, -9.81), 0.01)?;
    /// let id = world.add(body)?;
    /// let run = world.table_motion(id).unwrap();
    /// // At rest on the table: the contact sticks and carries the weight.
    /// assert!(run.is_resting());
    /// assert_eq!(run.modes(), [ContactMode::Sticking]);
    /// assert!((run.normal_forces()[0] - 9.81).abs() < 1e-12);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn table_motion(&self, id: BodyId) -> Option<&TableMotion> {
        match &self.entries.get(id.0)?.motion {
            Motion::Table(table) => Some(&table.run),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use glam::{DQuat, DVec3};

    use crate::{
        Body, BodyBuilder, ContactLaw, ContactShape, DynamicsError, Inputs, SphereContact,
        TableContact, TableEventKind, Tolerance, World,
    };

    const G: f64 = 9.81;
    const DOWN: DVec3 = DVec3::new(0.0, 0.0, -G);

    fn sphere(radius: f64, z: f64) -> ContactShape {
        ContactShape::Sphere(SphereContact::try_new(radius, DVec3::new(0.0, 0.0, z)).unwrap())
    }

    /// A ball of radius 0.1 m, e = 0.9, its centre at `height`.
    fn ball(height: f64) -> BodyBuilder {
        let law = ContactLaw::try_new(0.0)
            .and_then(|l| l.try_with_restitution(0.9))
            .unwrap();
        Body::from_principal_moments(0.5, DVec3::splat(0.002)).on_table(
            DVec3::new(0.0, 0.0, height),
            DVec3::ZERO,
            &[TableContact {
                shape: sphere(0.1, 0.0),
                law,
            }],
        )
    }

    /// Leine & Glocker's tippe top with its stem, tilted by 0.1 rad,
    /// spinning at 180 rad/s about its axis, its ball touching the table.
    fn tippe_top() -> BodyBuilder {
        let law = ContactLaw::try_new(0.3)
            .and_then(|l| l.try_with_contensou_radius(5e-4))
            .unwrap();
        let q = DQuat::from_rotation_x(0.1);
        let centre = q * DVec3::new(0.0, 0.0, 0.003);
        let position = DVec3::new(0.0, 0.0, 0.015 - centre.z);
        let contacts = [
            TableContact {
                shape: sphere(0.015, 0.003),
                law,
            },
            TableContact {
                shape: sphere(0.005, 0.016),
                law,
            },
        ];
        Body::from_principal_moments(0.006, DVec3::new(8e-7, 8e-7, 7e-7))
            .world_from_body(q)
            .omega_body(DVec3::new(0.0, 0.0, 180.0))
            .on_table(position, DVec3::ZERO, &contacts)
    }

    /// The world with `body` stepped by `step` up to `t_end` (a game loop).
    fn stepped(body: BodyBuilder, step: f64, t_end: f64) -> World {
        let mut world = World::try_new(DOWN, step).unwrap();
        world.add(body.try_build().unwrap()).unwrap();
        let n = (t_end / step).round() as u64;
        for _ in 0..n {
            world.step(step).unwrap();
        }
        world
    }

    #[test]
    fn the_dropped_ball_strikes_at_the_closed_form_time_on_any_grid() {
        // t₁ = √(2 (h − R)/g) (the issue's 0.42835 s).
        let t1 = (2.0 * 0.9 / G).sqrt();
        assert!((t1 - 0.42835).abs() < 1e-5);
        for step in [1.0 / 60.0, 1e-3] {
            let world = stepped(ball(1.0), step, 0.5);
            let events = world.events(super::BodyId(0)).unwrap();
            let first = events[0];
            assert_eq!(first.contact, Some(0));
            let TableEventKind::Impact {
                approach_speed,
                rebound_speed,
            } = first.kind
            else {
                panic!("{first}");
            };
            assert!((first.time - t1).abs() < 1e-12, "{}", first.time);
            let v1 = G * t1;
            assert!((approach_speed - v1).abs() < 1e-10 * v1);
            assert!((rebound_speed - 0.9 * approach_speed).abs() < 1e-12);
        }
    }

    #[test]
    fn the_tippe_top_reads_the_same_at_one_second_on_any_grid() {
        let coarse = stepped(tippe_top(), 1.0 / 60.0, 1.0);
        let fine = stepped(tippe_top(), 1e-3, 1.0);
        let id = super::BodyId(0);
        let (a, b) = (coarse.state(id).unwrap(), fine.state(id).unwrap());
        assert!((a.time - 1.0).abs() < 1e-13 && (b.time - 1.0).abs() < 1e-13);
        let angle =
            kreisel_kinematics::rotation_angle_between(a.world_from_body, b.world_from_body);
        let position = (a.position - b.position).length();
        eprintln!("dt 1/60 vs 1e-3 at 1 s: {angle:e} rad, {position:e} m");
        assert!(angle < 1e-8, "{angle:e}");
        assert!(position < 1e-10, "{position:e}");
        assert!((a.energy - b.energy).abs() < 1e-10 * a.energy.abs());
        // The reported state is the body's: L = q I ω_body, E as the table's.
        let l = a.world_from_body.normalize() * (DVec3::new(8e-7, 8e-7, 7e-7) * a.omega_body);
        let dl = (l - a.l_world).length() / a.l_world.length();
        // A few ulps: the round trip L → ω_body = I⁻¹ qᵀ L → q I ω_body.
        assert!(dl < 16.0 * f64::EPSILON, "{dl:e}");
        let run = coarse.table_motion(id).unwrap();
        assert_eq!(a.energy, run.body().energy(run.state()));
    }

    #[test]
    fn the_energy_of_the_tippe_top_never_rises_between_reads() {
        let mut world = World::try_new(DOWN, 1.0 / 60.0).unwrap();
        let id = world.add(tippe_top().try_build().unwrap()).unwrap();
        let mut last = world.state(id).unwrap().energy;
        for _ in 0..120 {
            world.step(1.0 / 60.0).unwrap();
            let e = world.state(id).unwrap().energy;
            assert!(e <= last + 1e-12 * last.abs(), "{e} after {last}");
            last = e;
        }
    }

    #[test]
    fn bad_starts_and_loads_are_typed_errors() {
        let mut world = World::try_new(DOWN, 0.01).unwrap();
        // The ball's bottom 1 cm below the table.
        let sunk = ball(0.09).try_build().unwrap();
        assert!(matches!(
            world.add(sunk),
            Err(DynamicsError::BodyInsideTable { contact: 0, gap }) if (gap + 0.01).abs() < 1e-12
        ));
        let mut sideways = World::try_new(DVec3::new(0.0, -G, 0.0), 0.01).unwrap();
        assert!(matches!(
            sideways.add(ball(1.0).try_build().unwrap()),
            Err(DynamicsError::InvalidBody {
                field: "gravity",
                ..
            })
        ));
        let pushed = ball(1.0).with_inputs(Inputs::default().with_torque_world(DVec3::Z));
        assert!(matches!(
            pushed.try_build(),
            Err(DynamicsError::InvalidBody {
                field: "inputs",
                ..
            })
        ));
        let none =
            Body::from_principal_moments(1.0, DVec3::ONE).on_table(DVec3::ZERO, DVec3::ZERO, &[]);
        assert!(matches!(
            none.try_build(),
            Err(DynamicsError::InvalidContact {
                parameter: "contacts",
                ..
            })
        ));
        let id = world.add(ball(1.0).try_build().unwrap()).unwrap();
        let torque = Inputs::default().with_torque_world(DVec3::Z);
        assert!(matches!(
            world.set_inputs(id, torque),
            Err(DynamicsError::InvalidBody {
                field: "inputs",
                ..
            })
        ));
        world.set_inputs(id, Inputs::default()).unwrap();
        assert_eq!(world.events(super::BodyId(7)), None);
    }

    #[test]
    fn setters_restart_the_run_from_the_new_state_and_keep_the_events() {
        let mut world = World::try_new(DOWN, 0.01).unwrap();
        let id = world.add(ball(1.0).try_build().unwrap()).unwrap();
        world.advance_to(0.5).unwrap();
        assert_eq!(world.events(id).unwrap().len(), 1);
        // Lifted back to 1 m at rest at t = 0.5: the next impact t₁ later.
        world
            .set_centre_of_mass(id, DVec3::new(0.0, 0.0, 1.0), DVec3::ZERO)
            .unwrap();
        world.advance_to(1.0).unwrap();
        let events = world.events(id).unwrap();
        assert_eq!(events.len(), 2);
        let t1 = (2.0 * 0.9 / G).sqrt();
        assert!((events[1].time - (0.5 + t1)).abs() < 1e-12, "{}", events[1]);
        // Into the table: refused, nothing changes.
        let before = world.state(id).unwrap();
        assert!(matches!(
            world.set_centre_of_mass(id, DVec3::ZERO, DVec3::ZERO),
            Err(DynamicsError::BodyInsideTable { .. })
        ));
        assert!(
            world
                .set_centre_of_mass(id, DVec3::NAN, DVec3::ZERO)
                .is_err()
        );
        assert_eq!(world.state(id).unwrap(), before);
        // A spin given: L = I ω, the centre of mass where it was.
        world.set_omega_body(id, DVec3::new(0.0, 0.0, 3.0)).unwrap();
        let s = world.state(id).unwrap();
        assert!((s.l_world - DVec3::new(0.0, 0.0, 0.006)).length() < 1e-15);
        assert_eq!((s.position, s.velocity), (before.position, before.velocity));
        world
            .apply_angular_impulse(id, DVec3::new(0.0, 0.0, -0.006))
            .unwrap();
        assert!(world.state(id).unwrap().l_world.length() < 1e-15);
        // A ball resting on the table, spun about the vertical: it stays
        // on the table, its contact touches down once (at the start).
        let mut world = World::try_new(DOWN, 0.01).unwrap();
        let id = world.add(ball(0.1).try_build().unwrap()).unwrap();
        let touchdown = world.events(id).unwrap().to_vec();
        assert_eq!(touchdown.len(), 2, "{touchdown:?}"); // touches down, rests
        assert_eq!(touchdown[0].kind, TableEventKind::Touchdown);
        world.advance_to(0.5).unwrap();
        world.set_omega_body(id, DVec3::new(0.0, 0.0, 3.0)).unwrap();
        world.advance_to(1.0).unwrap();
        let events = world.events(id).unwrap();
        assert!(
            events[2..]
                .iter()
                .all(|e| e.kind != TableEventKind::Touchdown),
            "{events:?}"
        );
        let s = world.state(id).unwrap();
        assert!((s.position.z - 0.1).abs() < 1e-12 && s.omega_body.z == 3.0);
    }

    /// A body whose body axes are not its principal axes: the state is
    /// read in body axes (as given), L = q I_body ω_body, and a setter's
    /// ω reads back as set.
    #[test]
    fn a_body_off_its_principal_axes_reads_in_body_axes() {
        let tensor = glam::DMat3::from_cols_array(&[
            0.004, 0.0005, 0.0, 0.0005, 0.005, 0.0002, 0.0, 0.0002, 0.006,
        ]);
        let props = kreisel_inertia::MassProperties::try_new(1.0, DVec3::ZERO, tensor).unwrap();
        let law = ContactLaw::try_new(0.3).unwrap();
        let omega = DVec3::new(0.3, -2.0, 5.0);
        let q = DQuat::from_rotation_y(0.3);
        let body = Body::from_mass_properties(props)
            .world_from_body(q)
            .omega_body(omega)
            .on_table(
                DVec3::new(0.0, 0.0, 1.0),
                DVec3::ZERO,
                &[TableContact {
                    shape: sphere(0.1, 0.0),
                    law,
                }],
            )
            .try_build()
            .unwrap();
        let mut world = World::try_new(DOWN, 0.01).unwrap();
        let id = world.add(body).unwrap();
        let s = world.state(id).unwrap();
        assert!((s.omega_body - omega).length() < 1e-14, "{}", s.omega_body);
        let error = (s.l_world - q * (tensor * omega)).length();
        assert!(error < 1e-15 * s.l_world.length(), "{error:e}");
        assert!(kreisel_kinematics::rotation_angle_between(s.world_from_body, q) < 1e-15);
        world.advance_to(0.1).unwrap();
        let turned = DVec3::new(-1.0, 0.5, 2.0);
        world.set_omega_body(id, turned).unwrap();
        let s = world.state(id).unwrap();
        assert!((s.omega_body - turned).length() < 1e-13, "{}", s.omega_body);
        let expected = s.world_from_body.normalize() * (tensor * turned);
        let error = (s.l_world - expected).length();
        assert!(error < 1e-14 * s.l_world.length(), "{error:e}");
    }

    /// Bodies on the table moved on two threads end bit for bit where one
    /// thread leaves them (each run is its own).
    #[test]
    fn threads_do_not_change_the_runs() {
        let run = |threads: usize| {
            let mut world = World::try_new(DOWN, 1e-3).unwrap();
            world.set_threads(std::num::NonZeroUsize::new(threads).unwrap());
            for k in 0..4 {
                let body = if k % 2 == 0 { tippe_top() } else { ball(1.0) };
                world.add(body.try_build().unwrap()).unwrap();
            }
            world.advance_to(0.5).unwrap();
            let states: Vec<_> = world.states().map(|(_, s)| s).collect();
            let events: Vec<_> = (0..4)
                .map(|i| world.events(super::BodyId(i)).unwrap().to_vec())
                .collect();
            (states, events)
        };
        let one = run(1);
        assert_eq!(one, run(2));
        // The two tippe tops (bodies 0 and 2, on different threads) alike.
        assert_eq!(one.0[0], one.0[2]);
        assert_eq!(one.1[1].len(), 1, "{:?}", one.1[1]);
    }

    #[test]
    fn the_world_tolerance_reaches_the_table() {
        assert_eq!(
            super::table_tolerance(None).rtol(),
            super::DEFAULT_TABLE_TOLERANCE
        );
        let mut loose = World::try_new(DOWN, 0.01).unwrap();
        loose
            .set_tolerance(Some(Tolerance::new(1e-3, 1.0)))
            .unwrap();
        let id = loose.add(tippe_top().try_build().unwrap()).unwrap();
        let mut tight = World::try_new(DOWN, 0.01).unwrap();
        tight.add(tippe_top().try_build().unwrap()).unwrap();
        loose.advance_to(0.5).unwrap();
        tight.advance_to(0.5).unwrap();
        let (a, b) = (
            loose.table_motion(id).unwrap(),
            tight.table_motion(id).unwrap(),
        );
        // The loose run takes fewer steps and lands near the tight one.
        assert!(
            a.stats().accepted < b.stats().accepted,
            "{:?} {:?}",
            a.stats(),
            b.stats()
        );
        let angle = kreisel_kinematics::rotation_angle_between(
            loose.state(id).unwrap().world_from_body,
            tight.state(id).unwrap().world_from_body,
        );
        assert!(angle > 0.0 && angle < 1e-3, "{angle:e}");
        // Setting the tolerance later restarts the run under it.
        loose.set_tolerance(None).unwrap();
        loose.advance_to(0.6).unwrap();
        tight.advance_to(0.6).unwrap();
        let (a, b) = (
            loose.table_motion(id).unwrap(),
            tight.table_motion(id).unwrap(),
        );
        assert!(a.time() < 0.2 && (b.time() - 0.6).abs() < 1e-15);
    }
}
