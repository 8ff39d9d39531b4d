//! A contact's keys as the scene layer names them ([`ContactKey`]), the
//! names of its shapes ([`ShapeName`]) and friction laws
//! ([`FrictionName`]), and what can be wrong with them
//! ([`ContactKeyProblem`]) and where ([`ContactKeyError`]): typed, so that
//! each client words them in its own names (`contact_keys.rs` for a
//! scene's `[[body.contact]]` tables, Python's `World.add_body(contacts=…)`).

use kreisel_dynamics::{DynamicsError, FrictionModel, MAX_OTHER_CONTACTS, TableBody};

/// A key of a contact, whatever a client calls the contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactKey {
    /// The surface: `"sphere"`, `"disk"` or `"ellipsoid"`.
    Shape,
    /// A sphere's or a disk rim's radius, m.
    Radius,
    /// The shape's centre from the centre of mass, body axes, m.
    Center,
    /// A disk's axis, body axes.
    Normal,
    /// An ellipsoid's semi-axes along the body axes, m.
    SemiAxes,
    /// The friction law's name.
    Friction,
    /// The friction coefficient μ.
    Mu,
    /// Friction "sliding"'s regularisation ε, m/s.
    SlipVelocity,
    /// Newton's restitution (friction "coulomb").
    Restitution,
    /// Garwin's tangential restitution (friction "coulomb").
    TangentialRestitution,
    /// Contensou's drilling patch, m (friction "coulomb").
    ContensouRadius,
    /// The rolling resistance δ, m (friction "coulomb").
    RollingResistance,
    /// Moffatt's air layer's viscosity, Pa s (friction "coulomb", a disk).
    AirViscosity,
    /// The air layer's floor, m.
    AirGap,
}

impl ContactKey {
    /// The key's name, as both the scene file and Python write it.
    ///
    /// ```
    /// use kreisel_scene::contact_key::ContactKey;
    /// assert_eq!(ContactKey::SemiAxes.name(), "semi_axes");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Self::Shape => "shape",
            Self::Radius => "radius",
            Self::Center => "center",
            Self::Normal => "normal",
            Self::SemiAxes => "semi_axes",
            Self::Friction => "friction",
            Self::Mu => "mu",
            Self::SlipVelocity => "slip_velocity",
            Self::Restitution => "restitution",
            Self::TangentialRestitution => "tangential_restitution",
            Self::ContensouRadius => "contensou_radius",
            Self::RollingResistance => "rolling_resistance",
            Self::AirViscosity => "air_viscosity",
            Self::AirGap => "air_gap",
        }
    }
}

/// The names of the contact shapes (`shape = ...`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ShapeName {
    /// A body-fixed sphere.
    Sphere,
    /// A body-fixed circular rim.
    Disk,
    /// A body-fixed ellipsoid.
    Ellipsoid,
}

impl ShapeName {
    /// Every shape, in the order listed in errors.
    pub const ALL: [ShapeName; 3] = [Self::Sphere, Self::Disk, Self::Ellipsoid];

    /// The name in a scene.
    pub fn name(self) -> &'static str {
        match self {
            Self::Sphere => "sphere",
            Self::Disk => "disk",
            Self::Ellipsoid => "ellipsoid",
        }
    }

    /// The names of every shape, comma-separated (for errors).
    pub fn known() -> String {
        Self::ALL.map(Self::name).join(", ")
    }
}

impl std::str::FromStr for ShapeName {
    type Err = ContactKeyProblem;

    /// The shape called `name`.
    ///
    /// # Errors
    /// [`ContactKeyProblem::UnknownShape`] for a name not in [`ShapeName::ALL`].
    ///
    /// ```
    /// use kreisel_scene::contact_key::{ContactKeyProblem, ShapeName};
    /// assert_eq!("disk".parse(), Ok(ShapeName::Disk));
    /// let e = "cube".parse::<ShapeName>().unwrap_err();
    /// assert_eq!(e, ContactKeyProblem::UnknownShape { name: "cube".to_owned() });
    /// ```
    fn from_str(name: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|s| s.name() == name)
            .ok_or_else(|| ContactKeyProblem::UnknownShape {
                name: name.to_owned(),
            })
    }
}

/// A contact's friction law by name: one of the ground's models, or the
/// table's exact Coulomb law (`"coulomb"`: the body is on the table).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FrictionName {
    /// A friction model of a body on the ground.
    Ground(FrictionModel),
    /// Set-valued Coulomb friction at a contact of a body on the table.
    Coulomb,
}

impl FrictionName {
    /// The name of the table's law.
    pub const COULOMB: &'static str = "coulomb";

