//! The tippe top of Leine & Glocker (2003) with its stem, a body on the
//! table of a [`World`] ([`kreisel::dynamics::Support::Table`]: ball and
//! stem as unilateral contacts, Coulomb–Contensou friction, impacts, moved
//! by the library's nonsmooth engine), and what the demo observes along
//! the way: the tilt θ, the energy, Jellett's λ about the touching sphere,
//! the axis' passage through the horizontal, and the world's events.

use glam::{DQuat, DVec3};
use kreisel::dynamics::{
    Body, BodyId, BodyState, ContactLaw, ContactMode, ContactShape, DynamicsError, SphereContact,
    TableContact, TableEvent, TableMotion, Tolerance, World,
};

use super::options::MAX_DURATION;

/// Mass, kg (Leine & Glocker, Eur. J. Mech. A/Solids 22 (2003) 193).
pub const MASS: f64 = 0.006;
/// Transverse moment of inertia about the centre of mass, kg·m².
pub const I1: f64 = 8e-7;
/// Axial moment of inertia, kg·m².
pub const I3: f64 = 7e-7;
/// Radius of the ball, m.
pub const BALL_RADIUS: f64 = 0.015;
/// Distance from the centre of mass to the ball's centre, towards the stem, m.
pub const BALL_OFFSET: f64 = 0.003;
/// Radius of the stem's ball, m.
pub const STEM_RADIUS: f64 = 0.005;
/// Distance from the centre of mass to the stem ball's centre, m.
pub const STEM_OFFSET: f64 = 0.016;
/// Initial tilt of the symmetry axis from the vertical, rad.
pub const THETA0: f64 = 0.1;
/// Initial spin about the symmetry axis, rad/s.
pub const SPIN0: f64 = 180.0;
/// Gravity, m/s².
pub const GRAVITY: f64 = 9.81;
/// The contacts' names, in the library's order (contact #0, #1).
pub const CONTACT_NAMES: [&str; 2] = ["ball", "stem"];

/// Bisections that locate the horizontal passage between two observed
/// instants (2⁻⁶⁰ of the interval: to rounding).
const BISECTIONS: usize = 60;

/// The world's `dt`: for a body on the table only the grid
/// [`World::advance_steps`] walks, which the demo does not use (it
/// advances to its own instants).
const WORLD_DT: f64 = 1e-3;

/// A world's attitude tolerance per unit of the table's `rtol = atol`
/// ([`kreisel::dynamics::table_tolerance`] takes a thousandth of it).
const ATTITUDE_PER_RTOL: f64 = 1000.0;

/// The top's state in a world: attitude, angular velocity (body axes),
/// centre of mass and its velocity.
type Start = (DQuat, DVec3, DVec3, DVec3);

/// Leine & Glocker's start: tilted by θ₀ about x, spinning at ω₀ about its
/// axis, its centre of mass at rest, the ball touching.
fn leine_glocker_start(ball: &ContactShape) -> Start {
    let q = DQuat::from_rotation_x(THETA0);
    let height = -ball.contact_from_com_world(q).z;
    (
        q,
        DVec3::new(0.0, 0.0, SPIN0),
        DVec3::new(0.0, 0.0, height),
        DVec3::ZERO,
    )
}

/// A world at time 0 holding the top with `contacts` on the table in
/// `start`, its run at `tolerance` (the table's `rtol = atol`).
///
/// # Errors
/// The library's: a tolerance or a state it refuses.
fn world_with_top(
    contacts: &[TableContact],
    tolerance: f64,
    (q, omega_body, position, velocity): Start,
) -> Result<(World, BodyId), DynamicsError> {
    let body = Body::from_principal_moments(MASS, DVec3::new(I1, I1, I3))
        .world_from_body(q)
        .omega_body(omega_body)
        .on_table(position, velocity, contacts)
        .try_build()?;
    let mut world = World::try_new(DVec3::new(0.0, 0.0, -GRAVITY), WORLD_DT)?;
    world.set_tolerance(Some(Tolerance::try_new(
        ATTITUDE_PER_RTOL * tolerance,
        MAX_DURATION,
    )?))?;
    let id = world.add(body)?;
    Ok((world, id))
}

