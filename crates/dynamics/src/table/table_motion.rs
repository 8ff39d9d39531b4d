//! [`TableMotion`]: a [`TableBody`] run from any start through sliding,
//! sticking, lifting off, flying, landing and bouncing — event-driven:
//! Dormand–Prince 5(4) with error control between events, each event
//! located in its step, impacts and mode changes solved there.
//!
//! ```text
//! between events:  ẏ = f(y; modes),  y = (r_G, v_G, q, L)     (contact_problem::mode_forces)
//!                  local error ≤ atol·s + rtol·|y| per component (AdaptiveTolerance)
//! an event in a step (end of the trial, or a dip of a gap's cubic Hermite inside it):
//!     open contact:      g < 0 while ġ < 0           → touchdown (impact when −ġ > v_res)
//!     closed contact:    N < 0                        → lift-off
//!     sticking contact:  |x_T| > μ N                  → slip
//!     slipping contact:  γ_T · d₀ < 0 (slip reversed)  → stick (if the cone holds it)
//! located by bisection on the step's length to a few ulps of t;
//! there: impact (impact::impact), then the modes (contact_problem::solve_blocks)
//! ```
//!
//! While every contact is open the body flies exactly — the centre of
//! mass on its parabola, the rotation the torque-free
//! [`crate::ExactSolution`] from the lift-off — and the gaps are checked
//! at least every 1/16 rad of turn (their cubic Hermite between checks).
//!
//! Method: the event-driven integration of Pfeiffer & Glocker
//! (*Multibody Dynamics with Unilateral Contacts*, 1996) with the
//! acceleration-level contact problem solved as in Studer & Glocker (Acta
//! Mech. 2006), Newton's impact law as in Glocker (2001). Between events
//! the motion is smooth and the Dormand–Prince pair (order 5) meets the
//! tolerance; events are located to rounding, so the order holds through
//! them (measured in `tests/table_*.rs`). Nothing is projected or
//! renormalised between events; at an event the impact law sets the
//! velocities and a contact that starts to stick has its residual slip
//! (below the resolution speed) removed by a tangential impulse, which
//! only dissipates.

use glam::{DQuat, DVec3};

use super::contact_block::{Block, Rolling};
use super::contact_frame::{ContactFrame, ContactRow};
use super::contact_problem::{
    ContactMode, Mode, ModeForces, mode_forces, roll_direction, slip_direction,
};
use super::face::FaceSlide;
use super::impact::{at_time, face_impact, impact, rim_flip_impact, stop_slip};
use super::rolling_resistance::solve_with_rolling;
use super::{TableBody, TableEvent, TableEventKind};
use crate::contact::{DOPRI_A, DOPRI_B_HAT, DOPRI_C, Flight, MAX_GROWTH, MIN_SHRINK, SAFETY};
use crate::{AdaptiveStats, AdaptiveTolerance, ContactShape, DynamicsError, GroundTopState};

/// The method's name in errors.
const METHOD: &str = "table dopri5";

/// The resolution speed, relative to the body's speed scale: slips and
/// approach speeds below it are zero.
pub const TABLE_RESOLUTION: f64 = 1e-9;

/// The rebound speed, relative to the body's speed scale, below which a
/// contact's bounces are summed rather than followed: the bounces then
/// accumulate within `2 e v/(a (1 − e))` (a few 10⁻⁴ s for a body of a
/// few cm), while following them would time each impact by gaps of a few
/// ulps (a ball's 10⁻¹⁷ m gap resolution at 10⁻⁵ m/s puts each impact
/// 10⁻¹² s off and the accumulation point 10⁻⁹ s off; measured in
/// `tests/table_bouncing_ball.rs`).
pub const TABLE_ACCUMULATION: f64 = 1e-4;

/// The sine of the smallest tilt of a disk rim's axis from the vertical
/// the rim contact follows: below it a touching disk lies flat (it lands
/// on its face, or rocks on through flat when its face arrives fast; see
/// [`FACE_LANDING`]).
pub const DISK_FLAT_TILT: f64 = 1e-6;

/// The slip speed, relative to the body's speed scale, at the default
/// tolerance and above, below which a slipping contact's friction keeps the
/// direction it had when the slip entered the band (or the consistent
/// direction a slip starts along) instead of following `γ_T/|γ_T|`: that
/// direction turns at a rate `~ μ N W/|γ_T|`, so following it at tiny
/// slips makes the motion stiff (steps of 10⁻¹⁰ s where the friction sits
/// on the cone's edge, measured on Euler's disk starting to slip). The
/// slip entering the band is an event; a slip that reverses inside it
/// sticks. The band is an approximation of the law, so it shrinks with the
/// tolerance and the answer converges as the tolerance tightens:
///
/// ```text
/// band = clamp(SLIP_BAND · rtol / 10⁻¹⁰, TABLE_RESOLUTION, SLIP_BAND) · speed scale
/// ```
///
/// — `SLIP_BAND` at the default rtol 10⁻¹⁰ and above (a wider band at a
/// looser tolerance moved the thrown ellipsoid's events at rtol 10⁻⁸ by
/// 1.8·10⁻⁷ s against 2.9·10⁻⁸ s with this one). Over the band's outer
/// half the direction passes over from the slip's own to the kept one,
/// so the friction is continuous at the edge (a slip hovering there
/// while its direction turned made the right-hand side jump, and the
/// error control took steps of 10⁻⁹ s).
pub const SLIP_BAND: f64 = 1e-6;

/// The speed, relative to the body's speed scale, below which a disk
/// rim that reaches flat lands on its face (a plastic landing): its face's
/// normal velocities `|v_z| + a |ω × n|` below it. Faster, the rim rocks
/// on through flat (its far point strikes, `impact::rim_flip_impact`).
/// The last rocking the landing stops holds below 10⁻⁴ of the body's
/// energy scale `m g ℓ`. A face closing from flight with restitution
/// `e > 0` strikes at any speed (Newton's law over the face).
pub const FACE_LANDING: f64 = 1e-2;

/// The smallest step, relative to `max(|t|, τ)` (`τ = √(ℓ/g)`).
const MIN_STEP_RELATIVE: f64 = 1e-14;

/// Events in a row at one instant before the modes are called chattering.
const MAX_EVENTS_IN_PLACE: usize = 64;

/// How many events within [`CREEP`] of time, each leaving the modes as
/// they were, make a chatter: the decision and the predicates disagree (a
/// decision on the cone's edge, or two slips starting in directions that
/// do not agree), and the run would creep on by 1e-13 s per event for
/// ever (a random throw took 10⁵ such events per second of wall time).
const MAX_CREEPING_EVENTS: usize = 1000;

/// The span of time, relative to the time scale, within which
/// [`MAX_CREEPING_EVENTS`] make a chatter.
const CREEP: f64 = 1e-8;

/// The time derivative of a state.
#[derive(Debug, Clone, Copy)]
struct Derivative {
    d_com: DVec3,
    d_velocity: DVec3,
    d_attitude: DQuat,
    d_l: DVec3,
}

/// A state with its derivative, forces and contact frame (what the
/// event predicates read).
#[derive(Debug, Clone)]
struct Snapshot {
    state: GroundTopState,
    derivative: Derivative,
    forces: ModeForces,
    frame: ContactFrame,
}

/// A trial step: its end and its error norm.
struct Trial {
    end: Snapshot,
    error: f64,
}

