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
//! - Free bodies with applied [`crate::Inputs`] take steps of `dt` on the
//!   same grid by a torque splitting ([`Plan::Forced`]); their centre of
//!   mass moves with the splitting, and their energy is the mechanical
//!   energy, whose change is the work of the inputs ([`BodyState`]).
//! - Bodies on a pivot with inputs (driven heavy tops, [`Plan::DrivenTop`])
//!   step by the same splitting about the pivot, gravity kicked with the
//!   loads.
//! - Bodies on the ground plane `z = 0` ([`Support::Ground`],
//!   [`Plan::OnGround`]; the world's gravity must point along −z) take
//!   error-controlled steps of their contact model within every step of
//!   the grid ([`crate::GroundTop::try_advance_adaptive`], at a tolerance
//!   the world's [`Tolerance`] sets): `dt` is only where they are read. A
//!   lift-off, a disk lying flat or Painlevé's case is the world's failure
//!   with its time. Further shapes that do not touch
//!   ([`BodyBuilder::other_contacts`], a tippe top's stem ball) are
//!   watched: one reaching the plane is the world's failure too, with its
//!   time, which shape and its approach speed
//!   ([`crate::DynamicsError::ContactTouchdown`]; the impact is not
//!   modelled). Their inputs enter the contact model, read at the world's
//!   time ([`crate::GroundTop::try_with_inputs`]); the methods do not
//!   change their plan (`ground.rs`).
//! - Bodies on the table `z = 0` ([`Support::Table`], [`Plan::OnTable`];
//!   gravity along −z) with any number of contact shapes, started above
//!   or touching it: a [`crate::TableMotion`] each (unilateral contacts,
//!   impacts, Coulomb–Contensou friction), advanced to the end of every
//!   move in its own error-controlled steps — the world's `dt` is only
//!   the grid the states are read on; its events (impacts, lift-offs,
//!   stick–slip, rest) are recorded ([`World::events`]) while the run
//!   goes on, or stopped at ([`World::advance_until_event`],
//!   `next_event.rs`). The world's [`Tolerance`] sets its accuracy
//!   ([`crate::table_tolerance`]; `table.rs`).
//! - With a [`Tolerance`] ([`World::set_tolerance`]) each body that steps
//!   takes the cheapest method and sub-steps predicted to meet it
//!   ([`World::choice`]).
//! - Every state reached is checked ([`crate::DivergenceCheck`]; for
//!   forced bodies: finiteness and `|q|`, since energy is not conserved;
//!   for uniform rotations: finiteness, the only thing that can change —
//!   see `uniform.rs`; for bodies on the ground: the contact model's own
//!   checks, finiteness and the contact).
//!
//! **What a move touches.** Bodies of one kind are kept together
//! (`lanes.rs`): resting bodies in no loop, uniform rotations in one
//! structure-of-arrays batch (`uniform.rs`), every other body on the
//! ascending list of entries a move visits.
//!
//! A setter remakes the body's plan and moves it between these (the batch
//! fills a freed slot with its last one). Reads ([`World::state`],
//! [`World::states`], [`World::attitudes`]) go through a compact per-body
//! table that keeps what is constant while a plan lasts (a resting body's
//! whole rotational state; a uniform rotation's ω and energy), so reading
//! every body each frame does not walk the large entries. Every number is
//! the one the body's exact solution gives on its own, bit for bit.

mod body;
mod clock;
mod ground;
mod ground_motion;
mod lanes;
mod motion;
mod next_event;
mod plan;
mod reads;
mod setters;
mod state;
mod stepping;
mod table;
mod table_run;
mod tolerance;
mod uniform;

use std::num::NonZeroUsize;

use glam::DVec3;

pub use self::body::{Body, BodyBuilder, Support};
pub use self::plan::Plan;
use self::reads::Reading;
pub use self::state::{BodyId, BodyState};
pub use self::table::{DEFAULT_TABLE_TOLERANCE, table_tolerance};
pub use self::tolerance::{Choice, Tolerance};