/// The symmetry axis (towards the stem) in world axes.
pub fn axis(state: &BodyState) -> DVec3 {
    state.world_from_body.normalize() * DVec3::Z
}

/// The tilt of the symmetry axis from the vertical, rad.
pub fn tilt(state: &BodyState) -> f64 {
    axis(state).z.clamp(-1.0, 1.0).acos()
}

/// Which contacts touch the table (closed: slipping or sticking).
pub fn touching(modes: &[ContactMode]) -> [bool; 2] {
    [0, 1].map(|i| modes.get(i).is_some_and(|m| *m != ContactMode::Open))
}

/// The largest relative change of Jellett's λ about one sphere while it
/// alone touched, and how long it touched alone.
#[derive(Debug, Clone, Copy, Default)]
pub struct JellettWatch {
    /// λ when this sphere began to touch alone (None: not touching alone).
    pub start: Option<f64>,
    /// max |λ − λ_start| / |λ_start| over the phases where it touched alone.
    pub drift: f64,
    /// Time it touched alone, s.
    pub time_alone: f64,
}

/// A run in progress: the world holding the top, the instants observed
/// so far and the budgets of the energy and of Jellett's λ.
#[derive(Debug)]
pub struct Simulation {
    /// The world and the top's id in it.
    world: World,
    id: BodyId,
    /// The top's contacts and tolerance (for the bisection's worlds).
    contacts: Vec<TableContact>,
    tolerance: f64,
    /// The energy at t = 0, J.
    pub energy0: f64,
    /// The largest rise of the energy between two observed instants, J
    /// (−∞ before the first).
    pub energy_rise: f64,
    /// The times the axis passed the horizontal (either way: nutating, it
    /// goes back and forth before it stays below) while inverting, until
    /// the stem first touches, s.
    pub horizontal: Vec<f64>,
    /// Jellett's λ about the ball (#0) and the stem (#1).
    pub jellett: [JellettWatch; 2],
    /// Observed instants: (t, which contacts touch) after each, for the
    /// chart's strip.
    pub touching_history: Vec<(f64, [bool; 2])>,
    /// The energy at the last observed instant, J.
    last_energy: f64,
    /// The time of the last observed instant, s.
    last_time: f64,
}

impl Simulation {
    /// Leine & Glocker's top with its ball and its stem's ball on the
    /// table, each contact with `law`, in their start
    /// ([`leine_glocker_start`]), its run at `tolerance` (relative and
    /// absolute): observed from t = 0.
    ///
    /// # Errors
    /// The library's: a tolerance it refuses, the first events' errors.
    pub fn try_new(law: ContactLaw, tolerance: f64) -> Result<Self, DynamicsError> {
        let ball = SphereContact::try_new(BALL_RADIUS, DVec3::new(0.0, 0.0, BALL_OFFSET))?;
        let stem = SphereContact::try_new(STEM_RADIUS, DVec3::new(0.0, 0.0, STEM_OFFSET))?;
        let contacts: Vec<TableContact> = [ball, stem]
            .map(|s| TableContact {
                shape: ContactShape::Sphere(s),
                law,
            })
            .to_vec();
        let start = leine_glocker_start(&contacts[0].shape);
        let (world, id) = world_with_top(&contacts, tolerance, start)?;
        let mut sim = Self {
            world,
            id,
            contacts,
            tolerance,
            energy0: 0.0,
            energy_rise: f64::NEG_INFINITY,
            horizontal: Vec::new(),
            jellett: [JellettWatch::default(); 2],
            touching_history: Vec::new(),
            last_energy: 0.0,
            last_time: 0.0,
        };
        sim.energy0 = sim.state().energy;
        sim.last_energy = sim.energy0;
        sim.observe();
        Ok(sim)
    }

    /// The time reached, s.
    pub fn time(&self) -> f64 {
        self.world.time()
    }

