//! Reading the world's bodies: [`World::state`], [`World::states`],
//! [`World::attitudes`] and [`World::stays_finite`], through the compact
//! per-body [`Reading`]s that keep what is constant while a plan lasts.

use glam::{DQuat, DVec3};

use super::motion::Motion;
use super::{BodyId, BodyState, Support, World};

impl World {
    /// The state of body `id` now (`None` for an id of another world).
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, World};
    /// let mut world = World::try_new(glam::DVec3::ZERO, 0.1)?;
    /// let id = world.add(Body::from_principal_moments(1.0, glam::DVec3::new(1.0, 2.0, 3.0)).omega_body(glam::DVec3::Y).try_build()?)?;
    /// let s = world.state(id).unwrap();
    /// assert_eq!((s.omega_body, s.l_world, s.energy), (glam::DVec3::Y, 2.0 * glam::DVec3::Y, 1.0));
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    #[inline]
    pub fn state(&self, id: BodyId) -> Option<BodyState> {
        let read = self.reads.get(id.0)?;
        // Two returns, each built in place: a value merged from both
        // branches is copied (a 144-byte memcpy per read, measured).
        if let Some(rotation) = self.kept_rotation(read) {
            return Some(self.compose(read, rotation));
        }
        Some(self.entry_state(id.0))
    }

    /// The rotational part of a reading that keeps it: attitude, ω (body
    /// axes), `L_world` and the rotational energy; `None` for
    /// [`Lane::Entry`].
    #[inline]
    fn kept_rotation(&self, read: &Reading) -> Option<(DQuat, DVec3, DVec3, f64)> {
        match &read.lane {
            Lane::Resting {
                world_from_body,
                omega_body,
                l_world,
                rotational,
            } => Some((*world_from_body, *omega_body, *l_world, *rotational)),
            Lane::Uniform {
                slot,
                body_from_principal,
                omega_body,
                rotational,
            } => {
                let (q, l) = self.uniform.state(*slot);
                let world_from_body = q * body_from_principal.conjugate();
                Some((world_from_body, *omega_body, q.normalize() * l, *rotational))
            }
            Lane::Entry => None,
        }
    }

    /// A free body's state from its rotational part and its flight.
    #[inline]
    fn compose(
        &self,
        read: &Reading,
        (world_from_body, omega_body, l_world, rotational): (DQuat, DVec3, DVec3, f64),
    ) -> BodyState {
        let (mass, g, time) = (read.mass, self.gravity, self.time());
        let (x0, v0, since) = read.ballistic;
        let (x, v) = ballistic(x0, v0, g, time - since);
        BodyState {
            time,
            world_from_body,
            omega_body,
            l_world,
            energy: rotational + 0.5 * mass * v.length_squared() - mass * g.dot(x),
            position: x,
            velocity: v,
        }
    }

    /// Every body's state now, in the order added: what a game loop or a
    /// writer of rows reads each frame (the same values as
    /// [`World::state`], read in order).
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, World};
    /// use glam::DVec3;
    /// let mut world = World::try_new(DVec3::ZERO, 0.1)?;
    /// for k in 0..3 {
    ///     world.add(Body::from_principal_moments(1.0, DVec3::ONE).omega_body(DVec3::X * k as f64).try_build()?)?;
    /// }
    /// world.step(0.1)?;
    /// for (id, s) in world.states() {
    ///     assert_eq!(Some(s), world.state(id));
    ///     assert_eq!(s.omega_body, DVec3::X * id.index() as f64);
    /// }
    /// assert_eq!(world.states().count(), 3);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn states(&self) -> impl ExactSizeIterator<Item = (BodyId, BodyState)> + '_ {
        self.reads
            .iter()
            .enumerate()
            .map(move |(i, read)| match self.kept_rotation(read) {
                Some(rotation) => (BodyId(i), self.compose(read, rotation)),
                None => (BodyId(i), self.entry_state(i)),
            })
    }

    /// Every body's attitude now (body → world), in the order added: what
    /// a renderer needs each frame, without the rest of [`BodyState`].
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, World};
    /// use glam::{DQuat, DVec3};
    /// let mut world = World::try_new(DVec3::ZERO, 0.5)?;
    /// world.add(Body::from_principal_moments(1.0, DVec3::ONE).omega_body(DVec3::Z).try_build()?)?;
    /// world.add(Body::from_principal_moments(1.0, DVec3::ONE).try_build()?)?;
    /// world.step(0.5)?;
    /// let q: Vec<DQuat> = world.attitudes().collect();
    /// assert!(kreisel_kinematics::rotation_angle_between(q[0], DQuat::from_rotation_z(0.5)) < 1e-15);
    /// assert_eq!(q[1], DQuat::IDENTITY);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn attitudes(&self) -> impl ExactSizeIterator<Item = DQuat> + '_ {
        self.reads
            .iter()
            .enumerate()
            .map(|(i, read)| match read.lane {
                Lane::Resting {
                    world_from_body, ..
                } => world_from_body,
                Lane::Uniform {
                    slot,
                    body_from_principal,
                    ..
                } => self.uniform.state(slot).0 * body_from_principal.conjugate(),
                Lane::Entry => match &self.entries[i].motion {
                    Motion::Ground(ground) => ground.attitude(),
                    Motion::Table(table) => table.attitude(),
                    _ => self.rotation(i).world_from_body(&self.entries[i].rigid),
                },
            })
    }

    /// The state of entry `index`, computed from the entry (any plan; not
    /// inlined, so that the reads of the compact lanes stay small).
    #[inline(never)]
    fn entry_state(&self, index: usize) -> BodyState {
        let entry = &self.entries[index];
        match &entry.motion {
            Motion::Ground(ground) => return ground.body_state(self.time()),
            Motion::Table(table) => return table.body_state(self.time()),
            _ => {}
        }
        let state = self.rotation(index);
        let world_from_body = state.world_from_body(&entry.rigid);
        let (mass, g, time) = (entry.body.mass(), self.gravity, self.time());
        let forced = entry.motion.forced_state();
        let (energy, position, velocity) = match (&entry.top, entry.body.support(), forced) {
            (_, _, Some((body, s))) => (
                body.mechanical_energy(s),
                s.position_world,
                s.velocity_world,
            ),
            (
                Some(top),
                Support::Pivot {
                    pivot_body,
                    pivot_world,
                },
                None,
            ) => {
                let c = entry.body.mass_properties().center_of_mass - pivot_body;
                let arm = world_from_body.normalize() * c;
                let omega_world = state.world_from_principal.normalize()
                    * (state.l_principal / entry.rigid.principal_moments());
                let energy = top.energy(&state) - mass * g.dot(pivot_world);
                (energy, pivot_world + arm, omega_world.cross(arm))
            }
            _ => {
                let (x0, v0, since) = self.reads[index].ballistic;
                let (x, v) = ballistic(x0, v0, g, time - since);
                let energy =
                    state.energy(&entry.rigid) + 0.5 * mass * v.length_squared() - mass * g.dot(x);
                (energy, x, v)
            }
        };
        BodyState {
            time,
            world_from_body,
            omega_body: state.omega_body(&entry.rigid),
            l_world: state.l_world(),
            energy,
            position,
            velocity,
        }
    }

    /// Whether body `id`'s energy and the motion of its centre of mass stay
    /// finite from now until `until` (s), checked at both ends: `|v|²` is
    /// convex in `t`, and `−g·x` is concave with its largest value at most
    /// `|v₀|²/2` per kg above the one now. For a body on a pivot or with
    /// applied inputs, whose motion no formula foresees: whether its energy
    /// now is finite. `false` for an unknown id.
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, World};
    /// use glam::DVec3;
    /// let mut world = World::try_new(DVec3::new(0.0, 0.0, -1e300), 0.1)?;
    /// let id = world.add(Body::from_principal_moments(1.0, DVec3::ONE).free(DVec3::new(0.0, 0.0, 1.0), DVec3::ZERO).try_build()?)?;
    /// assert!(world.stays_finite(id, 0.0));
    /// assert!(!world.stays_finite(id, 10.0));
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn stays_finite(&self, id: BodyId, until: f64) -> bool {
        let Some(entry) = self.entries.get(id.0) else {
            return false;
        };
        let Some(now) = self.state(id) else {
            return false;
        };
        let on_ground = matches!(entry.motion, Motion::Ground(_) | Motion::Table(_));
        if entry.top.is_some() || entry.motion.forced_state().is_some() || on_ground {
            // A pivot, or loads no formula foresees: only now is known.
            return now.energy.is_finite();
        }
        let (x0, v0, since) = self.reads[id.0].ballistic;
        let rotational = self.rotation(id.0).energy(&entry.rigid);
        let mass = entry.body.mass();
        [now.time, until].into_iter().all(|t| {
            let (x, v) = ballistic(x0, v0, self.gravity, t - since);
            let energy = rotational + 0.5 * mass * v.length_squared() - mass * self.gravity.dot(x);
            x.is_finite() && v.is_finite() && energy.is_finite()
        })
    }
}

