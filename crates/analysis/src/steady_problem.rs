//! [`SteadyProblem`]: one body's steady motion in physical parameters —
//! found near a body's state (a scene's, a World's) or named — that can be
//! linearised, changed one [`Parameter`] at a time (maps), and compared
//! with a closed-form stability boundary where one exists.

use glam::{DQuat, DVec3};
use kreisel_dynamics::{Body, Friction, HeavyTop, Support};
use kreisel_inertia::MassProperties;

use crate::{
    AnalysisError, BodyOnGround, FreeBodyRotation, HeavyTopPivot, Linearisation, Parameter,
    PrecessingTop, Precession, SteadyKind, find_steady_motion,
};

/// A top on a pivot, as the engine builds it: mass properties about the
/// centre of mass (body axes), the pivot in body coordinates, gravity.
#[derive(Debug, Clone, PartialEq)]
pub struct PivotBody {
    /// Mass properties about the centre of mass.
    pub mass_properties: MassProperties,
    /// The pivot in body coordinates, m.
    pub pivot_body: DVec3,
    /// Gravity, world axes, m/s².
    pub gravity_world: DVec3,
}

impl PivotBody {
    /// The engine's heavy top.
    fn heavy_top(&self) -> Result<HeavyTop, AnalysisError> {
        Ok(HeavyTop::try_new(
            &self.mass_properties,
            self.pivot_body,
            self.gravity_world,
        )?)
    }

    /// The distance from the pivot to the centre of mass, m.
    fn com_offset(&self) -> f64 {
        (self.mass_properties.center_of_mass - self.pivot_body).length()
    }
}

/// One body's steady motion.
///
/// ```text
/// free rotation:  ω = Ω e_a (principal axes)                         FreeBodyRotation
/// sleeping top:   γ = ±c/|c|, ω = Ω γ                                HeavyTopPivot
/// precession:     θ = θ₀, θ̇ = 0, φ̇ slow or fast (symmetric top)     PrecessingTop
/// ```
///
/// ```
/// use glam::DVec3;
/// use kreisel_analysis::{Parameter, SteadyProblem};
/// let mut spin = SteadyProblem::FreeRotation { moments: DVec3::new(1.0, 2.0, 3.0), axis: 1, spin: 2.0 };
/// assert_eq!(spin.linearise()?.verdict.name(), "unstable");
/// spin.set(Parameter::Spin, -1.0)?;
/// assert!(spin.set(Parameter::Tilt, 0.3).is_err()); // a free rotation has no tilt
/// # Ok::<(), kreisel_analysis::AnalysisError>(())
/// ```
#[derive(Debug, Clone)]
pub enum SteadyProblem {
    /// A free body spinning about a principal axis.
    FreeRotation {
        /// Principal moments, kg m².
        moments: DVec3,
        /// The principal axis, 0, 1 or 2.
        axis: usize,
        /// The rate, rad/s.
        spin: f64,
    },
    /// A top on a pivot spinning about the vertical through its centre of
    /// mass: above the pivot (sleeping) or below (hanging).
    SleepingTop {
        /// The top.
        top: PivotBody,
        /// The spin about the up vertical, rad/s.
        spin: f64,
        /// Centre of mass below the pivot.
        hanging: bool,
    },
    /// A body on the ground spinning about the vertical (the tippe top
    /// upright or inverted, the rattleback, a ball), with its contact
    /// shape and friction law.
    GroundSpin {
        /// The body as the scene built it (support on the ground; boxed:
        /// it holds its contact shapes and inputs).
        body: Box<Body>,
        /// Gravity, world axes, m/s² (along −z).
        gravity_world: DVec3,
        /// The body axis that points up.
        up_body: DVec3,
        /// The spin about the up vertical, rad/s.
        spin: f64,
    },
    /// A symmetric top on a pivot in steady precession.
    Precession {
        /// The top.
        top: PivotBody,
        /// The tilt from the up vertical, rad.
        tilt: f64,
        /// `ω₃`, rad/s.
        spin: f64,
        /// Slow or fast.
        which: Precession,
    },
}