use self::clock::Clock;
pub use self::clock::{WHOLE_STEPS_TOLERANCE, grid_steps};
use self::motion::Motion;
use self::uniform::UniformBatch;
use crate::{
    DivergenceCheck, DynamicsError, ForcedBody, ForcedState, FreeBodyMethod, HeavyTop,
    HeavyTopClosedForm, HeavyTopMethod, PrincipalState, RigidBody,
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
    /// What a read of each entry needs, compact and in body order.
    reads: Vec<Reading>,
    /// The uniform rotations (spheres, principal spins), evaluated together.
    uniform: UniformBatch,
    /// The entries a move touches one by one, ascending: every body that
    /// is neither resting nor a uniform rotation.
    moving: Vec<usize>,
    /// Resting bodies and uniform rotations planned since the world last
    /// moved: from the next move on they report the exact solution's state.
    fresh: Vec<usize>,
    failed: Option<DynamicsError>,
    threads: NonZeroUsize,
    tolerance: Option<Tolerance>,
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
    /// What the world's tolerance chose for the body, if one is set.
    choice: Option<Choice>,
}

/// A body's plan as [`World::plan_for`] makes it.
struct Planned {
    plan: Plan,
    motion: Motion,
    check: Option<DivergenceCheck<'static>>,
    choice: Option<Choice>,
}

impl std::fmt::Debug for World {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("World")
            .field("gravity", &self.gravity)
            .field("free_body_method", &self.free_method)
            .field("heavy_top_method", &self.heavy_method)
            .field("clock", &self.clock)
            .field("bodies", &self.entries)
            .field("uniform_rotations", &self.uniform.len())
            .field("moving", &self.moving.len())
            .field("failed", &self.failed)
            .field("threads", &self.threads)
            .field("tolerance", &self.tolerance)
            .finish()
    }
}

