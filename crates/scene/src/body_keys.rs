//! One `[[body]]` of the scene: its inertia (moments, a tensor or a mesh),
//! initial attitude, spin, support (free, a pivot, or the ground with a
//! `[body.contact]` table, `contact.rs`) and applied inputs (torques, a
//! force, damping), checked key by key and added to the scene's [`World`]
//! (which holds the physics).

#![forbid(unsafe_code)]

use std::io::Write;
use std::path::Path;

use glam::{DMat3, DQuat, DVec3};
use kreisel_dynamics::{
    Body, BodyBuilder, BodyId, DynamicsError, Friction, Inputs, Plan, TableContact, World,
};
use kreisel_inertia::io::{SolidOptions, SolidWarning, load_solid};
use kreisel_inertia::{MassProperties, Material};
use kreisel_kinematics::{EulerSequence, try_normalize_quat};
use serde::Deserialize;
use toml::Spanned;

use crate::contact_keys::{self as contact, Contacts, RawContacts};
use crate::error::SceneError;
use crate::numbers::Shortest;
use crate::scene_keys::{Keys, SceneFile};
use crate::table_start::{sliding_at_start, touching};

/// A `[[body]]` table as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawBody {
    name: Option<Spanned<String>>,
    mass: Option<Spanned<f64>>,
    inertia: Option<Spanned<[f64; 3]>>,
    inertia_tensor: Option<Spanned<[[f64; 3]; 3]>>,
    mesh: Option<Spanned<String>>,
    density: Option<Spanned<f64>>,
    orientation: Option<Spanned<[f64; 4]>>,
    euler: Option<Spanned<RawEuler>>,
    angular_velocity: Spanned<[f64; 3]>,
    position: Option<Spanned<[f64; 3]>>,
    velocity: Option<Spanned<[f64; 3]>>,
    pivot: Option<Spanned<[f64; 3]>>,
    torque: Option<Spanned<[f64; 3]>>,
    torque_body: Option<Spanned<[f64; 3]>>,
    force: Option<Spanned<[f64; 3]>>,
    angular_damping: Option<Spanned<f64>>,
    contact: Option<Spanned<RawContacts>>,
}

/// `euler = { sequence = "ZXZ", angles = [..] }` as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawEuler {
    sequence: Spanned<String>,
    angles: Spanned<[f64; 3]>,
}

impl RawBody {
    /// Whether the body has a `pivot` (is a heavy top).
    pub fn has_pivot(&self) -> bool {
        self.pivot.is_some()
    }

    /// Where the `contact` key is, if given (the body stands on the ground).
    pub fn contact_span(&self) -> Option<std::ops::Range<usize>> {
        self.contact.as_ref().map(Spanned::span)
    }

    /// The spans of the body's contact tables, in order (none without
    /// `contact`).
    pub fn contact_spans(&self) -> Vec<std::ops::Range<usize>> {
        self.contact.as_ref().map_or_else(Vec::new, |c| {
            contact::tables(c).into_iter().map(|(_, s)| s).collect()
        })
    }

    /// The spans of the `mu` keys of the body's contact tables, in order
    /// (`None` where not given; none without `contact`).
    pub fn mu_spans(&self) -> Vec<Option<std::ops::Range<usize>>> {
        self.contact.as_ref().map_or_else(Vec::new, |c| {
            contact::tables(c)
                .into_iter()
                .map(|(raw, _)| raw.mu_span())
                .collect()
        })
    }

    /// Where the `name` key is, if given.
    pub fn name_span(&self) -> Option<std::ops::Range<usize>> {
        self.name.as_ref().map(Spanned::span)
    }
}

