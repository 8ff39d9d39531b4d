//! The tippe top of Leine & Glocker (2003) with its stem, run by the
//! library's nonsmooth engine ([`TableMotion`]: ball and stem as unilateral
//! contacts, Coulomb–Contensou friction, impacts), and what the demo
//! observes along the way: the tilt θ, the energy, Jellett's λ about the
//! touching sphere, the axis' passage through the horizontal, and the
//! library's own events.

use glam::{DMat3, DQuat, DVec2, DVec3};
use kreisel::dynamics::{
    AdaptiveTolerance, ContactLaw, ContactMode, ContactShape, DynamicsError, Friction, GroundTop,
    GroundTopState, SphereContact, TableBody, TableContact, TableEvent, TableMotion,
};

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

/// Leine & Glocker's top with its ball and its stem's ball on the table,
/// each contact with `law`, tilted by θ₀ about x, spinning at ω₀ about its
/// axis, its centre of mass at rest, the ball touching: the library's
/// nonsmooth run at `tolerance` (relative and absolute).
///
/// # Errors
/// The library's: a tolerance it refuses, the first events' errors.
pub fn leine_glocker(law: ContactLaw, tolerance: f64) -> Result<TableMotion, DynamicsError> {
    let inertia = DMat3::from_diagonal(DVec3::new(I1, I1, I3));
    let ball = SphereContact::try_new(BALL_RADIUS, DVec3::new(0.0, 0.0, BALL_OFFSET))?;
    let stem = SphereContact::try_new(STEM_RADIUS, DVec3::new(0.0, 0.0, STEM_OFFSET))?;
    let contacts = [ball, stem]
        .map(|s| TableContact {
            shape: ContactShape::Sphere(s),
            law,
        })
        .to_vec();
    let body = TableBody::try_new(MASS, inertia, contacts, GRAVITY)?;
    // The start on the ball: GroundTop's placement (the ball touching, the
    // centre of mass at rest).
    let placer = GroundTop::try_new(MASS, inertia, ball, Friction::None, GRAVITY)?;
    let q = DQuat::from_rotation_x(THETA0);
    let start = placer.try_state_on_ground(q, q * DVec3::new(0.0, 0.0, SPIN0), DVec2::ZERO)?;
    TableMotion::try_new(
        body,
        start,
        AdaptiveTolerance::try_new(tolerance, tolerance)?,
    )
}

/// The symmetry axis (towards the stem) in world axes.
pub fn axis(state: &GroundTopState) -> DVec3 {
    state.world_from_body.normalize() * DVec3::Z
}

/// The tilt of the symmetry axis from the vertical, rad.
pub fn tilt(state: &GroundTopState) -> f64 {
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

/// A run in progress: the library's motion, the instants observed so far
/// and the budgets of the energy and of Jellett's λ.
#[derive(Debug, Clone)]
pub struct Simulation {
    /// The library's run.
    pub run: TableMotion,
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
    /// Starts observing `run` (at t = 0).
    pub fn new(run: TableMotion) -> Self {
        let energy0 = run.body().energy(run.state());
        let mut sim = Self {
            energy0,
            energy_rise: f64::NEG_INFINITY,
            horizontal: Vec::new(),
            jellett: [JellettWatch::default(); 2],
            touching_history: Vec::new(),
            last_energy: energy0,
            last_time: 0.0,
            run,
        };
        sim.observe();
        sim
    }

    /// The time reached, s.
    pub fn time(&self) -> f64 {
        self.run.time()
    }

    /// The state now.
    pub fn state(&self) -> &GroundTopState {
        self.run.state()
    }

    /// E/E₀ now.
    pub fn energy_ratio(&self) -> f64 {
        self.run.body().energy(self.run.state()) / self.energy0
    }

    /// The first time the axis passed the horizontal, s.
    pub fn horizontal_at(&self) -> Option<f64> {
        self.horizontal.first().copied()
    }

    /// Which contacts touch now.
    pub fn touching(&self) -> [bool; 2] {
        touching(&self.run.modes())
    }

    /// The library's events so far.
    pub fn events(&self) -> &[TableEvent] {
        self.run.events()
    }

    /// Advances to `t` (exactly), stopping at each of the library's events
    /// on the way to observe the state there.
    ///
    /// # Errors
    /// The library's errors (a step that cannot be made accurate, an
    /// indeterminate contact problem).
    pub fn advance_to(&mut self, t: f64) -> Result<(), DynamicsError> {
        while self.run.time() < t {
            let before = self.run.clone();
            self.run.try_advance_until_event(t)?;
            // The inversion's passages: until the stem first touches.
            let inverting = !self.touching_history.iter().any(|(_, c)| c[1]);
            if inverting && (axis(before.state()).z > 0.0) != (axis(self.run.state()).z > 0.0) {
                self.horizontal
                    .push(horizontal_passage(before, self.run.time())?);
            }
            self.observe();
        }
        Ok(())
    }

    /// Books the state now: the energy's rise, Jellett's λ, the contacts.
    fn observe(&mut self) {
        let (t, state) = (self.run.time(), *self.run.state());
        let energy = self.run.body().energy(&state);
        if t > self.last_time || self.touching_history.is_empty() {
            self.energy_rise = self.energy_rise.max(energy - self.last_energy);
        }
        let touching = self.touching();
        for (i, watch) in self.jellett.iter_mut().enumerate() {
            let lambda = self.run.body().jellett(&state, i);
            let alone = touching[i] && !touching[1 - i];
            // Measured at the instants where it still touches alone (an
            // event that ends the phase may change λ: an impact does).
            match (watch.start, alone) {
                (Some(start), true) => {
                    watch.drift = watch.drift.max(((lambda - start) / start).abs());
                    watch.time_alone += t - self.last_time;
                }
                (Some(_), false) => watch.start = None,
                (None, true) => watch.start = Some(lambda),
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
}

/// The instant in `(before.time(), t_end]` where the axis passes the
/// horizontal (its height positive at one end, not at the other), by
/// bisection: each trial is the library's run from `before` to the trial
/// time.
///
/// # Errors
/// The library's.
fn horizontal_passage(before: TableMotion, t_end: f64) -> Result<f64, DynamicsError> {
    let (mut lo, mut hi) = (before.time(), t_end);
    let above_at_start = axis(before.state()).z > 0.0;
    for _ in 0..BISECTIONS {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        let mut trial = before.clone();
        trial.try_advance_to(mid)?;
        if (axis(trial.state()).z > 0.0) == above_at_start {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(hi)
}
