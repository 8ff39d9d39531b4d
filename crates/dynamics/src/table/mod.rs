//! Bodies on a table as nonsmooth mechanics: any number of contact
//! shapes per body, unilateral contact (Signorini), impacts with Newton's
//! restitution, set-valued Coulomb friction with Contensou's drilling
//! friction, set-valued rolling resistance — run from any start to rest,
//! with the events recorded.
//!
//! - [`ContactLaw`]: `μ`, restitution `e`, tangential restitution `e_T`,
//!   the Contensou patch radius, the rolling resistance;
//! - [`TableBody`], [`TableContact`]: the body and its shapes
//!   ([`crate::ContactShape`]: spheres, disk rims, ellipsoids);
//! - [`TableMotion`]: the event-driven run (Dormand–Prince 5(4) with error
//!   control between events in contact, the exact flight between contacts;
//!   lift-off, touchdown, impacts, stick and slip located to rounding),
//!   [`TableEvent`]s while it goes on;
//! - [`ContactMode`]: open, slipping or sticking.
//!
//! # The model
//! State `y = (r_G, v_G, q, L)` as for [`crate::GroundTop`], velocities
//! `u = (v_G, ω)`, mass matrix `M = diag(m 𝟙, I_w)`. Each contact `i` has
//! a gap `gᵢ` (the height of its shape's lowest point) and, while closed,
//! a normal force `Nᵢ` and friction `Λᵢ` acting along the directions of
//! its frame (`contact_frame`): the normal `w_N`, the slip directions
//! `w_x, w_y` and, with a Contensou patch, the drilling direction
//! `w_d = (0, ε ẑ)`. Between events
//!
//! ```text
//! M u̇ = h(y) + Σ_i (w_N Nᵢ + W_T Λᵢ),     h = (−m g ẑ, −ω × L)
//! closed contact:   g̈ᵢ = 0,   Nᵢ ≥ 0
//! sticking:         γ̇_Tᵢ = 0, |Λᵢ| ≤ μ Nᵢ
//! slipping:         Λᵢ = −μ Nᵢ γ_Tᵢ/|γ_Tᵢ|
//! rolling held:     γ̇_Rᵢ = 0, |Λ_Rᵢ| ≤ Nᵢ      (rolling resistance δ: γ_R = δ ω_h, torque δ Λ_R)
//! rolling:          Λ_Rᵢ = −Nᵢ γ_Rᵢ/|γ_Rᵢ|
//! ```
//!
//! and at an impact (a contact closing with speed) Newton's law with
//! friction on the impulses ([`ContactLaw`] has the formulas). The energy
//! never rises: friction dissipates `μ N |γ_T|`, an impact that Newton's
//! law with `e_T ≠ e` would make gain energy takes `e_T = e` (which cannot),
//! every impact is checked (a gain is
//! [`crate::DynamicsError::ImpactGainsEnergy`]), a contact that
//! starts to stick loses its residual slip by a dissipative impulse.
//!
//! # Contacts that overconstrain the body
//! Two sticking contacts (a dumbbell on both feet, a body pivoting about
//! the line through two contact points) fix fewer freedoms than they have
//! force components: the motion is unique, the forces are not. The mode
//! system is then solved by complete pivoting (its least-norm solution and
//! null space) and the forces taken deepest inside the cones
//! (`force_distribution`, a barrier method on the margin): sticking ends
//! where no admissible distribution is left. At events, block
//! Gauss–Seidel has settled once its sweeps move only along that null
//! space; where it converges slowly, the modes it shows are solved exactly
//! and checked (`active_set`). A contact the solve leaves on the cone's
//! edge sticks where the forces of those modes keep every contact in its
//! cone (the solve's distribution is one of many; a slip read off it
//! reversed at once).
//!
//! # The contacts' problem
//! At events the accelerations and forces of the touching contacts solve
//! Signorini's law, the friction cones (drilling included) and the
//! rolling cones together: block Gauss–Seidel over the contacts, sweeps
//! between them and the rolling cones, and where those settle too slowly
//! or cycle, a semismooth Newton method on the Alart–Curnier equations of
//! the problem whole from where they got to (`contact_newton`); the same
//! at impacts, on the impulses. A slip is decided afresh where its
//! direction is not resolved: within the resolution, or turned by a right
//! angle or more within the band against the direction it holds there.
//!
//! # Disks: rim, face and air
//! A disk rim that reaches flat (its axis within [`DISK_FLAT_TILT`] of the
//! vertical) while touching either rocks on through flat — its far rim
//! point strikes, both rim points taking part in the impact — or, when its
//! face arrives slowly (normal speeds below [`FACE_LANDING`] of the speed
//! scale), lands on its face (a plastic landing, [`TableEventKind::LandsFlat`])
//! and slides and spins there under the face's Coulomb–Contensou friction
//! until it rests (`face`). A face closing flat from flight with the rim's
//! restitution `e > 0` bounces: Newton's law over the face (its centre's
//! normal speed and both tilting rates reverse by `e`) with friction at
//! the impact; the bounces accumulate and the disk lands flat.
//! [`AirLayer`] is Moffatt's viscous air layer under a rim, the
//! dissipation of Euler's disk.
//!
//! # What it does not do (yet)
//! The rolling resistance acts between impacts, not in them (its impulse
//! would be at most `δ P_N`). Newton's method on the contacts' problem can
//! stop at a local minimum of its merit where no sweep leads out
//! (`ContactUnsolved`, 2 of the 100 random throws of `BENCHMARKS.md`); a
//! slip hovering at the band's edge under a Contensou patch runs slowly
//! (1 of 100). Inputs
//! are not followed on a face ([`crate::DynamicsError::DiskFlat`]). Free
//! flight is exact (parabola and the torque-free
//! [`crate::ExactSolution`]); applied inputs ([`TableBody::try_with_inputs`])
//! and air layers
//! act beside the contacts (the flight is then integrated).

mod active_set;
mod air_layer;
mod contact_block;
mod contact_frame;
mod contact_law;
mod contact_newton;
mod contact_problem;
mod dense;
mod face;
mod force_distribution;
mod impact;
mod rolling_resistance;
mod slip_onset;
mod table_body;
mod table_event;
mod table_motion;

pub use self::air_layer::AirLayer;
pub use self::contact_law::ContactLaw;
pub use self::contact_problem::ContactMode;
pub use self::table_body::{TableBody, TableContact};
pub use self::table_event::{TableEvent, TableEventKind};
pub use self::table_motion::{
    DISK_FLAT_TILT, FACE_LANDING, SLIP_BAND, TABLE_ACCUMULATION, TABLE_RESOLUTION, TableMotion,
};