/// Checks body number `number` (1-based, for the default name) and adds it
/// to `world`; mesh paths are relative to `folder`. Returns its name and id.
///
/// # Errors
/// [`SceneError::Scene`] naming the line and key of the first problem.
pub fn add_body(
    file: SceneFile<'_>,
    raw: &Spanned<RawBody>,
    number: usize,
    folder: &Path,
    world: &mut World,
) -> Result<(String, BodyId), SceneError> {
    let b = raw.get_ref();
    let name = match &b.name {
        Some(name) => checked_name(file, name)?,
        None => format!("body{number}"),
    };
    let keys = Keys::new(file, format!("body `{name}`: "));
    let inertia = inertia(&keys, raw, folder)?;
    let attitude = attitude(&keys, b)?;
    let omega = keys.vector("angular_velocity", &b.angular_velocity)?;
    let position = optional_vector(&keys, "position", &b.position)?;
    let velocity = optional_vector(&keys, "velocity", &b.velocity)?;
    let (inputs, first_input) = inputs(&keys, b)?;
    let builder = inertia.builder.world_from_body(attitude).omega_body(omega);
    // A body on the table: its contacts and the start of its centre of mass.
    let mut on_table: Option<(Vec<TableContact>, DVec3)> = None;
    let builder = match (&b.contact, &b.pivot) {
        (Some(_), Some(pivot)) => {
            let message = "`pivot` cannot be given with `contact`: a body turns about a \
                           pivot or stands on the ground, not both";
            return Err(keys.fail(pivot, message));
        }
        (Some(contact), None) => match contact::check(&keys, contact)? {
            Contacts::Table(contacts) => {
                if let Some((key, span)) = &first_input {
                    let message = format!(
                        "`{key}`: applied loads are not modelled for a body on the table \
                         (friction \"coulomb\"): only gravity and the contacts act"
                    );
                    return Err(keys.fail_at(span.clone(), &message));
                }
                // Without `position`: above the origin, its lowest shape touching.
                let position = match &b.position {
                    Some(_) => position,
                    None => touching(&contacts, attitude),
                };
                let built = builder.on_table(position, velocity, &contacts);
                on_table = Some((contacts, position));
                built
            }
            Contacts::Ground(contacts) => {
                let checked = contacts.first;
                if let Some(v) = &b.velocity {
                    if checked.friction == Friction::Rolling {
                        let message = "`velocity` cannot be given with friction \"rolling\": \
                                   it follows from rolling without slipping";
                        return Err(keys.fail(v, message));
                    }
                    if velocity.z != 0.0 {
                        let message = format!(
                            "`velocity` of a body on the ground must be horizontal, \
                         [vx, vy, 0], got vz = {}: the vertical velocity follows from \
                         the spin",
                            Shortest(velocity.z)
                        );
                        return Err(keys.fail(v, &message));
                    }
                }
                builder
                    .on_ground_at(
                        checked.shape,
                        checked.friction,
                        position.truncate(),
                        velocity.truncate(),
                    )
                    .other_contacts(&contacts.others)
            }
        },
        (None, Some(pivot)) => {
            if let Some(v) = &b.velocity {
                let message = "`velocity` cannot be given with `pivot`: the pivot is fixed";
                return Err(keys.fail(v, message));
            }
            builder.pivot(keys.vector("pivot", pivot)?, position)
        }
        (None, None) => builder.free(position, velocity),
    };
    let state_error = |e: DynamicsError| keys.fail(&b.angular_velocity, &e.to_string());
    let body = builder.try_build().map_err(|e| match e {
        DynamicsError::InvalidState { .. } => state_error(e),
        other => keys.fail_at(inertia.span.clone(), &format!("`{}`: {other}", inertia.key)),
    })?;
    // Checked above: finite, damping not negative.
    let body = body
        .with_inputs(inputs)
        .map_err(|e| keys.fail(raw, &e.to_string()))?;
    let id = world
        .add(body)
        .map_err(|e| match (e, &b.pivot, &b.contact) {
            (DynamicsError::OtherContactTouching { contact: i, gap }, _, Some(contact)) => {
                watched_touching(&keys, contact, i, gap)
            }
            (DynamicsError::BodyInsideTable { contact: i, gap }, _, Some(contact)) => {
                inside_table(&keys, b.position.as_ref(), contact, i, gap)
            }
            (e @ DynamicsError::ContactIndeterminate { .. }, _, Some(contact)) => {
                painleve_at_start(&keys, contact, on_table.as_ref(), attitude, &e)
            }
            (e, _, Some(contact)) => keys.fail(contact, &format!("`contact`: {e}")),
            (e @ DynamicsError::InvalidState { .. }, _, _) => state_error(e),
            (e @ DynamicsError::MethodTakesNoInputs { .. }, _, _) => match &first_input {
                Some((key, span)) => keys.fail_at(span.clone(), &format!("`{key}`: {e}")),
                None => keys.fail(raw, &e.to_string()),
            },
            (e, Some(pivot), _) => keys.fail(pivot, &format!("`pivot`: {e}")),
            (e, None, _) => keys.fail(raw, &e.to_string()),
        })?;
    let on_ground = matches!(world.plan(id), Some(Plan::OnGround { .. }));
    if let (true, Some(given)) = (on_ground, &b.position) {
        check_height(&keys, given, world, id)?;
    }
    Ok((name, id))
}

