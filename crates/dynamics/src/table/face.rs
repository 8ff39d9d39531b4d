//! A disk lying flat on the table: its face lands, then slides and spins
//! under Coulomb friction spread over the face until it stops.
//!
//! ```text
//! landing (a closed rim whose axis is within DISK_FLAT_TILT of the vertical):
//!     the body turned flat about the rim's lowest point P (P stays, the
//!     face's centre on the table), then the plastic face impact of least
//!     kinetic energy: v_z → 0,  L → L + Λ,  Λ = ω_z I_w ẑ − L  (horizontal),
//!     ω_z = L_z / (ẑ·I_w ẑ)
//! sliding:  s = (v_x, v_y, ε ω_z),  ε = 2a/3,  N = m g
//!     m v̇ = −μ N v/|s|,   I_zz ω̇ = −μ N ε (ε ω_z)/|s|        until |s| = 0: at rest
//! ```
//!
//! The friction is Contensou's coupling of sliding and drilling on the
//! face, in the cone form of Leine & Glocker (Eur. J. Mech. A 22, 2003):
//! the generalised slip `s` and the force `(F, τ/ε)` are opposite, of
//! norm `μ N`; with a uniform pressure over a face of radius `a` the lever
//! `ε = 2a/3` makes pure spinning (`∫ μ p r dA = ⅔ μ N a`) and pure sliding
//! exact. `|s|` falls at a rate between `μ g min(1, m ε²/I_zz)` and
//! `μ g max(…)`, so the disk stops in finite time, both motions together
//! (`|v| ∝ |ω|^{k₁/k₂}` along the solution); the stop is located to
//! rounding. The face must hold the disk flat: the horizontal torque it
//! supplies (gyroscopic, and friction's about the centre of mass) keeps
//! the centre of pressure inside the face, else
//! [`DynamicsError::DiskFlat`].
//!
//! The landing is plastic. Before it, a face closing from flight with
//! the rim's restitution `e > 0` bounces (`impact::face_impact`: Newton's
//! law at every point of the face, `(v_z, ω_x, ω_y)⁺ = −e (v_z, ω_x,
//! ω_y)⁻` with the impulse wrench's centre of pressure inside the face,
//! Coulomb–Contensou friction at the impact with the lever `ε` below);
//! its bounces accumulate and the face lands here. A disk rocking through
//! flat strikes with its far rim point instead, which the rim contact
//! models with its restitution. Applied inputs are not followed on the
//! face ([`DynamicsError::DiskFlat`]).

use glam::{DMat3, DQuat, DVec3};

use super::TableBody;
use crate::contact::{DOPRI_A, DOPRI_B_HAT, MAX_GROWTH, MIN_SHRINK, SAFETY};
use crate::{AdaptiveStats, AdaptiveTolerance, ContactShape, DynamicsError, GroundTopState};

/// The planar state on the face: `x, y` of the centre of mass (m), the
/// turn `ψ` about the vertical since the landing (rad), `v_x, v_y` (m/s),
/// `ω_z` (rad/s).
type Planar = [f64; 6];

/// A disk on its face, from its landing to rest.
#[derive(Debug, Clone)]
pub(crate) struct FaceSlide {
    /// The contact whose face carries the body.
    pub(crate) contact: usize,
    /// The landed state (ψ = 0).
    landed: GroundTopState,
    /// `I_w ẑ` at the landing, kg m² (turns with ψ).
    inertia_z: DVec3,
    /// `k₁ = μ g`, `k₂ = μ m g ε²/I_zz`, 1/s·m/s; `ε`, m.
    k_slide: f64,
    k_spin: f64,
    lever: f64,
    time: f64,
    y: Planar,
    h: f64,
    scales: Planar,
    tolerance: AdaptiveTolerance,
    resolution: f64,
    /// The time the disk stopped, if it has.
    stopped: Option<f64>,
    pub(crate) stats: AdaptiveStats,
}

/// The derivative of the planar state under the face's friction.
fn rate(y: &Planar, k_slide: f64, k_spin: f64, lever: f64) -> Planar {
    let w = lever * y[5];
    let s = (y[3] * y[3] + y[4] * y[4] + w * w).sqrt();
    if s == 0.0 {
        return [0.0; 6];
    }
    [
        y[3],
        y[4],
        y[5],
        -k_slide * y[3] / s,
        -k_slide * y[4] / s,
        -k_spin * y[5] / s,
    ]
}

