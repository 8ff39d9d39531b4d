//! One `[[body]]` of the scene: its inertia (moments, a tensor or a mesh),
//! initial attitude, spin, support (free, a pivot, or the ground with a
//! `[body.contact]` table, `contact_keys.rs`) and applied inputs (torques,
//! a force, damping), read key by key (types, spans, the mesh, Euler
//! angles) into a [`BodyRequest`], which checks them together and adds the
//! body to the scene's [`World`] (`body_request.rs`, shared with Python's
//! `World.add_body`); this file words its problems at their lines.

#![forbid(unsafe_code)]

use std::io::Write;
use std::path::Path;

use glam::DVec3;
use kreisel_dynamics::{BodyId, Plan, World};
use kreisel_inertia::io::{SolidOptions, SolidWarning, load_solid};
use kreisel_inertia::{MassProperties, Material};
use kreisel_kinematics::EulerSequence;
use serde::Deserialize;
use toml::Spanned;

use crate::body_key::{BodyKey, BodyKeyError, BodyKeyProblem, Given};
use crate::body_request::{Attitude, BodyRequest, Inertia};
use crate::contact_keys::{self as contact, RawContacts};
use crate::contact_list::Contacts;
use crate::error::{KeyProblem, SceneError};
use crate::numbers::Shortest;
use crate::scene_keys::{Keys, SceneFile};

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
    /// The steady motion `kreisel stability` analyses (its name; `simulate`
    /// does not read it).
    steady: Option<Spanned<String>>,
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

    /// The `steady` key as written, with the byte span of its value.
    pub fn steady(&self) -> Option<(&str, std::ops::Range<usize>)> {
        self.steady
            .as_ref()
            .map(|s| (s.get_ref().as_str(), s.span()))
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
/// The keys' values are read here (types, finite numbers, the mesh, Euler
/// angles, the contact tables); what they must satisfy together is
/// checked, and the body built and added, by [`BodyRequest::add_to`].
///
/// # Errors
/// [`SceneError::Key`] (typed: the body's or a contact's problem) or
/// [`SceneError::Scene`] (a value's type, the mesh, Euler angles) naming the
/// line and key of the first problem.
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
    let keys = Keys::of_body(file, &name);
    let fail = |e: BodyKeyError<Span>| body_error(&keys, b, e);
    let given: Vec<(BodyKey, Span)> = [
        (BodyKey::Moments, b.inertia.as_ref().map(Spanned::span)),
        (
            BodyKey::Tensor,
            b.inertia_tensor.as_ref().map(Spanned::span),
        ),
        (BodyKey::Mesh, b.mesh.as_ref().map(Spanned::span)),
    ]
    .into_iter()
    .filter_map(|(key, span)| span.map(|s| (key, s)))
    .collect();
    let (key, span) = BodyRequest::one_inertia(&given, raw.span()).map_err(fail)?;
    let inertia = (key, inertia(&keys, raw, folder)?, span);
    let spanned = |v: &Option<Spanned<[f64; 3]>>, key| -> Result<Given<DVec3, Span>, SceneError> {
        v.as_ref()
            .map(|v| Ok((keys.vector(key, v)?, v.span())))
            .transpose()
    };
    let request = BodyRequest {
        body: raw.span(),
        mass: b.mass.as_ref().map(|m| (*m.get_ref(), m.span())),
        inertia,
        attitude: attitude(&keys, b)?,
        omega_body: Some((
            keys.vector("angular_velocity", &b.angular_velocity)?,
            b.angular_velocity.span(),
        )),
        position: spanned(&b.position, "position")?,
        velocity: spanned(&b.velocity, "velocity")?,
        torque: spanned(&b.torque, "torque")?,
        torque_body: spanned(&b.torque_body, "torque_body")?,
        force: spanned(&b.force, "force")?,
        angular_damping: b.angular_damping.as_ref().map(|c| (*c.get_ref(), c.span())),
        pivot: match (&b.pivot, &b.contact) {
            (Some(_), None) => spanned(&b.pivot, "pivot")?,
            // With `contact`, the conflict is the error, whatever the value.
            (Some(p), Some(_)) => Some((DVec3::ZERO, p.span())),
            (None, _) => None,
        },
        contacts: match (&b.contact, &b.pivot) {
            (Some(c), None) => Some((contact::check(&keys, c)?, c.span())),
            // With `pivot`, the conflict is the error, whatever the tables say.
            (Some(c), Some(_)) => Some((Contacts::Table(Vec::new()), c.span())),
            (None, _) => None,
        },
    };
    let id = request.add_to(world).map_err(fail)?;
    let on_ground = matches!(world.plan(id), Some(Plan::OnGround { .. }));
    if let (true, Some(given)) = (on_ground, &b.position) {
        check_height(&keys, given, world, id)?;
    }
    Ok((name, id))
}

