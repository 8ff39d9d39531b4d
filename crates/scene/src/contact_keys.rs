//! A body's `[body.contact]` table: the surface that touches the ground
//! plane z = 0 (a sphere, a disk rim, an ellipsoid with its semi-axes
//! along the body axes) and the friction law there, checked key by key into the
//! library's [`ContactShape`] and [`Friction`].
//!
//! ```text
//! shape = "sphere" | "disk" | "ellipsoid"
//! radius = R                  sphere, disk (m)
//! center = [x, y, z]          from the centre of mass, body axes, m [default: 0]
//! normal = [x, y, z]          disk only: its axis, body axes
//! semi_axes = [a, b, c]       ellipsoid only, body axes, m
//! friction = "none" | "viscous" | "sliding" | "rolling" | "coulomb"
//! mu = μ                      viscous (s/m), sliding and coulomb (Coulomb), ≥ 0
//! slip_velocity = ε           sliding only, m/s [default: 1e-3]
//! restitution = e             coulomb only: Newton's, in [0, 1] [default: 0]
//! tangential_restitution = eT coulomb only: Garwin's, in [0, 1] [default: 0]
//! contensou_radius = r_c      coulomb only: the drilling patch, m, ≥ 0 [default: 0]
//! rolling_resistance = δ      coulomb only: the rolling torque is at most δ N, m, ≥ 0 [default: 0]
//! air_viscosity = μ_air       coulomb disk only: Moffatt's air layer under the rim, Pa s, ≥ 0
//! air_gap = h₀                with air_viscosity: the layer's floor, m, > 0 [default: 1e-6]
//! ```
//!
//! **`friction = "coulomb"`: the body is on the table.** A body whose
//! contacts use `"coulomb"` moves with every one of them as a unilateral
//! contact of the table `z = 0` — set-valued Coulomb friction with
//! Contensou's drilling, Newton's impacts ([`ContactLaw`]) — by the
//! library's event-driven [`kreisel_dynamics::TableMotion`]
//! ([`kreisel_dynamics::Support::Table`]): each table gives its own law
//! (`friction = "coulomb"` on every one of them, up to
//! [`TableBody::MAX_CONTACTS`]; another friction model on the same body is
//! an error), and the body may start above the table.
//!
//! `[[body.contact]]`, an array of such tables: the first is the surface
//! the body stands on; the others (at most [`MAX_OTHER_CONTACTS`]) are
//! watched for touchdown — the stem's ball of a tippe top — and must be
//! above the plane at the start. They exert no force (the body moves on
//! its one contact), so `friction`, `mu` and `slip_velocity` are only for
//! the first table: given on another they are an error, not ignored. A
//! watched shape reaching the plane stops the run (the impact is not
//! modelled).
//!
//! `slip_velocity` defaults to the library's
//! [`Friction::DEFAULT_SLIP_VELOCITY`] (1 mm/s, Leine & Glocker's ε).

#![forbid(unsafe_code)]

use std::fmt;
use std::str::FromStr;

use glam::DVec3;
use kreisel_dynamics::{
    AirLayer, ContactLaw, ContactShape, DiskContact, DynamicsError, EllipsoidContact, Friction,
    FrictionModel, MAX_OTHER_CONTACTS, SphereContact, TableBody, TableContact,
};
use serde::Deserialize;
use serde::de::{self, Deserializer, MapAccess, SeqAccess, Visitor};
use toml::Spanned;

use crate::error::SceneError;
use crate::numbers::Shortest;
use crate::scene_keys::Keys;

/// A `[body.contact]` table as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawContact {
    shape: Spanned<String>,
    radius: Option<Spanned<f64>>,
    center: Option<Spanned<[f64; 3]>>,
    normal: Option<Spanned<[f64; 3]>>,
    semi_axes: Option<Spanned<[f64; 3]>>,
    friction: Option<Spanned<String>>,
    mu: Option<Spanned<f64>>,
    slip_velocity: Option<Spanned<f64>>,
    restitution: Option<Spanned<f64>>,
    tangential_restitution: Option<Spanned<f64>>,
    contensou_radius: Option<Spanned<f64>>,
    rolling_resistance: Option<Spanned<f64>>,
    air_viscosity: Option<Spanned<f64>>,
    air_gap: Option<Spanned<f64>>,
}

