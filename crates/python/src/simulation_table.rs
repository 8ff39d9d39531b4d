//! Bodies on the table from Python: the `contacts` of `World.add_body`
//! (dicts with the keys of a scene's `[[body.contact]]` table with
//! `friction = "coulomb"`), and the table's events as tuples — those of
//! `World.events` and those of `kreisel.simulate(..., events=True)` (the
//! rows of the CLI's `--events` file). No checks here: each dict fills in
//! the scene layer's [`ContactRequest`], which checks it as it checks a
//! scene's table; this converts the values and names the key.

use glam::DVec3;
use kreisel_dynamics::{DynamicsError, TableContact, TableEvent, TableEventKind, World};
use kreisel_scene::contact_key::{
    ContactKey, ContactKeyError, ContactKeyProblem, NotFor, ShapeName, Surface,
};
use kreisel_scene::contact_list::on_table;
use kreisel_scene::contact_request::ContactRequest;
use kreisel_scene::events::{kind_name, merged};
use kreisel_scene::run::Names;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PySequence, PyString, PyTuple};

use kreisel_scene::numbers::Shortest;

use crate::arguments::{finite, numbers};
use crate::errors::error;

/// The keys of a contact dict: those of the scene's `[[body.contact]]`
/// table that a body on the table takes (all but `slip_velocity`).
const KEYS: [ContactKey; 13] = [
    ContactKey::Shape,
    ContactKey::Radius,
    ContactKey::Center,
    ContactKey::Normal,
    ContactKey::SemiAxes,
    ContactKey::Friction,
    ContactKey::Mu,
    ContactKey::Restitution,
    ContactKey::TangentialRestitution,
    ContactKey::ContensouRadius,
    ContactKey::RollingResistance,
    ContactKey::AirViscosity,
    ContactKey::AirGap,
];

/// One contact dict (`name`: `contacts[i]`) as the scene layer's request:
/// each value converted under its full name (`contacts[0].mu`), `None`
/// as absent; the checks are the request's.
fn request(name: &str, dict: &Bound<'_, PyDict>) -> PyResult<ContactRequest<()>> {
    let mut r = ContactRequest::new(());
    for (key, value) in dict.iter() {
        let key: String = key.extract()?;
        let full = format!("{name}.{key}");
        let Some(known) = KEYS.into_iter().find(|k| k.name() == key) else {
            let known = KEYS.map(ContactKey::name).join(", ");
            return Err(error(format!("{full}: unknown key (known: {known})")));
        };
        if value.is_none() {
            continue;
        }
        let vector = || numbers::<3>(&full, &value).map(|v| Some((DVec3::from_array(v), ())));
        match known {
            ContactKey::Shape => {
                let shape: String = value
                    .extract()
                    .map_err(|_| PyTypeError::new_err(format!("{full} must be a str")))?;
                r.shape = Some((shape, ()));
            }
            // Any value: what is not "coulomb" is refused, as it prints.
            ContactKey::Friction => r.friction = Some((value.str()?.to_string(), ())),
            ContactKey::Center => r.center = vector()?,
            ContactKey::Normal => r.normal = vector()?,
            ContactKey::SemiAxes => r.semi_axes = vector()?,
            // The names and vectors are read above: every other key of
            // KEYS is a number, which has its slot.
            number => {
                if let Some(slot) = r.number_mut(number) {
                    *slot = Some((finite(&full, &value)?, ()));
                }
            }
        }
    }
    Ok(r)
}

