//! The world: bodies that do not interact, under uniform gravity, each
//! moved along the cheapest exact-enough path its [`Plan`] names.
//!
//! ```text
//! Body ──add──▶ World { bodies, gravity, methods, dt } ──step(h) / advance_steps(n) / advance_to(t)──▶ states
//! ```
//!
//! - Torque-free bodies under the exact method (`auto`) are never stepped:
//!   their exact solution is set up once (when added, or when a setter
//!   changes their state) and evaluated at the world's time, which is kept
//!   in double-double. [`World::advance_to`] evaluates them once at `t`.
//! - Bodies under a stepping method (one the user chose, and every heavy
//!   top) take steps of `dt` on the world's time grid; [`World::step`] takes
//!   one step of the size asked.
//! - Every state reached is checked ([`crate::DivergenceCheck`]).

mod body;
mod clock;
mod plan;
mod registry;
mod state;

use glam::{DQuat, DVec3};

pub use self::body::{Body, BodyBuilder, Support};
pub use self::plan::Plan;
pub use self::state::{BodyId, BodyState};

use self::clock::{Clock, Route};
use self::plan::Motion;
use crate::{
    DivergenceCheck, DynamicsError, FreeBodyMethod, HeavyTop, HeavyTopMethod, PrincipalState,
    RigidBody,
};

/// Bodies under gravity, stepped together: the library's engine.
///
/// ```
/// use glam::DVec3;
/// use kreisel_dynamics::{Body, ExactSolution, World};
/// let mut world = World::try_new(DVec3::new(0.0, 0.0, -9.81), 1.0 / 60.0)?;
/// let body = Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0))
///     .omega_body(DVec3::new(0.01, 1.0, 0.0))
///     .free(DVec3::ZERO, DVec3::new(1.0, 0.0, 5.0))
///     .try_build()?;
/// let id = world.add(body.clone())?;
/// for _ in 0..60 {
///     world.step(1.0 / 60.0)?; // a game loop
/// }
/// world.advance_to(10.0)?; // a simulation: no steps for a torque-free body
/// let s = world.state(id).unwrap();
/// // The exact solution from the same state, evaluated at t = 10 s.
/// let exact = ExactSolution::try_new(DVec3::new(1.0, 2.0, 3.0), kreisel_dynamics::PrincipalState::try_from_omega_body(body.rigid_body(), body.world_from_body(), body.omega_body())?)?;
/// let q = exact.state_at(10.0).world_from_principal;
/// assert!(kreisel_kinematics::rotation_angle_between(s.world_from_body, q) < 1e-14);
/// // The centre of mass flies exactly: x = v₀ t + g t²/2.
/// assert!((s.position - DVec3::new(10.0, 0.0, 50.0 - 490.5)).length() < 1e-12);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
pub struct World {
    gravity: DVec3,
    free_method: FreeBodyMethod,
    heavy_method: HeavyTopMethod,
    clock: Clock,
    entries: Vec<Entry>,
    failed: Option<DynamicsError>,
}

/// One body as the world moves it.
#[derive(Debug)]
struct Entry {
    body: Body,
    /// About the centre of mass, or about the pivot for a heavy top.
    rigid: RigidBody,
    top: Option<HeavyTop>,
    plan: Plan,
    motion: Motion,
    /// The state when the plan was made: the divergence checks' reference.
    baseline: PrincipalState,
    /// The free body's checks (a heavy top's borrow the top: made per call).
    check: Option<DivergenceCheck<'static>>,
    /// Centre of mass and velocity at world time `since` (free bodies).
    ballistic: (DVec3, DVec3, f64),
}

impl std::fmt::Debug for World {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("World")
            .field("gravity", &self.gravity)
            .field("free_body_method", &self.free_method)
            .field("heavy_top_method", &self.heavy_method)
            .field("clock", &self.clock)
            .field("bodies", &self.entries)
            .field("failed", &self.failed)
            .finish()
    }
}

