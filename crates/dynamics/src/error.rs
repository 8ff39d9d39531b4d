//! The one error type of `kreisel-dynamics`.

/// Everything that can go wrong when setting up or advancing a rigid body.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum DynamicsError {
    /// Principal moments that no physical body has.
    #[error("principal moments {moments:?} are not physical: {reason}")]
    UnphysicalInertia {
        /// The moments given, kg·m².
        moments: [f64; 3],
        /// Why (not positive and finite, or the triangle inequality broken).
        reason: &'static str,
    },
    /// A mass or inertia tensor that no physical body has: which check
    /// fails, typed (the inertia crate's [`kreisel_inertia::MassPropertiesError`]).
    #[error("inertia tensor: {error}")]
    InertiaTensor {
        /// Which check fails.
        #[from]
        error: kreisel_inertia::MassPropertiesError,
    },
    /// A state with a non-finite or zero-length attitude quaternion, or a
    /// non-finite angular momentum.
    #[error("invalid state: {reason}")]
    InvalidState {
        /// What is wrong.
        reason: &'static str,
    },
    /// A step size that is not positive and finite.
    #[error("step size must be positive and finite, got {h}")]
    InvalidStep {
        /// The step size given, s.
        h: f64,
    },
    /// A heavy-top parameter or initial condition outside its domain
    /// (a moment of inertia that is not positive, a non-finite number, …).
    #[error("heavy top: {parameter} = {value}: {reason}")]
    InvalidTop {
        /// The parameter's name as the user wrote it (e.g. `"i1"`, `"theta0"`).
        parameter: &'static str,
        /// The value given.
        value: f64,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A run stopped because its state became non-finite or an invariant
    /// blew up (see [`crate::DivergenceCheck`]): the step is too large for
    /// the method, or the method has no solution at this step.
    #[error("{method} diverged at t = {time} s: {reason}")]
    Diverged {
        /// The method's registry name.
        method: &'static str,
        /// The time of the first state found bad, s.
        time: f64,
        /// What went wrong.
        reason: Divergence,
    },
    /// A step that would need more sub-steps than a method allows (the
    /// heavy-top `auto`): a request that cannot be met in reasonable time.
    #[error(
        "{method}: a step of {h} s needs {needed:e} sub-steps to stay stable, more than the limit of {limit}"
    )]
    TooManySubsteps {
        /// The method's registry name.
        method: &'static str,
        /// The step asked for, s.
        h: f64,
        /// The sub-steps it would need (may be infinite).
        needed: f64,
        /// The most sub-steps a step may take.
        limit: usize,
    },
    /// An applied input (torque, force, damping) that cannot be used: a
    /// non-finite component, or a negative damping coefficient.
    #[error("applied input `{input}`{}: {value}: {reason}", index.map(|i| format!(" #{i}")).unwrap_or_default())]
    InvalidInput {
        /// The input's name (e.g. `"torque_world"`, `"angular_damping"`,
        /// `"point_force.point_body"`).
        input: &'static str,
        /// Which one, for inputs given as a list (the point forces).
        index: Option<usize>,
        /// The offending value (a component of a vector).
        value: f64,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A parameter or initial condition of a free body outside its domain
    /// (a mass that is not positive and finite, a non-finite gravity,
    /// position or velocity).
    #[error("free body: {parameter} = {value}: {reason}")]
    InvalidBodyParameter {
        /// The parameter's name (e.g. `"mass"`, `"gravity_world"`).
        parameter: &'static str,
        /// The value given (a component of a vector).
        value: f64,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A principal-axis index other than 0, 1 or 2.
    #[error("principal axis {axis} does not exist (0, 1 or 2)")]
    InvalidAxis {
        /// The index given.
        axis: usize,
    },
    /// A spin rate that is not finite, or so large that the quantities
    /// derived from it overflow.
    #[error("spin rate {omega} rad/s is not finite or too large to analyse")]
    InvalidRate {
        /// The rate given, rad/s.
        omega: f64,
    },
    /// A body setting that no body has (see [`crate::BodyBuilder::try_build`]).
    #[error("body: `{field}` {reason}")]
    InvalidBody {
        /// The setting (`"position"`, `"pivot_body"`, `"gravity"`, …).
        field: &'static str,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A body on the ground failed its guard ([`crate::GroundCheck`]):
    /// the step is too large for its motion, or its friction too stiff for
    /// an explicit step; the state is the one before the step.
    #[error(
        "the ground contact's check failed at t = {time} s: {violation} (steps of {step} s are too large for this motion: use a smaller dt or tolerance)"
    )]
    GroundCheckFailed {
        /// The time of the state that failed, s.
        time: f64,
        /// The step that reached it, s.
        step: f64,
        /// Which check failed.
        violation: crate::GroundViolation,
    },
    /// A time a [`crate::World`] cannot advance to.
    #[error("cannot advance the world from t = {now} s to t = {t} s: {reason}")]
    InvalidTime {
        /// The time asked, s.
        t: f64,
        /// The world's time, s.
        now: f64,
        /// What is wrong.
        reason: &'static str,
    },
    /// A [`crate::BodyId`] that names no body of this world.
    #[error("no body number {index} in this world")]
    UnknownBody {
        /// The id's index.
        index: usize,
    },
    /// A body of a [`crate::World`] whose step was refused or whose state
    /// diverged (`source`, usually [`DynamicsError::Diverged`]).
    #[error("body {body}: the step to t = {time} s failed: {source}")]
    BodyFailed {
        /// The body's index ([`crate::BodyId::index`]).
        body: usize,
        /// The end of the step that failed, s.
        time: f64,
        /// Why.
        source: Box<DynamicsError>,
    },
    /// A free-body or heavy-top method that cannot move a body with
    /// applied inputs (a [`crate::World`] body with [`crate::Inputs`]):
    /// only the splittings have a torque kick.
    #[error(
        "{kind} method `{method}` cannot move a body with applied inputs (methods that can: {known})"
    )]
    MethodTakesNoInputs {
        /// `"free-body"` or `"heavy-top"`.
        kind: &'static str,
        /// The method's name.
        method: &'static str,
        /// The methods that can, comma-separated.
        known: String,
    },
    /// A contact parameter outside its domain (a sphere radius that is
    /// not positive, a negative friction coefficient, a mass or inertia
    /// tensor no body has, …).
    #[error("contact: {parameter} = {value}: {reason}")]
    InvalidContact {
        /// The parameter's name (`"radius"`, `"mu"`, `"slip_velocity"`, …).
        parameter: &'static str,
        /// The value given (a component, or a leading minor of the inertia).
        value: f64,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// The normal force of a ground contact reached zero: the body lifts
    /// off the plane, which the contact model does not follow.
    #[error("the contact lifts off at t = {time} s (normal force {normal_force:e} N)")]
    ContactLost {
        /// The lift-off time, s.
        time: f64,
        /// The normal force found there, N (≈ 0 when located, negative
        /// when the step could not be taken).
        normal_force: f64,
    },
    /// A further contact shape of a ground body
    /// ([`crate::GroundTop::try_with_other_contacts`]) reached the plane:
    /// a second contact begins (an impact, then two contacts), which the
    /// contact model does not follow. The instant is located inside the
    /// step and the state left there (the shape's gap ≈ 0).
    #[error(
        "further contact #{contact} touches down at t = {time} s \
         (approach speed {approach_speed:e} m/s)"
    )]
    ContactTouchdown {
        /// The touchdown time, s.
        time: f64,
        /// Which shape: its index in [`crate::GroundTop::other_contacts`].
        contact: usize,
        /// The speed of its lowest point towards the plane there, m/s:
        /// `−ġ`, minus the gap's rate (≥ 0 when located; ≈ 0 for a graze).
        approach_speed: f64,
    },
    /// A state whose further contact shape
    /// ([`crate::GroundTop::try_with_other_contacts`]) is at or below the
    /// plane: only the main shape may touch.
    #[error(
        "further contact #{contact} is at or below the plane (gap {gap:e} m): \
         only the main contact may touch"
    )]
    OtherContactTouching {
        /// Which shape: its index in [`crate::GroundTop::other_contacts`].
        contact: usize,
        /// Its gap, the height of its lowest point, m (≤ 0).
        gap: f64,
    },
    /// A disk rim reached (or stepped through) lying flat: the contact
    /// point would jump across the rim (its far side touches down, an
    /// impact the contact model does not follow), or one step turned the
    /// contact more than a quarter of the way round the rim.
    #[error(
        "the disk's contact jumps across its rim in the step from t = {time} s \
         (it lies flat: the far side touches down; or the step is far too large)"
    )]
    DiskFlat {
        /// The start of the step, s (the state is left there).
        time: f64,
    },
    /// No normal force keeps the contact: its coefficient in the
    /// constraint's second derivative is not positive (Painlevé's paradox
    /// of strong friction).
    #[error("the contact is indeterminate at t = {time} s (compliance {compliance:e} 1/kg ≤ 0)")]
    ContactIndeterminate {
        /// The time, s (NaN when asked outside a run).
        time: f64,
        /// The coefficient of `N`, 1/kg.
        compliance: f64,
    },
    /// A body on the table placed with a contact shape below the plane.
    #[error("contact #{contact} is below the table (gap {gap:e} m): place the body on or above it")]
    BodyInsideTable {
        /// Which contact shape (its index in [`crate::TableBody::contacts`]).
        contact: usize,
        /// Its gap, the height of its lowest point, m (< 0).
        gap: f64,
    },
    /// An impact whose solution would raise the kinetic energy (an impact
    /// law can, with several frictional contacts: Glocker 2013): refused.
    #[error(
        "the impact at t = {time} s would raise the kinetic energy from {before:e} J to {after:e} J"
    )]
    ImpactGainsEnergy {
        /// The impact's time, s.
        time: f64,
        /// The kinetic energy before, J.
        before: f64,
        /// The kinetic energy the impact law gave, J.
        after: f64,
    },
    /// The set-valued contact problem of a body on the table at an event
    /// has no solution the block solver finds (the slip direction at a
    /// contact that starts to slip, or the sweeps over several contacts,
    /// did not settle).
    #[error(
        "the contact problem at t = {time} s has no solution the solver finds (the slip direction or the sweeps over the contacts did not settle)"
    )]
    ContactUnsolved {
        /// The time, s.
        time: f64,
    },
    /// The contact modes of a body on the table change again and again at
    /// one instant without the motion advancing (no consistent mode).
    #[error("the contact modes at t = {time} s change {count} times without the motion advancing")]
    ContactModesChatter {
        /// The time, s.
        time: f64,
        /// How many events in a row did not advance the time.
        count: usize,
    },
    /// An error tolerance of an adaptive integrator outside its domain
    /// (see [`crate::AdaptiveTolerance::try_new`]).
    #[error("adaptive tolerance: {parameter} = {value}: {reason}")]
    InvalidTolerance {
        /// `"rtol"` or `"atol"`.
        parameter: &'static str,
        /// The value given.
        value: f64,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A time interval that cannot be integrated: `t_end` before `t0`, or
    /// a time that is not finite.
    #[error(
        "cannot integrate from t = {t0} s to t = {t_end} s: the end must be finite and not before the start"
    )]
    InvalidInterval {
        /// The start, s.
        t0: f64,
        /// The end asked, s.
        t_end: f64,
    },
    /// An adaptive integrator whose error control asked for a step below
    /// its minimum: the solution is not smooth enough there for the
    /// tolerance (a discontinuity, stiffness, a singularity).
    #[error(
        "{method}: the error control needs a step of {h:e} s at t = {time} s, below the minimum {min:e} s"
    )]
    StepTooSmall {
        /// The method's name.
        method: &'static str,
        /// The time reached, s (the state is left there).
        time: f64,
        /// The step the controller asked for, s.
        h: f64,
        /// The smallest step allowed, s.
        min: f64,
    },
    /// A friction model name other than those of
    /// [`crate::FrictionModel::ALL`].
    #[error("unknown friction model `{name}` (known: {known})")]
    UnknownFriction {
        /// The name given.
        name: String,
        /// The known names, comma-separated.
        known: String,
    },
    /// A method name that the registry does not know.
    #[error("unknown method `{name}` (known: {known})")]
    UnknownMethod {
        /// The name given.
        name: String,
        /// The known names, comma-separated.
        known: String,
    },
}

/// Why a run was declared diverged ([`DynamicsError::Diverged`]).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Divergence {
    /// The attitude or the angular momentum is NaN or infinite.
    NonFinite,
    /// The state is finite but a quantity computed from it overflowed
    /// (e.g. the energy `½ L·I⁻¹L` of a finite but huge `L`).
    Overflow {
        /// Which quantity (`"energy"`, `"angular velocity"`, ...).
        quantity: &'static str,
    },
    /// A conserved quantity left its band: its value now and at the start.
    Drift {
        /// Which quantity (`"energy"`, `"|L|"`, `"|q|"`).
        quantity: &'static str,
        /// Its value at the start.
        initial: f64,
        /// Its value now.
        current: f64,
    },
}

impl std::fmt::Display for Divergence {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Divergence::NonFinite => write!(f, "the state is no longer finite"),
            Divergence::Overflow { quantity } => write!(f, "its {quantity} is no longer finite"),
            Divergence::Drift {
                quantity,
                initial,
                current,
            } => write!(
                f,
                "{quantity}, conserved by the exact motion, went from {initial:.4e} to \
                 {current:.4e}: beyond a factor {}",
                crate::DIVERGENCE_FACTOR
            ),
        }
    }
}