    /// The top's state now, as the world reports it.
    pub fn state(&self) -> BodyState {
        self.world
            .state(self.id)
            .expect("the top is a body of its own world")
    }

    /// The top's run on the table, as the world holds it (its contact
    /// modes, the resolution of its impacts, its body's Jellett's λ).
    pub fn run(&self) -> &TableMotion {
        self.world
            .table_motion(self.id)
            .expect("the top is on the table of its own world")
    }

    /// E/E₀ now.
    pub fn energy_ratio(&self) -> f64 {
        self.state().energy / self.energy0
    }

    /// The first time the axis passed the horizontal, s.
    pub fn horizontal_at(&self) -> Option<f64> {
        self.horizontal.first().copied()
    }

    /// Which contacts touch now.
    pub fn touching(&self) -> [bool; 2] {
        touching(&self.run().modes())
    }

    /// The world's events of the top so far.
    pub fn events(&self) -> &[TableEvent] {
        self.world.events(self.id).unwrap_or_default()
    }

    /// Advances to `t` (exactly), stopping at each of the world's events
    /// on the way ([`World::advance_until_event`]) to observe the state
    /// there.
    ///
    /// # Errors
    /// The library's errors (a step that cannot be made accurate, an
    /// indeterminate contact problem).
    pub fn advance_to(&mut self, t: f64) -> Result<(), DynamicsError> {
        while self.world.time() < t {
            let before = self.state();
            self.world.advance_until_event(t)?;
            // The inversion's passages: until the stem first touches.
            let inverting = !self.touching_history.iter().any(|(_, c)| c[1]);
            if inverting && (axis(&before).z > 0.0) != (axis(&self.state()).z > 0.0) {
                let passage = self.horizontal_passage(&before, self.world.time())?;
                self.horizontal.push(passage);
            }
            self.observe();
        }
        Ok(())
    }

    /// Books the state now: the energy's rise, Jellett's λ, the contacts.
    fn observe(&mut self) {
        let (t, energy) = (self.world.time(), self.state().energy);
        if t > self.last_time || self.touching_history.is_empty() {
            self.energy_rise = self.energy_rise.max(energy - self.last_energy);
        }
        let touching = self.touching();
        let run = self.run();
        let lambda = [0, 1].map(|i| run.body().jellett(run.state(), i));
        for (i, watch) in self.jellett.iter_mut().enumerate() {
            let alone = touching[i] && !touching[1 - i];
            // Measured at the instants where it still touches alone (an
            // event that ends the phase may change λ: an impact does).
            match (watch.start, alone) {
                (Some(start), true) => {
                    watch.drift = watch.drift.max(((lambda[i] - start) / start).abs());
                    watch.time_alone += t - self.last_time;
                }
                (Some(_), false) => watch.start = None,
                (None, true) => watch.start = Some(lambda[i]),
                (None, false) => {}
            }
        }
        if self
            .touching_history
            .last()
            .is_none_or(|&(_, c)| c != touching)
        {
            self.touching_history.push((t, touching));
        }
        self.last_energy = energy;
        self.last_time = t;
    }

    /// The instant in `(before.time, t_end]` where the axis passes the
    /// horizontal (its height positive at one end, not at the other), by
    /// bisection: each trial is a world started from `before` advanced to
    /// the trial time (the run started afresh there: the same motion to
    /// the tolerance).
    ///
    /// # Errors
    /// The library's.
    fn horizontal_passage(&self, before: &BodyState, t_end: f64) -> Result<f64, DynamicsError> {
        let (mut lo, mut hi) = (before.time, t_end);
        let above_at_start = axis(before).z > 0.0;
        let start = (
            before.world_from_body,
            before.omega_body,
            before.position,
            before.velocity,
        );
        for _ in 0..BISECTIONS {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            let (mut trial, id) = world_with_top(&self.contacts, self.tolerance, start)?;
            trial.advance_to(mid - before.time)?;
            let above = trial.state(id).is_some_and(|s| axis(&s).z > 0.0);
            if above == above_at_start {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Ok(hi)
    }
}