/// A span of the scene's text.
type Span = std::ops::Range<usize>;

/// The scene's words for `key`.
fn key_name(key: BodyKey) -> &'static str {
    match key {
        BodyKey::Body => "body",
        BodyKey::Mass => "mass",
        BodyKey::Moments => "inertia",
        BodyKey::Tensor => "inertia_tensor",
        BodyKey::Mesh => "mesh",
        BodyKey::Attitude => "orientation",
        BodyKey::Omega => "angular_velocity",
        BodyKey::Position => "position",
        BodyKey::Velocity => "velocity",
        BodyKey::Pivot => "pivot",
        BodyKey::Torque => "torque",
        BodyKey::TorqueBody => "torque_body",
        BodyKey::Force => "force",
        BodyKey::AngularDamping => "angular_damping",
        BodyKey::Contacts => "contact",
    }
}

/// The one line of a problem with body `b`'s keys, at its line.
fn body_error(keys: &Keys<'_>, b: &RawBody, e: BodyKeyError<Span>) -> SceneError {
    const ONE_OF: &str = "use exactly one of `inertia`, `inertia_tensor` and `mesh`";
    let (at, problem) = (e.at, e.problem);
    let message = match problem.clone() {
        BodyKeyProblem::NoInertia => format!("no inertia given: {ONE_OF}"),
        BodyKeyProblem::TwoInertias { first, second } => format!(
            "both `{}` and `{}` given: {ONE_OF}",
            key_name(first),
            key_name(second)
        ),
        BodyKeyProblem::MissingMass => "`mass` (kg) is missing".to_owned(),
        BodyKeyProblem::NotPositive { key, value } => format!(
            "`{}` must be positive and finite, got {}",
            key_name(key),
            Shortest(value)
        ),
        BodyKeyProblem::NotAQuaternion => {
            "`orientation` must be a quaternion w, x, y, z of finite numbers, not zero".to_owned()
        }
        BodyKeyProblem::PivotWithContacts => "`pivot` cannot be given with `contact`: a body \
             turns about a pivot or stands on the ground, not both"
            .to_owned(),
        BodyKeyProblem::VelocityWithPivot => {
            "`velocity` cannot be given with `pivot`: the pivot is fixed".to_owned()
        }
        BodyKeyProblem::VelocityWithRolling => "`velocity` cannot be given with friction \
             \"rolling\": it follows from rolling without slipping"
            .to_owned(),
        BodyKeyProblem::VelocityNotHorizontal { vz } => format!(
            "`velocity` of a body on the ground must be horizontal, [vx, vy, 0], got vz = {}: \
             the vertical velocity follows from the spin",
            Shortest(vz)
        ),
        BodyKeyProblem::LoadsOnTable { key } => format!(
            "`{}`: applied loads are not modelled for a body on the table (friction \
             \"coulomb\"): only gravity and the contacts act",
            key_name(key)
        ),
        BodyKeyProblem::Damping { value } => format!(
            "`angular_damping` must be zero or positive and finite (N m s), got {}",
            Shortest(value)
        ),
        BodyKeyProblem::InsideTable { contact, gap, .. } => {
            let (span, message) =
                inside_table(b.position.as_ref(), b.contact.as_ref(), contact, gap);
            return keys.fail_key(span, KeyProblem::Body(problem), &message);
        }
        BodyKeyProblem::WatchedTouching { index, gap } => {
            let (span, message) = watched_touching(b.contact.as_ref(), index, gap);
            return keys.fail_key(span, KeyProblem::Body(problem), &message);
        }
        BodyKeyProblem::Painleve {
            contact,
            mu,
            ref error,
        } => {
            let span = table_span(b.contact.as_ref(), contact, true);
            let message = contact::painleve_message(contact, mu, error);
            return keys.fail_key(span, KeyProblem::Body(problem), &message);
        }
        BodyKeyProblem::Library { key, error } => match key {
            BodyKey::Body | BodyKey::Omega => error.to_string(),
            other => format!("`{}`: {error}", key_name(other)),
        },
    };
    keys.fail_key(at, KeyProblem::Body(problem), &message)
}