impl RawContact {
    /// Where the `mu` key is, if given.
    pub fn mu_span(&self) -> Option<std::ops::Range<usize>> {
        self.mu.as_ref().map(Spanned::span)
    }
}

/// The message (after the body's name) for Painlevé's case at contact
/// `index` (0-based) of a body on the table, whose law has `mu`: the
/// table's `error` ([`DynamicsError::ContactIndeterminate`]) read as the
/// bad input it is — no normal force keeps that contact sliding, a
/// friction coefficient beyond the bound of the slip.
pub fn painleve_message(index: usize, mu: f64, error: &DynamicsError) -> String {
    format!(
        "`contact.mu` = {} of [[body.contact]] #{} is beyond the Painlevé bound of its slip \
         ({error}): no normal force keeps the sliding contact on the table; lower `mu`",
        Shortest(mu),
        index + 1
    )
}

/// The friction name of the nonsmooth contacts of a body on the table.
pub const COULOMB: &str = "coulomb";

/// `[body.contact]` (one table) or `[[body.contact]]` (an array of them).
#[derive(Debug)]
pub enum RawContacts {
    /// One table.
    One(Box<RawContact>),
    /// An array of tables, each with its span.
    Many(Vec<Spanned<RawContact>>),
}

impl<'de> Deserialize<'de> for RawContacts {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct OneOrMany;
        impl<'de> Visitor<'de> for OneOrMany {
            type Value = RawContacts;

            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a [body.contact] table or an array of them")
            }

            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<Self::Value, A::Error> {
                let one = RawContact::deserialize(de::value::MapAccessDeserializer::new(map))?;
                Ok(RawContacts::One(Box::new(one)))
            }

            fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<Self::Value, A::Error> {
                let many = Vec::deserialize(de::value::SeqAccessDeserializer::new(seq))?;
                Ok(RawContacts::Many(many))
            }
        }
        deserializer.deserialize_any(OneOrMany)
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
}

impl FromStr for ShapeName {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|m| m.name() == s)
            .ok_or_else(|| {
                let known = Self::ALL.map(Self::name).join(", ");
                format!("unknown contact shape `{s}` (known: {known})")
            })
    }
}

/// A checked contact: the shape and the friction.
#[derive(Debug, Clone, Copy)]
pub struct CheckedContact {
    /// The touching surface.
    pub shape: ContactShape,
    /// The friction law at the contact.
    pub friction: Friction,
}

/// A body's checked contacts: on the ground (one touching, others
/// watched) or on the table (every one a contact with its law).
#[derive(Debug, Clone)]
pub enum Contacts {
    /// Regularised or rolling friction at the first table.
    Ground(CheckedContacts),
    /// `friction = "coulomb"`: every table, in order.
    Table(Vec<TableContact>),
}

/// A body's checked contacts: the one it stands on, and the further
/// shapes watched for touchdown (the tables after the first).
#[derive(Debug, Clone)]
pub struct CheckedContacts {
    /// The first table: the surface touching the plane and its friction.
    pub first: CheckedContact,
    /// The shapes of the other tables, in order.
    pub others: Vec<ContactShape>,
}

/// The `[[body.contact]]` tables of `contacts` with their spans (one
/// `[body.contact]` table: that one, at the key's span).
pub fn tables(contacts: &Spanned<RawContacts>) -> Vec<(&RawContact, std::ops::Range<usize>)> {
    match contacts.get_ref() {
        RawContacts::One(one) => vec![(one.as_ref(), contacts.span())],
        RawContacts::Many(many) => many.iter().map(|c| (c.get_ref(), c.span())).collect(),
    }
}

/// Checks the `contact` key of a body: one table, or an array of them
/// (the first touching, the others watched; with `friction = "coulomb"`
/// all of them on the table; module docs).
///
/// # Errors
/// [`SceneError::Scene`] naming the line and key of the first problem.
pub fn check(keys: &Keys<'_>, contacts: &Spanned<RawContacts>) -> Result<Contacts, SceneError> {
    let tables = tables(contacts);
    let Some(((first, _), others)) = tables.split_first() else {
        return Err(keys.fail(contacts, "`contact` is an empty array: give one table"));
    };
    let coulomb = tables.iter().find_map(|(raw, _)| {
        raw.friction
            .as_ref()
            .filter(|f| f.get_ref().as_str() == COULOMB)
    });
    match coulomb {
        Some(at) => on_table(keys, &tables, at).map(Contacts::Table),
        None => on_ground(keys, first, others).map(Contacts::Ground),
    }
}

