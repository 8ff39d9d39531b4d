//! The tippe top of Leine & Glocker (2003) on the library's
//! [`GroundTop`], stepped by its RK4 with lift-off and the stem ball's
//! touchdown reported, and what the demo observes along the way: the tilt
//! θ, the energy, Jellett's λ, the inversion instant and the instant the
//! stem's ball reaches the floor.

use glam::{DMat3, DQuat, DVec2, DVec3};
use kreisel::dynamics::{
    ContactShape, DynamicsError, Friction, GroundTop, GroundTopState, SphereContact,
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
/// Radius of the stem's ball, m (drawn, and watched for touchdown: its
/// contact force is not modelled).
pub const STEM_RADIUS: f64 = 0.005;
/// Distance from the centre of mass to the stem ball's centre, m.
pub const STEM_OFFSET: f64 = 0.016;
/// Initial tilt of the symmetry axis from the vertical, rad.
pub const THETA0: f64 = 0.1;
/// Initial spin about the symmetry axis, rad/s.
pub const SPIN0: f64 = 180.0;
/// Gravity, m/s².
pub const GRAVITY: f64 = 9.81;

/// Bisection steps that locate the inversion inside an RK4 step (2⁻⁵⁰ of it).
const BISECTIONS: usize = 50;

/// Leine & Glocker's top with `friction`, tilted by θ₀ about x, spinning
/// at ω₀ about its axis, touching the floor: centre of mass at rest, or,
/// rolling, moving so that the contact point is at rest. The stem's ball
/// is watched for touchdown ([`GroundTop::try_with_other_contacts`]).
///
/// # Errors
/// [`DynamicsError::InvalidContact`] for bad friction parameters.
pub fn leine_glocker(friction: Friction) -> Result<(GroundTop, GroundTopState), DynamicsError> {
    let ball = SphereContact::try_new(BALL_RADIUS, DVec3::new(0.0, 0.0, BALL_OFFSET))?;
    let stem = SphereContact::try_new(STEM_RADIUS, DVec3::new(0.0, 0.0, STEM_OFFSET))?;
    let inertia = DMat3::from_diagonal(DVec3::new(I1, I1, I3));
    let top = GroundTop::try_new(MASS, inertia, ball, friction, GRAVITY)?
        .try_with_other_contacts(&[ContactShape::Sphere(stem)])?;
    let q = DQuat::from_rotation_x(THETA0);
    let omega = q * DVec3::new(0.0, 0.0, SPIN0);
    let start = match friction {
        Friction::Rolling => top.try_rolling_state_on_ground(q, omega)?,
        _ => top.try_state_on_ground(q, omega, DVec2::ZERO)?,
    };
    Ok((top, start))
}

/// The symmetry axis (towards the stem) in world axes.
pub fn axis(state: &GroundTopState) -> DVec3 {
    state.world_from_body.normalize() * DVec3::Z
}

/// The tilt of the symmetry axis from the vertical, rad.
pub fn tilt(state: &GroundTopState) -> f64 {
    axis(state).z.clamp(-1.0, 1.0).acos()
}

/// What has happened so far.
#[derive(Debug, Clone, Copy, Default)]
pub struct Events {
    /// The first time the axis passed the horizontal going down, s.
    pub inverted_at: Option<f64>,
    /// The time the stem's ball reached the floor (the library's
    /// [`DynamicsError::ContactTouchdown`]) and the tilt then, s and rad.
    pub stem_touch: Option<(f64, f64)>,
    /// When the ball left the floor (the run stops there), s.
    pub lift_off: Option<f64>,
}

/// A run in progress: the state, the time, the events and the drift of
/// the invariants.
#[derive(Debug, Clone)]
pub struct Simulation {
    /// The top, watching its stem's ball.
    pub top: GroundTop,
    /// The same top on its ball alone, stepped once the stem has touched
    /// down (the demo goes on without modelling the stem's contact).
    pub ball_only: GroundTop,
    /// The current state.
    pub state: GroundTopState,
    /// The current time, s.
    pub time: f64,
    /// The step, s.
    pub dt: f64,
    /// What has happened so far.
    pub events: Events,
    /// The energy and Jellett's λ at t = 0.
    pub energy0: f64,
    /// See [`Simulation::energy0`].
    pub jellett0: f64,
    /// max |λ − λ₀| / |λ₀| so far.
    pub jellett_drift: f64,
    /// The largest one-step rise of the energy so far, relative to E₀
    /// (negative: it fell in every step).
    pub energy_rise: f64,
    steps: u64,
}

impl Simulation {
    /// A run of `top` from `start` at t = 0 in steps of `dt`.
    ///
    /// # Errors
    /// None in practice (an empty list of further contacts is accepted).
    pub fn new(top: GroundTop, start: GroundTopState, dt: f64) -> Result<Self, DynamicsError> {
        Ok(Self {
            ball_only: top.clone().try_with_other_contacts(&[])?,
            state: start,
            time: 0.0,
            dt,
            events: Events::default(),
            energy0: top.energy(&start),
            jellett0: top.jellett(&start),
            top,
            jellett_drift: 0.0,
            energy_rise: f64::NEG_INFINITY,
            steps: 0,
        })
    }

    /// Whether the ball has left the floor (nothing more to step).
    pub fn stopped(&self) -> bool {
        self.events.lift_off.is_some()
    }

    /// The relative change of Jellett's λ now: (λ − λ₀)/|λ₀|.
    pub fn jellett_change(&self) -> f64 {
        (self.top.jellett(&self.state) - self.jellett0) / self.jellett0.abs()
    }

    /// The top being stepped: watching the stem until it touches down,
    /// the ball alone after.
    fn active(&self) -> &GroundTop {
        if self.events.stem_touch.is_none() {
            &self.top
        } else {
            &self.ball_only
        }
    }

    /// One RK4 step of `dt` (nothing after a lift-off). The inversion is
    /// located inside the step by bisection on the step size: the RK4 step
    /// of size τ from the step's start (the method's own continuation) is
    /// bisected for the sign change of the axis' height. When the library
    /// reports the stem's touchdown, its time and the tilt there are
    /// recorded and the step is taken again from its start on the ball
    /// alone (the same RK4 step: the trajectory is the ball-only one).
    ///
    /// # Errors
    /// The library's errors other than a lift-off (which is recorded in
    /// [`Events::lift_off`] and stops the run) and the stem's touchdown.
    pub fn step(&mut self) -> Result<(), DynamicsError> {
        if self.stopped() {
            return Ok(());
        }
        let before = self.state;
        let (t0, e_before) = (self.time, self.top.energy(&before));
        let mut state = self.state;
        let mut result = self.active().try_step(&mut state, t0, self.dt);
        self.state = state;
        if let Err(DynamicsError::ContactTouchdown { time, .. }) = result {
            self.events.stem_touch = Some((time, tilt(&self.state)));
            self.state = before;
            result = self.ball_only.try_step(&mut self.state, t0, self.dt);
        }
        match result {
            Ok(()) => {}
            Err(DynamicsError::ContactLost { time, .. }) => {
                self.events.lift_off = Some(time);
                return Ok(());
            }
            Err(e) => return Err(e),
        }
        self.steps += 1;
        self.time = self.steps as f64 * self.dt;
        let e = self.top.energy(&self.state);
        self.energy_rise = self.energy_rise.max((e - e_before) / self.energy0);
        self.jellett_drift = self.jellett_drift.max(self.jellett_change().abs());
        if self.events.inverted_at.is_none() && axis(&before).z > 0.0 && axis(&self.state).z <= 0.0
        {
            self.events.inverted_at = Some(t0 + self.crossing_in(&before, t0)?);
        }
        Ok(())
    }

    /// The τ ∈ (0, dt] where the axis' height along the RK4 step from
    /// `before` (at `t0`) reaches zero: positive at 0, not positive at dt.
    fn crossing_in(&self, before: &GroundTopState, t0: f64) -> Result<f64, DynamicsError> {
        let (mut lo, mut hi) = (0.0, self.dt);
        for _ in 0..BISECTIONS {
            let mid = 0.5 * (lo + hi);
            let mut s = *before;
            self.ball_only.try_step(&mut s, t0, mid)?;
            if axis(&s).z > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Ok(0.5 * (lo + hi))
    }
}