/// A body on the table moving through its contact events.
///
/// ```
/// use glam::{DMat3, DQuat, DVec3};
/// use kreisel_dynamics::{
///     AdaptiveTolerance, ContactLaw, ContactShape, GroundTopState, SphereContact, TableBody,
///     TableContact, TableEventKind, TableMotion,
/// };
/// // A ball dropped from 1 m (centre), e = 0.9: the first impact at √(2 · 0.9/9.81) s.
/// let shape = ContactShape::Sphere(SphereContact::try_new(0.1, DVec3::ZERO)?);
/// let law = ContactLaw::new(0.0).try_with_restitution(0.9)?;
/// let body = TableBody::try_new(1.0, DMat3::from_diagonal(DVec3::splat(0.004)),
///     vec![TableContact { shape, law }], 9.81)?;
/// let start = GroundTopState { com_world: DVec3::new(0.0, 0.0, 1.0), velocity_world: DVec3::ZERO,
///     world_from_body: DQuat::IDENTITY, l_world: DVec3::ZERO };
/// let mut run = TableMotion::try_new(body, start, AdaptiveTolerance::new(1e-10, 1e-10))?;
/// run.try_advance_to(0.5)?;
/// let first = run.events()[0];
/// assert!(matches!(first.kind, TableEventKind::Impact { .. }));
/// assert!((first.time - (2.0 * 0.9 / 9.81f64).sqrt()).abs() < 1e-12);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone)]
pub struct TableMotion {
    body: TableBody,
    tolerance: AdaptiveTolerance,
    time: f64,
    current: Snapshot,
    modes: Vec<Mode>,
    events: Vec<TableEvent>,
    /// The next step to try, s.
    h: f64,
    /// Error weights of the 13 components (the body's units).
    scales: [f64; 13],
    /// `ℓ`, m; `√(g ℓ)`-based speed scale, m/s; `τ = √(ℓ/g)`, s.
    length: f64,
    speed: f64,
    time_scale: f64,
    resting: bool,
    /// While every contact is open: the exact flight and when it began.
    flight: Option<(f64, Flight)>,
    /// The latest accumulation point of bounces, s (the body rests no
    /// earlier).
    accumulation: f64,
    /// A disk on its face, once one lands flat.
    face: Option<FaceSlide>,
    /// While set, [`TableMotion::resolve`] decides every mode afresh (no
    /// contact kept slipping along its slip).
    afresh: bool,
    stats: AdaptiveStats,
}

/// `s + h Σ wᵢ kᵢ`.
fn combine(s: &GroundTopState, ks: &[Derivative], weights: &[f64], h: f64) -> GroundTopState {
    let mut out = *s;
    for (k, &w) in ks.iter().zip(weights) {
        if w != 0.0 {
            let f = w * h;
            out.com_world += k.d_com * f;
            out.velocity_world += k.d_velocity * f;
            out.world_from_body += k.d_attitude * f;
            out.l_world += k.d_l * f;
        }
    }
    out
}

/// The 13 components of a state.
fn flat(s: &GroundTopState) -> [f64; 13] {
    let (r, v, q, l) = (s.com_world, s.velocity_world, s.world_from_body, s.l_world);
    [
        r.x, r.y, r.z, v.x, v.y, v.z, q.w, q.x, q.y, q.z, l.x, l.y, l.z,
    ]
}

impl TableMotion {
    /// The body in `state` at `t = 0`, with the contacts that touch closed
    /// (an impact first where one approaches the table) and their modes
    /// found.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidState`] for a state that is not finite;
    /// [`DynamicsError::BodyInsideTable`] for a contact below the plane
    /// (beyond `10⁻⁹ ℓ`); the errors of the first events
    /// ([`DynamicsError::ContactIndeterminate`],
    /// [`DynamicsError::ImpactGainsEnergy`]).
    pub fn try_new(
        body: TableBody,
        state: GroundTopState,
        tolerance: AdaptiveTolerance,
    ) -> Result<Self, DynamicsError> {
        if !state.is_valid() {
            return Err(DynamicsError::InvalidState {
                reason: "the table body's state is not finite",
            });
        }
        let length = body.length_scale();
        let g = body.gravity();
        let frame = ContactFrame::of(&body, &state, 0.0);
        for (i, row) in frame.rows.iter().enumerate() {
            if row.gap < -1e-9 * length {
                return Err(DynamicsError::BodyInsideTable {
                    contact: i,
                    gap: row.gap,
                });
            }
        }
        let omega = frame.omega;
        let speed = (g * length)
            .sqrt()
            .max(state.velocity_world.length())
            .max(omega.length() * length);
        let time_scale = (length / g).sqrt();
        let i_max = body
            .inertia_body()
            .to_cols_array()
            .into_iter()
            .fold(0.0, f64::max);
        let s = [length, speed, 1.0, i_max * speed / length];
        let mut scales = [0.0; 13];
        for (k, v) in scales.iter_mut().enumerate() {
            *v = s[match k {
                0..=2 => 0,
                3..=5 => 1,
                6..=9 => 2,
                _ => 3,
            }];
        }
        let modes = vec![Mode::OPEN; body.contacts().len()];
        let band = slip_band(tolerance, speed);
        let current = Self::snapshot_of(&body, &modes, state, 0.0, band)?;
        let mut run = Self {
            body,
            tolerance,
            time: 0.0,
            current,
            modes,
            events: Vec::new(),
            h: 1e-3 * time_scale,
            scales,
            length,
            speed,
            time_scale,
            resting: false,
            flight: None,
            accumulation: f64::NEG_INFINITY,
            face: None,
            afresh: false,
            stats: AdaptiveStats::default(),
        };
        run.settle()?;
        Ok(run)
    }

    /// The body.
    pub fn body(&self) -> &TableBody {
        &self.body
    }

    /// The time reached, s.
    pub fn time(&self) -> f64 {
        self.time
    }

    /// The state at [`TableMotion::time`].
    pub fn state(&self) -> &GroundTopState {
        &self.current.state
    }

    /// Each contact's mode now.
    pub fn modes(&self) -> Vec<ContactMode> {
        self.modes.iter().map(|m| m.mode).collect()
    }

    /// Each contact's normal force now, N (0 when open; a disk on its
    /// face carries `m g`).
    pub fn normal_forces(&self) -> Vec<f64> {
        let mut normal = self.current.forces.normal[..self.modes.len()].to_vec();
        if let Some(face) = &self.face {
            normal.iter_mut().for_each(|n| *n = 0.0);
            normal[face.contact] = self.body.mass() * self.body.gravity();
        }
        normal
    }

    /// The disk contact whose face the body lies on, if it does.
    pub fn lying_flat_on(&self) -> Option<usize> {
        self.face.as_ref().map(|f| f.contact)
    }

    /// The events so far, in time order.
    pub fn events(&self) -> &[TableEvent] {
        &self.events
    }

    /// Whether the body has come to rest (it stays there).
    pub fn is_resting(&self) -> bool {
        self.resting
    }

    /// Steps accepted and rejected, evaluations of the vector field (the
    /// slide on a face included).
    pub fn stats(&self) -> AdaptiveStats {
        let mut stats = self.stats;
        if let Some(face) = &self.face {
            stats.accepted += face.stats.accepted;
            stats.rejected += face.stats.rejected;
            stats.evaluations += face.stats.evaluations;
        }
        stats
    }

    /// The resolution speed `v_res`, m/s: [`TABLE_RESOLUTION`] times the
    /// body's speed scale `max(√(g ℓ), |v_G|, |ω| ℓ)` at the start.
    pub fn resolution_speed(&self) -> f64 {
        TABLE_RESOLUTION * self.speed
    }

    /// The slip band, m/s ([`SLIP_BAND`]).
    fn band(&self) -> f64 {
        slip_band(self.tolerance, self.speed)
    }

