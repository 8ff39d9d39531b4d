//! # kreisel-dynamics
//!
//! The torque-free rigid body and the heavy top to machine precision:
//! - [`ExactSolution`] (method `exact`, the default `auto`): the exact
//!   motion, attitude included — a uniform rotation for a sphere or a spin
//!   about a principal axis, two commuting rotations for a symmetric body,
//!   Jacobi elliptic functions for an asymmetric one, parametrised by the
//!   complementary parameter so that it stays exact next to the separatrix
//!   and on it. ≤ 2e-14 rad against 60-digit references, at any step;
//! - integrators behind one trait, [`FreeBodyIntegrator`]: the classical
//!   RK4 as the honest baseline, splittings into exact rotations and their
//!   symmetric compositions to order 8, the discrete Moser–Veselov
//!   algorithm and its preprocessed versions of orders 4–10;
//! - invariants, the principal-axis stability of notes §3.7 and the exact
//!   flip period ([`axis_stability`], [`elliptic_motion`]);
//! - the heavy top on a fixed pivot, any inertia tensor and centre of mass,
//!   [`HeavyTop`]: the kick–free–kick splitting (exact free flow for a
//!   symmetric top, PDMV10 otherwise) and its compositions to order 8 with
//!   their stability limits, [`HeavyTopAuto`] (sub-stepped order 8, the
//!   default) and RK4, behind [`HeavyTopIntegrator`];
//! - the heavy symmetric (Lagrange) top in closed form, [`LagrangeTop`] →
//!   [`LagrangeTopMotion`]: nutation by Jacobi's sn², precession and spin by
//!   elliptic integrals of the third kind, turning points, nutation period,
//!   the kinds of motion, sleeping-top stability and steady precession
//!   (notes §3.10–3.11);
//! - [`elliptic`]: the elliptic integrals and Jacobi functions this needs;
//! - the methods as types, [`FreeBodyMethod`] and [`HeavyTopMethod`]: one
//!   list per enum, one line per method (`Variant => &INTEGRATOR`), that
//!   the CLI, the Python package, the benches and the tests read
//!   ([`FreeBodyMethod::ALL`], `FromStr`, `Display`, `integrator()`); each
//!   method's name, order, one-line description and step limit are its
//!   integrator's. Adding a method is one file (the integrator) and one
//!   line of the list in `method/free_body.rs` or `method/heavy_top.rs`
//!   (`method/forward_euler.rs` does it in a test);
//! - a body touching the ground plane with a sphere (the tippe top),
//!   [`GroundTop`]: the normal force solved from the constraint, friction
//!   models [`Friction`], lift-off reported ([`contact`]);
//! - [`World`]: bodies ([`Body`]: mass properties, attitude, spin, a free
//!   or pivot [`Support`]) under gravity, moved by `step(h)` for game loops
//!   or `advance_to(t)` for simulations along each body's cheapest exact
//!   [`Plan`] (a torque-free body is never stepped, only evaluated);
//! - for `f32` game engines (bevy, avian, rapier), [`FreeBodyF32`]: one
//!   frame of torque-free motion on glam's `Quat`/`Vec3`, attitude and
//!   world-axes `ω` in and out, computed in `f64` and rounded once.
//!
//! ## Conventions
//! - SI units, radians. States live in the principal frame:
//!   `world_from_principal` maps principal coordinates to world coordinates,
//!   `l_principal` is the angular momentum in principal axes,
//!   `ω = I⁻¹ L`. [`RigidBody`] converts to and from body axes.
//! - Euler's equations `L̇ = L × ω` and `q̇ = ½ q ⊗ (0, ω)` (notes §3.5–3.7).
//!
//! ## Which body and state type is for what
//! One line each; a user of the engine needs only [`Body`], [`World`] and
//! [`BodyState`], the rest are the models the World plans a body onto.
//! - [`Body`] (built by [`BodyBuilder`]): what a [`World`] holds — mass
//!   properties, attitude, spin, support, inputs, contacts.
//! - [`BodyState`]: what the World reports of a body at a time (attitude,
//!   `omega_body`, `l_world`, energy, centre of mass and its velocity):
//!   every output row.
//! - [`RigidBody`] with [`PrincipalState`]: the torque-free body's moments
//!   and its state in the principal frame, what [`FreeBodyIntegrator`]s
//!   and [`ExactSolution`] advance.
//! - [`ForcedBody`] with [`ForcedState`]: a free body under torques, forces
//!   and damping ([`Inputs`]), its centre of mass moving too.
//! - [`HeavyTop`] (moments about the pivot, a [`PrincipalState`]): a body
//!   on a fixed pivot under gravity, for [`HeavyTopIntegrator`]s.
//! - [`LagrangeTop`] → [`LagrangeTopMotion`]: the symmetric heavy top's
//!   parameters and its motion in closed form.
//! - [`GroundTop`] with [`GroundTopState`]: a body on the ground plane with
//!   one contact kept closed and smooth friction ([`Friction`]).
//! - [`TableBody`] → [`TableMotion`]: a body on the table with unilateral
//!   contacts, impacts and set-valued friction, run event to event.
//!
//! ```
//! use glam::{DQuat, DVec3};
//! use kreisel_dynamics::{integrate, FreeBodyMethod, PrincipalState, RigidBody};
//! let body = RigidBody::try_from_principal_moments(DVec3::new(1.0, 2.0, 3.0))?;
//! let mut s = PrincipalState::try_from_omega_body(&body, DQuat::IDENTITY, DVec3::new(0.01, 1.0, 0.0))?;
//! let l0 = s.l_world();
//! let method: FreeBodyMethod = "splitting6".parse()?;
//! integrate(method.integrator(), body.principal_moments(), &mut s, 0.01, 1000)?;
//! // Exact rotations conserve L_world up to rounding (~1e-13 after 17 000 flows).
//! assert!((s.l_world() - l0).length() < 1e-12 * l0.length());
//! # Ok::<(), kreisel_dynamics::DynamicsError>(())
//! ```
#![deny(missing_docs)]
#![forbid(unsafe_code)]