/// The contacts of a body on the table: every table with
/// `friction = "coulomb"` (`at`, the first such key, names the body's
/// kind in the errors).
fn on_table(
    keys: &Keys<'_>,
    tables: &[(&RawContact, std::ops::Range<usize>)],
    at: &Spanned<String>,
) -> Result<Vec<TableContact>, SceneError> {
    if let Some((_, span)) = tables.get(TableBody::MAX_CONTACTS) {
        let message = format!(
            "{} [[body.contact]] tables: a body on the table has at most {}",
            tables.len(),
            TableBody::MAX_CONTACTS
        );
        return Err(keys.fail_at(span.clone(), &message));
    }
    let mut checked = Vec::with_capacity(tables.len());
    for (n, (raw, _)) in tables.iter().enumerate() {
        let shape = shape(keys, raw)?;
        let Some(given) = &raw.friction else {
            let message = format!(
                "`contact.friction` is missing: the body is on the table (friction \"coulomb\" \
                 at line {}), and every [[body.contact]] gives its own law: friction = \"coulomb\" \
                 with its mu (table #{})",
                keys.line_of(at),
                n + 1
            );
            return Err(keys.fail(&raw.shape, &message));
        };
        if given.get_ref() != COULOMB {
            let message = format!(
                "`contact.friction` = \"{}\" cannot be mixed with \"coulomb\" on one body (line \
                 {}): a body on the table has friction \"coulomb\" at every contact",
                given.get_ref(),
                keys.line_of(at)
            );
            return Err(keys.fail(given, &message));
        }
        let law = law(keys, raw, given)?;
        checked.push(TableContact { shape, law });
    }
    Ok(checked)
}

/// The law of a `friction = "coulomb"` table from `mu`, `restitution`,
/// `tangential_restitution`, `contensou_radius` and `rolling_resistance`.
fn law(
    keys: &Keys<'_>,
    raw: &RawContact,
    given: &Spanned<String>,
) -> Result<ContactLaw, SceneError> {
    let why = "is only for friction \"sliding\" (the ε of F = −μ N v/√(|v|² + ε²)); \
               \"coulomb\" is exact Coulomb friction";
    not_with(keys, "slip_velocity", &raw.slip_velocity, why)?;
    let what = "friction \"coulomb\" needs the coefficient μ (dimensionless)";
    let mu = required(keys, "mu", &raw.mu, given, what)?;
    // Each key's value, checked by the law itself; its error at the key.
    let keyed = |value: &Spanned<f64>, made: Result<ContactLaw, DynamicsError>| {
        made.map_err(|e| match e {
            DynamicsError::InvalidContact {
                parameter, reason, ..
            } => keys.fail(
                value,
                &format!(
                    "`contact.{parameter}` {reason}, got {}",
                    Shortest(*value.get_ref())
                ),
            ),
            other => keys.fail(value, &format!("`contact`: {other}")),
        })
    };
    let mut law = keyed(mu, ContactLaw::try_new(*mu.get_ref()))?;
    if let Some(e) = &raw.restitution {
        law = keyed(e, law.try_with_restitution(*e.get_ref()))?;
    }
    if let Some(e) = &raw.tangential_restitution {
        law = keyed(e, law.try_with_tangential_restitution(*e.get_ref()))?;
    }
    if let Some(r) = &raw.contensou_radius {
        law = keyed(r, law.try_with_contensou_radius(*r.get_ref()))?;
    }
    if let Some(d) = &raw.rolling_resistance {
        law = keyed(d, law.try_with_rolling_resistance(*d.get_ref()))?;
    }
    if let Some(viscosity) = &raw.air_viscosity {
        if raw.shape.get_ref() != "disk" {
            return Err(keys.fail(
                viscosity,
                "`contact.air_viscosity` is Moffatt's air layer under a disk rim: only for \
                 shape = \"disk\"",
            ));
        }
        let floor = raw
            .air_gap
            .as_ref()
            .map_or(DEFAULT_AIR_GAP, |g| *g.get_ref());
        let layer = AirLayer::try_new(*viscosity.get_ref(), floor);
        let at = match &layer {
            Err(DynamicsError::InvalidContact {
                parameter: "air_gap",
                ..
            }) => raw.air_gap.as_ref().unwrap_or(viscosity),
            _ => viscosity,
        };
        law = keyed(at, layer.map(|l| law.with_air_layer(l)))?;
    } else {
        let why = "needs `air_viscosity` (the air layer's viscosity)";
        not_with(keys, "air_gap", &raw.air_gap, why)?;
    }
    Ok(law)
}