impl FaceSlide {
    /// Lands the face of disk contact `contact` at time `t`: the landed
    /// state and the slide that follows it.
    ///
    /// # Errors
    /// [`DynamicsError::DiskFlat`] when the contact is no disk, the body
    /// has applied inputs, or the face cannot hold the disk flat;
    /// [`DynamicsError::ImpactGainsEnergy`] when the landing would raise
    /// the energy (it cannot beyond rounding: the turn lowers the centre
    /// of mass to first order only for a centre of mass above the face).
    pub(crate) fn land(
        body: &TableBody,
        state: &GroundTopState,
        contact: usize,
        t: f64,
        tolerance: AdaptiveTolerance,
        speed: f64,
    ) -> Result<Self, DynamicsError> {
        let flat_error = DynamicsError::DiskFlat { time: t };
        let ContactShape::Disk(disk) = body.contacts()[contact].shape else {
            return Err(flat_error);
        };
        if body.inputs().is_some() {
            return Err(flat_error);
        }
        let q = state.world_from_body.normalize();
        let n = q * disk.normal_body();
        let down = if n.z >= 0.0 { DVec3::Z } else { -DVec3::Z };
        // The turn taking the axis onto the vertical, about the rim's
        // lowest point P.
        let turn = DQuat::from_rotation_arc(n, down);
        let p =
            state.com_world + offset_and_rate(&body.contacts()[contact].shape, q, DVec3::ZERO).0;
        let q_flat = (turn * q).normalize();
        let mut com = p + turn * (state.com_world - p);
        // The face's plane on the table exactly.
        com.z = -(q_flat * disk.center_body()).z;
        let inertia_z = inertia_world(body, q_flat) * DVec3::Z;
        let omega_z = state.l_world.z / inertia_z.z;
        let landed = GroundTopState {
            com_world: com,
            velocity_world: DVec3::new(state.velocity_world.x, state.velocity_world.y, 0.0),
            world_from_body: q_flat,
            l_world: inertia_z * omega_z,
        };
        let before = body.energy(state);
        let after = body.energy(&landed);
        // Rounding: of the energy, and of the face's height set onto the
        // table (a located touchdown leaves it ulps of ℓ below: m g ℓ).
        let scale = before
            .abs()
            .max(body.kinetic_energy(state))
            .max(body.mass() * body.gravity() * body.length_scale());
        if after > before + 1e-12 * scale {
            return Err(DynamicsError::ImpactGainsEnergy {
                time: t,
                before,
                after,
            });
        }
        let (m, g) = (body.mass(), body.gravity());
        let mu = body.contacts()[contact].law.mu();
        let radius = disk.radius();
        let lever = face_lever(radius);
        // The face holds the disk flat when the horizontal torque it must
        // supply keeps the centre of pressure inside it.
        let height = com.z;
        let gyroscopic = omega_z * omega_z * DVec3::Z.cross(inertia_z).length();
        if gyroscopic + mu * m * g * height.abs() > radius * m * g {
            return Err(flat_error);
        }
        let length = radius.max(height.abs());
        let scales = [length, length, 1.0, speed, speed, speed / length];
        Ok(Self {
            contact,
            landed,
            inertia_z,
            k_slide: mu * g,
            k_spin: mu * m * g * lever * lever / inertia_z.z,
            lever,
            time: t,
            y: [
                com.x,
                com.y,
                0.0,
                landed.velocity_world.x,
                landed.velocity_world.y,
                omega_z,
            ],
            h: 1e-3 * (length / g).sqrt(),
            scales,
            tolerance,
            resolution: super::TABLE_RESOLUTION * speed,
            stopped: None,
            stats: AdaptiveStats::default(),
        })
    }

    /// The body's state now.
    pub(crate) fn state(&self) -> GroundTopState {
        let turn = DQuat::from_rotation_z(self.y[2]);
        GroundTopState {
            com_world: DVec3::new(self.y[0], self.y[1], self.landed.com_world.z),
            velocity_world: DVec3::new(self.y[3], self.y[4], 0.0),
            world_from_body: turn * self.landed.world_from_body,
            l_world: turn * self.inertia_z * self.y[5],
        }
    }

    /// The time reached, s.
    pub(crate) fn time(&self) -> f64 {
        self.time
    }

    /// Whether the face still slips (`|s|` above the resolution).
    fn slips(&self, y: &Planar) -> bool {
        let w = self.lever * y[5];
        (y[3] * y[3] + y[4] * y[4] + w * w).sqrt() > self.resolution
    }

    /// One Dormand–Prince trial of length `h`: the end and its error norm.
    fn trial(&mut self, h: f64) -> (Planar, f64) {
        let y0 = self.y;
        let f = |y: &Planar| rate(y, self.k_slide, self.k_spin, self.lever);
        let mut k = [[0.0; 6]; 7];
        k[0] = f(&y0);
        let combine = |k: &[Planar; 7], weights: &[f64]| {
            let mut y = y0;
            for (kj, &wj) in k.iter().zip(weights) {
                for c in 0..6 {
                    y[c] += h * wj * kj[c];
                }
            }
            y
        };
        for i in 1..7 {
            let y = combine(&k, &DOPRI_A[i][..i]);
            k[i] = f(&y);
        }
        self.stats.evaluations += 6;
        let end = combine(&k, &DOPRI_A[6][..6]);
        let low = combine(&k, &DOPRI_B_HAT);
        let mut error: f64 = 0.0;
        for c in 0..6 {
            let bound = self.tolerance.atol() * self.scales[c]
                + self.tolerance.rtol() * y0[c].abs().max(end[c].abs());
            error = error.max((end[c] - low[c]).abs() / bound);
        }
        (end, error)
    }