/// The error for further contact `index` (0-based among the watched
/// ones, the table after the first) at or below the plane at the start,
/// at its table's line.
fn watched_touching(
    keys: &Keys<'_>,
    contacts: &Spanned<RawContacts>,
    index: usize,
    gap: f64,
) -> SceneError {
    let tables = contact::tables(contacts);
    let span = tables
        .get(index + 1)
        .map_or(contacts.span(), |(_, span)| span.clone());
    let message = format!(
        "[[body.contact]] #{} is at or below the plane at the start (its lowest point at \
         z = {} m): the contacts after the first are watched for touchdown and must start \
         above the plane",
        index + 2,
        Shortest(gap)
    );
    keys.fail_at(span, &message)
}

/// The error for Painlevé's case when a body on the table (`on_table`: its
/// contacts and centre of mass at attitude `q`) is added: at the `mu` key
/// of the first contact that touches at the start with friction (else
/// the first table).
fn painleve_at_start(
    keys: &Keys<'_>,
    contacts: &Spanned<RawContacts>,
    on_table: Option<&(Vec<TableContact>, DVec3)>,
    q: DQuat,
    error: &DynamicsError,
) -> SceneError {
    let (laws, position) = on_table.map_or((&[][..], DVec3::ZERO), |(c, p)| (c.as_slice(), *p));
    let (index, mu) = sliding_at_start(laws, position, q);
    let tables = contact::tables(contacts);
    let span = tables.get(index).map_or(contacts.span(), |(raw, span)| {
        raw.mu_span().unwrap_or(span.clone())
    });
    keys.fail_at(span, &contact::painleve_message(index, mu, error))
}

/// The error for contact `index` (0-based) of a body on the table below
/// it at the start, at the `position` key if given, else at the table's
/// line.
fn inside_table(
    keys: &Keys<'_>,
    position: Option<&Spanned<[f64; 3]>>,
    contacts: &Spanned<RawContacts>,
    index: usize,
    gap: f64,
) -> SceneError {
    let message = format!(
        "[[body.contact]] #{} is below the table at the start (its lowest point at z = {} m): \
         a body on the table starts above it or touching it",
        index + 1,
        Shortest(gap)
    );
    match position {
        Some(p) => keys.fail(p, &format!("`position`: {message}")),
        None => {
            let tables = contact::tables(contacts);
            let span = tables
                .get(index)
                .map_or(contacts.span(), |(_, span)| span.clone());
            keys.fail_at(span, &message)
        }
    }
}

/// The largest difference between a ground body's `position` z and the
/// height at which it touches the plane, m (a nanometre: the height is
/// typed in, not computed).
pub const HEIGHT_TOLERANCE: f64 = 1e-9;

/// A ground body's `position` z must be the height at which it touches
/// the plane at its attitude (within [`HEIGHT_TOLERANCE`]).
fn check_height(
    keys: &Keys<'_>,
    given: &Spanned<[f64; 3]>,
    world: &World,
    id: BodyId,
) -> Result<(), SceneError> {
    let Some(state) = world.state(id) else {
        return Ok(());
    };
    let (z, touching) = (given.get_ref()[2], state.position.z);
    if (z - touching).abs() <= HEIGHT_TOLERANCE {
        return Ok(());
    }
    let side = if z < touching {
        "below the plane"
    } else {
        "above the plane, not touching it"
    };
    let message = format!(
        "`position` z = {} m puts the body {side}: at its attitude it touches the plane \
         with its centre of mass at z = {} m (the height follows from the attitude: \
         give that z, or leave `position` out)",
        Shortest(z),
        Shortest(touching)
    );
    Err(keys.fail(given, &message))
}