impl SteadyProblem {
    /// What it is, in words (`"sleeping top"`).
    pub fn kind(&self) -> &'static str {
        match self {
            Self::FreeRotation { .. } => "free rotation about a principal axis",
            Self::SleepingTop { hanging: false, .. } => "sleeping top",
            Self::SleepingTop { hanging: true, .. } => "hanging top",
            Self::GroundSpin { .. } => "spin about the vertical on its contact point",
            Self::Precession {
                which: Precession::Slow,
                ..
            } => "slow steady precession",
            Self::Precession {
                which: Precession::Fast,
                ..
            } => "fast steady precession",
        }
    }

    /// The frame and order of its linearisation's coordinates, in words.
    pub fn coordinates(&self) -> &'static str {
        match self {
            Self::FreeRotation { .. } => "principal axes, moments ascending",
            Self::SleepingTop { .. } => {
                "γ the up vertical; principal axes about the pivot, moments ascending"
            }
            Self::Precession { .. } => "Euler angles ZXZ, θ from the up vertical",
            Self::GroundSpin { .. } => {
                "γ the up vertical, body axes; v the centre of mass's velocity"
            }
        }
    }

    /// The parameters it can be swept in, with their values.
    pub fn parameters(&self) -> Vec<(Parameter, f64)> {
        match self {
            Self::FreeRotation { spin, .. } | Self::GroundSpin { spin, .. } => {
                vec![(Parameter::Spin, *spin)]
            }
            Self::SleepingTop { top, spin, .. } => vec![
                (Parameter::Spin, *spin),
                (Parameter::ComOffset, top.com_offset()),
                (Parameter::Gravity, top.gravity_world.length()),
            ],
            Self::Precession {
                top, tilt, spin, ..
            } => vec![
                (Parameter::Spin, *spin),
                (Parameter::Tilt, *tilt),
                (Parameter::ComOffset, top.com_offset()),
                (Parameter::Gravity, top.gravity_world.length()),
            ],
        }
    }

    /// Sets `parameter` to `value`.
    ///
    /// # Errors
    /// [`AnalysisError::Sweep`] naming the parameters this motion has if it
    /// has not this one, or for a value that is not finite (a negative
    /// offset or gravity too).
    pub fn set(&mut self, parameter: Parameter, value: f64) -> Result<(), AnalysisError> {
        let has: Vec<&str> = self.parameters().iter().map(|(p, _)| p.name()).collect();
        let refuse = |why: String| AnalysisError::Sweep {
            name: parameter.name().into(),
            why,
        };
        if !value.is_finite() {
            return Err(refuse(format!("{value} is not a finite number")));
        }
        let kind = self.kind();
        let missing = refuse(format!(
            "a {kind} has no {parameter} (it has {})",
            has.join(", ")
        ));
        match (self, parameter) {
            (
                Self::FreeRotation { spin, .. }
                | Self::SleepingTop { spin, .. }
                | Self::GroundSpin { spin, .. }
                | Self::Precession { spin, .. },
                Parameter::Spin,
            ) => *spin = value,
            (Self::Precession { tilt, .. }, Parameter::Tilt) => *tilt = value,
            (
                Self::SleepingTop { top, .. } | Self::Precession { top, .. },
                Parameter::ComOffset,
            ) => {
                if value <= 0.0 || top.com_offset() == 0.0 {
                    return Err(refuse(format!(
                        "{value} m from a pivot at the centre of mass: the offset must be positive, and so must the body's"
                    )));
                }
                let com = top.mass_properties.center_of_mass;
                let along = (com - top.pivot_body) / top.com_offset();
                top.pivot_body = com - along * value;
            }
            (Self::SleepingTop { top, .. } | Self::Precession { top, .. }, Parameter::Gravity) => {
                if value < 0.0 {
                    return Err(refuse(format!(
                        "{value} m/s²: gravity must not be negative"
                    )));
                }
                top.gravity_world = top.gravity_world.normalize_or(DVec3::NEG_Z) * value;
            }
            _ => return Err(missing),
        }
        Ok(())
    }

    /// Its linearisation.
    ///
    /// # Errors
    /// The family's errors: no such motion at these parameters (a
    /// precession too slow for its tilt), a body the engine refuses.
    pub fn linearise(&self) -> Result<Linearisation, AnalysisError> {
        match self {
            Self::FreeRotation {
                moments,
                axis,
                spin,
            } => {
                let family = FreeBodyRotation::try_new(*moments)?;
                Linearisation::try_new(&family, &family.about_axis(*axis, *spin)?)
            }
            Self::SleepingTop { top, spin, hanging } => {
                let family = HeavyTopPivot::of(&top.heavy_top()?);
                let x = if *hanging {
                    family.hanging(*spin)?
                } else {
                    family.sleeping(*spin)?
                };
                Linearisation::try_new(&family, &x)
            }
            Self::GroundSpin {
                body,
                gravity_world,
                up_body,
                spin,
            } => {
                let family = BodyOnGround::try_from_body(body, *gravity_world)?;
                Linearisation::try_new(&family, &family.spinning_about_vertical(*up_body, *spin)?)
            }
            Self::Precession {
                top,
                tilt,
                spin,
                which,
            } => {
                let family = PrecessingTop::of(&top.heavy_top()?)?;
                Linearisation::try_new(&family, &family.steady(*tilt, *spin, *which)?)
            }
        }
    }

    /// The values of `parameter` (the others as they are) where the closed
    /// form says stability changes, if there is a closed form; empty if it
    /// never changes.
    ///
    /// ```text
    /// sleeping top (J₁ = J₂ about the pivot):  J₃² Ω² = 4 J₁ M g l
    ///   spin: Ω = ±√(4 J₁ M g l)/J₃;  gravity: g = J₃²Ω²/(4 J₁ M l)
    ///   com_offset: 4 M² g l³ + 4 I₁ M g l − J₃² Ω² = 0   (J₁ = I₁ + M l², one positive root)
    /// ```
    pub fn closed_form_boundary(&self, parameter: Parameter) -> Option<Vec<f64>> {
        match self {
            Self::FreeRotation { .. } | Self::Precession { .. } => Some(Vec::new()),
            Self::GroundSpin { .. } => None,
            Self::SleepingTop { hanging: true, .. } => Some(Vec::new()),
            Self::SleepingTop { top, spin, .. } => {
                let family = HeavyTopPivot::of(&top.heavy_top().ok()?);
                let j = family.moments_about_pivot().to_array();
                let c = family.com_principal();
                let k = (0..3).max_by(|&a, &b| c[a].abs().total_cmp(&c[b].abs()))?;
                let (a, b) = ((k + 1) % 3, (k + 2) % 3);
                if (j[a] - j[b]).abs() > 1e-12 * j[a] {
                    return None;
                }
                let mass = top.mass_properties.mass;
                let (g, l, j1, j3) = (top.gravity_world.length(), c.length(), j[a], j[k]);
                match parameter {
                    Parameter::Spin => {
                        let critical = (4.0 * j1 * mass * g * l).sqrt() / j3;
                        Some(vec![-critical, critical])
                    }
                    Parameter::Gravity => Some(vec![(j3 * spin).powi(2) / (4.0 * j1 * mass * l)]),
                    Parameter::ComOffset => {
                        let i1 = j1 - mass * l * l;
                        Some(vec![positive_cubic_root(
                            4.0 * mass * mass * g,
                            4.0 * i1 * mass * g,
                            -(j3 * spin).powi(2),
                        )])
                    }
                    Parameter::Tilt | Parameter::Speed => None,
                }
            }
        }
    }

    /// The steady motion `kind` of `body` at its state's parameters: a top
    /// on a pivot sleeping or hanging at its spin about the axis through
    /// the centre of mass, or precessing at its tilt and that spin; or
    /// the one nearest its state ([`SteadyProblem::near`]).
    ///
    /// ```text
    /// ĉ = (c − pivot)/|c − pivot|,   spin = ω·ĉ,   tilt = ∠(γ, ĉ)   (body axes)
    /// ```
    ///
    /// # Errors
    /// [`AnalysisError::NoSuchMotion`] for a named kind on a body without
    /// a pivot; as [`SteadyProblem::near`] for the nearest.
    pub fn named(
        body: &Body,
        gravity_world: DVec3,
        kind: SteadyKind,
    ) -> Result<Self, AnalysisError> {
        let which = match kind {
            SteadyKind::Nearest => return Self::near(body, gravity_world),
            SteadyKind::Sleeping | SteadyKind::Hanging => None,
            SteadyKind::SlowPrecession => Some(Precession::Slow),
            SteadyKind::FastPrecession => Some(Precession::Fast),
        };
        refuse_driven(body)?;
        let Support::Pivot { pivot_body, .. } = body.support() else {
            return Err(AnalysisError::NoSuchMotion {
                kind: "named steady motion",
                why: format!(
                    "steady = \"{kind}\" needs a body on a pivot; give steady = \"nearest\" (or none)"
                ),
            });
        };
        let top = PivotBody {
            mass_properties: *body.mass_properties(),
            pivot_body,
            gravity_world,
        };
        let axis = (top.mass_properties.center_of_mass - pivot_body).normalize_or_zero();
        let spin = body.omega_body().dot(axis);
        Ok(match which {
            None => Self::SleepingTop {
                top,
                spin,
                hanging: kind == SteadyKind::Hanging,
            },
            Some(which) => {
                let up_body = body.world_from_body().normalize().conjugate()
                    * (-gravity_world.normalize_or(DVec3::NEG_Z));
                Self::Precession {
                    top,
                    tilt: up_body.dot(axis).clamp(-1.0, 1.0).acos(),
                    spin,
                    which,
                }
            }
        })
    }

    /// The steady motion nearest the state of `body` (at rest or spinning;
    /// free, on a pivot, on the ground, or on the table with one contact
    /// shape, sticking) under `gravity_world`, found with the start's
    /// Casimirs and momenta kept ([`find_steady_motion`]).
    ///
    /// # Errors
    /// [`AnalysisError::NoSteadyMotionNearby`] with the residuals when
    /// there is none; [`AnalysisError::NoSuchMotion`] for a body on the
    /// table it cannot take (see `sticking_on_ground`: several contact
    /// shapes, not touching, a set-valued law), or a body with applied
    /// torques, forces or damping.
    pub fn near(body: &Body, gravity_world: DVec3) -> Result<Self, AnalysisError> {
        refuse_driven(body)?;
        let rigid = body.rigid_body();
        match body.support() {
            Support::Free { .. } => {
                let family = FreeBodyRotation::of(rigid);
                let omega_principal = rigid.body_from_principal().conjugate() * body.omega_body();
                let found = find_steady_motion(&family, &omega_principal.to_array())?;
                let axis = (0..3)
                    .max_by(|&a, &b| found.state[a].abs().total_cmp(&found.state[b].abs()))
                    .unwrap_or(0);
                Ok(Self::FreeRotation {
                    moments: family.moments(),
                    axis,
                    spin: found.state[axis],
                })
            }
            Support::Pivot { pivot_body, .. } => {
                let top = PivotBody {
                    mass_properties: *body.mass_properties(),
                    pivot_body,
                    gravity_world,
                };
                near_pivot(top, body.world_from_body(), body.omega_body())
            }
            Support::Ground { velocity_xy, .. } => {
                let family = BodyOnGround::try_from_body(body, gravity_world)?;
                let body_from_world = body.world_from_body().normalize().conjugate();
                let up = body_from_world * DVec3::Z;
                let mut start: Vec<f64> = up
                    .to_array()
                    .into_iter()
                    .chain(body.omega_body().to_array())
                    .collect();
                if !family.rolls() {
                    start.extend((body_from_world * velocity_xy.extend(0.0)).to_array());
                }
                let found = find_steady_motion(&family, &start)?;
                let up_body = DVec3::from_slice(&found.state[..3]);
                let omega = DVec3::from_slice(&found.state[3..6]);
                Ok(Self::GroundSpin {
                    body: Box::new(body.clone()),
                    gravity_world,
                    spin: omega.dot(up_body) / up_body.length_squared(),
                    up_body,
                })
            }
            Support::Table { position, .. } => {
                let on_ground = sticking_on_ground(body, position)?;
                Self::near(&on_ground, gravity_world)
            }
        }
    }
}

