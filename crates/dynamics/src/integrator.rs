//! One stepping interface for every torque-free integrator, and the string
//! registry that maps method names to integrators (a thin wrapper over
//! [`FreeBodyMethod`]).

use glam::DVec3;

use crate::{DivergenceCheck, DynamicsError, FreeBodyMethod, PrincipalState, RigidBody};

/// A one-step method for the torque-free rigid body in its principal frame
/// (`Sync`: a [`crate::World`] steps its bodies on threads and may be sent
/// between threads, e.g. by the Python package, which releases the GIL).
pub trait FreeBodyIntegrator: Sync {
    /// The method's registry name (e.g. `"rk4"`).
    fn name(&self) -> &'static str;
    /// The order of the method (global error `O(hᵖ)`); `u32::MAX` for the
    /// exact solution, which has no truncation error (where
    /// [`FreeBodyMethod::order`] says `None`).
    fn order(&self) -> u32;
    /// Advances `state` by `h` seconds for principal moments `moments`.
    ///
    /// Infallible by design (the inner loop of every run): a step that has
    /// no solution (an implicit method beyond its range) or bad moments
    /// leaves a non-finite state, which [`integrate`] and
    /// [`DivergenceCheck`] report as [`DynamicsError::Diverged`].
    fn step(&self, moments: DVec3, state: &mut PrincipalState, h: f64);

    /// One body from `state`, to be advanced step after step: what
    /// [`integrate`] and `kreisel simulate` use. By default each
    /// [`Propagator::advance`] is one [`FreeBodyIntegrator::step`]; a method
    /// with per-body set-up (the exact solution) prepares it here once.
    fn propagator<'a>(&'a self, moments: DVec3, state: PrincipalState) -> Box<dyn Propagator + 'a> {
        Box::new(Stepping {
            method: self,
            moments,
            state,
        })
    }
}

/// One body advanced by an integrator, step after step (`Send + Sync`, so
/// that a [`crate::World`] holding it can move between threads).
///
/// ```text
/// xₙ₊₁ = Φₕ(xₙ)
/// ```
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{method, PrincipalState};
/// let s0 = PrincipalState { world_from_principal: DQuat::IDENTITY, l_principal: DVec3::new(0.0, 0.0, 2.0) };
/// let strang = method("strang")?;
/// let mut body = strang.propagator(DVec3::new(1.0, 1.0, 2.0), s0);
/// body.advance(0.5);
/// body.advance(0.5);
/// assert!(kreisel_kinematics::rotation_angle_between(body.state().world_from_principal, DQuat::from_rotation_z(1.0)) < 1e-15);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
pub trait Propagator: Send + Sync {
    /// Advances the body by `h` seconds (a step the method cannot take
    /// leaves a non-finite state: see [`DivergenceCheck`]).
    fn advance(&mut self, h: f64);
    /// Advances the body by `h` seconds, or says why the method refuses the
    /// step (e.g. the heavy-top `auto`'s sub-step cap). By default one
    /// [`Propagator::advance`].
    ///
    /// # Errors
    /// The method's refusal, e.g. [`DynamicsError::TooManySubsteps`].
    fn try_advance(&mut self, h: f64) -> Result<(), DynamicsError> {
        self.advance(h);
        Ok(())
    }
    /// The current state.
    fn state(&self) -> PrincipalState;
}

/// The default propagator: repeated steps of a method.
struct Stepping<'a, M: ?Sized> {
    method: &'a M,
    moments: DVec3,
    state: PrincipalState,
}

impl<M: FreeBodyIntegrator + ?Sized> Propagator for Stepping<'_, M> {
    fn advance(&mut self, h: f64) {
        self.method.step(self.moments, &mut self.state, h);
    }

    fn state(&self) -> PrincipalState {
        self.state
    }
}