/// A key and where it is.
type KeySpan = (&'static str, std::ops::Range<usize>);

/// The applied inputs from `torque`, `torque_body`, `force` and
/// `angular_damping` (all zero when absent), and the first of those keys
/// given with its span.
fn inputs(keys: &Keys<'_>, b: &RawBody) -> Result<(Inputs, Option<KeySpan>), SceneError> {
    let vectors = [
        ("torque", &b.torque),
        ("torque_body", &b.torque_body),
        ("force", &b.force),
    ];
    let mut first = vectors
        .iter()
        .find_map(|(key, v)| v.as_ref().map(|v| (*key, v.span())));
    let [torque, torque_body, force] = vectors.map(|(key, v)| optional_vector(keys, key, v));
    let mut inputs = Inputs::default()
        .with_torque_world(torque?)
        .with_torque_body(torque_body?)
        .with_force_world(force?);
    if let Some(c) = &b.angular_damping {
        let value = *c.get_ref();
        if !(value.is_finite() && value >= 0.0) {
            let message = format!(
                "`angular_damping` must be zero or positive and finite (N m s), got {}",
                Shortest(value)
            );
            return Err(keys.fail(c, &message));
        }
        inputs = inputs.with_angular_damping(value);
        first = first.or(Some(("angular_damping", c.span())));
    }
    Ok((inputs, first))
}

/// The `name`, which must be a plain CSV field.
fn checked_name(file: SceneFile<'_>, name: &Spanned<String>) -> Result<String, SceneError> {
    let text = name.get_ref();
    if text.is_empty() || text.chars().any(|c| c == ',' || c == '"' || c.is_control()) {
        let message = "`name` must be non-empty, without commas, quotes or control characters \
                       (it is a CSV field)";
        return Err(Keys::new(file, String::new()).fail(name, message));
    }
    Ok(text.clone())
}

/// `[0, 0, 0]` when absent.
fn optional_vector(
    keys: &Keys<'_>,
    key: &str,
    value: &Option<Spanned<[f64; 3]>>,
) -> Result<DVec3, SceneError> {
    value
        .as_ref()
        .map_or(Ok(DVec3::ZERO), |v| keys.vector(key, v))
}

/// The inertia of a body, checked, and the key it came from.
struct CheckedInertia {
    /// The body with this inertia (state and support still to set).
    builder: BodyBuilder,
    /// `inertia`, `inertia_tensor` or `mesh`.
    key: &'static str,
    /// Where that key is.
    span: std::ops::Range<usize>,
}

/// The inertia from exactly one of `inertia` (principal moments, body axes
/// = principal axes, centre of mass at the origin), `inertia_tensor` (about
/// the centre of mass at the origin) and `mesh` (a solid of `density`,
/// mesh coordinates), checked by building a body at rest with it.
fn inertia(
    keys: &Keys<'_>,
    raw: &Spanned<RawBody>,
    folder: &Path,
) -> Result<CheckedInertia, SceneError> {
    let b = raw.get_ref();
    let given: Vec<(&'static str, std::ops::Range<usize>)> = [
        ("inertia", b.inertia.as_ref().map(Spanned::span)),
        (
            "inertia_tensor",
            b.inertia_tensor.as_ref().map(Spanned::span),
        ),
        ("mesh", b.mesh.as_ref().map(Spanned::span)),
    ]
    .into_iter()
    .filter_map(|(key, span)| span.map(|s| (key, s)))
    .collect();
    const ONE_OF: &str = "use exactly one of `inertia`, `inertia_tensor` and `mesh`";
    let (key, span) = match given.as_slice() {
        [] => return Err(keys.fail(raw, &format!("no inertia given: {ONE_OF}"))),
        [(key, span)] => (*key, span.clone()),
        [(first, _), (second, span), ..] => {
            let message = format!("both `{first}` and `{second}` given: {ONE_OF}");
            return Err(keys.fail_at(span.clone(), &message));
        }
    };
    let builder = if let Some(mesh) = &b.mesh {
        if let Some(mass) = &b.mass {
            let message =
                "`mass` cannot be given with `mesh`: it follows from the mesh and `density`";
            return Err(keys.fail(mass, message));
        }
        let Some(density) = &b.density else {
            return Err(keys.fail(mesh, "`mesh` needs `density` (kg/m^3)"));
        };
        let density = keys.positive("density", density)?;
        Body::from_mass_properties(mesh_properties(keys, mesh, density, folder)?)
    } else {
        if let Some(density) = &b.density {
            return Err(keys.fail(density, "`density` is only used with `mesh`"));
        }
        let Some(mass) = &b.mass else {
            return Err(keys.fail(raw, "`mass` (kg) is missing"));
        };
        let mass = keys.positive("mass", mass)?;
        match (&b.inertia, &b.inertia_tensor) {
            (Some(moments), _) => {
                Body::from_principal_moments(mass, DVec3::from_array(*moments.get_ref()))
            }
            (None, Some(tensor)) => {
                let rows = *tensor.get_ref();
                if !rows.as_flattened().iter().all(|x| x.is_finite()) {
                    return Err(keys.fail(tensor, "`inertia_tensor` must be finite numbers"));
                }
                let matrix = DMat3::from_cols_array_2d(&rows).transpose();
                let props = MassProperties::try_new(mass, DVec3::ZERO, matrix).map_err(|e| {
                    let e = DynamicsError::InertiaTensor {
                        reason: e.to_string(),
                    };
                    keys.fail(tensor, &format!("`inertia_tensor`: {e}"))
                })?;
                Body::from_mass_properties(props)
            }
            // Ruled out above; kept as an error rather than a panic.
            (None, None) => return Err(keys.fail(raw, &format!("no inertia given: {ONE_OF}"))),
        }
    };
    // At rest, identity attitude, free: only the inertia can be refused.
    builder
        .clone()
        .try_build()
        .map_err(|e| keys.fail_at(span.clone(), &format!("`{key}`: {e}")))?;
    Ok(CheckedInertia { builder, key, span })
}

/// The solid mass properties of every body of the mesh file, summed (mesh axes).
fn mesh_properties(
    keys: &Keys<'_>,
    mesh: &Spanned<String>,
    density: f64,
    folder: &Path,
) -> Result<MassProperties, SceneError> {
    let path = folder.join(mesh.get_ref());
    let options = SolidOptions::new(Material::Density(density));
    let solid =
        load_solid(&path, &options).map_err(|e| keys.fail(mesh, &format!("`mesh`: {e}")))?;
    for (body, warning) in solid.warnings() {
        // Repairs (winding, degenerate triangles) are worth knowing, not
        // fatal; the loader's own notes (welds, skipped faces) are not shown.
        if let SolidWarning::Mesh(warning) = warning {
            let _ = writeln!(
                std::io::stderr(),
                "kreisel: warning: {}: body '{body}': {warning}",
                path.display(),
            );
        }
    }
    Ok(solid.properties)
}

/// The initial attitude from `orientation` or `euler` (identity without either).
fn attitude(keys: &Keys<'_>, b: &RawBody) -> Result<DQuat, SceneError> {
    match (&b.orientation, &b.euler) {
        (Some(_), Some(euler)) => Err(keys.fail(
            euler,
            "both `orientation` and `euler` given: use at most one",
        )),
        (Some(q), None) => {
            let [w, x, y, z] = *q.get_ref();
            try_normalize_quat(DQuat::from_xyzw(x, y, z, w)).map_err(|_| {
                let message =
                    "`orientation` must be a quaternion w, x, y, z of finite numbers, not zero";
                keys.fail(q, message)
            })
        }
        (None, Some(euler)) => {
            let e = euler.get_ref();
            let sequence: EulerSequence = e
                .sequence
                .get_ref()
                .parse()
                .map_err(|err| keys.fail(&e.sequence, &format!("`euler.sequence`: {err}")))?;
            let angles = keys.vector("euler.angles", &e.angles)?;
            Ok(sequence.to_quat(angles))
        }
        (None, None) => Ok(DQuat::IDENTITY),
    }
}