/// The steady motion of a top on a pivot nearest its state.
fn near_pivot(
    top: PivotBody,
    world_from_body: DQuat,
    omega_body: DVec3,
) -> Result<SteadyProblem, AnalysisError> {
    let engine = top.heavy_top()?;
    let body_from_principal = engine.body().body_from_principal();
    let up_world = -top.gravity_world.normalize_or(DVec3::NEG_Z);
    let principal_from_world = (world_from_body.normalize() * body_from_principal).conjugate();
    let gamma = principal_from_world * up_world;
    let omega = body_from_principal.conjugate() * omega_body;
    let c = engine.com_principal();
    let cos_tilt = gamma.dot(c.normalize_or_zero()).clamp(-1.0, 1.0);
    let upright = 1.0 - cos_tilt.abs() <= 1e-9;
    if upright || engine.symmetry_axis().is_none() {
        let family = HeavyTopPivot::of(&engine);
        let start: Vec<f64> = gamma
            .to_array()
            .into_iter()
            .chain(omega.to_array())
            .collect();
        let found = find_steady_motion(&family, &start)?;
        let g = DVec3::from_slice(&found.state[..3]);
        let w = DVec3::from_slice(&found.state[3..]);
        return Ok(SteadyProblem::SleepingTop {
            spin: w.dot(g) / g.length_squared(),
            hanging: g.dot(c) < 0.0,
            top,
        });
    }
    // Symmetric and tilted: the Euler-angle reduction.
    let family = PrecessingTop::of(&engine)?;
    let (j1, j3, _) = family.parameters();
    let axis = c.normalize();
    let theta = cos_tilt.acos();
    let theta_dot = -gamma.cross(omega).dot(axis) / theta.sin();
    let moments = engine.body().principal_moments();
    let p_phi = (moments * omega).dot(gamma);
    let p_psi = j3 * omega.dot(axis);
    let found = find_steady_motion(&family, &[theta, j1 * theta_dot, p_phi, p_psi])?;
    let (theta0, spin) = (found.state[0], found.state[3] / j3);
    let phi_dot = (found.state[2] - found.state[3] * theta0.cos()) / (j1 * theta0.sin().powi(2));
    let distance = |which| {
        family
            .precession_rate(theta0, spin, which)
            .map_or(f64::INFINITY, |rate| (rate - phi_dot).abs())
    };
    let which = if distance(Precession::Slow) <= distance(Precession::Fast) {
        Precession::Slow
    } else {
        Precession::Fast
    };
    Ok(SteadyProblem::Precession {
        top,
        tilt: theta0,
        spin,
        which,
    })
}