    /// The derivative, forces and frame of `state` in `modes` (slips
    /// within `band` along their modes' directions).
    fn snapshot_of(
        body: &TableBody,
        modes: &[Mode],
        state: GroundTopState,
        t: f64,
        band: f64,
    ) -> Result<Snapshot, DynamicsError> {
        let frame = ContactFrame::of(body, &state, t);
        let forces = mode_forces(&frame, modes, band)?;
        let q = state.world_from_body;
        let w = frame.omega;
        let derivative = Derivative {
            d_com: state.velocity_world,
            d_velocity: forces.velocity_rate,
            d_attitude: DQuat::from_xyzw(w.x, w.y, w.z, 0.0) * q * 0.5,
            d_l: forces.l_rate,
        };
        Ok(Snapshot {
            state,
            derivative,
            forces,
            frame,
        })
    }

    /// [`TableMotion::snapshot_of`] in the current modes at time `t`.
    fn snapshot(&self, state: GroundTopState, t: f64) -> Result<Snapshot, DynamicsError> {
        Self::snapshot_of(&self.body, &self.modes, state, t, self.band())
    }

    /// One Dormand–Prince trial of length `h` from the current state.
    fn trial(&mut self, h: f64) -> Result<Trial, DynamicsError> {
        if let Some((start, flight)) = &self.flight {
            let state = flight.at(self.time + h - start);
            self.stats.evaluations += 1;
            let end = self.snapshot(state, self.time + h)?;
            return Ok(Trial { end, error: 0.0 });
        }
        let s0 = self.current.state;
        let mut k = [self.current.derivative; 7];
        let mut stage = |k: &[Derivative], i: usize| {
            let state = combine(&s0, &k[..i], &DOPRI_A[i][..i], h);
            self.stats.evaluations += 1;
            self.snapshot(state, self.time + DOPRI_C[i] * h)
        };
        for i in 1..6 {
            k[i] = stage(&k, i)?.derivative;
        }
        // FSAL: stage 7 is the fifth-order solution itself.
        let end = stage(&k, 6)?;
        k[6] = end.derivative;
        let (y0, y1) = (flat(&s0), flat(&end.state));
        let low = flat(&combine(&s0, &k, &DOPRI_B_HAT, h));
        let mut error: f64 = 0.0;
        for c in 0..13 {
            let bound = self.tolerance.atol() * self.scales[c]
                + self.tolerance.rtol() * y0[c].abs().max(y1[c].abs());
            error = error.max((y1[c] - low[c]).abs() / bound);
        }
        Ok(Trial { end, error })
    }

    /// Whether an event happened between the current snapshot and `end`
    /// (a trial of length `h`).
    fn event_in(&self, end: &Snapshot, h: f64) -> bool {
        let start = &self.current;
        let floor = self.resolution_speed();
        let band = self.band();
        for (i, mode) in self.modes.iter().enumerate() {
            let (r0, r1) = (&start.frame.rows[i], &end.frame.rows[i]);
            match mode.mode {
                ContactMode::Open => {
                    // A crossing of the plane; or, from a start already
                    // below it by drift, sinking faster than the resolution.
                    let crossed = r0.gap >= 0.0 && r1.gap < 0.0 && r1.velocity[0] < 0.0;
                    let sinking = r1.gap < r0.gap.min(0.0) && r1.velocity[0] < -floor;
                    if crossed || sinking {
                        return true;
                    }
                    if dips_below(r0.gap, r0.velocity[0], r1.gap, r1.velocity[0], h) {
                        return true;
                    }
                }
                ContactMode::Sticking | ContactMode::Slipping => {
                    let n = end.forces.normal[i];
                    if n < 0.0 || self.rim_side(i, &end.state) < 0.0 {
                        return true;
                    }
                    let friction = end.forces.friction[i].length();
                    if mode.mode == ContactMode::Sticking && friction > r1.mu * n {
                        return true;
                    }
                    // The slip reversed, or crossed the edge of the band
                    // within which its direction is held (SLIP_BAND).
                    if mode.mode == ContactMode::Slipping
                        && r1.friction_dimensions > 0
                        && (progress(r0, r1, mode, floor, band, Along::Slip) < 0.0
                            || crosses_band(r0.slip(), r1.slip(), band))
                    {
                        return true;
                    }
                    // The same for the rolling under a rolling resistance.
                    let rolling = end.forces.rolling[i].length();
                    if r1.rolls
                        && match mode.roll {
                            ContactMode::Sticking => rolling > n,
                            ContactMode::Slipping => {
                                progress(r0, r1, mode, floor, band, Along::Roll) < 0.0
                                    || crosses_band(r0.roll(), r1.roll(), band)
                            }
                            ContactMode::Open => false,
                        }
                    {
                        return true;
                    }
                }
            }
        }
        false
    }

    /// Advances to time `t_end` (exactly; the last step shortened),
    /// recording events on the way.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidInterval`] for `t_end` before now or not
    /// finite; [`DynamicsError::StepTooSmall`] when the error control
    /// needs a step below `10⁻¹⁴ max(t, τ)`; the errors of the events
    /// ([`DynamicsError::ContactIndeterminate`] — Painlevé —,
    /// [`DynamicsError::ImpactGainsEnergy`],
    /// [`DynamicsError::ContactModesChatter`]); [`DynamicsError::DiskFlat`]
    /// when a disk lands flat whose face cannot hold it flat or that has
    /// inputs. The motion keeps the last state reached.
    pub fn try_advance_to(&mut self, t_end: f64) -> Result<(), DynamicsError> {
        self.advance(t_end, false).map(|_| ())
    }