    /// The name in a scene.
    pub fn name(self) -> &'static str {
        match self {
            Self::Ground(model) => model.name(),
            Self::Coulomb => Self::COULOMB,
        }
    }

    /// The names of every law, comma-separated (for errors).
    ///
    /// ```
    /// use kreisel_scene::contact_key::FrictionName;
    /// assert_eq!(FrictionName::known(), "none, viscous, sliding, rolling, coulomb");
    /// ```
    pub fn known() -> String {
        let ground = FrictionModel::ALL.map(FrictionModel::name).join(", ");
        format!("{ground}, {}", Self::COULOMB)
    }
}

/// Where a body with contacts stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Surface {
    /// On the ground plane: one contact touching, the others watched.
    Ground,
    /// On the table: every contact unilateral, with its Coulomb law.
    Table,
}

impl Surface {
    /// The most contacts a body standing there has.
    ///
    /// ```
    /// use kreisel_scene::contact_key::Surface;
    /// assert_eq!(Surface::Table.most(), 8);
    /// assert_eq!(Surface::Ground.most(), 5);
    /// ```
    pub fn most(self) -> usize {
        match self {
            Self::Ground => 1 + MAX_OTHER_CONTACTS,
            Self::Table => TableBody::MAX_CONTACTS,
        }
    }
}

/// What a missing key is needed for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Needs {
    /// The contact's surface: its shape, a shape's size, a disk's axis.
    Shape,
    /// The friction model at the contact the body stands on (on the ground).
    Standing,
    /// Every contact of a body on the table gives its own law.
    TableLaw {
        /// The contact (0-based) whose friction "coulomb" puts the body there.
        coulomb: usize,
    },
    /// The friction law's coefficient μ.
    Coefficient {
        /// The law.
        friction: FrictionName,
    },
}

/// Why a key given has no meaning where it is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NotFor {
    /// Only a disk has an axis.
    OnlyDisk,
    /// Only an ellipsoid has semi-axes.
    OnlyEllipsoid,
    /// An ellipsoid's size is its semi-axes, not a radius.
    Ellipsoid,
    /// Only friction "sliding" has a slip velocity.
    OnlySliding {
        /// The contact's friction law.
        friction: FrictionName,
    },
    /// The friction law has no coefficient (`"none"`, `"rolling"`).
    NoCoefficient {
        /// The law.
        friction: FrictionName,
    },
    /// Only friction "coulomb" (a body on the table) has this key.
    OnlyCoulomb,
    /// Only the first contact of a body on the ground exerts a force: this
    /// one is watched for touchdown.
    Watched,
    /// Moffatt's air layer is under a disk rim only.
    AirOnlyDisk,
    /// The air layer's floor needs its viscosity.
    NoAirViscosity,
}

/// What is wrong with a body's contacts.
#[derive(Debug, Clone, PartialEq)]
pub enum ContactKeyProblem {
    /// No contact is given.
    NoContacts,
    /// More contacts than a body standing on `surface` has.
    TooMany {
        /// How many are given.
        given: usize,
        /// Where the body stands.
        surface: Surface,
    },
    /// A shape name not among [`ShapeName::ALL`].
    UnknownShape {
        /// The name given.
        name: String,
    },
    /// A friction name that is no law ([`FrictionName::known`]).
    UnknownFriction {
        /// The name given.
        name: String,
    },
    /// A key that is needed is missing.
    Missing {
        /// The key.
        key: ContactKey,
        /// What it is needed for.
        needs: Needs,
    },
    /// A key given where it has no meaning (an error, not ignored).
    NotFor {
        /// The key.
        key: ContactKey,
        /// Why it has none.
        why: NotFor,
    },
    /// Numbers that must be finite are not.
    NotFinite {
        /// The key.
        key: ContactKey,
    },
    /// A value that must be positive and finite is not.
    NotPositive {
        /// The key.
        key: ContactKey,
        /// The value (the first bad one of a vector).
        value: f64,
    },
    /// A value that must be zero or positive and finite is not.
    Negative {
        /// The key.
        key: ContactKey,
        /// The value.
        value: f64,
    },
    /// Another friction law than "coulomb" at a contact of a body on the
    /// table, which has "coulomb" at every contact.
    NotCoulomb {
        /// The law given.
        friction: String,
        /// The contact (0-based) whose "coulomb" puts the body on the
        /// table (none: the client's bodies with contacts all are).
        coulomb: Option<usize>,
    },
    /// The library refused the value of `key`.
    Library {
        /// The key the error is about.
        key: ContactKey,
        /// The library's error.
        error: DynamicsError,
    },
}

/// A problem with a body's contacts and where it is.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactKeyError<A> {
    /// Where the key it is about was given.
    pub at: A,
    /// The contact it is about, 0-based (none: the list as a whole).
    pub contact: Option<usize>,
    /// What is wrong.
    pub problem: ContactKeyProblem,
}