/// Advances `state` by `steps` steps of size `h`, checking every state
/// reached ([`DivergenceCheck`]).
///
/// ```text
/// x(t₀ + n h) ≈ Φₕⁿ x(t₀)
/// ```
///
/// The answer does not depend on the unit system: every method works in
/// the body's own unit of inertia ([`RigidBody`]'s checks keep it
/// representable), so moments scaled by `s` (and `L` with them) give the
/// same attitude, and `ω` scaled by `s` with `h` by `1/s` the same motion,
/// to rounding.
///
/// # Errors
/// [`DynamicsError::InvalidStep`] for `h` that is not positive and finite;
/// [`DynamicsError::UnphysicalInertia`] for moments that
/// [`RigidBody::try_from_principal_moments`] refuses;
/// [`DynamicsError::InvalidState`] for a state that
/// [`PrincipalState::validate`] refuses; [`DynamicsError::Diverged`] when a
/// state becomes non-finite or drifts beyond [`crate::DIVERGENCE_FACTOR`]
/// (`state` then holds the last good state).
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{integrate, method, PrincipalState};
/// let mut s = PrincipalState { world_from_principal: DQuat::IDENTITY, l_principal: DVec3::new(0.0, 0.0, 2.0) };
/// integrate(method("rk4")?.as_ref(), DVec3::new(1.0, 1.0, 2.0), &mut s, 0.01, 100)?;
/// // Spin about a principal axis: uniform rotation by ω t = 1 rad
/// // (RK4's phase error here: 100 · (h ω/2)⁵/120 ≈ 3e-12 rad).
/// assert!(kreisel_kinematics::rotation_angle_between(s.world_from_principal, DQuat::from_rotation_z(1.0)) < 1e-10);
/// // h ω = 100: far beyond RK4's stability, an error rather than NaN.
/// let mut fast = PrincipalState { world_from_principal: DQuat::IDENTITY, l_principal: DVec3::new(1e4, 2e2, 0.0) };
/// let e = integrate(method("rk4")?.as_ref(), DVec3::new(1.0, 2.0, 3.0), &mut fast, 0.01, 100).unwrap_err();
/// assert!(matches!(e, kreisel_dynamics::DynamicsError::Diverged { method: "rk4", .. }), "{e}");
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
pub fn integrate(
    method: &dyn FreeBodyIntegrator,
    moments: DVec3,
    state: &mut PrincipalState,
    h: f64,
    steps: usize,
) -> Result<(), DynamicsError> {
    if !(h.is_finite() && h > 0.0) {
        return Err(DynamicsError::InvalidStep { h });
    }
    RigidBody::try_from_principal_moments(moments)?;
    state.validate(moments)?;
    let check = DivergenceCheck::free_body(method.name(), moments, state);
    let mut body = method.propagator(moments, *state);
    for k in 1..=steps {
        body.advance(h);
        let next = body.state();
        check.check(&next, k as f64 * h)?;
        *state = next;
    }
    Ok(())
}

/// The names the registry knows, in [`FreeBodyMethod::ALL`]'s order:
/// `auto`, the exact solution, then the integrators (RK4, the
/// exact-rotation splittings and their compositions, the discrete
/// Moser–Veselov family). A thin wrapper over [`FreeBodyMethod::name`].
///
/// ```
/// use kreisel_dynamics::{FreeBodyMethod, METHODS};
/// assert_eq!(METHODS, FreeBodyMethod::ALL.map(FreeBodyMethod::name));
/// ```
pub const METHODS: [&str; FreeBodyMethod::ALL.len()] = {
    let mut names = [""; FreeBodyMethod::ALL.len()];
    let mut k = 0;
    while k < names.len() {
        names[k] = FreeBodyMethod::ALL[k].name();
        k += 1;
    }
    names
};

/// What `auto` resolves to ([`FreeBodyMethod::resolve`]): the exact
/// solution. It skips what a body does not need — a sphere or a spin about
/// a principal axis is one uniform rotation, a symmetric body two commuting
/// rotations, an asymmetric body the elliptic-function solution — has no
/// truncation error at any step (`tests/free_body_exact.rs`: ≤ 2e-14 rad
/// against every reference sample), and a step costs less than one Strang
/// splitting step (`BENCHMARKS.md`).
pub const AUTO: &str = FreeBodyMethod::Auto.resolve().name();

/// The integrator registered under `name`: a thin wrapper over
/// [`FreeBodyMethod`]'s `FromStr` and [`FreeBodyMethod::integrator`].
///
/// # Errors
/// [`DynamicsError::UnknownMethod`] listing the known names.
///
/// ```
/// use kreisel_dynamics::method;
/// assert_eq!(method("splitting6")?.order(), 6);
/// assert_eq!(method("auto")?.name(), "exact");
/// assert!(method("euler").is_err());
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
pub fn method(name: &str) -> Result<Box<dyn FreeBodyIntegrator>, DynamicsError> {
    name.parse::<FreeBodyMethod>()
        .map(FreeBodyMethod::integrator)
}