/// The contacts of a body on the ground: the first table touching, the
/// others watched (module docs).
fn on_ground(
    keys: &Keys<'_>,
    first: &RawContact,
    others: &[(&RawContact, std::ops::Range<usize>)],
) -> Result<CheckedContacts, SceneError> {
    if let Some((_, span)) = others.get(MAX_OTHER_CONTACTS) {
        let message = format!(
            "{} [[body.contact]] tables: at most {} (the first touching the plane, up to \
             {MAX_OTHER_CONTACTS} more watched for touchdown)",
            1 + others.len(),
            1 + MAX_OTHER_CONTACTS
        );
        return Err(keys.fail_at(span.clone(), &message));
    }
    let checked = CheckedContact {
        shape: shape(keys, first)?,
        friction: friction(keys, first)?,
    };
    let mut watched = Vec::with_capacity(others.len());
    for (n, (raw, _)) in others.iter().enumerate() {
        let why = format!(
            "is only for the first contact (the one touching): [[body.contact]] #{} is \
             watched for touchdown and exerts no force",
            n + 2
        );
        watched.push(shape(keys, raw)?);
        not_with(keys, "friction", &raw.friction, &why)?;
        not_with(keys, "mu", &raw.mu, &why)?;
        not_with(keys, "slip_velocity", &raw.slip_velocity, &why)?;
        not_coulomb_keys(keys, raw, &why)?;
    }
    Ok(CheckedContacts {
        first: checked,
        others: watched,
    })
}

/// The keys of friction "coulomb" given where they have no meaning
/// (`why`): an error at the first one's line.
fn not_coulomb_keys(keys: &Keys<'_>, raw: &RawContact, why: &str) -> Result<(), SceneError> {
    not_with(keys, "restitution", &raw.restitution, why)?;
    not_with(
        keys,
        "tangential_restitution",
        &raw.tangential_restitution,
        why,
    )?;
    not_with(keys, "contensou_radius", &raw.contensou_radius, why)?;
    not_with(keys, "rolling_resistance", &raw.rolling_resistance, why)?;
    not_with(keys, "air_viscosity", &raw.air_viscosity, why)?;
    not_with(keys, "air_gap", &raw.air_gap, why)
}

/// The air layer's floor `h₀` when `air_gap` is not given, m.
const DEFAULT_AIR_GAP: f64 = 1e-6;

/// `key` given where it has no meaning: an error at its line.
fn not_with<T>(
    keys: &Keys<'_>,
    key: &str,
    value: &Option<Spanned<T>>,
    why: &str,
) -> Result<(), SceneError> {
    match value {
        Some(v) => Err(keys.fail(v, &format!("`contact.{key}` {why}"))),
        None => Ok(()),
    }
}

/// A required key, or an error at `shape`'s line.
fn required<'v, T>(
    keys: &Keys<'_>,
    key: &str,
    value: &'v Option<Spanned<T>>,
    at: &Spanned<String>,
    what: &str,
) -> Result<&'v Spanned<T>, SceneError> {
    value.as_ref().ok_or_else(|| {
        let message = format!("`contact.{key}` is missing: {what}");
        keys.fail(at, &message)
    })
}