/// The one line of a problem with the `contacts` argument, naming the
/// key (`contacts[1].mu: …`).
fn contact_error(e: ContactKeyError<()>) -> PyErr {
    let place = e
        .contact
        .map_or_else(|| "contacts".to_owned(), |i| format!("contacts[{i}]"));
    let full = |key: &str| format!("{place}.{key}");
    let how_many = |given: usize| {
        format!(
            "contacts: {given} contacts: a body on the table has 1 to {}",
            Surface::Table.most()
        )
    };
    let message = match &e.problem {
        ContactKeyProblem::NoContacts => how_many(0),
        ContactKeyProblem::TooMany { given, .. } => how_many(*given),
        ContactKeyProblem::UnknownShape { name } => format!(
            "{}: unknown contact shape '{name}' (known: {})",
            full("shape"),
            ShapeName::known()
        ),
        ContactKeyProblem::UnknownFriction { name }
        | ContactKeyProblem::NotCoulomb { friction: name, .. } => format!(
            "{}: a body on the table has friction 'coulomb' (the only law here), got {name}",
            full("friction")
        ),
        ContactKeyProblem::Missing { key, .. } => format!("{}: is missing", full(key.name())),
        ContactKeyProblem::NotFor { key, why } => {
            let why = match why {
                NotFor::OnlyDisk => "is only for a disk (its axis)",
                NotFor::OnlyEllipsoid => "is only for an ellipsoid",
                NotFor::Ellipsoid => "is not used by an ellipsoid (give semi_axes)",
                NotFor::AirOnlyDisk => {
                    "is Moffatt's air layer under a disk rim: only for shape 'disk'"
                }
                NotFor::NoAirViscosity => "needs air_viscosity (the air layer's viscosity)",
                // A body on the ground's rules: not Python's.
                _ => "has no meaning for a body on the table",
            };
            format!("{}: {why}", full(key.name()))
        }
        ContactKeyProblem::NotFinite { key } => {
            format!("{}: must be finite numbers", full(key.name()))
        }
        ContactKeyProblem::NotPositive { key, value } => format!(
            "{}: must be positive and finite, got {}",
            full(key.name()),
            Shortest(*value)
        ),
        ContactKeyProblem::Negative { key, value } => format!(
            "{}: must be zero or positive and finite, got {}",
            full(key.name()),
            Shortest(*value)
        ),
        ContactKeyProblem::Library {
            error:
                DynamicsError::InvalidContact {
                    parameter,
                    value,
                    reason,
                },
            ..
        } => format!("{}: {reason}, got {}", full(parameter), Shortest(*value)),
        ContactKeyProblem::Library { error, .. } => format!("{place}: {error}"),
    };
    error(message)
}

/// The `contacts` argument: a list of dicts, each a contact shape and its
/// law (module docs of `World.add_body`).
///
/// # Errors
/// `TypeError` for something that is not a list of dicts; `KreiselError`
/// naming the key (`contacts[1].mu: …`) for a bad or unknown key, none or
/// more contacts than a body carries.
pub fn contacts(value: &Bound<'_, PyAny>) -> PyResult<Vec<TableContact>> {
    let list = value
        .cast::<PySequence>()
        .ok()
        .filter(|_| !value.is_instance_of::<PyString>())
        .ok_or_else(|| PyTypeError::new_err("contacts must be a list of dicts"))?;
    let requests = (0..list.len()?)
        .map(|i| {
            let name = format!("contacts[{i}]");
            let item = list.get_item(i)?;
            let dict = item
                .cast::<PyDict>()
                .map_err(|_| PyTypeError::new_err(format!("{name} must be a dict")))?;
            request(&name, dict)
        })
        .collect::<PyResult<Vec<_>>>()?;
    on_table(&requests, ()).map_err(contact_error)
}

/// The fields after `kind` of an event: the speeds of an impact, the
/// accumulation time (`None` where the `--events` CSV is empty).
fn values(kind: TableEventKind) -> [Option<f64>; 3] {
    match kind {
        TableEventKind::Impact {
            approach_speed,
            rebound_speed,
        } => [Some(approach_speed), Some(rebound_speed), None],
        TableEventKind::ImpactsAccumulate { accumulation_time } => {
            [None, None, Some(accumulation_time)]
        }
        _ => [None, None, None],
    }
}

/// `(time, contact, kind, approach_speed, rebound_speed,
/// accumulation_time)` per event, `contact` the index in the body's
/// `contacts` (`None`: the whole body).
pub fn world_events<'py>(py: Python<'py>, events: &[TableEvent]) -> PyResult<Bound<'py, PyList>> {
    let rows = events.iter().map(|e| {
        let [approach, rebound, accumulation] = values(e.kind);
        (
            e.time,
            e.contact,
            kind_name(e.kind),
            approach,
            rebound,
            accumulation,
        )
    });
    PyList::new(py, rows)
}

/// The rows of the `--events` CSV of `world`'s bodies `bodies`, in its
/// order: `(time, body, contact, kind, approach_speed, rebound_speed,
/// accumulation_time)`, `contact` the `[[body.contact]]` table's number
/// (1 = the first; `None`: the whole body).
pub fn scene_events<'py>(
    py: Python<'py>,
    world: &World,
    bodies: &Names,
) -> PyResult<Bound<'py, PyList>> {
    let rows: Vec<Bound<'py, PyTuple>> = merged(world, bodies)
        .into_iter()
        .map(|(name, e)| {
            let [approach, rebound, accumulation] = values(e.kind);
            let contact = e.contact.map(|i| i + 1);
            let row = (
                e.time,
                name,
                contact,
                kind_name(e.kind),
                approach,
                rebound,
                accumulation,
            );
            row.into_pyobject(py)
        })
        .collect::<PyResult<_>>()?;
    PyList::new(py, rows)
}