    /// Whether the slip stopped (fell below the resolution or reversed)
    /// by the end `y` of a trial.
    fn stops_by(&self, y: &Planar) -> bool {
        let along =
            y[3] * self.y[3] + y[4] * self.y[4] + self.lever * self.lever * y[5] * self.y[5];
        !self.slips(y) || along <= 0.0
    }

    /// Slides to `t_end` or to the stop, whichever comes first; the stop's
    /// time when it stopped in this call.
    ///
    /// # Errors
    /// [`DynamicsError::StepTooSmall`] when the error control needs a step
    /// below `10⁻¹⁴ max(t, τ)` (it cannot: the field is smooth away from
    /// the stop, which is located, not stepped over).
    pub(crate) fn advance(&mut self, t_end: f64) -> Result<Option<f64>, DynamicsError> {
        if self.stopped.is_some() || !self.slips(&self.y) {
            if self.stopped.is_none() {
                self.stop_here();
                return Ok(Some(self.time));
            }
            self.time = self.time.max(t_end);
            return Ok(None);
        }
        // Up to `target`: `t_end`, or the stop once located.
        let mut target = t_end;
        let mut stop_at = None;
        while self.time < target {
            let remaining = target - self.time;
            let last = self.h >= remaining;
            let h = if last { remaining } else { self.h };
            let (end, error) = self.trial(h);
            if stop_at.is_none() && self.stops_by(&end) {
                // The stop: the longest trial that still slips, to rounding;
                // then stepped to under error control (the field is smooth
                // before it).
                let (mut lo, mut hi) = (0.0, h);
                while hi - lo > 2.0 * f64::EPSILON * (self.time.abs() + h) {
                    let mid = 0.5 * (lo + hi);
                    let (y, _) = self.trial(mid);
                    if self.stops_by(&y) {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                stop_at = Some(self.time + lo);
                target = self.time + lo;
                continue;
            }
            if error.is_nan() || error > 1.0 {
                self.stats.rejected += 1;
                self.h = h * (SAFETY * error.powf(-0.2)).max(MIN_SHRINK);
                let min = 1e-14 * self.time.abs().max(1e-3);
                if self.h.is_nan() || self.h < min {
                    return Err(DynamicsError::StepTooSmall {
                        method: "face dopri5",
                        time: self.time,
                        h: self.h,
                        min,
                    });
                }
                continue;
            }
            self.stats.accepted += 1;
            self.y = end;
            self.time = if last { target } else { self.time + h };
            if !last {
                self.h = h * (SAFETY * error.powf(-0.2)).clamp(MIN_SHRINK, MAX_GROWTH);
            }
        }
        if let Some(t) = stop_at {
            self.time = t;
            self.stop_here();
        }
        Ok(stop_at)
    }

    /// The slip, below the resolution, set to zero: at rest (no load
    /// acts on the face to move it again).
    fn stop_here(&mut self) {
        self.y[3] = 0.0;
        self.y[4] = 0.0;
        self.y[5] = 0.0;
        self.stopped = Some(self.time);
    }
}

/// `I_w = A I Aᵀ` at the attitude `q`.
fn inertia_world(body: &TableBody, q: DQuat) -> DMat3 {
    let a = DMat3::from_quat(q);
    a * body.inertia_body() * a.transpose()
}

/// The face's friction lever `ε = ⅔ a` for a face of radius `a`, m: the
/// pure-spin torque `∫ μ p r dA = ⅔ μ N a` of a uniform pressure per
/// newton of friction (the same for the impulses of a face striking flat:
/// its pressure is uniform when only `v_z` reverses).
pub(crate) fn face_lever(radius: f64) -> f64 {
    2.0 * radius / 3.0
}

/// `ρ` and `ρ̇` of `shape` (its lowest point from the centre of mass and
/// that point's rate) at the unit attitude `q` and angular velocity
/// `omega_world`; for a disk rim lying exactly flat (no single lowest
/// point, the shape's own `ρ` NaN) the rim's centre, at the height of the
/// whole rim, moving with the body (`ρ̇ = ω × A c`).
pub(crate) fn offset_and_rate(
    shape: &ContactShape,
    q: DQuat,
    omega_world: DVec3,
) -> (DVec3, DVec3) {
    let (rho, rate) = shape.offset_and_rate(q, omega_world);
    if rho.is_finite() {
        return (rho, rate);
    }
    match shape {
        ContactShape::Disk(d) => {
            let centre = q * d.center_body();
            (centre, omega_world.cross(centre))
        }
        _ => (rho, rate),
    }
}
