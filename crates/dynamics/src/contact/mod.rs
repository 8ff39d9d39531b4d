//! Bodies on a table: a rigid body touching the ground plane `z = 0`
//! (gravity `−g ẑ`) with a body-fixed sphere — the ball-ended top, the
//! tippe top —, a circular rim — a coin, Euler's disk — or an ellipsoid —
//! the rattleback.
//!
//! - [`SphereContact`]: the sphere's geometry (radius `R`, centre `c` in
//!   body axes from the centre of mass) and the constraint's residual;
//! - [`DiskContact`]: a rim (radius `r`, centre `c`, axis `n` in body
//!   axes), its lowest point and that point's rate;
//! - [`EllipsoidContact`]: an ellipsoid (semi-axes along the body axes,
//!   centre `c`), its lowest point and that point's rate; [`ContactShape`]
//!   chooses among the three ([`GroundTop::try_with_shape`]);
//! - [`Friction`] ([`FrictionModel`] names it): `none`, `viscous`,
//!   regularised Coulomb `sliding`, and `rolling` without slipping
//!   (nonholonomic, conservative);
//! - [`GroundTop`], [`GroundTopState`]: the equations of motion, energy,
//!   Jellett's integral, the normal force; a fixed-step RK4 with lift-off
//!   located and reported ([`GroundTop::try_step`]);
//! - [`GroundTop::try_with_other_contacts`]: further shapes (a stem's
//!   ball) watched for touchdown, reported with its time;
//! - [`GroundTop::try_fly`]: after a lift-off, the exact ballistic flight
//!   until a shape lands ([`Landing`], with its time);
//! - [`GroundCheck`]: the guard after every step of a run (|q|, the
//!   contact on the plane, the centre of mass above it, the energy), a
//!   typed error with its time beyond [`GROUND_CHECK_TOLERANCE`];
//! - [`GroundTop::try_advance_adaptive`]: Dormand–Prince 5(4) with
//!   step-size control to an [`AdaptiveTolerance`], the same contact
//!   checks, statistics in [`AdaptiveStats`].
//!
//! # The model
//! State: centre of mass `r_G`, its velocity `v_G`, attitude `q`
//! (body → world, rotation `A`), angular momentum about the centre of mass
//! in world axes `L`. Inertia `I` about the centre of mass in body axes
//! (any symmetric positive-definite tensor), in world axes
//! `I_w = A I Aᵀ`, `ω = I_w⁻¹ L`. The sphere's centre seen from the centre
//! of mass is `A c`; its lowest point, the contact point, is
//! `r_P = r_G + ρ` with `ρ = A c − R ẑ`.
//!
//! While the sphere touches, the holonomic constraint and its derivatives
//! are (`(ω × ẑ)_z = 0`, so the vertical velocity of the contact point is
//! `ġ`):
//!
//! ```text
//! g  = z_G + (A c)_z − R = 0
//! ġ  = ż_G + (ω × A c)_z = (v_P)_z,          v_P = v_G + ω × ρ
//! g̈  = z̈_G + (ω̇ × A c)_z + (ω × (ω × A c))_z = 0
//! ```
//!
//! The plane pushes with `N ẑ` and rubs with `F = N f(v_P)`, `f` the
//! horizontal force per newton of [`Friction`] evaluated on the horizontal
//! part of `v_P` (not on accelerations), so the contact force is `N e`,
//! `e = ẑ + f`. Newton and Euler about the centre of mass, with
//! `d(I_w ω)/dt = I_w ω̇ + ω × L`:
//!
//! ```text
//! m v̇_G = N e − m g ẑ
//! L̇     = ρ × N e
//! ω̇     = I_w⁻¹ (L̇ + L × ω)
//! q̇     = ½ (0, ω) ⊗ q
//! ```
//!
//! Putting `z̈_G = N/m − g` (`e_z = 1`) and `ω̇` into `g̈ = 0` gives one
//! linear equation for `N` — the DAE of index 3 reduced to an ODE, as in
//! the tippe-top models of Leine & Glocker (2003), Ueda, Sasaki & Watanabe
//! (2005) and Rauch-Wojciechowski & Rutstam (2014):
//!
//! ```text
//! N = [g − ((I_w⁻¹ (L × ω)) × A c)_z − (ω × (ω × A c))_z] / κ
//! κ = 1/m + ((I_w⁻¹ (ρ × e)) × A c)_z
//! ```
//!
//! Without friction `κ = 1/m + (ρ × ẑ)·I_w⁻¹(ρ × ẑ) > 0`; with strong
//! friction `κ` may vanish (Painlevé), reported as
//! [`crate::DynamicsError::ContactIndeterminate`]. `N ≤ 0` is lift-off,
//! reported as [`crate::DynamicsError::ContactLost`] with its time: the
//! model never lets the contact pull.
//!
//! # Rolling without slipping
//! With [`Friction::Rolling`] the contact point's material velocity is
//! held at zero, all three components (the vertical one is `ġ`):
//!
//! ```text
//! v_P = v_G + ω × ρ = 0,     ρ̇ = ω × A c   (ẑ is fixed)
//! ```
//!
//! The whole contact force `F` (three unknowns: normal and tangential) is
//! the reaction that keeps it there. Differentiating, with `v̇_G = F/m − g ẑ`,
//! `L̇ = ρ × F` and `ω̇ = I_w⁻¹ (ρ × F) + I_w⁻¹ (L × ω)`:
//!
//! ```text
//! 0 = d v_P/dt = F/m − g ẑ + ω̇ × ρ + ω × (ω × A c)
//!   = F/m − g ẑ − ρ × (I_w⁻¹ (ρ × F)) − ρ × (I_w⁻¹ (L × ω)) + ω × (ω × A c)
//!
//! K F = b,   K = 1/m 𝟙 − [ρ]× I_w⁻¹ [ρ]× = 1/m 𝟙 + [ρ]×ᵀ I_w⁻¹ [ρ]×
//!            b = g ẑ + ρ × (I_w⁻¹ (L × ω)) − ω × (ω × A c)
//! ```
//!
//! (`[ρ]× x = ρ × x`). `K` is symmetric positive definite (`x·K x =
//! |x|²/m + (ρ × x)·I_w⁻¹(ρ × x)`), so `F` always exists and is unique —
//! no Painlevé case; its vertical row is the `g̈ = 0` equation of the
//! friction laws. `F_z ≤ 0` is lift-off, reported as
//! [`crate::DynamicsError::ContactLost`] as for the other models. The
//! reaction does no work (`Ė = F·v_P = 0`), so the energy is conserved,
//! and λ as for every force at the contact point.
//!
//! The initial state must satisfy the constraint:
//! [`GroundTop::try_rolling_state_on_ground`] sets `v_G = −ω × ρ`;
//! [`GroundTop::try_state_on_ground`] refuses a rolling start with slip.
//! The ODE keeps `d v_P/dt = 0` exactly, so RK4 keeps `v_P` constant up to
//! its `O(h⁴)` error per unit time: `v_P` drifts, it is not projected back
//! (measured in `tests/contact_sphere_rolling.rs`).
//!
//! # A disk rim
//! For a [`DiskContact`] the contact point moves over the rim, so
//! `ρ = A c + r û` (formulas at [`DiskContact`]) has a rate `ρ̇` other than
//! `ω × A c`. Everything above holds with `A c` replaced by `ρ` in the
//! cross products with `ω̇` and `ω × (ω × A c)` replaced by `ω × ρ̇`: for a
//! convex contact `ġ = (v_P)_z` (the lowest point is a minimum of the
//! height over the surface), so `g̈ = d(v_P)_z/dt` and
//!
//! ```text
//! d v_P/dt = v̇_G + ω̇ × ρ + ω × ρ̇
//! N = [g − ((I_w⁻¹ (L × ω)) × ρ)_z − (ω × ρ̇)_z] / [1/m + ((I_w⁻¹ (ρ × e)) × ρ)_z]
//! b = g ẑ + ρ × (I_w⁻¹ (L × ω)) − ω × ρ̇          (rolling)
//! ```
//!
//! (for a sphere `(x × ρ)_z = (x × A c)_z` and `ρ̇ = ω × A c`: the same
//! equations; the code evaluates this general form for both). Jellett's
//! λ is an integral of the sphere only.
//!
//! # An ellipsoid
//! An [`EllipsoidContact`] (semi-axes `E = diag(a, b, c)` along the body
//! axes) touches at the surface point whose outward normal is `−ẑ`, in
//! body axes `n_b = Aᵀ(−ẑ)`: `ρ = A (c + E² n_b/√(n_bᵀ E² n_b))`. It too
//! moves over the surface, with `ρ̇ = ω × ρ + A ṗ_b` (formulas at
//! [`EllipsoidContact`]), and the surface is convex, so the disk's general
//! form above holds unchanged. With equal semi-axes it is the sphere
//! (tested to rounding). Kane & Levinson's rattleback (an ellipsoid whose
//! inertia axes are turned about the vertical against its geometric axes)
//! rolling without slipping reverses its spin while conserving energy
//! (`tests/contact_rattleback.rs`); λ is not conserved.
//!
//! # Applied loads
//! [`GroundTop::try_with_inputs`] adds the crate's [`crate::Inputs`] — a
//! torque `τ` about the centre of mass and a force `F` through it, both
//! world axes, summed from constant parts, forces at body points, angular
//! damping and a user law of `(t, state)`. They enter Newton and Euler
//! beside the contact force, and so the contact force itself:
//!
//! ```text
//! m v̇_G = N e + F − m g ẑ,   L̇ = ρ × N e + τ,   ω̇ = I_w⁻¹ (ρ × N e + τ + L × ω)
//! N = [g − F_z/m − ((I_w⁻¹ (L × ω + τ)) × ρ)_z − (ω × ρ̇)_z] / κ
//! b = g ẑ − F/m + ρ × (I_w⁻¹ (L × ω + τ)) − ω × ρ̇          (rolling)
//! ```
//!
//! The energy then changes by the inputs' power too,
//! `Ė = N f·v_P + τ·ω + F·v_G` ([`GroundTop::input_power`]; tested as
//! `E(T) − E(0) = ∫ P dt` in `tests/contact_loads.rs`, with Moffatt's
//! finite-time law for Euler's disk under a dissipation of his form).
//!

