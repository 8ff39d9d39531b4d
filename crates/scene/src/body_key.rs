//! A body's keys as the scene layer names them ([`BodyKey`]), whatever a
//! client calls them, and what can be wrong with them
//! ([`BodyKeyProblem`]) and where ([`BodyKeyError`]): typed, so that each
//! client words them in its own key names (`body_keys.rs` for a scene
//! file, Python's `World.add_body`).

use kreisel_dynamics::DynamicsError;

/// A value and where it was given.
pub type Given<T, A> = Option<(T, A)>;

/// A key of a body, whatever a client calls it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BodyKey {
    /// The body as a whole (its table; the call).
    Body,
    /// The mass, kg.
    Mass,
    /// Principal moments about the centre of mass, kg m².
    Moments,
    /// The inertia tensor about the centre of mass, body axes.
    Tensor,
    /// A mesh file (a solid of a density).
    Mesh,
    /// The initial attitude, world_from_body.
    Attitude,
    /// The angular velocity in body axes.
    Omega,
    /// The centre of mass, world axes.
    Position,
    /// Its velocity, world axes.
    Velocity,
    /// The fixed pivot, body axes.
    Pivot,
    /// Torque in world axes.
    Torque,
    /// Torque in body axes.
    TorqueBody,
    /// Force through the centre of mass, world axes.
    Force,
    /// Angular damping, N m s.
    AngularDamping,
    /// The contacts with the ground plane or the table.
    Contacts,
}

/// What is wrong with a body's keys.
#[derive(Debug, Clone, PartialEq)]
pub enum BodyKeyProblem {
    /// None of the inertia keys is given.
    NoInertia,
    /// Two inertia keys are given.
    TwoInertias {
        /// The one given first.
        first: BodyKey,
        /// The other one (where the error is).
        second: BodyKey,
    },
    /// The mass is missing (it is needed unless the inertia is a mesh's).
    MissingMass,
    /// A value that must be positive and finite is not.
    NotPositive {
        /// The key.
        key: BodyKey,
        /// Its value.
        value: f64,
    },
    /// The attitude quaternion is zero or not finite.
    NotAQuaternion,
    /// A pivot and contacts are both given.
    PivotWithContacts,
    /// A velocity is given with a pivot.
    VelocityWithPivot,
    /// A velocity is given with rolling friction on the ground.
    VelocityWithRolling,
    /// A body on the ground with a vertical velocity.
    VelocityNotHorizontal {
        /// The vertical velocity given, m/s.
        vz: f64,
    },
    /// An applied load given for a body on the table.
    LoadsOnTable {
        /// The first load key given.
        key: BodyKey,
    },
    /// The angular damping is negative or not finite.
    Damping {
        /// The value given.
        value: f64,
    },
    /// Contact `contact` of a body on the table is below it at the start.
    InsideTable {
        /// The contact, 0-based.
        contact: usize,
        /// Its lowest point, m.
        gap: f64,
        /// Whether the position was given (else it was the default).
        position_given: bool,
    },
    /// A watched contact of a body on the ground is at or below the plane
    /// at the start.
    WatchedTouching {
        /// The watched contact, 0-based among the watched ones.
        index: usize,
        /// Its lowest point, m.
        gap: f64,
    },
    /// Painlevé's case at the start of a body on the table: its contact
    /// `contact` of friction `mu` is beyond the bound of its slip.
    Painleve {
        /// The contact, 0-based.
        contact: usize,
        /// Its friction coefficient.
        mu: f64,
        /// The library's error.
        error: DynamicsError,
    },
    /// The library refused the value of `key`.
    Library {
        /// The key the error is about ([`BodyKey::Body`]: the body).
        key: BodyKey,
        /// The library's error.
        error: DynamicsError,
    },
}

/// A problem and where it is.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyKeyError<A> {
    /// Where the key it is about was given.
    pub at: A,
    /// What is wrong.
    pub problem: BodyKeyProblem,
}