/// The first failure of a run: step number, body, error.
type Failure = (u64, usize, DynamicsError);

impl World {
    /// An empty world at time 0 with gravitational acceleration `gravity`
    /// (world axes, m/s²) and time step `dt` (s) for the methods that step;
    /// the methods are `auto` (the exact solution for free bodies, the
    /// sub-stepped order-8 splitting for heavy tops).
    ///
    /// # Errors
    /// [`DynamicsError::InvalidStep`] for a `dt` that is not positive and
    /// finite; [`DynamicsError::InvalidBody`] for a non-finite gravity.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::World;
    /// let world = World::try_new(DVec3::new(0.0, 0.0, -9.81), 0.01)?;
    /// assert_eq!((world.time(), world.dt(), world.len()), (0.0, 0.01, 0));
    /// assert!(World::try_new(DVec3::ZERO, 0.0).is_err());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_new(gravity: DVec3, dt: f64) -> Result<Self, DynamicsError> {
        if !(dt.is_finite() && dt > 0.0) {
            return Err(DynamicsError::InvalidStep { h: dt });
        }
        if !gravity.is_finite() {
            return Err(DynamicsError::InvalidBody {
                field: "gravity",
                reason: "must be finite",
            });
        }
        Ok(Self {
            gravity,
            free_method: FreeBodyMethod::Auto,
            heavy_method: HeavyTopMethod::Auto,
            clock: Clock::new(dt),
            entries: Vec::new(),
            failed: None,
        })
    }

    /// Chooses the free-body method; the bodies' plans are remade from
    /// their current states.
    ///
    /// # Errors
    /// The set-up errors of a plan.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::{Body, FreeBodyMethod, Plan, World};
    /// let mut world = World::try_new(DVec3::ZERO, 0.01)?;
    /// let id = world.add(Body::from_principal_moments(1.0, DVec3::ONE).omega_body(DVec3::Z).try_build()?)?;
    /// assert_eq!(world.plan(id), Some(&Plan::Sphere));
    /// world.set_free_body_method("pdmv6".parse()?)?;
    /// assert_eq!(world.plan(id), Some(&Plan::Stepping(FreeBodyMethod::Pdmv6)));
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn set_free_body_method(&mut self, method: FreeBodyMethod) -> Result<(), DynamicsError> {
        self.free_method = method;
        self.replan_all()
    }

    /// Chooses the heavy-top method; the plans are remade.
    ///
    /// # Errors
    /// The set-up errors of a plan.
    ///
    /// ```
    /// use kreisel_dynamics::{HeavyTopMethod, World};
    /// let mut world = World::try_new(glam::DVec3::ZERO, 0.01)?;
    /// world.set_heavy_top_method(HeavyTopMethod::Splitting6)?;
    /// assert_eq!(world.heavy_top_method(), HeavyTopMethod::Splitting6);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn set_heavy_top_method(&mut self, method: HeavyTopMethod) -> Result<(), DynamicsError> {
        self.heavy_method = method;
        self.replan_all()
    }

    /// The free-body method (`auto` by default).
    ///
    /// ```
    /// # let world = kreisel_dynamics::World::try_new(glam::DVec3::ZERO, 0.01)?;
    /// assert_eq!(world.free_body_method(), kreisel_dynamics::FreeBodyMethod::Auto);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn free_body_method(&self) -> FreeBodyMethod {
        self.free_method
    }

    /// The heavy-top method (`auto` by default).
    ///
    /// ```
    /// # let world = kreisel_dynamics::World::try_new(glam::DVec3::ZERO, 0.01)?;
    /// assert_eq!(world.heavy_top_method(), kreisel_dynamics::HeavyTopMethod::Auto);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn heavy_top_method(&self) -> HeavyTopMethod {
        self.heavy_method
    }

    /// The time step of the stepping methods, s.
    ///
    /// ```
    /// # let world = kreisel_dynamics::World::try_new(glam::DVec3::ZERO, 0.25)?;
    /// assert_eq!(world.dt(), 0.25);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn dt(&self) -> f64 {
        self.clock.dt()
    }

    /// Gravitational acceleration, world axes, m/s².
    ///
    /// ```
    /// # let world = kreisel_dynamics::World::try_new(glam::DVec3::Z, 0.25)?;
    /// assert_eq!(world.gravity(), glam::DVec3::Z);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn gravity(&self) -> DVec3 {
        self.gravity
    }

    /// The world's time, s.
    ///
    /// ```
    /// # let mut world = kreisel_dynamics::World::try_new(glam::DVec3::ZERO, 0.1)?;
    /// world.advance_to(0.35)?;
    /// assert_eq!(world.time(), 0.35);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn time(&self) -> f64 {
        self.clock.time()
    }

    /// The number of bodies.
    ///
    /// ```
    /// # let world = kreisel_dynamics::World::try_new(glam::DVec3::ZERO, 0.1)?;
    /// assert_eq!(world.len(), 0);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    /// Whether the world has no bodies.
    ///
    /// ```
    /// # let world = kreisel_dynamics::World::try_new(glam::DVec3::ZERO, 0.1)?;
    /// assert!(world.is_empty());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// Adds a body at the world's current time and makes its plan.
    ///
    /// # Errors
    /// For a body on a pivot, the errors of [`HeavyTop::try_new`] and
    /// [`DynamicsError::InvalidState`] when its spin about the pivot
    /// overflows; the set-up errors of its plan.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::{Body, Plan, World};
    /// let mut world = World::try_new(DVec3::new(0.0, 0.0, -9.81), 1e-3)?;
    /// let top = Body::from_principal_moments(1.0, DVec3::new(0.02, 0.02, 0.01))
    ///     .omega_body(DVec3::new(0.0, 0.0, 50.0))
    ///     .pivot(DVec3::new(0.0, 0.0, -0.1), DVec3::ZERO)
    ///     .try_build()?;
    /// let id = world.add(top)?;
    /// assert_eq!(world.plan(id), Some(&Plan::HeavyTop(kreisel_dynamics::HeavyTopMethod::Auto)));
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn add(&mut self, body: Body) -> Result<BodyId, DynamicsError> {
        let (rigid, top, ballistic) = match body.support() {
            Support::Free { position, velocity } => {
                (*body.rigid_body(), None, (position, velocity, self.time()))
            }
            Support::Pivot {
                pivot_body,
                pivot_world,
            } => {
                let top = HeavyTop::try_new(body.mass_properties(), pivot_body, self.gravity)?;
                (
                    *top.body(),
                    Some(top),
                    (pivot_world, DVec3::ZERO, self.time()),
                )
            }
        };
        let state =
            PrincipalState::try_from_omega_body(&rigid, body.world_from_body(), body.omega_body())?;
        let (plan, motion, check) = self.plan_for(&rigid, top.as_ref(), state)?;
        self.entries.push(Entry {
            body,
            rigid,
            top,
            plan,
            motion,
            baseline: state,
            check,
            ballistic,
        });
        Ok(BodyId(self.entries.len() - 1))
    }

    /// The plan, the motion and the checks of a body in `state` now.
    fn plan_for(
        &self,
        rigid: &RigidBody,
        top: Option<&HeavyTop>,
        state: PrincipalState,
    ) -> Result<(Plan, Motion, Option<DivergenceCheck<'static>>), DynamicsError> {
        Ok(match top {
            Some(_) => {
                let (plan, motion) = Motion::heavy_top(self.heavy_method, state);
                (plan, motion, None)
            }
            None => {
                let moments = rigid.principal_moments();
                let (plan, motion) =
                    Motion::free(self.free_method, moments, state, self.clock.now())?;
                let name = registry::free_body(self.free_method).name();
                let check = DivergenceCheck::free_body(name, moments, &state);
                (plan, motion, Some(check))
            }
        })
    }

    /// Remakes every plan from the current states.
    fn replan_all(&mut self) -> Result<(), DynamicsError> {
        for index in 0..self.entries.len() {
            let state = self.entries[index].motion.state();
            self.replan(index, state)?;
        }
        Ok(())
    }

    /// Gives body `index` the rotational state `state` now and remakes its plan.
    fn replan(&mut self, index: usize, state: PrincipalState) -> Result<(), DynamicsError> {
        let entry = &self.entries[index];
        state.validate(entry.rigid.principal_moments())?;
        let (plan, motion, check) = self.plan_for(&entry.rigid, entry.top.as_ref(), state)?;
        let entry = &mut self.entries[index];
        (entry.plan, entry.motion, entry.check, entry.baseline) = (plan, motion, check, state);
        Ok(())
    }

    /// The body `id` as it was added.
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, World};
    /// let mut world = World::try_new(glam::DVec3::ZERO, 0.1)?;
    /// let id = world.add(Body::from_principal_moments(4.0, glam::DVec3::ONE).try_build()?)?;
    /// assert_eq!(world.body(id).unwrap().mass(), 4.0);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn body(&self, id: BodyId) -> Option<&Body> {
        self.entries.get(id.0).map(|e| &e.body)
    }

    /// The plan of body `id`: what it is, which method, why.
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, Plan, World};
    /// let mut world = World::try_new(glam::DVec3::ZERO, 0.1)?;
    /// let id = world.add(Body::from_principal_moments(1.0, glam::DVec3::new(1.0, 2.0, 3.0)).try_build()?)?;
    /// // At rest: nothing to compute.
    /// assert_eq!(world.plan(id), Some(&Plan::Resting));
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn plan(&self, id: BodyId) -> Option<&Plan> {
        self.entries.get(id.0).map(|e| &e.plan)
    }

    /// Every body's plan, in the order added (what `kreisel simulate
    /// --explain` prints).
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, Plan, World};
    /// let mut world = World::try_new(glam::DVec3::ZERO, 0.1)?;
    /// world.add(Body::from_principal_moments(1.0, glam::DVec3::ONE).omega_body(glam::DVec3::X).try_build()?)?;
    /// let plans: Vec<_> = world.plans().map(|(_, p)| *p).collect();
    /// assert_eq!(plans, [Plan::Sphere]);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn plans(&self) -> impl Iterator<Item = (BodyId, &Plan)> {
        self.entries
            .iter()
            .enumerate()
            .map(|(i, e)| (BodyId(i), &e.plan))
    }

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
    pub fn state(&self, id: BodyId) -> Option<BodyState> {
        let entry = self.entries.get(id.0)?;
        let state = entry.motion.state();
        let world_from_body = state.world_from_body(&entry.rigid);
        let (mass, g, time) = (entry.body.mass(), self.gravity, self.time());
        let (energy, position, velocity) = match (&entry.top, entry.body.support()) {
            (
                Some(top),
                Support::Pivot {
                    pivot_body,
                    pivot_world,
                },
            ) => {
                let c = entry.body.mass_properties().center_of_mass - pivot_body;
                let arm = world_from_body.normalize() * c;
                let omega_world = state.world_from_principal.normalize()
                    * (state.l_principal / entry.rigid.principal_moments());
                let energy = top.energy(&state) - mass * g.dot(pivot_world);
                (energy, pivot_world + arm, omega_world.cross(arm))
            }
            _ => {
                let (x0, v0, since) = entry.ballistic;
                let (x, v) = ballistic(x0, v0, g, time - since);
                let energy =
                    state.energy(&entry.rigid) + 0.5 * mass * v.length_squared() - mass * g.dot(x);
                (energy, x, v)
            }
        };
        Some(BodyState {
            time,
            world_from_body,
            omega_body: state.omega_body(&entry.rigid),
            l_world: state.l_world(),
            energy,
            position,
            velocity,
        })
    }

    /// Whether body `id`'s energy and the motion of its centre of mass stay
    /// finite from now until `until` (s), checked at both ends: `|v|²` is
    /// convex in `t`, and `−g·x` is concave with its largest value at most
    /// `|v₀|²/2` per kg above the one now. `false` for an unknown id.
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
        if entry.top.is_some() {
            return now.energy.is_finite();
        }
        let (x0, v0, since) = entry.ballistic;
        let rotational = entry.motion.state().energy(&entry.rigid);
        let mass = entry.body.mass();
        [now.time, until].into_iter().all(|t| {
            let (x, v) = ballistic(x0, v0, self.gravity, t - since);
            let energy = rotational + 0.5 * mass * v.length_squared() - mass * self.gravity.dot(x);
            x.is_finite() && v.is_finite() && energy.is_finite()
        })
    }

    /// One step of `h` seconds for every body (a game loop's frame): a
    /// stepping method takes one step of `h`, an exact solution is
    /// evaluated at the new time (accumulated in double-double, exactly as
    /// [`crate::ExactPropagator`] does), a resting body costs nothing.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidStep`] for an `h` that is not positive and
    /// finite; [`DynamicsError::BodyFailed`] naming the first body whose
    /// step failed or diverged, and when (see [`World::advance_to`]).
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::{Body, World};
    /// let mut world = World::try_new(DVec3::ZERO, 1.0 / 60.0)?;
    /// world.add(Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0)).omega_body(DVec3::Y).try_build()?)?;
    /// for _ in 0..60 {
    ///     world.step(1.0 / 60.0)?;
    /// }
    /// assert!((world.time() - 1.0).abs() < 1e-15);
    /// assert!(world.step(-1.0).is_err());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn step(&mut self, h: f64) -> Result<(), DynamicsError> {
        if !(h.is_finite() && h > 0.0) {
            return Err(DynamicsError::InvalidStep { h });
        }
        let route = self.clock.step_route(h);
        self.run(route)
    }

    /// `n` whole steps of `dt`: exact solutions are evaluated once, at the
    /// end; stepping methods take the `n` steps.
    ///
    /// # Errors
    /// As [`World::advance_to`].
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, World};
    /// let mut world = World::try_new(glam::DVec3::ZERO, 0.1)?;
    /// world.advance_steps(3)?;
    /// assert_eq!(world.time(), 3.0 * 0.1);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn advance_steps(&mut self, n: u64) -> Result<(), DynamicsError> {
        let route = Route {
            whole: n,
            last: None,
            end: self.clock.after_whole(n),
        };
        self.run(route)
    }

    /// Advances the world to time `t` (s): exact solutions are evaluated
    /// once, at `t`; stepping methods take steps of `dt` along the world's
    /// grid, the last one shortened to land on `t` exactly — the grid of
    /// `kreisel simulate`:
    ///
    /// ```text
    /// N = (t − t_grid)/dt rounded up (to the nearest whole number within 1e-6)
    /// steps of dt up to grid point N − 1, then one of t − (t_grid + (N − 1) dt)
    /// ```
    ///
    /// (`t_grid` is 0, or the time of the last step that was not a whole
    /// step of `dt`.)
    ///
    /// # Errors
    /// [`DynamicsError::InvalidTime`] for a `t` that is not finite or lies
    /// before the world's time; [`DynamicsError::BodyFailed`] naming the
    /// first body (earliest step, then lowest index) whose step was refused
    /// ([`DynamicsError::TooManySubsteps`]) or whose state became
    /// non-finite or drifted ([`DynamicsError::Diverged`]). After such an
    /// error each body holds the state it had reached and the world refuses
    /// to move on (it returns the same error).
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::{Body, World};
    /// let mut world = World::try_new(DVec3::ZERO, 0.01)?;
    /// world.set_free_body_method(kreisel_dynamics::FreeBodyMethod::Rk4)?;
    /// let fast = Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0)).omega_body(DVec3::new(1e4, 1e2, 0.0));
    /// world.add(fast.try_build()?)?;
    /// // h ω = 100: far beyond RK4's stability.
    /// let e = world.advance_to(1.0).unwrap_err();
    /// assert!(matches!(e, kreisel_dynamics::DynamicsError::BodyFailed { body: 0, .. }), "{e}");
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn advance_to(&mut self, t: f64) -> Result<(), DynamicsError> {
        let route = self.clock.route_to(t)?;
        self.run(route)
    }

    /// Moves every body along `route`, checking every state reached.
    fn run(&mut self, route: Route) -> Result<(), DynamicsError> {
        if let Some(error) = &self.failed {
            return Err(error.clone());
        }
        if route.whole == 0 && route.last.is_none() {
            return Ok(());
        }
        let end = self.clock.end_of(&route);
        let (clock, dt) = (self.clock, self.clock.dt());
        let heavy = registry::heavy_top(self.heavy_method);
        // The time of step k of the route (1-based; the last one ends at route.end).
        let time_of = |k: u64| {
            if k <= route.whole {
                clock.after_whole(k)
            } else {
                route.end
            }
        };
        let mut first: Option<Failure> = None;
        for (index, entry) in self.entries.iter_mut().enumerate() {
            let failure = match &mut entry.motion {
                // At rest the state is the exact solution's value at its
                // start, finite and checked when the plan was made.
                Motion::Resting { state, settled } => {
                    *state = *settled;
                    None
                }
                motion @ Motion::Exact { .. } => {
                    motion.evaluate_at(end);
                    let check = entry.check.as_ref();
                    check
                        .and_then(|c| c.check(&motion.state(), route.end).err())
                        .map(|e| (route.whole + 1, e))
                }
                Motion::Stepping(propagator) => {
                    let check = entry.check.as_ref();
                    let mut step = |k: u64, h: f64| {
                        propagator.try_advance(h)?;
                        match check {
                            Some(c) => c.check(&propagator.state(), time_of(k)),
                            None => Ok(()),
                        }
                    };
                    walk(&route, dt, &mut step)
                }
                Motion::HeavyTop(state) => match &entry.top {
                    Some(top) => {
                        let check = DivergenceCheck::heavy_top(heavy.name(), top, &entry.baseline);
                        let mut step = |k: u64, h: f64| {
                            let mut next = *state;
                            heavy.try_step(top, &mut next, h)?;
                            check.check(&next, time_of(k))?;
                            *state = next;
                            Ok(())
                        };
                        walk(&route, dt, &mut step)
                    }
                    None => None,
                },
            };
            if let Some((k, error)) = failure
                && first.as_ref().is_none_or(|(k0, _, _)| k < *k0)
            {
                first = Some((k, index, error));
            }
        }
        match first {
            None => {
                self.clock.follow(&route);
                Ok(())
            }
            Some((k, body, source)) => {
                let error = DynamicsError::BodyFailed {
                    body,
                    time: time_of(k),
                    source: Box::new(source),
                };
                self.failed = Some(error.clone());
                Err(error)
            }
        }
    }

    /// The entry of `id`, or [`DynamicsError::UnknownBody`].
    fn entry(&self, id: BodyId) -> Result<&Entry, DynamicsError> {
        self.entries
            .get(id.0)
            .ok_or(DynamicsError::UnknownBody { index: id.0 })
    }

    /// Sets body `id`'s angular velocity (body axes, rad/s) now, keeping
    /// its attitude; its plan is remade from the new state.
    ///
    /// # Errors
    /// [`DynamicsError::UnknownBody`]; [`DynamicsError::InvalidState`] for
    /// a non-finite or overflowing ω; the plan's set-up errors.
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, Plan, World};
    /// use glam::DVec3;
    /// let mut world = World::try_new(DVec3::ZERO, 0.1)?;
    /// let id = world.add(Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0)).try_build()?)?;
    /// assert_eq!(world.plan(id), Some(&Plan::Resting));
    /// world.set_omega_body(id, DVec3::new(0.1, 1.0, 0.0))?;
    /// assert_eq!(world.plan(id), Some(&Plan::Asymmetric));
    /// assert!((world.state(id).unwrap().omega_body - DVec3::new(0.1, 1.0, 0.0)).length() < 1e-15);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn set_omega_body(&mut self, id: BodyId, omega_body: DVec3) -> Result<(), DynamicsError> {
        let entry = self.entry(id)?;
        let state = entry.motion.state();
        let world_from_body = state.world_from_body(&entry.rigid);
        let next = PrincipalState::try_from_omega_body(&entry.rigid, world_from_body, omega_body)?;
        self.replan(id.0, next)
    }

    /// Applies an angular impulse `j_world` (N·m·s, world axes; about the
    /// centre of mass, or about the pivot) to body `id` now: `L_world += J`.
    ///
    /// # Errors
    /// As [`World::set_omega_body`].
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, World};
    /// use glam::DVec3;
    /// let mut world = World::try_new(DVec3::ZERO, 0.1)?;
    /// let id = world.add(Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0)).omega_body(DVec3::Y).try_build()?)?;
    /// world.apply_angular_impulse(id, DVec3::new(0.0, 0.0, 3.0))?;
    /// assert!((world.state(id).unwrap().l_world - DVec3::new(0.0, 2.0, 3.0)).length() < 1e-15);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn apply_angular_impulse(
        &mut self,
        id: BodyId,
        j_world: DVec3,
    ) -> Result<(), DynamicsError> {
        if !j_world.is_finite() {
            return Err(DynamicsError::InvalidState {
                reason: "angular impulse is not finite",
            });
        }
        let state = self.entry(id)?.motion.state();
        let q = state.world_from_principal.normalize();
        let next = PrincipalState {
            world_from_principal: q,
            l_principal: state.l_principal + q.conjugate() * j_world,
        };
        self.replan(id.0, next)
    }

    /// Sets body `id`'s attitude (body → world; normalised) now, keeping
    /// its angular velocity in body axes.
    ///
    /// # Errors
    /// As [`World::set_omega_body`], and for a zero or non-finite quaternion.
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, World};
    /// use glam::{DQuat, DVec3};
    /// let mut world = World::try_new(DVec3::ZERO, 0.1)?;
    /// let id = world.add(Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0)).omega_body(DVec3::Y).try_build()?)?;
    /// world.set_attitude(id, DQuat::from_rotation_z(1.0))?;
    /// assert!((world.state(id).unwrap().l_world - DVec3::new(-2.0 * 1f64.sin(), 2.0 * 1f64.cos(), 0.0)).length() < 1e-15);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn set_attitude(
        &mut self,
        id: BodyId,
        world_from_body: DQuat,
    ) -> Result<(), DynamicsError> {
        let entry = self.entry(id)?;
        let omega_body = entry.motion.state().omega_body(&entry.rigid);
        let next = PrincipalState::try_from_omega_body(&entry.rigid, world_from_body, omega_body)?;
        self.replan(id.0, next)
    }
}

/// Takes the route's whole steps of `dt` and its last step through
/// `step(k, h)` (k from 1); the first failure and its step number.
fn walk(
    route: &Route,
    dt: f64,
    step: &mut dyn FnMut(u64, f64) -> Result<(), DynamicsError>,
) -> Option<(u64, DynamicsError)> {
    for k in 1..=route.whole {
        if let Err(e) = step(k, dt) {
            return Some((k, e));
        }
    }
    let h = route.last?;
    step(route.whole + 1, h).err().map(|e| (route.whole + 1, e))
}

/// The ballistic flight: position and velocity after `t` seconds.
///
/// ```text
/// x(t) = x₀ + v₀ t + ½ g t²,   v(t) = v₀ + g t
/// ```
fn ballistic(x0: DVec3, v0: DVec3, g: DVec3, t: f64) -> (DVec3, DVec3) {
    (x0 + v0 * t + g * (0.5 * t * t), v0 + g * t)
}