/// The positive root of `a x³ + b x + d = 0` with `a, b > 0`, `d < 0`
/// (increasing in `x`: exactly one), by Newton from a bound.
fn positive_cubic_root(a: f64, b: f64, d: f64) -> f64 {
    let mut x = (-d / b).min((-d / a).cbrt());
    for _ in 0..100 {
        let step = (a * x * x * x + b * x + d) / (3.0 * a * x * x + b);
        x -= step;
        if step.abs() <= 1e-16 * x.abs() {
            break;
        }
    }
    x
}

/// The families are the bodies' own motions under gravity and contact: a
/// body with applied torques, forces or damping ([`kreisel_dynamics::Inputs`])
/// is refused, not analysed as if it had none.
fn refuse_driven(body: &Body) -> Result<(), AnalysisError> {
    if body.inputs().is_none() {
        return Ok(());
    }
    Err(AnalysisError::NoSuchMotion {
        kind: "steady motion",
        why: "the body is driven (torque, force or angular damping): the analysis takes \
              the motion under gravity and contact alone"
            .into(),
    })
}

/// A body on the table touching it with one contact shape, as the same
/// body on the ground: a steady spin about the vertical has no slip at
/// the contact, so Coulomb friction (μ > 0) sticks there, and small
/// perturbations keep the friction force inside the cone: to first order
/// the contact rolls ([`Friction::Rolling`]); with μ = 0 it slides
/// freely ([`Friction::None`]).
///
/// ```text
/// gap z_G + ρ_z = 0 (to 1e-9 of the shape's size),   μ > 0 → rolling,   μ = 0 → frictionless
/// ```
///
/// # Errors
/// [`AnalysisError::NoSuchMotion`] for several contact shapes, a body
/// above the table, or a law the linearisation cannot take (a drilling
/// Contensou torque, rolling resistance or an air layer: each is
/// set-valued or slows the spin, so nothing is steady).
fn sticking_on_ground(body: &Body, position: DVec3) -> Result<Body, AnalysisError> {
    let refuse = |why: String| AnalysisError::NoSuchMotion {
        kind: "steady motion on the table",
        why,
    };
    let [contact] = body.table_contacts() else {
        return Err(refuse(format!(
            "the body touches the table with {} contact shapes; the analysis takes one",
            body.table_contacts().len()
        )));
    };
    let law = contact.law;
    if law.contensou_radius() > 0.0 || law.rolling_resistance() > 0.0 || law.air_layer().is_some() {
        return Err(refuse(
            "its contact law has a drilling torque, rolling resistance or an air layer \
             (set-valued, or slowing the spin: nothing is steady)"
                .into(),
        ));
    }
    let gap = position.z
        + contact
            .shape
            .contact_from_com_world(body.world_from_body())
            .z;
    if gap.abs() > 1e-9 * contact.shape.size() {
        return Err(refuse(format!(
            "it starts {gap:.3e} m from the table (it must touch it to spin steadily on it)"
        )));
    }
    let friction = if law.mu() > 0.0 {
        Friction::Rolling
    } else {
        Friction::None
    };
    Ok(Body::from_mass_properties(*body.mass_properties())
        .world_from_body(body.world_from_body())
        .omega_body(body.omega_body())
        .on_ground(contact.shape, friction)
        .try_build()?)
}