    /// Advances to the next event or to `t_end`, whichever comes first:
    /// `true` when it stopped at an event (the state is the one just after
    /// it, [`TableMotion::events`] ends with it).
    ///
    /// # Errors
    /// As [`TableMotion::try_advance_to`].
    ///
    /// ```
    /// use glam::{DMat3, DQuat, DVec3};
    /// use kreisel_dynamics::{
    ///     AdaptiveTolerance, ContactLaw, ContactShape, GroundTopState, SphereContact, TableBody,
    ///     TableContact, TableMotion,
    /// };
    /// let shape = ContactShape::Sphere(SphereContact::try_new(0.1, DVec3::ZERO)?);
    /// let body = TableBody::try_new(1.0, DMat3::from_diagonal(DVec3::splat(0.004)),
    ///     vec![TableContact { shape, law: ContactLaw::new(0.0) }], 9.81)?;
    /// let start = GroundTopState { com_world: DVec3::new(0.0, 0.0, 0.2), velocity_world: DVec3::ZERO,
    ///     world_from_body: DQuat::IDENTITY, l_world: DVec3::ZERO };
    /// let mut run = TableMotion::try_new(body, start, AdaptiveTolerance::new(1e-10, 1e-10))?;
    /// assert!(run.try_advance_until_event(1.0)?);
    /// // A plastic landing after falling 0.1 m.
    /// assert!((run.time() - (0.2 / 9.81f64).sqrt()).abs() < 1e-12);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_advance_until_event(&mut self, t_end: f64) -> Result<bool, DynamicsError> {
        self.advance(t_end, true)
    }

    /// The loop of [`TableMotion::try_advance_to`], stopping after the
    /// first event when `stop_at_event`.
    fn advance(&mut self, t_end: f64, stop_at_event: bool) -> Result<bool, DynamicsError> {
        if !(t_end.is_finite() && t_end >= self.time) {
            return Err(DynamicsError::InvalidInterval {
                t0: self.time,
                t_end,
            });
        }
        let mut in_place = 0;
        // Decisions in a row that changed no mode, and when the first was.
        let mut creep = (0, f64::NAN);
        // When the modes were last decided afresh for a step too small.
        let mut afresh_at = f64::NAN;
        while self.time < t_end {
            if self.resting {
                self.time = t_end;
                break;
            }
            if let Some(face) = &mut self.face {
                let stopped = face.advance(t_end)?;
                self.time = face.time().max(self.time);
                self.current.state = face.state();
                if let Some(t) = stopped {
                    self.time = t;
                    self.modes[face.contact].mode = ContactMode::Sticking;
                    self.events.push(TableEvent {
                        time: t,
                        contact: Some(face.contact),
                        kind: TableEventKind::Stick,
                    });
                    self.resting = true;
                    self.events.push(TableEvent {
                        // No earlier than the face's bounces accumulate.
                        time: t.max(self.accumulation),
                        contact: None,
                        kind: TableEventKind::Rest,
                    });
                    if stop_at_event {
                        return Ok(true);
                    }
                }
                continue;
            }
            let remaining = t_end - self.time;
            if let Some((_, flight)) = &self.flight {
                // The gaps are checked at least every 1/16 rad of turn.
                if flight.fastest_turn > 0.0 {
                    self.h = self.h.min(1.0 / (16.0 * flight.fastest_turn));
                }
            }
            let last = self.h >= remaining;
            let h = if last { remaining } else { self.h };
            let min = MIN_STEP_RELATIVE * self.time.abs().max(self.time_scale);
            let trial = match self.trial(h) {
                Ok(t) => t,
                Err(DynamicsError::ContactIndeterminate { .. }) if h > min => {
                    // A stage beyond an event may be indeterminate: shorter.
                    self.stats.rejected += 1;
                    self.h = h * MIN_SHRINK;
                    continue;
                }
                Err(DynamicsError::ContactIndeterminate { .. }) if !self.afresh => {
                    // No step holds the slip along its direction (no normal
                    // force would, Painlevé's case for that direction): the
                    // modes are decided afresh, stick where the cone holds.
                    // Still indeterminate in the modes found: the error.
                    self.decide_afresh(&mut in_place)?;
                    self.h = h.max(min);
                    continue;
                }
                Err(e) => return Err(at_time(e, self.time)),
            };
            if trial.error.is_nan() || trial.error > 1.0 {
                self.stats.rejected += 1;
                let factor = if trial.error.is_finite() {
                    (SAFETY * trial.error.powf(-0.2)).max(MIN_SHRINK)
                } else {
                    MIN_SHRINK
                };
                self.h = h * factor;
                let slipping = self.slip_within(f64::INFINITY, None);
                if self.h < min && slipping && afresh_at != self.time {
                    // No step holds a slip (near Painlevé's case for its
                    // direction, κ → 0⁺, the normal force without bound:
                    // 4e6 N on the 0.3 kg ellipsoid at μ = 1000): the modes
                    // decided afresh, once here, stick where the cone holds.
                    afresh_at = self.time;
                    self.decide_afresh(&mut in_place)?;
                    self.h = h;
                    continue;
                }
                if self.h < min {
                    return Err(DynamicsError::StepTooSmall {
                        method: METHOD,
                        time: self.time,
                        h: self.h,
                        min,
                    });
                }
                continue;
            }
            self.stats.accepted += 1;
            let growth = if trial.error > 0.0 {
                (SAFETY * trial.error.powf(-0.2)).clamp(MIN_SHRINK, MAX_GROWTH)
            } else {
                MAX_GROWTH
            };
            if self.event_in(&trial.end, h) {
                let (tau, end) = self.locate(h, trial.end)?;
                self.time = if tau == h && last {
                    t_end
                } else {
                    self.time + tau
                };
                self.current = end;
                self.h = h.max(tau * 4.0);
                in_place = if tau <= 4.0 * f64::EPSILON * self.time.abs().max(self.time_scale) {
                    in_place + 1
                } else {
                    0
                };
                if in_place > MAX_EVENTS_IN_PLACE {
                    return Err(DynamicsError::ContactModesChatter {
                        time: self.time,
                        count: in_place,
                    });
                }
                let before = self.events.len();
                self.settle_creeping(&mut creep)?;
                if stop_at_event && self.events.len() > before {
                    return Ok(true);
                }
                continue;
            }
            in_place = 0;
            self.time = if last { t_end } else { self.time + h };
            let start = std::mem::replace(&mut self.current, trial.end);
            self.hold_directions();
            if self.land_flat_disks()? && stop_at_event {
                return Ok(true);
            }
            if self.slip_within(self.resolution_speed(), Some(&start.frame)) {
                // A slip that has fallen into the resolution band (without
                // reversing) is decided again: stick where the cone holds.
                let before = self.events.len();
                self.settle_creeping(&mut creep)?;
                if stop_at_event && self.events.len() > before {
                    return Ok(true);
                }
            }
            if !last || growth < 1.0 {
                self.h = h * growth;
            }
        }
        Ok(false)
    }

    /// [`TableMotion::settle`], counting in `creep` (how many, since
    /// when) the decisions in a row that leave every mode as it was.
    ///
    /// # Errors
    /// Those of [`TableMotion::settle`]; [`DynamicsError::ContactModesChatter`]
    /// past [`MAX_CREEPING_EVENTS`] such decisions within [`CREEP`] of the
    /// time scale.
    fn settle_creeping(&mut self, creep: &mut (usize, f64)) -> Result<(), DynamicsError> {
        let kinds = |modes: &[Mode]| -> Vec<_> { modes.iter().map(|m| (m.mode, m.roll)).collect() };
        let before = kinds(&self.modes);
        self.settle()?;
        if kinds(&self.modes) == before && self.time - creep.1 < CREEP * self.time_scale {
            creep.0 += 1;
        } else {
            *creep = (0, self.time);
        }
        if creep.0 > MAX_CREEPING_EVENTS {
            return Err(DynamicsError::ContactModesChatter {
                time: self.time,
                count: creep.0,
            });
        }
        Ok(())
    }

    /// The modes decided afresh (no contact kept slipping along its slip)
    /// where no step holds the current ones; `in_place` counts the
    /// decisions at one instant.
    ///
    /// # Errors
    /// Those of [`TableMotion::settle`]; [`DynamicsError::ContactModesChatter`]
    /// past [`MAX_EVENTS_IN_PLACE`] decisions in place.
    fn decide_afresh(&mut self, in_place: &mut usize) -> Result<(), DynamicsError> {
        self.afresh = true;
        let decided = self.settle();
        self.afresh = false;
        decided?;
        *in_place += 1;
        if *in_place > MAX_EVENTS_IN_PLACE {
            return Err(DynamicsError::ContactModesChatter {
                time: self.time,
                count: *in_place,
            });
        }
        Ok(())
    }

    /// A continuous measure of how far `end` is from the events the
    /// predicates of [`TableMotion::event_in`] look for (each normalised by
    /// the body's units; the smallest): the gaps of open contacts that
    /// start above the plane, the normal forces of closed ones, the
    /// friction's room in the cone of sticking ones, the slip along its
    /// start direction of slipping ones. It steers the location, the
    /// predicates decide it.
    fn event_value(&self, end: &Snapshot) -> f64 {
        let start = &self.current;
        let floor = self.resolution_speed();
        let band = self.band();
        let weight = self.body.mass() * self.body.gravity();
        let mut value = f64::INFINITY;
        for (i, mode) in self.modes.iter().enumerate() {
            let (r0, r1) = (&start.frame.rows[i], &end.frame.rows[i]);
            let n = end.forces.normal[i];
            let v = match mode.mode {
                ContactMode::Open if r0.gap >= 0.0 => r1.gap / self.length,
                ContactMode::Open => f64::INFINITY,
                ContactMode::Sticking => {
                    (n.min(r1.mu * n - end.forces.friction[i].length())) / weight
                }
                ContactMode::Slipping if r1.friction_dimensions > 0 => {
                    (n / weight).min(progress(r0, r1, mode, floor, band, Along::Slip) / self.speed)
                }
                ContactMode::Slipping => n / weight,
            };
            let v = match mode.roll {
                _ if !r1.rolls || mode.mode == ContactMode::Open => v,
                ContactMode::Sticking => v.min((n - end.forces.rolling[i].length()) / weight),
                ContactMode::Slipping => {
                    v.min(progress(r0, r1, mode, floor, band, Along::Roll) / self.speed)
                }
                ContactMode::Open => v,
            };
            let side = match mode.mode {
                ContactMode::Open => f64::INFINITY,
                _ => self.rim_side(i, &end.state),
            };
            value = value.min(v).min(side);
        }
        value
    }

    /// Keeps each slipping contact's direction (and each rolling one's)
    /// at its slip's while the slip lies beyond the band: the direction it
    /// holds once the slip enters the band is the one it had there, also
    /// in the stages of the step that crosses into it (a direction kept
    /// from the mode's last decision made that step's right-hand side
    /// jump at the band's edge: the error control then shrank the steps
    /// towards the edge without ever reaching it — 10⁵ steps per ms).
    fn hold_directions(&mut self) {
        let band = self.band();
        for (mode, row) in self.modes.iter_mut().zip(&self.current.frame.rows) {
            if mode.mode == ContactMode::Slipping && row.slip().length() > band {
                mode.direction = row.slip().normalize();
            }
            if mode.roll == ContactMode::Slipping && row.roll().length() > band {
                mode.roll_direction = row.roll().normalize();
            }
        }
    }

    /// Whether contact `i` slips within the band against (or across) the
    /// direction it holds there: its slip turned by a right angle or more
    /// while the friction held its direction, and that slip's own
    /// direction is not the motion's — decided afresh from the cone, its
    /// residual taken (read as a resolved slip, it flipped at every
    /// decision, 10⁻⁹ s apart: cases 37 and 98 of the scan).
    fn reversed_in_band(&self, i: usize) -> bool {
        let (mode, row) = (&self.modes[i], &self.current.frame.rows[i]);
        mode.mode == ContactMode::Slipping
            && row.friction_dimensions > 0
            && row.slip().length() <= self.band()
            && row.slip().dot(mode.direction) <= 0.0
    }

    /// Whether a slipping contact's slip lies within `floor` (m/s): within
    /// the resolution speed its direction is not resolved, and following it
    /// would chatter about the band's edge; within [`SLIP_BAND`] its
    /// direction is held. With `from` (the frame a step started from):
    /// whether it fell within `floor` in that step — a slip that started
    /// within it and has not left it yet (one starting on the cone's edge,
    /// its acceleration ~0) is not decided again at every step.
    fn slip_within(&self, floor: f64, from: Option<&ContactFrame>) -> bool {
        let fell = |now: DVec3, then: Option<DVec3>| {
            now.length() <= floor && then.is_none_or(|then| then.length() > floor)
        };
        self.modes.iter().enumerate().any(|(i, m)| {
            let row = &self.current.frame.rows[i];
            let start = from.map(|f| &f.rows[i]);
            (m.mode == ContactMode::Slipping
                && row.friction_dimensions > 0
                && fell(row.slip(), start.map(ContactRow::slip)))
                || (m.mode != ContactMode::Open
                    && m.roll == ContactMode::Slipping
                    && row.rolls
                    && fell(row.roll(), start.map(ContactRow::roll)))
        })
    }

    /// The lone participant that is a disk rim lying flat (its axis within
    /// [`DISK_FLAT_TILT`] of the vertical) and striking: a rim rocking
    /// through flat, whose far point strikes.
    fn flipping_rim(&self, participants: &[usize]) -> Option<usize> {
        let [i] = participants else {
            return None;
        };
        let ContactShape::Disk(d) = self.body.contacts()[*i].shape else {
            return None;
        };
        let n = self.current.state.world_from_body.normalize() * d.normal_body();
        let striking = self.current.frame.rows[*i].velocity[0] < -self.resolution_speed();
        (striking && DVec3::Z.cross(n).length() < DISK_FLAT_TILT).then_some(*i)
    }

    /// For a disk rim: on which side of the rim its lowest point lies in
    /// `state`, against the current one: `(n_z n_h)·d₀` with `d₀` the
    /// current lowest point's horizontal direction — positive on the same
    /// side, negative once the disk has rocked through flat (its far rim
    /// point strikes). `+∞` for other shapes.
    fn rim_side(&self, i: usize, state: &GroundTopState) -> f64 {
        let ContactShape::Disk(d) = self.body.contacts()[i].shape else {
            return f64::INFINITY;
        };
        let lowest = |q: DQuat| {
            let n = q.normalize() * d.normal_body();
            n.z * DVec3::new(n.x, n.y, 0.0)
        };
        let d0 = lowest(self.current.state.world_from_body).normalize_or_zero();
        lowest(state.world_from_body).dot(d0)
    }

    /// The earliest length `τ ≤ h` by which an event has happened, to a
    /// few ulps of the time, and the state there: the predicates bracket
    /// it, regula falsi on [`TableMotion::event_value`] (Illinois) picks
    /// the next trial, bisection where that does not halve the bracket.
    fn locate(&mut self, h: f64, at_h: Snapshot) -> Result<(f64, Snapshot), DynamicsError> {
        let (mut lo, mut hi) = (0.0, h);
        let mut f_lo = self.event_value(&self.current);
        let mut f_hi = self.event_value(&at_h);
        let mut end = Some(at_h);
        let resolution = 2.0 * f64::EPSILON * (self.time.abs() + h);
        let (mut side, mut bisect) = (0i8, false);
        while hi - lo > resolution {
            let secant = lo + (hi - lo) * f_lo / (f_lo - f_hi);
            let usable = f_lo > 0.0 && f_hi <= 0.0 && secant > lo && secant < hi;
            // Bisect after a secant trial that did not halve the bracket.
            let mid = if usable && !bisect {
                secant
            } else {
                0.5 * (lo + hi)
            };
            if mid <= lo || mid >= hi {
                break;
            }
            let width = hi - lo;
            let secant_trial = usable && !bisect;
            let trial = match self.trial(mid) {
                Ok(trial) => trial,
                Err(DynamicsError::ContactIndeterminate { .. }) => {
                    // A stage beyond the event may be indeterminate (a slip
                    // past its band along a direction no normal force
                    // holds): the event lies before `mid`, bisected.
                    (hi, f_hi, end) = (mid, 0.0, None);
                    bisect = true;
                    continue;
                }
                Err(e) => return Err(at_time(e, self.time + mid)),
            };
            let value = self.event_value(&trial.end);
            if self.event_in(&trial.end, mid) {
                hi = mid;
                f_hi = value.min(0.0);
                end = Some(trial.end);
                if side == -1 {
                    f_lo *= 0.5;
                }
                side = -1;
            } else {
                lo = mid;
                f_lo = value.max(f64::MIN_POSITIVE);
                if side == 1 {
                    f_hi *= 0.5;
                }
                side = 1;
            }
            bisect = secant_trial && hi - lo > 0.5 * width;
        }
        match end {
            Some(end) => Ok((hi, end)),
            // Indeterminate at the bracket's end: the event at its start.
            None if lo == 0.0 => Ok((0.0, self.current.clone())),
            None => {
                let at_lo = self.trial(lo).map_err(|e| at_time(e, self.time + lo))?;
                Ok((lo, at_lo.end))
            }
        }
    }

    /// Lands a disk on its face when a closed (or touching) rim's axis is
    /// within [`DISK_FLAT_TILT`] of the vertical: the rim's lowest point is
    /// then ill-defined and the face carries the disk (`face`): `true`
    /// when it landed. A face closing from flight (its rim open, at or
    /// below the table) with restitution `e > 0` strikes face first
    /// instead ([`TableMotion::strike_face`]): it bounces off, or lands
    /// once its bounces are summed; rising from its strike it does not
    /// land.
    ///
    /// # Errors
    /// Those of the landing ([`DynamicsError::DiskFlat`] when the face
    /// cannot hold the disk flat or inputs act) and of the strike
    /// ([`DynamicsError::ImpactGainsEnergy`]).
    fn land_flat_disks(&mut self) -> Result<bool, DynamicsError> {
        if self.face.is_some() {
            return Ok(true);
        }
        let q = self.current.state.world_from_body.normalize();
        let gap_tol = 1e-9 * self.length;
        let omega = self.current.frame.omega;
        let v_z = self.current.state.velocity_world.z.abs();
        let v_land = FACE_LANDING * self.speed;
        let v_res = self.resolution_speed();
        // Each flat disk that touches: (contact, its face arrives slowly,
        // its face may strike — the rim open, restitution e > 0).
        let flat: Vec<(usize, bool, bool)> = self
            .body
            .contacts()
            .iter()
            .enumerate()
            .filter_map(|(i, c)| match c.shape {
                ContactShape::Disk(d) => {
                    let n = q * d.normal_body();
                    let row = &self.current.frame.rows[i];
                    let open = self.modes[i].mode == ContactMode::Open;
                    let touching = !open || row.gap <= gap_tol;
                    // The face arrives slowly: its normal velocities below
                    // FACE_LANDING of the speed scale.
                    let slow = v_z + d.radius() * omega.cross(n).length() <= v_land;
                    // With restitution, an open face strikes, and one
                    // rebounding from its strike flies off.
                    let bouncing = open && c.law.restitution() > 0.0;
                    let strikes = bouncing && row.gap <= 0.0;
                    let rising = bouncing && row.velocity[0] > v_res;
                    (touching && DVec3::Z.cross(n).length() < DISK_FLAT_TILT).then_some((
                        i,
                        slow && !rising,
                        strikes,
                    ))
                }
                _ => None,
            })
            .collect();
        let mut landing = None;
        for &(i, slow, strikes) in &flat {
            if strikes && let Some(rests) = self.strike_face(i)? {
                // Struck: it lands when the bounces stopped, else flies.
                landing = rests.then_some(i);
                break;
            }
            if slow {
                landing = Some(i);
                break;
            }
        }
        let Some(i) = landing else {
            return Ok(false);
        };
        let face = FaceSlide::land(
            &self.body,
            &self.current.state,
            i,
            self.time,
            self.tolerance,
            self.speed,
        )?;
        self.current.state = face.state();
        self.flight = None;
        for (k, mode) in self.modes.iter_mut().enumerate() {
            *mode = if k == i {
                Mode::closed(ContactMode::Slipping, DVec3::ZERO)
            } else {
                Mode::OPEN
            };
        }
        self.face = Some(face);
        self.record(Some(i), TableEventKind::LandsFlat);
        Ok(true)
    }

    /// The face of flat disk `i`, its rim open, striking the table face
    /// first ([`face_impact`]: Newton's restitution over the face, with
    /// friction): the impact recorded and applied, `Some(true)` when the
    /// face then rests on the table (its rebound summed or plastic),
    /// `Some(false)` when it flies off; `None` when the face does not
    /// strike face first or its pressure would leave it (the rim strikes).
    ///
    /// # Errors
    /// Those of [`face_impact`].
    fn strike_face(&mut self, i: usize) -> Result<Option<bool>, DynamicsError> {
        let Some(outcome) = face_impact(
            &self.body,
            &self.current.state,
            i,
            TABLE_ACCUMULATION * self.speed,
            self.time,
        )?
        else {
            return Ok(None);
        };
        let mut rebound = 0.0;
        for &(c, approach_speed, rebound_speed, _) in &outcome.speeds {
            rebound = rebound_speed;
            self.record(
                Some(c),
                TableEventKind::Impact {
                    approach_speed,
                    rebound_speed,
                },
            );
        }
        self.record_accumulations(&outcome.accumulations);
        self.flight = None;
        self.current = self
            .snapshot(outcome.state, self.time)
            .map_err(|e| at_time(e, self.time))?;
        Ok(Some(rebound <= self.resolution_speed()))
    }

    /// Records an event of `contact` (`None`: the body) now.
    fn record(&mut self, contact: Option<usize>, kind: TableEventKind) {
        self.events.push(TableEvent {
            time: self.time,
            contact,
            kind,
        });
    }

    /// Records the accumulations of an impact's bounces, `(contact, τ)`:
    /// each at `t + τ`, the body resting no earlier than the latest.
    fn record_accumulations(&mut self, accumulations: &[(usize, f64)]) {
        for &(i, tau) in accumulations {
            self.accumulation = self.accumulation.max(self.time + tau);
            let accumulation_time = self.time + tau;
            self.record(
                Some(i),
                TableEventKind::ImpactsAccumulate { accumulation_time },
            );
        }
    }

    /// At an event (or the start): impacts where a contact approaches,
    /// then each contact's mode from the acceleration-level problem,
    /// events recorded for every change, rest detected.
    fn settle(&mut self) -> Result<(), DynamicsError> {
        if self.land_flat_disks()? {
            return Ok(());
        }
        let v_res = self.resolution_speed();
        let gap_tol = 1e-9 * self.length;
        let frame = &self.current.frame;
        let participants: Vec<usize> = (0..self.modes.len())
            .filter(|&i| self.modes[i].mode != ContactMode::Open || frame.rows[i].gap <= gap_tol)
            .collect();
        let impacting = participants
            .iter()
            .any(|&i| frame.rows[i].velocity[0] < -v_res);
        let mut struck = vec![false; self.modes.len()];
        if impacting {
            let flipping = self.flipping_rim(&participants);
            let outcome = match flipping {
                Some(i) => rim_flip_impact(
                    &self.body,
                    &self.current.state,
                    i,
                    TABLE_ACCUMULATION * self.speed,
                    self.time,
                )?,
                None => impact(
                    &self.body,
                    &self.current.state,
                    &participants,
                    TABLE_ACCUMULATION * self.speed,
                    self.time,
                )?,
            };
            for &(i, approach, rebound, approached) in &outcome.speeds {
                // An impact is a shape that was off the table striking it;
                // a closed contact that takes part (its drift towards the
                // table ~ the tolerance) is no event of its own.
                let was_open = self.modes[i].mode == ContactMode::Open;
                // A rim rocking through flat: its far point strikes.
                let flipped = flipping == Some(i);
                if (was_open || flipped) && approached && approach > v_res {
                    struck[i] = true;
                    self.record(
                        Some(i),
                        TableEventKind::Impact {
                            approach_speed: approach,
                            rebound_speed: rebound,
                        },
                    );
                }
            }
            self.record_accumulations(&outcome.accumulations);
            // Modes are chosen below; the snapshot is refreshed there.
            self.current.state = outcome.state;
            self.current.frame = ContactFrame::of(&self.body, &outcome.state, self.time);
        }
        let reversed: Vec<bool> = (0..self.modes.len())
            .map(|i| self.reversed_in_band(i))
            .collect();
        let new_modes = self.resolve(&participants, &reversed)?;
        let before = std::mem::replace(&mut self.modes, new_modes);
        for (i, (old, new)) in before.iter().zip(self.modes.clone()).enumerate() {
            let kind = match (old.mode, new.mode) {
                (a, b) if a == b => None,
                (ContactMode::Open, _) if struck[i] => None,
                (ContactMode::Open, _) => Some(TableEventKind::Touchdown),
                (_, ContactMode::Open) => Some(TableEventKind::LiftOff),
                (_, ContactMode::Sticking) => Some(TableEventKind::Stick),
                (_, ContactMode::Slipping) => Some(TableEventKind::Slip),
            };
            let row = &self.current.frame.rows[i];
            let residual =
                row.friction_dimensions > 0 && (row.slip().length() <= v_res || reversed[i]);
            let rolling_residual = row.rolls && row.roll().length() <= v_res;
            // A contact that starts to stick, or to slip from within the
            // resolution band, loses its residual slip: the slip then
            // grows from zero along the consistent direction (left, it
            // chatters about the band's edge). The same for the rolling.
            let stops_slip = (new.mode == ContactMode::Sticking
                && old.mode != ContactMode::Sticking)
                || (new.mode == ContactMode::Slipping && residual);
            let closed = new.mode != ContactMode::Open;
            let stops_roll = closed
                && row.rolls
                && ((new.roll == ContactMode::Sticking && old.roll != ContactMode::Sticking)
                    || (new.roll == ContactMode::Slipping && rolling_residual));
            if stops_slip || stops_roll {
                self.current.state =
                    stop_slip(&self.body, &self.current.state, i, stops_slip, stops_roll);
                self.current.frame = ContactFrame::of(&self.body, &self.current.state, self.time);
            }
            if closed && old.mode != ContactMode::Open && old.roll != new.roll {
                let kind = match new.roll {
                    ContactMode::Sticking => Some(TableEventKind::StopsRolling),
                    ContactMode::Slipping => Some(TableEventKind::StartsRolling),
                    ContactMode::Open => None,
                };
                if let Some(kind) = kind {
                    self.record(Some(i), kind);
                }
            }
            if new.mode == ContactMode::Open && old.mode != ContactMode::Open {
                self.accumulation = f64::NEG_INFINITY;
            }
            if let Some(kind) = kind {
                self.record(Some(i), kind);
            }
        }
        self.current = self
            .snapshot(self.current.state, self.time)
            .map_err(|e| at_time(e, self.time))?;
        if self.land_flat_disks()? {
            return Ok(());
        }
        let ballistic = !self.body.has_loads();
        self.flight = if ballistic && self.modes.iter().all(|m| m.mode == ContactMode::Open) {
            let g = self.body.gravity();
            let flight = Flight::try_new(self.body.inertia_body(), &self.current.state, g)
                .map_err(|e| at_time(e, self.time))?;
            Some((self.time, flight))
        } else {
            None
        };
        self.detect_rest();
        Ok(())
    }

    /// The modes of the contacts that touch without separating: the
    /// acceleration-level problem (Signorini and Coulomb–Contensou on
    /// accelerations, slipping contacts along their slip, but those
    /// `reversed` within the band — [`TableMotion::reversed_in_band`] —
    /// decided afresh from the cone).
    fn resolve(
        &self,
        participants: &[usize],
        reversed: &[bool],
    ) -> Result<Vec<Mode>, DynamicsError> {
        let v_res = self.resolution_speed();
        let frame = &self.current.frame;
        let touching: Vec<usize> = participants
            .iter()
            .copied()
            .filter(|&i| frame.rows[i].velocity[0] <= v_res)
            .collect();
        let free = (frame.free_velocity_rate, frame.free_omega_rate);
        let mut blocks = Vec::with_capacity(touching.len());
        let mut y_free = Vec::with_capacity(touching.len());
        let mut rolling = Vec::with_capacity(touching.len());
        for &i in &touching {
            let row = &frame.rows[i];
            let slip = row.slip();
            let sliding = row.friction_dimensions > 0
                && self.modes[i].mode != ContactMode::Sticking
                && slip.length() > v_res
                && !reversed[i]
                && !self.afresh;
            let size = 1 + row.friction_dimensions;
            let mut y = [0.0; 4];
            for (k, v) in y.iter_mut().enumerate().take(size) {
                *v = frame.rate(i, k, free);
            }
            y_free.push(y);
            blocks.push(Block {
                size,
                mu: row.mu,
                slipping: sliding.then(|| slip.normalize()),
            });
            let roll = row.roll();
            rolling.push(if !row.rolls {
                Rolling::Free
            } else if self.modes[i].roll != ContactMode::Sticking
                && roll.length() > v_res
                && !self.afresh
            {
                Rolling::Along(roll.normalize())
            } else {
                Rolling::Cone
            });
        }
        let g = |a: usize, ca: usize, b: usize, cb: usize| {
            frame.delassus(
                &frame.rows[touching[a]].directions[ca],
                &frame.rows[touching[b]].directions[cb],
            )
        };
        // A slip within its band whose direction no normal force holds
        // (Painlevé's case for that direction; the direction within the
        // band is not resolved, SLIP_BAND): that contact decided afresh.
        let band = self.band();
        let unresolved: Vec<usize> = (0..touching.len())
            .filter(|&a| {
                blocks[a].slipping.is_some_and(|d| {
                    let kappa = (0..blocks[a].size - 1).fold(g(a, 0, a, 0), |k, c| {
                        k - blocks[a].mu * g(a, 0, a, 1 + c) * d[c]
                    });
                    frame.rows[touching[a]].slip().length() <= band
                        && (kappa.is_nan() || kappa <= 0.0)
                })
            })
            .collect();
        let (x, x_r) = match solve_with_rolling(frame, &touching, &blocks, &y_free, &rolling) {
            Err(DynamicsError::ContactIndeterminate { .. }) if !unresolved.is_empty() => {
                unresolved.iter().for_each(|&a| blocks[a].slipping = None);
                solve_with_rolling(frame, &touching, &blocks, &y_free, &rolling)
            }
            solved => solved,
        }
        .map_err(|e| at_time(e, self.time))?;
        let mut modes = vec![Mode::OPEN; self.modes.len()];
        let mut on_edge = Vec::new();
        for (k, &i) in touching.iter().enumerate() {
            let (xi, block) = (&x[k], &blocks[k]);
            if xi[0].is_nan() || xi[0] <= 0.0 {
                continue;
            }
            let t = DVec3::new(xi[1], xi[2], xi[3]);
            let (mode, direction) = if block.size == 1 {
                (ContactMode::Slipping, DVec3::ZERO)
            } else if let Some(d) = block.slipping {
                (ContactMode::Slipping, d)
            } else if t.length() < block.mu * xi[0] * (1.0 - 1e-12) {
                (ContactMode::Sticking, DVec3::ZERO)
            } else {
                (ContactMode::Slipping, -t.normalize_or_zero())
            };
            let (roll, roll_direction) = match rolling[k] {
                Rolling::Free => (ContactMode::Open, DVec3::ZERO),
                Rolling::Along(d) => (ContactMode::Slipping, d),
                Rolling::Cone if x_r[k].length() < xi[0] * (1.0 - 1e-12) => {
                    (ContactMode::Sticking, DVec3::ZERO)
                }
                Rolling::Cone => (ContactMode::Slipping, -x_r[k].normalize_or_zero()),
            };
            modes[i] = Mode {
                mode,
                direction,
                roll,
                roll_direction,
            };
            if block.slipping.is_none() && block.size > 1 && mode == ContactMode::Slipping {
                on_edge.push(i);
            }
        }
        Ok(self.held_on_the_edge(modes, &on_edge))
    }

    /// `modes` with the contacts `on_edge` (the cone's solve left their
    /// friction on the cone's edge) sticking, where the forces of those
    /// modes keep every contact inside its cone: where contacts
    /// overconstrain the body the forces are not unique, and the solve's
    /// are one admissible distribution of many; the slip it reads off one
    /// on the edge need not be the motion's (case 27 of the scan: its
    /// direction flipped at every decision, each slip reversing at once).
    fn held_on_the_edge(&self, modes: Vec<Mode>, on_edge: &[usize]) -> Vec<Mode> {
        if on_edge.is_empty() {
            return modes;
        }
        let mut held = modes.clone();
        for &i in on_edge {
            held[i].mode = ContactMode::Sticking;
            held[i].direction = DVec3::ZERO;
        }
        let Ok(forces) = mode_forces(&self.current.frame, &held, self.band()) else {
            return modes;
        };
        let admissible = held.iter().enumerate().all(|(i, m)| {
            let (n, mu) = (forces.normal[i], self.current.frame.rows[i].mu);
            m.mode == ContactMode::Open
                || (n >= 0.0
                    && (m.mode != ContactMode::Sticking || forces.friction[i].length() <= mu * n)
                    && (m.roll != ContactMode::Sticking || forces.rolling[i].length() <= n))
        });
        if admissible { held } else { modes }
    }

    /// Rest: a closed contact, every closed contact sticking (or
    /// frictionless), velocities and accelerations below the resolution.
    fn detect_rest(&mut self) {
        if self.body.inputs().is_some() {
            return;
        }
        let closed: Vec<usize> = (0..self.modes.len())
            .filter(|&i| self.modes[i].mode != ContactMode::Open)
            .collect();
        if closed.is_empty() {
            return;
        }
        let frictional_slip = closed.iter().any(|&i| {
            let row = &self.current.frame.rows[i];
            (self.modes[i].mode == ContactMode::Slipping && row.friction_dimensions > 0)
                || (self.modes[i].roll == ContactMode::Slipping && row.rolls)
        });
        let v_res = self.resolution_speed();
        let a_res = TABLE_RESOLUTION * self.body.gravity();
        let s = &self.current;
        let still = s.state.velocity_world.length() <= v_res
            && s.frame.omega.length() * self.length <= v_res
            && s.forces.velocity_rate.length() <= a_res
            && s.forces.omega_rate.length() * self.length <= a_res;
        if still && !frictional_slip {
            self.resting = true;
            self.events.push(TableEvent {
                time: self.time.max(self.accumulation),
                contact: None,
                kind: TableEventKind::Rest,
            });
        }
    }
}