//! A body may carry further body-fixed shapes that do not touch at the
//! start ([`GroundTop::try_with_other_contacts`], at most
//! [`MAX_OTHER_CONTACTS`]) — the stem's ball of Leine & Glocker's tippe
//! top, which reaches the table near θ = 140°. They exert no force: the
//! equations above are those of the main shape's contact alone. Each
//! further shape's gap, the height of its lowest point, and its rate
//!
//! ```text
//! gᵢ = z_G + (ρᵢ)_z,   ġᵢ = ż_G + (ω × ρᵢ)_z     (sphere: ρᵢ = A cᵢ − Rᵢ ẑ)
//! ```
//!
//! are checked after every step: where a gap is not positive at the
//! step's end — or the cubic Hermite interpolant of `gᵢ` over the step
//! dips below zero and the redone step confirms it (a graze) — the
//! instant is located by bisection on the step size, the state left there
//! (`gᵢ ≈ 0`), and [`crate::DynamicsError::ContactTouchdown`] reports the
//! time, which shape and its approach speed `−ġᵢ`. The model does not
//! handle the impact nor the two-contact motion after it: it stops and
//! reports, as for a lift-off. A start state with a further shape at or
//! below the plane is [`crate::DynamicsError::OtherContactTouching`].
//!
//! After a lift-off the body may be carried on in free flight by
//! [`GroundTop::try_fly`]: no contact force, the centre of mass on its
//! parabola and the rotation the exact torque-free motion
//! ([`crate::ExactSolution`]), until the main shape or a further one
//! reaches the plane ([`Landing`], its time located by bisection on the
//! exact flight). The impact is not modelled there either.
//!
//! # What is conserved
//! The energy `E = ½ m |v_G|² + ½ L·ω + m g z_G` changes by the power of the
//! contact force at the contact point's velocity:
//!
//! ```text
//! Ė = N e · v_P = N ġ + N f·v_P  =  N f·v_P ≤ 0   on the constraint
//! ```
//!
//! so it is conserved without friction and never increases with it.
//! Jellett's integral `λ = L·(R ẑ − A c) = −L·ρ` (for a tippe top
//! `A c = a ŝ`, `ŝ` the unit vector from the centre of mass to the ball's
//! centre): with `ρ̇ = ω × A c`,
//!
//! ```text
//! λ̇ = −(ρ × N e)·ρ − L·(ω × A c) = −L·(ω × A c)
//! ```
//!
//! and for `c` on an axis of symmetry of `I` (`I₁ = I₂`, `c ∥ e₃`),
//! `L = I₁ ω + (I₃ − I₁)(ω·ĉ) ĉ` is in the plane of `ω` and `ĉ`, so
//! `λ̇ = 0` for every force applied at the contact point, whatever the
//! friction.
//!
//! # Numerics
//! Classical RK4 at a fixed step on `(r_G, v_G, q, L)`: `q` is never
//! renormalised (every function reads `q/|q|`), the constraint is never
//! projected, and nothing conserved is restored. The energy, `λ` and the
//! constraint's residuals `g`, `ġ` (which the ODE keeps at `g̈ = 0` only
//! up to the method's error) drift by `O(h⁴)` and are the measures of
//! accuracy (tests in `tests/contact_sphere.rs`).
//!
//! [`GroundTop::try_advance_adaptive`] integrates the same equations with
//! the embedded Dormand–Prince 5(4) pair, the step chosen so that each
//! step's estimated local error meets an [`AdaptiveTolerance`] (error norm
//! over `r_G`, `v_G`, `q`, `L` scaled by the body's own units), with the
//! same contact checks; nothing is renormalised or projected either. A
//! fixed step gives no warning when it is too large: with the regularised
//! Coulomb law at `ε = 0.1 mm/s` (stiff while the contact nearly sticks,
//! `μ N/(m ε) ≈ 3·10⁴ s⁻¹` for Leine & Glocker's top) RK4 at
//! `dt = 5e-5` s puts the inversion at 19.19 s against 19.478416 s; the
//! error-controlled run finds it to 10⁻⁶ without a convergence study
//! (`tests/contact_adaptive.rs`).
//!
//! # Conventions
//! A tippe top's body axis `e₃` points to the stem; the ball's centre lies
//! at `c = +a e₃` from the centre of mass (the centre of mass is `a` *below*
//! the ball's centre when the stem points up, `α = a/R`). Upright, the
//! centre of mass is at height `R − a`; standing on the inverted ball, at
//! `R + a`. From `λ`, spinning at `ω₀` about `e₃` tilted by `θ₀`, a full
//! inversion ends at `ω_z = ω₀ (cos θ₀ − α)/(1 + α)`.

mod adaptive;
mod applied_loads;
mod contact_shape;
mod disk_contact;
mod ellipsoid_contact;
mod flight;
mod friction;
mod ground_check;
mod ground_top;
mod rk4;
mod sphere_contact;
mod touchdown;

pub(crate) use self::adaptive::{
    A as DOPRI_A, B_HAT as DOPRI_B_HAT, C as DOPRI_C, Controlled, MAX_GROWTH, MIN_SHRINK, SAFETY,
};
pub use self::adaptive::{AdaptiveStats, AdaptiveTolerance};
pub(crate) use self::applied_loads::AppliedLoads;
pub use self::contact_shape::ContactShape;
pub use self::disk_contact::DiskContact;
pub use self::ellipsoid_contact::EllipsoidContact;
pub(crate) use self::flight::Flight;
pub use self::flight::Landing;
pub use self::friction::{Friction, FrictionModel};
pub use self::ground_check::{GROUND_CHECK_TOLERANCE, GroundCheck, GroundViolation};
pub(crate) use self::ground_top::check_mass_properties;
pub use self::ground_top::{GroundTop, GroundTopState};
pub use self::sphere_contact::SphereContact;
pub use self::touchdown::MAX_OTHER_CONTACTS;
