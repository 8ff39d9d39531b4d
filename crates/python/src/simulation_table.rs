//! Bodies on the table from Python: the `contacts` of `World.add_body`
//! (dicts with the keys of a scene's `[[body.contact]]` table with
//! `friction = "coulomb"`), and the table's events as tuples — those of
//! `World.events` and those of `kreisel.simulate(..., events=True)` (the
//! rows of the CLI's `--events` file). No physics here: the library's
//! [`ContactLaw`] and shapes check the numbers, this names the key.

use glam::DVec3;
use kreisel_dynamics::{
    ContactLaw, ContactShape, DiskContact, DynamicsError, EllipsoidContact, SphereContact,
    TableContact, TableEvent, TableEventKind, World,
};
use kreisel_scene::events::{kind_name, merged};
use kreisel_scene::run::Names;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PySequence, PyString, PyTuple};

use kreisel_scene::numbers::Shortest;

use crate::arguments::{finite, numbers};
use crate::errors::error;

/// The keys of a contact dict (those of the scene's `[[body.contact]]`
/// table that a body on the table takes).
const KEYS: [&str; 11] = [
    "shape",
    "radius",
    "center",
    "normal",
    "semi_axes",
    "friction",
    "mu",
    "restitution",
    "tangential_restitution",
    "contensou_radius",
    "rolling_resistance",
];

/// One contact dict, read key by key under the name `contacts[i]`.
struct Keys<'a, 'py> {
    name: &'a str,
    dict: &'a Bound<'py, PyDict>,
}

impl Keys<'_, '_> {
    /// The value of `key`, if given (and not `None`).
    fn get(&self, key: &str) -> PyResult<Option<Bound<'_, PyAny>>> {
        Ok(self.dict.get_item(key)?.filter(|v| !v.is_none()))
    }

    /// The full name of `key` in messages: `contacts[0].mu`.
    fn full(&self, key: &str) -> String {
        format!("{}.{key}", self.name)
    }

    /// A finite number under `key`, or `default` when it is absent.
    fn number(&self, key: &str, default: Option<f64>) -> PyResult<f64> {
        match (self.get(key)?, default) {
            (Some(v), _) => finite(&self.full(key), &v),
            (None, Some(d)) => Ok(d),
            (None, None) => Err(error(format!("{}: is missing", self.full(key)))),
        }
    }

    /// A vector of 3 finite numbers under `key` (zero when absent and
    /// `required` is false).
    fn vector(&self, key: &str, required: bool) -> PyResult<DVec3> {
        match self.get(key)? {
            Some(v) => numbers::<3>(&self.full(key), &v).map(DVec3::from_array),
            None if required => Err(error(format!("{}: is missing", self.full(key)))),
            None => Ok(DVec3::ZERO),
        }
    }

    /// `key` given where the shape has no use for it: an error.
    fn unused(&self, key: &str, why: &str) -> PyResult<()> {
        match self.get(key)? {
            Some(_) => Err(error(format!("{}: {why}", self.full(key)))),
            None => Ok(()),
        }
    }

    /// A library error about a contact parameter, naming its key.
    fn invalid(&self, e: DynamicsError) -> PyErr {
        match e {
            DynamicsError::InvalidContact {
                parameter,
                value,
                reason,
            } => error(format!(
                "{}: {reason}, got {}",
                self.full(parameter),
                Shortest(value)
            )),
            other => error(format!("{}: {other}", self.name)),
        }
    }
}

/// The surface from `shape`, `radius`, `center`, `normal`, `semi_axes`.
fn shape(keys: &Keys<'_, '_>) -> PyResult<ContactShape> {
    let name: String = match keys.get("shape")? {
        Some(v) => v
            .extract()
            .map_err(|_| PyTypeError::new_err(format!("{} must be a str", keys.full("shape"))))?,
        None => return Err(error(format!("{}: is missing", keys.full("shape")))),
    };
    let center = keys.vector("center", false)?;
    let only_disk = "is only for a disk (its axis)";
    let made = match name.as_str() {
        "sphere" => {
            keys.unused("normal", only_disk)?;
            keys.unused("semi_axes", "is only for an ellipsoid")?;
            SphereContact::try_new(keys.number("radius", None)?, center).map(ContactShape::Sphere)
        }
        "disk" => {
            keys.unused("semi_axes", "is only for an ellipsoid")?;
            let radius = keys.number("radius", None)?;
            let normal = keys.vector("normal", true)?;
            DiskContact::try_new(radius, center, normal).map(ContactShape::Disk)
        }
        "ellipsoid" => {
            keys.unused("normal", only_disk)?;
            keys.unused("radius", "is not used by an ellipsoid (give semi_axes)")?;
            let axes = keys.vector("semi_axes", true)?;
            EllipsoidContact::try_new(axes, center).map(ContactShape::Ellipsoid)
        }
        other => {
            return Err(error(format!(
                "{}: unknown contact shape '{other}' (known: sphere, disk, ellipsoid)",
                keys.full("shape")
            )));
        }
    };
    made.map_err(|e| keys.invalid(e))
}

/// The Coulomb law from `mu`, `restitution`, `tangential_restitution`,
/// `contensou_radius`, `rolling_resistance` (the scene's defaults: 0).
fn law(keys: &Keys<'_, '_>) -> PyResult<ContactLaw> {
    if let Some(f) = keys.get("friction")? {
        let name: String = f.extract().unwrap_or_default();
        if name != "coulomb" {
            return Err(error(format!(
                "{}: a body on the table has friction 'coulomb' (the only law here), got {f}",
                keys.full("friction")
            )));
        }
    }
    let mu = keys.number("mu", None)?;
    let e = keys.number("restitution", Some(0.0))?;
    let e_t = keys.number("tangential_restitution", Some(0.0))?;
    let r_c = keys.number("contensou_radius", Some(0.0))?;
    let delta = keys.number("rolling_resistance", Some(0.0))?;
    ContactLaw::try_new(mu)
        .and_then(|l| l.try_with_restitution(e))
        .and_then(|l| l.try_with_tangential_restitution(e_t))
        .and_then(|l| l.try_with_contensou_radius(r_c))
        .and_then(|l| l.try_with_rolling_resistance(delta))
        .map_err(|e| keys.invalid(e))
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
    let n = list.len()?;
    if n == 0 || n > kreisel_dynamics::TableBody::MAX_CONTACTS {
        return Err(error(format!(
            "contacts: {n} contacts: a body on the table has 1 to {}",
            kreisel_dynamics::TableBody::MAX_CONTACTS
        )));
    }
    (0..n)
        .map(|i| {
            let name = format!("contacts[{i}]");
            let item = list.get_item(i)?;
            let dict = item
                .cast::<PyDict>()
                .map_err(|_| PyTypeError::new_err(format!("{name} must be a dict")))?;
            for key in dict.keys() {
                let key: String = key.extract()?;
                if !KEYS.contains(&key.as_str()) {
                    return Err(error(format!(
                        "{name}.{key}: unknown key (known: {})",
                        KEYS.join(", ")
                    )));
                }
            }
            let keys = Keys { name: &name, dict };
            Ok(TableContact {
                shape: shape(&keys)?,
                law: law(&keys)?,
            })
        })
        .collect()
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