/// The error for further contact `index` (0-based among the watched
/// ones, the table after the first) at or below the plane at the start,
/// at its table's line.
fn watched_touching(
    contacts: Option<&Spanned<RawContacts>>,
    index: usize,
    gap: f64,
) -> (Span, String) {
    let span = table_span(contacts, index + 1, false);
    let message = format!(
        "[[body.contact]] #{} is at or below the plane at the start (its lowest point at \
         z = {} m): the contacts after the first are watched for touchdown and must start \
         above the plane",
        index + 2,
        Shortest(gap)
    );
    (span, message)
}

/// Where contact table `index` (0-based) of `contacts` is — its `mu` key
/// with `mu` when given — else the `contact` key.
fn table_span(contacts: Option<&Spanned<RawContacts>>, index: usize, mu: bool) -> Span {
    contacts.map_or(0..0, |contacts| {
        contact::tables(contacts)
            .get(index)
            .map_or(contacts.span(), |(raw, span)| {
                raw.mu_span().filter(|_| mu).unwrap_or_else(|| span.clone())
            })
    })
}

/// The error for contact `index` (0-based) of a body on the table below
/// it at the start, at the `position` key if given, else at the table's
/// line.
fn inside_table(
    position: Option<&Spanned<[f64; 3]>>,
    contacts: Option<&Spanned<RawContacts>>,
    index: usize,
    gap: f64,
) -> (Span, String) {
    let message = format!(
        "[[body.contact]] #{} is below the table at the start (its lowest point at z = {} m): \
         a body on the table starts above it or touching it",
        index + 1,
        Shortest(gap)
    );
    match position {
        Some(p) => (p.span(), format!("`position`: {message}")),
        None => (table_span(contacts, index, false), message),
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

/// The inertia of the key given (one of `inertia`, `inertia_tensor` and
/// `mesh`: principal moments, body axes = principal axes, centre of mass
/// at the origin; the tensor about the centre of mass at the origin; a
/// solid of `density`, mesh coordinates), read as far as its keys go:
/// the mass and the inertia's physics are [`BodyRequest::add_to`]'s.
fn inertia(keys: &Keys<'_>, raw: &Spanned<RawBody>, folder: &Path) -> Result<Inertia, SceneError> {
    let b = raw.get_ref();
    if let Some(mesh) = &b.mesh {
        if let Some(mass) = &b.mass {
            let message =
                "`mass` cannot be given with `mesh`: it follows from the mesh and `density`";
            return Err(keys.fail(mass, message));
        }
        let Some(density) = &b.density else {
            return Err(keys.fail(mesh, "`mesh` needs `density` (kg/m^3)"));
        };
        let density = keys.positive("density", density)?;
        return Ok(Inertia::Properties(mesh_properties(
            keys, mesh, density, folder,
        )?));
    }
    if let Some(density) = &b.density {
        return Err(keys.fail(density, "`density` is only used with `mesh`"));
    }
    match (&b.inertia, &b.inertia_tensor) {
        (Some(moments), _) => Ok(Inertia::Moments(DVec3::from_array(*moments.get_ref()))),
        (None, Some(tensor)) => {
            let rows = *tensor.get_ref();
            if !rows.as_flattened().iter().all(|x| x.is_finite()) {
                return Err(keys.fail(tensor, "`inertia_tensor` must be finite numbers"));
            }
            Ok(Inertia::Tensor(rows))
        }
        // Ruled out by BodyRequest::one_inertia; kept as an error rather than a panic.
        (None, None) => Err(keys.fail(raw, "no inertia given")),
    }
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

/// The initial attitude from `orientation` (normalised by
/// [`BodyRequest::add_to`]) or `euler` (none without either).
fn attitude(keys: &Keys<'_>, b: &RawBody) -> Result<Given<Attitude, Span>, SceneError> {
    match (&b.orientation, &b.euler) {
        (Some(_), Some(euler)) => Err(keys.fail(
            euler,
            "both `orientation` and `euler` given: use at most one",
        )),
        (Some(q), None) => Ok(Some((Attitude::Quaternion(*q.get_ref()), q.span()))),
        (None, Some(euler)) => {
            let e = euler.get_ref();
            let sequence: EulerSequence = e
                .sequence
                .get_ref()
                .parse()
                .map_err(|err| keys.fail(&e.sequence, &format!("`euler.sequence`: {err}")))?;
            let angles = keys.vector("euler.angles", &e.angles)?;
            Ok(Some((
                Attitude::Rotation(sequence.to_quat(angles)),
                euler.span(),
            )))
        }
        (None, None) => Ok(None),
    }
}