/// The ballistic flight: position and velocity after `t` seconds.
///
/// ```text
/// x(t) = x₀ + v₀ t + ½ g t²,   v(t) = v₀ + g t
/// ```
pub(super) fn ballistic(x0: DVec3, v0: DVec3, g: DVec3, t: f64) -> (DVec3, DVec3) {
    (x0 + v0 * t + g * (0.5 * t * t), v0 + g * t)
}

/// What a read of one body needs, kept apart from its entry (compact, in
/// body order), so that reading every body touches little memory.
#[derive(Debug, Clone, Copy)]
pub(super) struct Reading {
    /// Mass, kg.
    pub(super) mass: f64,
    /// Centre of mass and velocity at world time `since` (free bodies; a
    /// forced body's are in its motion, copied here when it is replanned).
    pub(super) ballistic: (DVec3, DVec3, f64),
    /// Where the rotational state is read from.
    lane: Lane,
}

/// Where a read finds a body's rotational state: what is constant while
/// the plan lasts is kept (the same numbers [`World::state`] would compute).
#[derive(Debug, Clone, Copy)]
enum Lane {
    /// Computed from the entry (every plan but the two below).
    Entry,
    /// A resting free body: nothing rotational changes.
    Resting {
        world_from_body: DQuat,
        omega_body: DVec3,
        l_world: DVec3,
        rotational: f64,
    },
    /// A uniform rotation: its attitude is read from the batch; `L`, so
    /// `ω` and the energy, are constant.
    Uniform {
        slot: usize,
        body_from_principal: DQuat,
        omega_body: DVec3,
        rotational: f64,
    },
}

impl Reading {
    /// A body of mass `mass` flying from `ballistic`, read from its entry.
    pub(super) fn new(mass: f64, ballistic: (DVec3, DVec3, f64)) -> Self {
        Self {
            mass,
            ballistic,
            lane: Lane::Entry,
        }
    }
}

impl World {
    /// Remakes the reading of entry `index` from its motion (after a plan
    /// is made, a slot moves, or a fresh state settles).
    pub(super) fn refresh_reading(&mut self, index: usize) {
        let entry = &self.entries[index];
        let state = self.rotation(index);
        let rigid = &entry.rigid;
        let lane = match entry.motion {
            Motion::Resting { .. } => Lane::Resting {
                world_from_body: state.world_from_body(rigid),
                omega_body: state.omega_body(rigid),
                l_world: state.l_world(),
                rotational: state.energy(rigid),
            },
            Motion::Uniform { slot } => Lane::Uniform {
                slot,
                body_from_principal: rigid.body_from_principal(),
                omega_body: state.omega_body(rigid),
                rotational: state.energy(rigid),
            },
            _ => Lane::Entry,
        };
        self.reads[index].lane = lane;
    }
}