/// The surface from `shape`, `radius`, `center`, `normal`, `semi_axes`.
fn shape(keys: &Keys<'_>, raw: &RawContact) -> Result<ContactShape, SceneError> {
    let name: ShapeName = raw
        .shape
        .get_ref()
        .parse()
        .map_err(|e: String| keys.fail(&raw.shape, &format!("`contact.shape`: {e}")))?;
    let center = match &raw.center {
        Some(c) => keys.vector("contact.center", c)?,
        None => DVec3::ZERO,
    };
    let radius_of = |keys: &Keys<'_>| -> Result<f64, SceneError> {
        let r = required(
            keys,
            "radius",
            &raw.radius,
            &raw.shape,
            "the radius in metres",
        )?;
        keys.positive("contact.radius", r)
    };
    if name != ShapeName::Ellipsoid {
        let why = "is only for an ellipsoid";
        not_with(keys, "semi_axes", &raw.semi_axes, why)?;
    }
    match name {
        ShapeName::Sphere => {
            not_with(keys, "normal", &raw.normal, "is only for a disk (its axis)")?;
            let radius = radius_of(keys)?;
            let sphere = SphereContact::try_new(radius, center)
                .map_err(|e| keys.fail(&raw.shape, &format!("`contact`: {e}")))?;
            Ok(ContactShape::Sphere(sphere))
        }
        ShapeName::Disk => {
            let radius = radius_of(keys)?;
            let normal = required(
                keys,
                "normal",
                &raw.normal,
                &raw.shape,
                "a disk needs its axis in body coordinates",
            )?;
            let axis = keys.vector("contact.normal", normal)?;
            let disk = DiskContact::try_new(radius, center, axis)
                .map_err(|e| keys.fail(normal, &format!("`contact.normal`: {e}")))?;
            Ok(ContactShape::Disk(disk))
        }
        ShapeName::Ellipsoid => {
            not_with(
                keys,
                "radius",
                &raw.radius,
                "is not used by an ellipsoid (give `semi_axes`)",
            )?;
            not_with(keys, "normal", &raw.normal, "is only for a disk (its axis)")?;
            let axes = required(
                keys,
                "semi_axes",
                &raw.semi_axes,
                &raw.shape,
                "an ellipsoid needs its semi-axes a, b, c in metres",
            )?;
            let [a, b, c] = keys.finite("contact.semi_axes", axes)?;
            if ![a, b, c].iter().all(|&x| x > 0.0) {
                return Err(keys.fail(axes, "`contact.semi_axes` must be positive"));
            }
            let ellipsoid = EllipsoidContact::try_new(DVec3::new(a, b, c), center)
                .map_err(|e| keys.fail(axes, &format!("`contact.semi_axes`: {e}")))?;
            Ok(ContactShape::Ellipsoid(ellipsoid))
        }
    }
}

/// The friction law from `friction`, `mu` and `slip_velocity`.
fn friction(keys: &Keys<'_>, raw: &RawContact) -> Result<Friction, SceneError> {
    let given = required(
        keys,
        "friction",
        &raw.friction,
        &raw.shape,
        "\"none\", \"viscous\", \"sliding\", \"rolling\" or \"coulomb\" at the contact the body \
         stands on",
    )?;
    let model: FrictionModel = given.get_ref().parse().map_err(|e| match e {
        DynamicsError::UnknownFriction { name, known } => keys.fail(
            given,
            &format!(
                "`contact.friction`: unknown friction model `{name}` (known: {known}, {COULOMB})"
            ),
        ),
        other => keys.fail(given, &format!("`contact.friction`: {other}")),
    })?;
    let unused = format!("is not used with friction \"{model}\"");
    let only_coulomb = "is only for friction \"coulomb\" (a body on the table)";
    not_coulomb_keys(keys, raw, only_coulomb)?;
    if model != FrictionModel::Sliding {
        let why = "is only for friction \"sliding\" (the ε of F = −μ N v/√(|v|² + ε²))";
        not_with(keys, "slip_velocity", &raw.slip_velocity, why)?;
    }
    let mu = |keys: &Keys<'_>, unit: &str| -> Result<f64, SceneError> {
        let what = format!("friction \"{model}\" needs the coefficient μ ({unit})");
        let mu = required(keys, "mu", &raw.mu, given, &what)?;
        let value = *mu.get_ref();
        if value.is_finite() && value >= 0.0 {
            Ok(value)
        } else {
            let message = format!(
                "`contact.mu` must be zero or positive and finite, got {}",
                Shortest(value)
            );
            Err(keys.fail(mu, &message))
        }
    };
    match model {
        FrictionModel::None => {
            not_with(keys, "mu", &raw.mu, &unused)?;
            Ok(Friction::None)
        }
        FrictionModel::Rolling => {
            not_with(keys, "mu", &raw.mu, &unused)?;
            Ok(Friction::Rolling)
        }
        FrictionModel::Viscous => Ok(Friction::Viscous {
            mu: mu(keys, "s/m")?,
        }),
        FrictionModel::Sliding => {
            let mu = mu(keys, "Coulomb's, dimensionless")?;
            let slip_velocity = match &raw.slip_velocity {
                Some(v) => keys.positive("contact.slip_velocity", v)?,
                None => Friction::DEFAULT_SLIP_VELOCITY,
            };
            Ok(Friction::Sliding { mu, slip_velocity })
        }
    }
}