/// The slip band of `tolerance` for the speed scale `speed`, m/s
/// ([`SLIP_BAND`]).
fn slip_band(tolerance: AdaptiveTolerance, speed: f64) -> f64 {
    (SLIP_BAND * (tolerance.rtol() / 1e-10)).clamp(TABLE_RESOLUTION, SLIP_BAND) * speed
}

/// Which relative rate [`progress`] follows.
#[derive(Debug, Clone, Copy)]
enum Along {
    /// The slip `γ_T` (friction).
    Slip,
    /// The rolling rate `γ_R` (rolling resistance).
    Roll,
}

/// How far a slipping contact's slip (or rolling rate) at the trial's end
/// `r1` lies along its direction at the start `r0`: `γ_T(τ) · d₀` (`d₀`
/// the mode's direction while the slip is within `band`), negative once
/// the slip has reversed (the contact may stick). A slip that has just
/// started (`|γ_T(0)|` below `floor`, its direction the mode's) is
/// measured from its start value, the residual the sticking phase left:
/// that residual is not a reversal; nor is a change back by less than
/// `floor`, which the resolution does not resolve (a slip starting on the
/// cone's edge, its acceleration ~0, read the rounding of every step as a
/// reversal: case 32 of the scan decided 10⁴ times per second of wall
/// time, 10⁻⁹ s apart).
///
/// ```text
/// |γ_T(0)| > floor:  γ_T(τ)·d₀
/// otherwise:         c = (γ_T(τ) − γ_T(0))·d₀;  c if c ≥ 0, min(c + floor, 0) if c < 0
/// ```
fn progress(
    r0: &ContactRow,
    r1: &ContactRow,
    mode: &Mode,
    floor: f64,
    band: f64,
    along: Along,
) -> f64 {
    let (s0, s1, d0) = match along {
        Along::Slip => (r0.slip(), r1.slip(), slip_direction(r0.slip(), mode, band)),
        Along::Roll => (r0.roll(), r1.roll(), roll_direction(r0.roll(), mode, band)),
    };
    if s0.length() > floor {
        s1.dot(d0)
    } else {
        let change = (s1 - s0).dot(d0);
        if change < 0.0 {
            (change + floor).min(0.0)
        } else {
            change
        }
    }
}

