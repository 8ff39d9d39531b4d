//! One `[[body]]` of the scene: its inertia (moments, a tensor or a mesh),
//! initial attitude and spin, and the ballistic motion of its centre of mass.

#![forbid(unsafe_code)]

use std::io::Write;
use std::path::Path;

use glam::{DMat3, DQuat, DVec3};
use kreisel_dynamics::{HeavyTop, PrincipalState, RigidBody};
use kreisel_inertia::io::{SolidOptions, SolidWarning, load_solid};
use kreisel_inertia::{MassProperties, Material};
use kreisel_kinematics::{EulerSequence, try_normalize_quat};
use serde::Deserialize;
use toml::Spanned;

use super::scene::{Keys, SceneFile};
use crate::error::CliError;

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
}

/// `euler = { sequence = "ZXZ", angles = [..] }` as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawEuler {
    sequence: Spanned<String>,
    angles: Spanned<[f64; 3]>,
}

impl RawBody {
    /// Where the `name` key is, if given.
    pub fn name_span(&self) -> Option<std::ops::Range<usize>> {
        self.name.as_ref().map(Spanned::span)
    }
}

/// A checked body and its initial state.
#[derive(Debug, Clone)]
pub struct SimBody {
    /// The name in the CSV: a plain field (no commas, quotes, line breaks).
    pub name: String,
    /// Mass, kg.
    pub mass: f64,
    /// Principal moments and the body-from-principal rotation: about the
    /// centre of mass, or about the pivot for a body with one.
    pub rigid: RigidBody,
    /// Attitude and angular momentum (about the pivot if there is one) at t = 0.
    pub initial: PrincipalState,
    /// Centre of mass at t = 0 in world axes, m (the pivot for a body with one).
    pub position: DVec3,
    /// Its velocity at t = 0, m/s (zero with a pivot).
    pub velocity: DVec3,
    /// The heavy top, for a body with a `pivot`.
    pub top: Option<HeavyTop>,
}

impl SimBody {
    /// Checks body number `number` (1-based, for the default name); mesh
    /// paths are relative to `folder`; `gravity` (world axes, m/s²) pulls
    /// a body with a pivot.
    ///
    /// # Errors
    /// [`CliError::Scene`] naming the line and key of the first problem.
    pub fn from_raw(
        file: SceneFile<'_>,
        raw: &Spanned<RawBody>,
        number: usize,
        folder: &Path,
        gravity: DVec3,
    ) -> Result<Self, CliError> {
        let b = raw.get_ref();
        let name = match &b.name {
            Some(name) => checked_name(file, name)?,
            None => format!("body{number}"),
        };
        let keys = Keys::new(file, format!("body `{name}`: "));
        let (props, rigid) = mass_and_inertia(&keys, raw, folder)?;
        let attitude = attitude(&keys, b)?;
        let omega = keys.vector("angular_velocity", &b.angular_velocity)?;
        let position = optional_vector(&keys, "position", &b.position)?;
        let velocity = optional_vector(&keys, "velocity", &b.velocity)?;
        let top = match &b.pivot {
            Some(pivot) => {
                if let Some(v) = &b.velocity {
                    let message = "`velocity` cannot be given with `pivot`: the pivot is fixed";
                    return Err(keys.fail(v, message));
                }
                let at = keys.vector("pivot", pivot)?;
                let top = HeavyTop::try_new(&props, at, gravity)
                    .map_err(|e| keys.fail(pivot, &format!("`pivot`: {e}")))?;
                Some(top)
            }
            None => None,
        };
        let rigid = top.as_ref().map_or(rigid, |top| *top.body());
        let initial = PrincipalState::try_from_omega_body(&rigid, attitude, omega)
            .map_err(|e| keys.fail(&b.angular_velocity, &e.to_string()))?;
        Ok(Self {
            name,
            mass: props.mass,
            rigid,
            initial,
            position,
            velocity,
            top,
        })
    }

    /// Position and velocity of the centre of mass at time `t` (exact ballistic motion).
    ///
    /// ```text
    /// x(t) = x₀ + v₀ t + ½ g t²,   v(t) = v₀ + g t
    /// ```
    pub fn centre_of_mass(&self, t: f64, gravity: DVec3) -> (DVec3, DVec3) {
        let x = self.position + self.velocity * t + gravity * (0.5 * t * t);
        (x, self.velocity + gravity * t)
    }