impl World {
    /// An empty world at time 0 with gravitational acceleration `gravity`
    /// (world axes, m/s²) and time step `dt` (s) for the methods that step;
    /// the methods are `auto` (the exact solution for free bodies, the
    /// sub-stepped order-8 splitting for heavy tops).
    ///
    /// **`dt` here, `h` in [`World::step`].** `dt` is the world's own step:
    /// the grid that [`World::advance_steps`] and [`World::advance_to`]
    /// walk (the steps a heavy top or a driven body takes, the rows of
    /// `kreisel simulate`), the longest step the contact model of a body on
    /// the ground takes, and the step a [`crate::Tolerance`] plans for.
    /// [`World::step`]`(h)` moves every body forward by `h` now, whatever
    /// `dt` is. A game loop sets `dt` to its frame time and calls
    /// `step(dt)` each frame: then every step is a whole step of the grid
    /// and the world's time stays `n · dt` to the last bit.
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
            reads: Vec::new(),
            uniform: UniformBatch::default(),
            moving: Vec::new(),
            fresh: Vec::new(),
            failed: None,
            threads: NonZeroUsize::MIN,
            tolerance: None,
        })
    }

    /// Chooses the free-body method; the bodies' plans are remade from
    /// their current states. For bodies with applied inputs the method maps
    /// to a torque splitting ([`Plan::forced_splitting`]).
    ///
    /// # Errors
    /// [`DynamicsError::MethodTakesNoInputs`] when a body has inputs and
    /// the method cannot move it (then nothing changes); the set-up errors
    /// of a plan.
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
        if self
            .entries
            .iter()
            .any(|e| e.top.is_none() && !e.body.inputs().is_none())
        {
            Plan::forced_splitting(method)?;
        }
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
        if self
            .entries
            .iter()
            .any(|e| e.top.is_some() && !e.body.inputs().is_none())
        {
            Plan::driven_top_splitting(method)?;
        }
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

    /// Sets how many threads may move the bodies that step every `dt`
    /// (heavy tops and bodies with inputs) and evaluate the symmetric and
    /// asymmetric exact solutions; 1 (the default) moves every body on the
    /// calling thread. The world splits those bodies into contiguous
    /// chunks, one per scoped thread (the calling thread takes the first),
    /// and only when the work is worth a thread:
    ///
    /// ```text
    /// threads used = min(n, bodies / 2, body-steps / 64), at least 1   (an exact evaluation counts as one step)
    /// ```
    ///
    /// Bodies do not interact and each one's arithmetic is the same on any
    /// thread, so the states are bit-identical whatever `n`, and so is the
    /// error of a failed run (the earliest step, then the lowest index).
    /// Free bodies under a stepping method the user chose and uniform
    /// rotations (their batch) stay on the calling thread. Loads given as closures run on
    /// the worker threads (they are `Send + Sync`).
    ///
    /// ```
    /// use std::num::NonZeroUsize;
    /// use glam::DVec3;
    /// use kreisel_dynamics::{Body, World};
    /// let top = Body::from_principal_moments(1.0, DVec3::new(0.02, 0.02, 0.01))
    ///     .omega_body(DVec3::new(0.0, 1.0, 50.0))
    ///     .pivot(DVec3::new(0.0, 0.0, -0.1), DVec3::ZERO)
    ///     .try_build()?;
    /// let mut states = Vec::new();
    /// for n in [1, 3] {
    ///     let mut world = World::try_new(DVec3::new(0.0, 0.0, -9.81), 1e-3)?;
    ///     world.set_threads(NonZeroUsize::new(n).unwrap());
    ///     assert_eq!(world.threads().get(), n);
    ///     let ids: Vec<_> = (0..8).map(|_| world.add(top.clone())).collect::<Result<_, _>>()?;
    ///     world.advance_to(0.1)?;
    ///     states.push(ids.iter().map(|&id| world.state(id).unwrap().world_from_body).collect::<Vec<_>>());
    /// }
    /// assert_eq!(states[0], states[1]);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn set_threads(&mut self, n: NonZeroUsize) {
        self.threads = n;
    }

    /// How many threads may move the bodies (1 by default; see
    /// [`World::set_threads`]).
    ///
    /// ```
    /// # let world = kreisel_dynamics::World::try_new(glam::DVec3::ZERO, 0.1)?;
    /// assert_eq!(world.threads().get(), 1);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn threads(&self) -> NonZeroUsize {
        self.threads
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
    /// overflows; for a body on the ground, [`DynamicsError::InvalidBody`]
    /// when the world's gravity does not point along −z, the errors of
    /// [`crate::GroundTop::try_with_shape`] and of its state on the ground
    /// ([`crate::GroundTop::try_state_on_ground`]: a disk lying flat, a
    /// rolling start that slips) and
    /// [`DynamicsError::OtherContactTouching`] when a further shape
    /// ([`BodyBuilder::other_contacts`]) is at or below the plane; for a
    /// body on the table, [`DynamicsError::InvalidBody`] for gravity not
    /// along −z or applied inputs, the errors of [`crate::TableBody::try_new`]
    /// and [`crate::TableMotion::try_new`] (a shape below the table:
    /// [`DynamicsError::BodyInsideTable`]); for a free body with inputs,
    /// [`DynamicsError::MethodTakesNoInputs`] when the world's free-body
    /// method cannot move it and [`DynamicsError::InvalidBodyParameter`]
    /// for a non-finite gravity term; the set-up errors of its plan.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::{Body, Plan, World};
    /// let mut world = World::try_new(DVec3::new(0.0, 0.0, -9.81), 1e-3)?;
    /// let top = |pivot_body| {
    ///     Body::from_principal_moments(1.0, DVec3::new(0.02, 0.02, 0.01))
    ///         .omega_body(DVec3::new(0.0, 0.0, 50.0))
    ///         .pivot(pivot_body, DVec3::ZERO)
    ///         .try_build()
    /// };
    /// let id = world.add(top(DVec3::new(0.0, 0.0, -0.1))?)?;
    /// // Two equal moments, the centre of mass on the axis: a Lagrange top.
    /// assert_eq!(world.plan(id), Some(&Plan::LagrangeTop));
    /// let id = world.add(top(DVec3::new(0.01, 0.0, -0.1))?)?;
    /// assert_eq!(world.plan(id), Some(&Plan::HeavyTop(kreisel_dynamics::HeavyTopMethod::Auto)));
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn add(&mut self, body: Body) -> Result<BodyId, DynamicsError> {
        let (rigid, top, ballistic) = match body.support() {
            Support::Ground { .. } => return self.add_on_ground(body),
            Support::Table { .. } => return self.add_on_table(body),
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
        let Planned {
            plan,
            motion,
            check,
            choice,
        } = self.plan_for(&body, &rigid, top.as_ref(), state, ballistic)?;
        let body_mass = body.mass();
        self.entries.push(Entry {
            body,
            rigid,
            top,
            plan,
            motion,
            baseline: state,
            check,
            choice,
        });
        self.reads.push(Reading::new(body_mass, ballistic));
        let index = self.entries.len() - 1;
        self.place(index);
        Ok(BodyId(index))
    }

    /// The plan, the motion, the checks and the tolerance's choice of a
    /// body in `state` now, its centre of mass flying from `ballistic`.
    fn plan_for(
        &self,
        body: &Body,
        rigid: &RigidBody,
        top: Option<&HeavyTop>,
        state: PrincipalState,
        ballistic: (DVec3, DVec3, f64),
    ) -> Result<Planned, DynamicsError> {
        // A tolerance chooses only where the method is left to the world.
        let tolerance = self
            .tolerance
            .filter(|_| self.free_method == FreeBodyMethod::Auto);
        let (plan, motion, check, choice) = match top {
            Some(top) => {
                let (plan, motion, choice) = self.plan_on_pivot(body, top, state)?;
                (plan, motion, None, choice)
            }
            None if !body.inputs().is_none() => {
                let (x0, v0, since) = ballistic;
                let (position_world, velocity_world) =
                    reads::ballistic(x0, v0, self.gravity, self.time() - since);
                let forced =
                    ForcedBody::try_new(*rigid, body.mass(), self.gravity, body.inputs().clone())?;
                let start = ForcedState {
                    rotation: state,
                    position_world,
                    velocity_world,
                };
                let default = Plan::forced_splitting(self.free_method)?;
                let chosen = tolerance.and_then(|tol| {
                    let at = (self.time(), self.dt());
                    tolerance::choose_forced(&tol, &forced, &start, at, (default, 1))
                });
                let (method, substeps, choice) = match chosen {
                    Some((method, choice)) => (method, choice.substeps, Some(choice)),
                    None => (default, 1, None),
                };
                let motion = Motion::forced(method, substeps, false, forced, start);
                (Plan::Forced { method }, motion, None, choice)
            }
            None => {
                let moments = rigid.principal_moments();
                let now = self.clock.now();
                let (mut plan, mut motion) = Motion::free(self.free_method, moments, state, now)?;
                let mut method = self.free_method;
                let mut choice = None;
                if let (Some(tol), Plan::Asymmetric, Motion::Exact { solution, .. }) =
                    (tolerance, plan, &motion)
                    && let Some((chosen, c)) =
                        tolerance::choose_free(&tol, solution, moments, self.dt())
                {
                    choice = Some(c);
                    if chosen != FreeBodyMethod::Exact {
                        method = chosen;
                        (plan, motion) = Motion::free(method, moments, state, now)?;
                    }
                }
                let name = method.integrator().name();
                let check = DivergenceCheck::free_body(name, moments, &state);
                (plan, motion, Some(check), choice)
            }
        };
        Ok(Planned {
            plan,
            motion,
            check,
            choice,
        })
    }

    /// The plan, motion and tolerance's choice of a body on a pivot in
    /// `state` now: the heavy-top method's; with inputs, or with a
    /// tolerance under the `auto` heavy-top method, the torque splitting
    /// about the pivot (gravity kicked with the loads), sub-stepped within
    /// its stability limit under `auto`.
    fn plan_on_pivot(
        &self,
        body: &Body,
        top: &HeavyTop,
        state: PrincipalState,
    ) -> Result<(Plan, Motion, Option<Choice>), DynamicsError> {
        let auto = self.heavy_method == HeavyTopMethod::Auto;
        let tolerance = self.tolerance.filter(|_| auto);
        let driven = !body.inputs().is_none();
        let Support::Pivot {
            pivot_body,
            pivot_world,
        } = body.support()
        else {
            return Err(DynamicsError::InvalidBody {
                field: "support",
                reason: "has no pivot",
            });
        };
        // A Lagrange top under auto: its closed form, at rounding level
        // and evaluated only where asked, whatever the tolerance.
        if !driven && auto && top.symmetry_axis().is_some() {
            let closed = HeavyTopClosedForm::try_new(top, state)?;
            let motion = Motion::LagrangeTop {
                closed: Box::new(closed),
                start: self.clock.now(),
                state,
            };
            return Ok((Plan::LagrangeTop, motion, None));
        }
        if !driven && tolerance.is_none() {
            let (plan, motion) = Motion::heavy_top(self.heavy_method, state);
            return Ok((plan, motion, None));
        }
        let inputs = body.inputs().clone();
        let forced = ForcedBody::try_on_pivot(
            body.mass_properties(),
            pivot_body,
            pivot_world,
            self.gravity,
            inputs,
        )?;
        let start = forced.state_on_pivot(state);
        let default = Plan::driven_top_splitting(self.heavy_method)?;
        // A top too fast for the sub-step limit fails at its first step.
        let stable = forced
            .stable_substeps(&start, self.dt())
            .unwrap_or(tolerance::MAX_SUBSTEPS);
        let chosen = tolerance.and_then(|tol| {
            let at = (self.time(), self.dt());
            tolerance::choose_forced(&tol, &forced, &start, at, (default, stable))
        });
        // Without inputs, the Taylor series of the whole top where it meets
        // the tolerance for less work than any splitting.
        let default_work = tolerance::splitting_work(&forced, default, stable, self.dt());
        let series = tolerance
            .filter(|_| !driven)
            .and_then(|tol| tolerance::choose_taylor(&tol, top, &state, self.dt(), default_work))
            .filter(|taylor| chosen.as_ref().is_none_or(|(_, c)| taylor.work < c.work));
        if let Some(choice) = series {
            let integrator = &crate::HeavyTopTaylor::DEFAULT;
            let motion = Motion::HeavyTop { state, integrator };
            return Ok((Plan::HeavyTopSeries, motion, Some(choice)));
        }
        let (method, substeps, choice) = match chosen {
            Some((method, choice)) => (method, choice.substeps, Some(choice)),
            // Nothing chosen (at rounding level): the heavy top's own plan.
            None if !driven => {
                let (plan, motion) = Motion::heavy_top(self.heavy_method, state);
                return Ok((plan, motion, None));
            }
            None => (default, 1, None),
        };
        let plan = if driven {
            Plan::DrivenTop { method }
        } else {
            Plan::HeavyTop(Plan::heavy_top_method_of(method))
        };
        let motion = Motion::forced(method, substeps, auto, forced, start);
        Ok((plan, motion, choice))
    }

    /// Remakes every plan from the current states (a body on the ground
    /// keeps its own, only its accuracy follows the tolerance; a body on
    /// the table keeps its run: only the tolerance changes it,
    /// [`World::set_tolerance`]).
    fn replan_all(&mut self) -> Result<(), DynamicsError> {
        for index in 0..self.entries.len() {
            if matches!(self.entries[index].motion, Motion::Ground(_)) {
                self.retune_ground(index)?;
                continue;
            }
            if matches!(self.entries[index].motion, Motion::Table(_)) {
                continue;
            }
            let state = self.rotation(index);
            self.replan(index, state)?;
        }
        Ok(())
    }

    /// Gives body `index` the rotational state `state` now and remakes its plan.
    fn replan(&mut self, index: usize, state: PrincipalState) -> Result<(), DynamicsError> {
        match self.entries[index].motion {
            Motion::Ground(_) => return self.replan_ground(index, state),
            Motion::Table(_) => return self.replan_table(index, state),
            _ => {}
        }
        let now = self.time();
        let entry = &self.entries[index];
        state.validate(entry.rigid.principal_moments())?;
        // A free body's centre of mass flies on from where its splitting
        // left it (a top's pivot stays where it is).
        if let (None, Some((_, s))) = (&entry.top, entry.motion.forced_state()) {
            self.reads[index].ballistic = (s.position_world, s.velocity_world, now);
        }
        let entry = &self.entries[index];
        let planned = self.plan_for(
            &entry.body,
            &entry.rigid,
            entry.top.as_ref(),
            state,
            self.reads[index].ballistic,
        )?;
        // A body that moves before and after stays where it is in `moving`
        // (a controller replanning every body each frame pays no list work).
        let stays = self.entries[index].motion.is_moving() && planned.motion.is_moving();
        if !stays {
            self.unplace(index);
        }
        let entry = &mut self.entries[index];
        (entry.plan, entry.motion, entry.check, entry.choice) =
            (planned.plan, planned.motion, planned.check, planned.choice);
        entry.baseline = state;
        if stays {
            self.refresh_reading(index);
        } else {
            self.place(index);
        }
        Ok(())
    }

    /// The body `id` as it was added (with the inputs of the last
    /// [`World::set_inputs`]).
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

    /// What the world's [`Tolerance`] chose for body `id` (`None` without
    /// a tolerance, for a method the user chose, for a body whose plan is
    /// exact and cheapest anyway — a sphere, a symmetric body, a body at
    /// rest — and for a heavy top).
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::{Body, Inputs, Tolerance, World};
    /// let mut world = World::try_new(DVec3::ZERO, 0.1)?;
    /// world.set_tolerance(Some(Tolerance::new(1e-6, 10.0)))?;
    /// let wheel = Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0))
    ///     .omega_body(DVec3::new(0.2, 1.0, 0.1))
    ///     .try_build()?
    ///     .with_inputs(Inputs::default().with_torque_body(DVec3::new(0.5, 0.0, 0.0)))?;
    /// let id = world.add(wheel)?;
    /// let choice = world.choice(id).unwrap();
    /// assert!(choice.predicted <= 1e-6);
    /// world.set_tolerance(None)?;
    /// assert!(world.choice(id).is_none());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn choice(&self, id: BodyId) -> Option<&Choice> {
        self.entries.get(id.0).and_then(|e| e.choice.as_ref())
    }

    /// Sets the accuracy asked of every body (`None`: the default plans, at
    /// rounding level); the plans are remade from the current states. With
    /// a tolerance and the `auto` free-body method, an asymmetric free
    /// body is stepped by RK4 or PDMV6 where that is predicted to meet it
    /// for less work than the exact solution (a game loop that reads every
    /// frame), and a body with inputs by the cheapest splitting and
    /// sub-steps that meet it ([`Choice`]; the model is in [`Tolerance`]'s
    /// module docs). A body on the table starts its run again from its
    /// state now under the tolerance's error control
    /// ([`crate::table_tolerance`]), whatever the methods.
    ///
    /// # Errors
    /// The set-up errors of a plan.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::{Body, Plan, Tolerance, World};
    /// let mut world = World::try_new(DVec3::ZERO, 0.01)?;
    /// let id = world.add(Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0)).omega_body(DVec3::new(0.3, 1.0, 0.2)).try_build()?)?;
    /// assert_eq!(world.plan(id), Some(&Plan::Asymmetric));
    /// // Read once per simulated second, the exact solution stays cheapest.
    /// world.set_tolerance(Some(Tolerance::new(1e-3, 100.0).try_reading_every(1.0)?))?;
    /// assert_eq!(world.plan(id), Some(&Plan::Asymmetric));
    /// assert_eq!(world.choice(id).unwrap().method, "exact");
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn set_tolerance(&mut self, tolerance: Option<Tolerance>) -> Result<(), DynamicsError> {
        self.tolerance = tolerance;
        self.replan_all()?;
        self.retune_tables()
    }

    /// The accuracy asked of the bodies (`None` by default).
    ///
    /// ```
    /// # let world = kreisel_dynamics::World::try_new(glam::DVec3::ZERO, 0.01)?;
    /// assert_eq!(world.tolerance(), None);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn tolerance(&self) -> Option<Tolerance> {
        self.tolerance
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
}