mod composition;
pub mod contact;
mod divergence;
pub mod elliptic;
mod error;
mod exact;
mod forced;
mod free_body_f32;
mod heavy_top;
mod lagrange_top;
mod method;
mod moser_veselov;
mod moser_veselov_preprocessed;
pub mod polhode;
mod rigid_body;
mod rk4;
#[doc(hidden)]
pub mod splitting;
mod stability;
mod state;
mod stepping;
pub mod table;
mod world;

pub use composition::{Composition, CompositionCoefficients, KAHAN_LI_6, KAHAN_LI_8, SUZUKI_4};
pub use contact::{
    AdaptiveStats, AdaptiveTolerance, ContactShape, DiskContact, EllipsoidContact, Friction,
    FrictionModel, GROUND_CHECK_TOLERANCE, GroundCheck, GroundTop, GroundTopState, GroundViolation,
    Landing, MAX_OTHER_CONTACTS, SphereContact,
};
pub use divergence::{DIVERGENCE_FACTOR, DivergenceCheck};
pub use error::{Divergence, DynamicsError};
pub use exact::{ExactFlow, ExactPropagator, ExactSolution};
pub use forced::{
    ForcedBody, ForcedPropagator, ForcedSplitting, ForcedState, Inputs, Load, LoadFn, PointForce,
};
pub use free_body_f32::{FreeBodyF32, try_free_body_step_f32};
pub use heavy_top::{
    HeavyTop, HeavyTopAuto, HeavyTopRk4, HeavyTopSplitting, HeavyTopTaylor, MAX_SUBSTEPS,
    TAYLOR_MAX_ORDER,
};
pub use lagrange_top::{
    EulerAnglesAndRates, HeavyTopClosedForm, LagrangeTop, LagrangeTopInitial, LagrangeTopMotion,
    SteadyPrecession, TopMotionKind,
};
pub use method::{FreeBodyMethod, HeavyTopMethod, STEP_LIMIT_ENERGY_ERROR};
pub use moser_veselov::MoserVeselov;
pub use moser_veselov_preprocessed::PreprocessedMoserVeselov;
pub use rigid_body::{MIN_MOMENT_RATIO, RigidBody};
pub use rk4::Rk4;
pub use splitting::{AxisStrang, SymmetricTopSplitting};
pub use stability::{
    AxisStability, EllipticMotion, axis_stability, elliptic_motion, try_axis_stability,
};
pub use state::PrincipalState;
pub use stepping::{
    FreeBodyIntegrator, HeavyTopIntegrator, Propagator, integrate, integrate_heavy_top,
};
pub use table::{
    AirLayer, ContactLaw, ContactMode, DISK_FLAT_TILT, FACE_LANDING, SLIP_BAND, TABLE_ACCUMULATION,
    TABLE_RESOLUTION, TableBody, TableContact, TableEvent, TableEventKind, TableMotion,
};
pub use world::{
    Body, BodyBuilder, BodyId, BodyState, Choice, DEFAULT_TABLE_TOLERANCE, Plan, Support,
    Tolerance, WHOLE_STEPS_TOLERANCE, World, grid_steps, table_tolerance,
};