    /// Whether the centre of mass's motion and the energy stay finite over
    /// `[0, duration]`, checked at both ends: `|v|²` is convex in `t`, and
    /// `−g·x` is concave, its largest value exceeding the one at `t = 0` by
    /// at most `|v₀|²/2` per kg.
    pub fn stays_finite(&self, duration: f64, gravity: DVec3) -> bool {
        [0.0, duration].into_iter().all(|t| {
            let (x, v) = self.centre_of_mass(t, gravity);
            x.is_finite() && v.is_finite() && self.energy(&self.initial, t, gravity).is_finite()
        })
    }

    /// Total energy at time `t` in rotational state `state`.
    ///
    /// ```text
    /// free:   E = ½ Σ Lₖ²/Iₖ + ½ m |v|² − m g·x
    /// pivot:  E = ½ Σ Lₖ²/Jₖ − m g·(p + R c)   (J about the pivot p, c the centre of mass from it)
    /// ```
    pub fn energy(&self, state: &PrincipalState, t: f64, gravity: DVec3) -> f64 {
        match &self.top {
            Some(top) => top.energy(state) - self.mass * gravity.dot(self.position),
            None => {
                let (x, v) = self.centre_of_mass(t, gravity);
                state.energy(&self.rigid) + 0.5 * self.mass * v.length_squared()
                    - self.mass * gravity.dot(x)
            }
        }
    }
}

/// The `name`, which must be a plain CSV field.
fn checked_name(file: SceneFile<'_>, name: &Spanned<String>) -> Result<String, CliError> {
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
) -> Result<DVec3, CliError> {
    value
        .as_ref()
        .map_or(Ok(DVec3::ZERO), |v| keys.vector(key, v))
}

/// The mass properties (body axes; the centre of mass at the origin for
/// `inertia` and `inertia_tensor`, where the mesh puts it for `mesh`) and
/// the rotational inertia about the centre of mass, from exactly one of
/// `inertia`, `inertia_tensor` and `mesh`.
fn mass_and_inertia(
    keys: &Keys<'_>,
    raw: &Spanned<RawBody>,
    folder: &Path,
) -> Result<(MassProperties, RigidBody), CliError> {
    let b = raw.get_ref();
    let given: Vec<(&str, std::ops::Range<usize>)> = [
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
    match given.as_slice() {
        [] => return Err(keys.fail(raw, &format!("no inertia given: {ONE_OF}"))),
        [_] => {}
        [(first, _), (second, span), ..] => {
            let message = format!("both `{first}` and `{second}` given: {ONE_OF}");
            return Err(keys.fail_at(span.clone(), &message));
        }
    }
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
        let props = mesh_properties(keys, mesh, density, folder)?;
        let rigid = RigidBody::from_mass_properties(&props)
            .map_err(|e| keys.fail(mesh, &format!("`mesh`: {e}")))?;
        return Ok((props, rigid));
    }
    if let Some(density) = &b.density {
        return Err(keys.fail(density, "`density` is only used with `mesh`"));
    }
    let Some(mass) = &b.mass else {
        return Err(keys.fail(raw, "`mass` (kg) is missing"));
    };
    let mass = keys.positive("mass", mass)?;
    let (rigid, tensor) = match (&b.inertia, &b.inertia_tensor) {
        (Some(moments), _) => {
            let diagonal = DVec3::from_array(*moments.get_ref());
            let rigid = RigidBody::try_from_principal_moments(diagonal)
                .map_err(|e| keys.fail(moments, &format!("`inertia`: {e}")))?;
            (rigid, DMat3::from_diagonal(diagonal))
        }
        (None, Some(tensor)) => {
            let rows = *tensor.get_ref();
            if !rows.as_flattened().iter().all(|x| x.is_finite()) {
                return Err(keys.fail(tensor, "`inertia_tensor` must be finite numbers"));
            }
            let matrix = DMat3::from_cols_array_2d(&rows).transpose();
            let rigid = RigidBody::try_from_inertia_tensor(matrix)
                .map_err(|e| keys.fail(tensor, &format!("`inertia_tensor`: {e}")))?;
            (rigid, matrix)
        }
        // Ruled out above; kept as an error rather than a panic.
        (None, None) => return Err(keys.fail(raw, &format!("no inertia given: {ONE_OF}"))),
    };
    // Checked above: positive mass, a physical tensor.
    let props = MassProperties::try_new(mass, DVec3::ZERO, tensor)
        .map_err(|e| keys.fail(raw, &e.to_string()))?;
    Ok((props, rigid))
}

/// The solid mass properties of every body of the mesh file, summed (mesh axes).
fn mesh_properties(
    keys: &Keys<'_>,
    mesh: &Spanned<String>,
    density: f64,
    folder: &Path,
) -> Result<MassProperties, CliError> {
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
fn attitude(keys: &Keys<'_>, b: &RawBody) -> Result<DQuat, CliError> {
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
