//! A body's `[body.contact]` table: the surface that touches the ground
//! plane z = 0 (a sphere, a disk rim, an ellipsoid with its semi-axes
//! along the body axes) and the friction law there, read with the spans
//! of its keys into a [`ContactRequest`] each, which the scene layer
//! checks (`contact_request.rs`, `contact_list.rs`, shared with Python's
//! `World.add_body`); this file words their problems at their lines.
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
//! Contensou's drilling, Newton's impacts
//! ([`kreisel_dynamics::ContactLaw`]) — by the library's event-driven
//! [`kreisel_dynamics::TableMotion`] ([`kreisel_dynamics::Support::Table`]):
//! each table gives its own law (`friction = "coulomb"` on every one of
//! them, up to [`kreisel_dynamics::TableBody::MAX_CONTACTS`]; another
//! friction model on the same body is an error), and the body may start
//! above the table.
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
//! [`kreisel_dynamics::Friction::DEFAULT_SLIP_VELOCITY`] (1 mm/s, Leine &
//! Glocker's ε).

#![forbid(unsafe_code)]

use std::fmt;

use glam::DVec3;
use kreisel_dynamics::{DynamicsError, FrictionModel, MAX_OTHER_CONTACTS};
use serde::Deserialize;
use serde::de::{self, Deserializer, MapAccess, SeqAccess, Visitor};
use toml::Spanned;

use crate::contact_key::{
    ContactKey, ContactKeyError, ContactKeyProblem, FrictionName, Needs, NotFor, ShapeName, Surface,
};
use crate::contact_list::{self, Contacts};
use crate::contact_request::ContactRequest;
use crate::error::{KeyProblem, SceneError};
use crate::numbers::Shortest;
use crate::scene_keys::Keys;