/// Whether a slip (or rolling rate) crossed the edge of the band within
/// which its direction is held ([`SLIP_BAND`]).
fn crosses_band(s0: DVec3, s1: DVec3, band: f64) -> bool {
    (s1.length() <= band) != (s0.length() <= band)
}

/// Whether a gap's cubic Hermite over a step of length `h` (from `g0, ġ0`
/// to `g1, ġ1`) dips below zero and below both its ends inside the step:
/// a graze the step's end does not show (sampled at 16 interior points).
fn dips_below(g0: f64, d0: f64, g1: f64, d1: f64, h: f64) -> bool {
    let floor = g0.min(g1).min(0.0);
    (1..16).any(|k| {
        let s = f64::from(k) / 16.0;
        let (s2, s3) = (s * s, s * s * s);
        let value = (2.0 * s3 - 3.0 * s2 + 1.0) * g0
            + (s3 - 2.0 * s2 + s) * h * d0
            + (-2.0 * s3 + 3.0 * s2) * g1
            + (s3 - s2) * h * d1;
        value < floor
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::table::contact_frame::Wrench;

    /// A contact row with three friction directions slipping at `slip`.
    fn row(slip: f64) -> ContactRow {
        ContactRow {
            gap: 0.0,
            friction_dimensions: 3,
            rolls: false,
            mu: 0.5,
            directions: [Wrench::default(); 6],
            velocity: [0.0, slip, 0.0, 0.0, 0.0, 0.0],
            bias: [0.0; 6],
        }
    }

    #[test]
    fn a_slip_from_rest_reverses_only_beyond_the_resolution() {
        let mode = Mode {
            mode: ContactMode::Slipping,
            direction: DVec3::X,
            ..Mode::OPEN
        };
        let (floor, band) = (1e-9, 1e-6);
        let along =
            |s0: f64, s1: f64| progress(&row(s0), &row(s1), &mode, floor, band, Along::Slip);
        // A slip started on the cone's edge (from 1e-14, the residual), its
        // acceleration ~0: the rounding of a step is no reversal.
        assert_eq!(along(1e-14, 1e-14 - 1e-17), 0.0);
        assert_eq!(along(1e-14, 1e-14 - 0.9e-9), 0.0);
        // Back beyond the resolution: reversed, continuous at its edge.
        assert!((along(1e-14, 1e-14 - 3e-9) + 2e-9).abs() < 1e-22);
        // Growing: its change from the residual.
        assert!((along(1e-14, 1e-14 + 3e-9) - 3e-9).abs() < 1e-22);
        // A resolved slip reverses at zero.
        assert!(along(1e-8, -1e-15) < 0.0);
        assert!(along(1e-8, 1e-15) > 0.0);
    }
}