/// A span of the scene's text.
type Span = std::ops::Range<usize>;

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
    pub fn mu_span(&self) -> Option<Span> {
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

/// The `[[body.contact]]` tables of `contacts` with their spans (one
/// `[body.contact]` table: that one, at the key's span).
pub fn tables(contacts: &Spanned<RawContacts>) -> Vec<(&RawContact, Span)> {
    match contacts.get_ref() {
        RawContacts::One(one) => vec![(one.as_ref(), contacts.span())],
        RawContacts::Many(many) => many.iter().map(|c| (c.get_ref(), c.span())).collect(),
    }
}

/// Checks the `contact` key of a body: one table, or an array of them
/// (the first touching, the others watched; with `friction = "coulomb"`
/// all of them on the table; module docs), by [`contact_list::contacts`].
///
/// # Errors
/// [`SceneError::Key`] naming the line and key of the first problem, typed
/// ([`crate::error::KeyProblem::Contact`]).
pub fn check(keys: &Keys<'_>, contacts: &Spanned<RawContacts>) -> Result<Contacts, SceneError> {
    let tables = tables(contacts);
    let requests: Vec<ContactRequest<Span>> = tables
        .iter()
        .map(|(raw, span)| request(raw, span.clone()))
        .collect();
    contact_list::contacts(&requests, contacts.span()).map_err(|e| contact_error(keys, &tables, e))
}

/// The request of one table given at `span`, each value at its span.
fn request(raw: &RawContact, span: Span) -> ContactRequest<Span> {
    let number = |v: &Option<Spanned<f64>>| v.as_ref().map(|v| (*v.get_ref(), v.span()));
    let vector = |v: &Option<Spanned<[f64; 3]>>| {
        v.as_ref()
            .map(|v| (DVec3::from_array(*v.get_ref()), v.span()))
    };
    let name = |v: &Spanned<String>| (v.get_ref().clone(), v.span());
    ContactRequest {
        contact: span,
        shape: Some(name(&raw.shape)),
        radius: number(&raw.radius),
        center: vector(&raw.center),
        normal: vector(&raw.normal),
        semi_axes: vector(&raw.semi_axes),
        friction: raw.friction.as_ref().map(name),
        mu: number(&raw.mu),
        slip_velocity: number(&raw.slip_velocity),
        restitution: number(&raw.restitution),
        tangential_restitution: number(&raw.tangential_restitution),
        contensou_radius: number(&raw.contensou_radius),
        rolling_resistance: number(&raw.rolling_resistance),
        air_viscosity: number(&raw.air_viscosity),
        air_gap: number(&raw.air_gap),
    }
}

/// The one line of a problem with the contact `tables` of a body, at its
/// line.
fn contact_error(
    keys: &Keys<'_>,
    tables: &[(&RawContact, Span)],
    e: ContactKeyError<Span>,
) -> SceneError {
    // The table's number (1-based), and the line of contact c's "coulomb".
    let table = e.contact.map_or(0, |n| n + 1);
    let named = |key: ContactKey| format!("`contact.{}`", key.name());
    let coulomb_line = |c: usize| {
        let friction = tables.get(c).and_then(|(raw, _)| raw.friction.as_ref());
        friction.map_or(0, |f| keys.line_of(f))
    };
    let message = match e.problem.clone() {
        ContactKeyProblem::NoContacts => "`contact` is an empty array: give one table".to_owned(),
        ContactKeyProblem::TooMany {
            given,
            surface: Surface::Table,
        } => format!(
            "{given} [[body.contact]] tables: a body on the table has at most {}",
            Surface::Table.most()
        ),
        ContactKeyProblem::TooMany {
            given,
            surface: Surface::Ground,
        } => format!(
            "{given} [[body.contact]] tables: at most {} (the first touching the plane, up to \
             {MAX_OTHER_CONTACTS} more watched for touchdown)",
            Surface::Ground.most()
        ),
        ContactKeyProblem::UnknownShape { name } => format!(
            "`contact.shape`: unknown contact shape `{name}` (known: {})",
            ShapeName::known()
        ),
        ContactKeyProblem::UnknownFriction { name } => format!(
            "`contact.friction`: unknown friction model `{name}` (known: {})",
            FrictionName::known()
        ),
        ContactKeyProblem::Missing { key, needs } => {
            let what = match needs {
                Needs::TableLaw { coulomb } => format!(
                    "the body is on the table (friction \"coulomb\" at line {}), and every \
                     [[body.contact]] gives its own law: friction = \"coulomb\" with its mu \
                     (table #{table})",
                    coulomb_line(coulomb)
                ),
                other => needed_for(key, other),
            };
            format!("{} is missing: {what}", named(key))
        }
        ContactKeyProblem::NotFor { key, why } => format!("{} {}", named(key), unused(why, table)),
        ContactKeyProblem::NotFinite { key } => format!("{} must be finite numbers", named(key)),
        ContactKeyProblem::NotPositive {
            key: ContactKey::SemiAxes,
            ..
        } => "`contact.semi_axes` must be positive".to_owned(),
        ContactKeyProblem::NotPositive { key, value } => format!(
            "{} must be positive and finite, got {}",
            named(key),
            Shortest(value)
        ),
        ContactKeyProblem::Negative { key, value } => format!(
            "{} must be zero or positive and finite, got {}",
            named(key),
            Shortest(value)
        ),
        ContactKeyProblem::NotCoulomb { friction, coulomb } => format!(
            "`contact.friction` = \"{friction}\" cannot be mixed with \"coulomb\" on one body \
             (line {}): a body on the table has friction \"coulomb\" at every contact",
            coulomb.map_or(0, coulomb_line)
        ),
        ContactKeyProblem::Library { key, error } => refused(key, &error),
    };
    let problem = KeyProblem::Contact {
        contact: e.contact,
        problem: e.problem,
    };
    keys.fail_key(e.at, problem, &message)
}

/// What a missing `key` is needed for (`needs`; a body on the table's
/// law is worded with its line by [`contact_error`]).
fn needed_for(key: ContactKey, needs: Needs) -> String {
    match (needs, key) {
        (Needs::Coefficient { friction }, _) => {
            let unit = match friction {
                FrictionName::Ground(FrictionModel::Viscous) => "s/m",
                FrictionName::Ground(FrictionModel::Sliding) => "Coulomb's, dimensionless",
                _ => "dimensionless",
            };
            format!(
                "friction \"{}\" needs the coefficient μ ({unit})",
                friction.name()
            )
        }
        (Needs::Standing | Needs::TableLaw { .. }, _) => "\"none\", \"viscous\", \"sliding\", \
             \"rolling\" or \"coulomb\" at the contact the body stands on"
            .to_owned(),
        (Needs::Shape, ContactKey::Radius) => "the radius in metres".to_owned(),
        (Needs::Shape, ContactKey::Normal) => {
            "a disk needs its axis in body coordinates".to_owned()
        }
        (Needs::Shape, ContactKey::SemiAxes) => {
            "an ellipsoid needs its semi-axes a, b, c in metres".to_owned()
        }
        (Needs::Shape, _) => format!("one of {}", ShapeName::known()),
    }
}

/// Why a key has no meaning where it is given (on table number `table`).
fn unused(why: NotFor, table: usize) -> String {
    const SLIDING: &str = "is only for friction \"sliding\" (the ε of F = −μ N v/√(|v|² + ε²))";
    match why {
        NotFor::OnlyDisk => "is only for a disk (its axis)".to_owned(),
        NotFor::OnlyEllipsoid => "is only for an ellipsoid".to_owned(),
        NotFor::Ellipsoid => "is not used by an ellipsoid (give `semi_axes`)".to_owned(),
        NotFor::OnlySliding {
            friction: FrictionName::Coulomb,
        } => format!("{SLIDING}; \"coulomb\" is exact Coulomb friction"),
        NotFor::OnlySliding { .. } => SLIDING.to_owned(),
        NotFor::NoCoefficient { friction } => {
            format!("is not used with friction \"{}\"", friction.name())
        }
        NotFor::OnlyCoulomb => "is only for friction \"coulomb\" (a body on the table)".to_owned(),
        NotFor::Watched => format!(
            "is only for the first contact (the one touching): [[body.contact]] #{table} is \
             watched for touchdown and exerts no force"
        ),
        NotFor::AirOnlyDisk => {
            "is Moffatt's air layer under a disk rim: only for shape = \"disk\"".to_owned()
        }
        NotFor::NoAirViscosity => "needs `air_viscosity` (the air layer's viscosity)".to_owned(),
    }
}

/// The library's refusal of the value of `key`: the law's parameters
/// with their value, a shape's error as the library words it.
fn refused(key: ContactKey, error: &DynamicsError) -> String {
    match (key, error) {
        (ContactKey::Shape, e) => format!("`contact`: {e}"),
        (ContactKey::Normal | ContactKey::SemiAxes, e) => format!("`contact.{}`: {e}", key.name()),
        (
            _,
            DynamicsError::InvalidContact {
                parameter,
                value,
                reason,
            },
        ) => format!("`contact.{parameter}` {reason}, got {}", Shortest(*value)),
        (_, e) => format!("`contact`: {e}"),
    }
}
