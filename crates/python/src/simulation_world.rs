//! `kreisel.World`: the engine's [`World`] as a Python object: add bodies
//! (principal moments or an inertia tensor; attitude, spin; free, on a
//! pivot or on the table; torques, forces, damping), change what is applied to them, move
//! the world (`step`, `advance_steps`, `advance_to`) and read the states as
//! numpy arrays. Every number is the engine's; this file converts and
//! names errors.

use glam::{DQuat, DVec3};
use kreisel_dynamics::{Body, BodyId, DynamicsError, FreeBodyMethod, Inputs, World};
use kreisel_kinematics::try_normalize_quat;
use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use kreisel_scene::body_key::{BodyKey, BodyKeyProblem};
use kreisel_scene::body_request::{Attitude, BodyRequest, Inertia};
use kreisel_scene::contact_list::Contacts;
use kreisel_scene::numbers::Shortest;

use super::table;
use crate::arguments::{finite, int, integer, matrix3, named, numbers};
use crate::errors::{error, guard};

/// A world of rigid bodies that do not interact, each moved by the
/// engine's best method for it (exact solutions for free bodies and
/// Lagrange tops, stepping methods otherwise, the nonsmooth table for
/// bodies with ``contacts``), all SI units and radians.
///
/// ``World(dt, gravity=(0, 0, 0), method="auto")``: ``dt`` is the step of
/// the stepping methods (s), ``gravity`` in world axes (m/s^2), ``method``
/// a name of ``kreisel simulate --list-methods``. ``step``,
/// ``advance_steps`` and ``advance_to`` release the GIL while the bodies
/// move; a World may be used from any thread.
///
/// >>> import kreisel
/// >>> w = kreisel.World(dt=0.01)
/// >>> b = w.add_body(1.0, moments=(1.0, 2.0, 3.0), omega_body=(0.0, 0.0, 2.0))
/// >>> w.advance_to(1.0)
/// >>> s = w.state(b)
/// >>> float(s["energy"]), s["attitude"].shape   # 3 * 2^2 / 2
/// (6.0, (4,))
// The engine's World is `Send`: its moves release the GIL.
#[pyclass(module = "kreisel", name = "World")]
pub struct PyWorld {
    world: World,
    ids: Vec<BodyId>,
}

/// An optional argument.
type Arg<'a, 'py> = Option<&'a Bound<'py, PyAny>>;

/// The vector argument `name` (zero when absent).
fn vector(name: &str, value: Arg<'_, '_>) -> PyResult<DVec3> {
    value.map_or(Ok(DVec3::ZERO), |v| {
        numbers::<3>(name, v).map(DVec3::from_array)
    })
}

/// The inputs from the keywords (zero when absent).
fn inputs(
    torque: Arg<'_, '_>,
    torque_body: Arg<'_, '_>,
    force: Arg<'_, '_>,
    angular_damping: Arg<'_, '_>,
) -> PyResult<Inputs> {
    let damping = angular_damping.map_or(Ok(0.0), |d| finite("angular_damping", d))?;
    Ok(Inputs::default()
        .with_torque_world(vector("torque", torque)?)
        .with_torque_body(vector("torque_body", torque_body)?)
        .with_force_world(vector("force", force)?)
        .with_angular_damping(damping))
}

/// The attitude `[w, x, y, z]`, normalised as a scene's `orientation` is.
fn quaternion(value: &Bound<'_, PyAny>) -> PyResult<DQuat> {
    let [w, x, y, z] = numbers::<4>("attitude", value)?;
    try_normalize_quat(DQuat::from_xyzw(x, y, z, w))
        .map_err(|_| error("attitude: must be a quaternion w, x, y, z, not zero"))
}

/// The Python argument a library error is about, if it is about one.
fn argument_of(e: &DynamicsError) -> Option<&'static str> {
    match e {
        DynamicsError::UnphysicalInertia { .. } => Some("moments"),
        DynamicsError::InvalidStep { .. } => Some("dt"),
        DynamicsError::InvalidTime { .. } => Some("t"),
        DynamicsError::InvalidBody { field, .. } => match *field {
            "position" => Some("position"),
            "velocity" => Some("velocity"),
            "pivot_body" => Some("pivot"),
            "gravity" => Some("gravity"),
            _ => None,
        },
        DynamicsError::InvalidInput { input, .. } => match *input {
            "torque_world" => Some("torque"),
            "torque_body" => Some("torque_body"),
            "force_world" => Some("force"),
            "angular_damping" => Some("angular_damping"),
            _ => None,
        },
        _ => None,
    }
}

/// The library's error, naming the Python argument it is about.
fn world_error(e: DynamicsError) -> PyErr {
    match argument_of(&e) {
        Some(name) => named(name)(e),
        None => error(e),
    }
}

/// The Python keyword of a body's key.
fn keyword(key: BodyKey) -> &'static str {
    match key {
        BodyKey::Body => "body",
        BodyKey::Mass => "mass",
        BodyKey::Moments => "moments",
        BodyKey::Tensor => "inertia",
        BodyKey::Mesh => "mesh",
        BodyKey::Attitude => "attitude",
        BodyKey::Omega => "omega_body",
        BodyKey::Position => "position",
        BodyKey::Velocity => "velocity",
        BodyKey::Pivot => "pivot",
        BodyKey::Torque => "torque",
        BodyKey::TorqueBody => "torque_body",
        BodyKey::Force => "force",
        BodyKey::AngularDamping => "angular_damping",
        BodyKey::Contacts => "contacts",
    }
}

/// The one line of a problem with `add_body`'s keywords.
fn key_error(problem: BodyKeyProblem) -> PyErr {
    match problem {
        BodyKeyProblem::NoInertia | BodyKeyProblem::TwoInertias { .. } => {
            error("give exactly one of moments (principal, kg m^2) and inertia (3 x 3 tensor)")
        }
        BodyKeyProblem::MissingMass => error("mass: is missing"),
        BodyKeyProblem::NotPositive { key, value } => {
            error(format!("{}: {value} kg: must be positive", keyword(key)))
        }
        BodyKeyProblem::NotAQuaternion => {
            error("attitude: must be a quaternion w, x, y, z, not zero")
        }
        BodyKeyProblem::PivotWithContacts => error(
            "pivot cannot be given with contacts: a body turns about a pivot or is on the \
             table, not both",
        ),
        BodyKeyProblem::VelocityWithPivot => {
            error("velocity cannot be given with pivot: the pivot is fixed")
        }
        BodyKeyProblem::LoadsOnTable { key } => error(format!(
            "{}: applied loads are not modelled for a body on the table (contacts): only \
             gravity and the contacts act",
            keyword(key)
        )),
        BodyKeyProblem::Damping { value } => error(format!(
            "angular_damping: must be zero or positive and finite (N m s), got {}",
            Shortest(value)
        )),
        BodyKeyProblem::InsideTable { contact, gap, .. } => error(format!(
            "position: contacts[{contact}] is below the table at the start (its lowest point \
             at z = {} m): a body on the table starts above it or touching it",
            Shortest(gap)
        )),
        BodyKeyProblem::Painleve {
            contact,
            mu,
            error: e,
        } => error(format!(
            "contacts[{contact}].mu: {} is beyond the Painlevé bound of its slip ({e}): no \
             normal force keeps the sliding contact on the table",
            Shortest(mu)
        )),
        BodyKeyProblem::Library {
            key: BodyKey::Tensor,
            error: DynamicsError::InertiaTensor { error: e },
        } => error(format!("inertia: {e}")),
        BodyKeyProblem::Library { error: e, .. } => world_error(e),
        // Only a scene's bodies stand on the ground plane.
        other @ (BodyKeyProblem::VelocityWithRolling
        | BodyKeyProblem::VelocityNotHorizontal { .. }
        | BodyKeyProblem::WatchedTouching { .. }) => error(format!("{other:?}")),
    }
}

impl PyWorld {
    /// The engine's body Python calls `body` (an int), as it is now, and
    /// the world's gravity (world axes, m/s²): what the stability analysis
    /// starts from.
    pub(crate) fn body_and_gravity(&self, body: &Bound<'_, PyAny>) -> PyResult<(&Body, DVec3)> {
        let id = self.id(body)?;
        let found = self.world.body(id);
        let found = found.ok_or_else(|| error(format!("body: no body {body} in this world")))?;
        Ok((found, self.world.gravity()))
    }

    /// The engine's id of the body Python calls `body` (an int).
    fn id(&self, body: &Bound<'_, PyAny>) -> PyResult<BodyId> {
        let n = int("body", body)?;
        let found = usize::try_from(n).ok().and_then(|i| self.ids.get(i));
        found.copied().ok_or_else(|| {
            let has = match self.ids.len() {
                0 => "no bodies".to_owned(),
                1 => "1 body: 0 to 0".to_owned(),
                len => format!("{len} bodies: 0 to {}", len - 1),
            };
            error(format!("body: no body {n} in this world (it has {has})"))
        })
    }
}

#[pymethods]
impl PyWorld {
    #[new]
    #[pyo3(signature = (dt, gravity=None, method="auto"))]
    #[pyo3(text_signature = "(dt, gravity=(0.0, 0.0, 0.0), method='auto')")]
    fn new(dt: &Bound<'_, PyAny>, gravity: Arg<'_, '_>, method: &str) -> PyResult<Self> {
        guard(|| {
            let dt = finite("dt", dt)?;
            let gravity = vector("gravity", gravity)?;
            let mut world = World::try_new(gravity, dt).map_err(world_error)?;
            let free: FreeBodyMethod = method.parse().map_err(named("method"))?;
            // As the scene: a method without a heavy-top version leaves the default.
            world
                .set_free_body_method(free)
                .and_then(|()| world.set_heavy_top_method(free.heavy_top().unwrap_or_default()))
                .map_err(error)?;
            Ok(Self {
                world,
                ids: Vec::new(),
            })
        })
    }

    /// Adds a body and returns its number (0, 1, ...).
    ///
    /// Inertia: ``moments`` (principal moments about the centre of mass,
    /// body axes = principal axes, in this order) or ``inertia`` (the 3 x 3
    /// tensor about the centre of mass in body axes), kg m^2, with ``mass``
    /// (kg). ``attitude``: world_from_body quaternion w, x, y, z (default
    /// identity); ``omega_body``: rad/s, body axes. Free (``position``,
    /// ``velocity`` of the centre of mass, world axes) or, with ``pivot``
    /// (body coordinates, m), a heavy top turning about that fixed point,
    /// placed at ``position``. ``torque`` (world axes), ``torque_body``,
    /// ``force`` (through the centre of mass, world axes), N m / N, and
    /// ``angular_damping`` (N m s) are applied from now on.
    ///
    /// With ``contacts`` the body is on the table z = 0 (gravity along -z),
    /// moved as ``friction = "coulomb"`` moves a scene's body: every contact
    /// unilateral, Newton's impacts, set-valued Coulomb friction with
    /// Contensou's drilling; it may start above the table (``position``,
    /// default: above the origin, its lowest contact touching) and be
    /// thrown (``velocity``); no pivot and no applied loads. ``contacts`` is a
    /// list of dicts with the keys of a scene's ``[[body.contact]]`` table:
    /// ``shape`` (``"sphere"``, ``"disk"``, ``"ellipsoid"``), ``radius``,
    /// ``center`` (from the centre of mass, body axes, m), ``normal``
    /// (disk), ``semi_axes`` (ellipsoid), ``mu`` (required, >= 0),
    /// ``restitution`` and ``tangential_restitution`` (in [0, 1], default
    /// 0), ``contensou_radius`` and ``rolling_resistance`` (m, default 0),
    /// ``air_viscosity`` (Pa s; a disk: Moffatt's air layer under the rim)
    /// with ``air_gap`` (its floor, m, default 1e-6), ``friction`` (only
    /// ``"coulomb"``). A bad value raises KreiselError naming its key
    /// (``contacts[0].mu: ...``); a contact below the table names
    /// ``position``. ``events(body)`` lists what happens.
    ///
    /// >>> import kreisel
    /// >>> w = kreisel.World(dt=0.001, gravity=(0, 0, -9.81))
    /// >>> top = w.add_body(0.5, moments=(0.02, 0.02, 0.01), omega_body=(0, 0, 50),
    /// ...                  attitude=(0.99, 0.14, 0, 0), pivot=(0, 0, -0.05))
    /// >>> w.plan(top)
    /// 'Lagrange top on a pivot: exact, closed form ...'
    /// >>> ball = w.add_body(0.5, moments=(0.002,) * 3, position=(0, 0, 1.0),
    /// ...                   contacts=[dict(shape="sphere", radius=0.1, mu=0.0, restitution=0.9)])
    /// >>> w.advance_to(0.5)
    /// >>> t, contact, kind, v_in, v_out, _ = w.events(ball)[0]
    /// >>> round(t, 5), contact, kind, round(v_out / v_in, 12)
    /// (0.42835, 0, 'impact', 0.9)
    #[pyo3(signature = (mass, moments=None, inertia=None, *, attitude=None, omega_body=None, position=None, velocity=None, pivot=None, torque=None, torque_body=None, force=None, angular_damping=None, contacts=None))]
    #[pyo3(
        text_signature = "($self, mass, moments=None, inertia=None, *, attitude=None, omega_body=(0.0, 0.0, 0.0), position=(0.0, 0.0, 0.0), velocity=None, pivot=None, torque=None, torque_body=None, force=None, angular_damping=0.0, contacts=None)"
    )]
    #[allow(clippy::too_many_arguments)] // the Python keywords, one each
    fn add_body(
        &mut self,
        mass: &Bound<'_, PyAny>,
        moments: Arg<'_, '_>,
        inertia: Arg<'_, '_>,
        attitude: Arg<'_, '_>,
        omega_body: Arg<'_, '_>,
        position: Arg<'_, '_>,
        velocity: Arg<'_, '_>,
        pivot: Arg<'_, '_>,
        torque: Arg<'_, '_>,
        torque_body: Arg<'_, '_>,
        force: Arg<'_, '_>,
        angular_damping: Arg<'_, '_>,
        contacts: Arg<'_, '_>,
    ) -> PyResult<usize> {
        guard(|| {
            let given = |key, value: Arg<'_, '_>| value.map(|_| (key, ()));
            let inertias: Vec<(BodyKey, ())> = [
                given(BodyKey::Moments, moments),
                given(BodyKey::Tensor, inertia),
            ]
            .into_iter()
            .flatten()
            .collect();
            let mass = finite("mass", mass)?;
            let (key, ()) =
                BodyRequest::one_inertia(&inertias, ()).map_err(|e| key_error(e.problem))?;
            let inertia = match (moments, inertia) {
                (Some(m), _) => Inertia::Moments(vector("moments", Some(m))?),
                (None, Some(rows)) => Inertia::Tensor(matrix3("inertia", rows)?),
                (None, None) => return Err(key_error(BodyKeyProblem::NoInertia)),
            };
            let vector_of = |name, value: Arg<'_, '_>| -> PyResult<Option<(DVec3, ())>> {
                value.map(|v| Ok((vector(name, Some(v))?, ()))).transpose()
            };
            let attitude = attitude
                .map(|q| numbers::<4>("attitude", q).map(|q| (Attitude::Quaternion(q), ())))
                .transpose()?;
            let omega_body = vector_of("omega_body", omega_body)?;
            let position = vector_of("position", position)?;
            let loads = [
                vector_of("torque", torque)?,
                vector_of("torque_body", torque_body)?,
                vector_of("force", force)?,
            ];
            let angular_damping = angular_damping
                .map(|d| finite("angular_damping", d).map(|d| (d, ())))
                .transpose()?;
            let contacts = match (contacts, pivot) {
                (Some(c), None) => Some((Contacts::Table(table::contacts(c)?), ())),
                // With a pivot, the conflict is the error, whatever the contacts.
                (Some(_), Some(_)) => Some((Contacts::Table(Vec::new()), ())),
                (None, _) => None,
            };
            let [torque, torque_body, force] = loads;
            let request = BodyRequest {
                body: (),
                mass: Some((mass, ())),
                inertia: (key, inertia, ()),
                attitude,
                omega_body,
                position,
                velocity: vector_of("velocity", velocity)?,
                pivot: vector_of("pivot", pivot)?,
                torque,
                torque_body,
                force,
                angular_damping,
                contacts,
            };
            let id = request
                .add_to(&mut self.world)
                .map_err(|e| key_error(e.problem))?;
            self.ids.push(id);
            Ok(self.ids.len() - 1)
        })
    }

    /// Replaces what is applied to body ``body`` from now on (all zero when
    /// omitted): ``torque`` (world axes), ``torque_body``, ``force``
    /// (world axes, through the centre of mass), ``angular_damping``.
    #[pyo3(signature = (body, *, torque=None, torque_body=None, force=None, angular_damping=None))]
    #[pyo3(
        text_signature = "($self, body, *, torque=None, torque_body=None, force=None, angular_damping=0.0)"
    )]
    fn set_inputs(
        &mut self,
        body: &Bound<'_, PyAny>,
        torque: Arg<'_, '_>,
        torque_body: Arg<'_, '_>,
        force: Arg<'_, '_>,
        angular_damping: Arg<'_, '_>,
    ) -> PyResult<()> {
        guard(|| {
            let id = self.id(body)?;
            let inputs = inputs(torque, torque_body, force, angular_damping)?;
            self.world.set_inputs(id, inputs).map_err(world_error)
        })
    }

    /// Sets body ``body``'s attitude (w, x, y, z, normalised) and angular
    /// velocity (body axes, rad/s) now.
    fn set_rotation(
        &mut self,
        body: &Bound<'_, PyAny>,
        attitude: &Bound<'_, PyAny>,
        omega_body: &Bound<'_, PyAny>,
    ) -> PyResult<()> {
        guard(|| {
            let id = self.id(body)?;
            let attitude = quaternion(attitude)?;
            let omega = vector("omega_body", Some(omega_body))?;
            self.world
                .set_rotation(id, attitude, omega)
                .map_err(world_error)
        })
    }

    /// One step of ``h`` seconds (exact solutions are evaluated at its end).
    fn step(&mut self, py: Python<'_>, h: &Bound<'_, PyAny>) -> PyResult<()> {
        guard(|| {
            let h = finite("h", h)?;
            py.detach(|| self.world.step(h)).map_err(|e| match e {
                DynamicsError::InvalidStep { .. } => named("h")(e),
                other => world_error(other),
            })
        })
    }

    /// ``n`` whole steps of ``dt`` (the grid of ``kreisel simulate``; n
    /// from 0 to 2^64 - 1).
    fn advance_steps(&mut self, py: Python<'_>, n: &Bound<'_, PyAny>) -> PyResult<()> {
        guard(|| {
            let n = integer("n", n, 0, u64::MAX)?;
            py.detach(|| self.world.advance_steps(n))
                .map_err(world_error)
        })
    }

    /// Advances to time ``t`` (s): stepping methods take steps of ``dt``,
    /// the last shortened to land on ``t``; exact solutions are evaluated
    /// at ``t`` once.
    fn advance_to(&mut self, py: Python<'_>, t: &Bound<'_, PyAny>) -> PyResult<()> {
        guard(|| {
            let t = finite("t", t)?;
            py.detach(|| self.world.advance_to(t)).map_err(world_error)
        })
    }

    /// The world's time, s.
    #[getter]
    fn time(&self) -> f64 {
        self.world.time()
    }

    /// The step of the stepping methods, s.
    #[getter]
    fn dt(&self) -> f64 {
        self.world.dt()
    }

    /// Gravity, world axes, m/s^2.
    #[getter]
    fn gravity<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.world.gravity().to_array())
    }

    /// The number of bodies.
    fn __len__(&self) -> usize {
        self.ids.len()
    }

    /// How body ``body`` is moved (what it is, which method, why).
    fn plan(&self, body: &Bound<'_, PyAny>) -> PyResult<String> {
        guard(|| {
            let id = self.id(body)?;
            Ok(self
                .world
                .plan(id)
                .map(ToString::to_string)
                .unwrap_or_default())
        })
    }

    /// The events of body ``body`` so far (a body on the table: added with
    /// ``contacts``; none for the others), in time order: tuples ``(time,
    /// contact, kind, approach_speed, rebound_speed, accumulation_time)``
    /// — ``time`` in s; ``contact`` the index in the body's ``contacts``
    /// (``None``: the whole body); ``kind`` one of ``"impact"``,
    /// ``"impacts_accumulate"``, ``"touchdown"``, ``"lift_off"``,
    /// ``"stick"``, ``"slip"``, ``"stops_rolling"``, ``"starts_rolling"``,
    /// ``"lands_flat"``, ``"rest"``; the normal speeds before and
    /// after an impact (m/s) and where accumulating bounces end (s), else
    /// ``None``. The rows of the CLI's ``--events`` file, numbered as the
    /// library numbers contacts (from 0).
    ///
    /// >>> import kreisel
    /// >>> w = kreisel.World(0.01, gravity=(0, 0, -9.81))
    /// >>> b = w.add_body(1.0, moments=(0.004,) * 3, contacts=[{"shape": "sphere", "radius": 0.1, "mu": 0.5}])
    /// >>> [e[2] for e in w.events(b)]  # placed on the table, it rests there
    /// ['touchdown', 'rest']
    fn events<'py>(
        &self,
        py: Python<'py>,
        body: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, pyo3::types::PyList>> {
        guard(|| {
            let id = self.id(body)?;
            let events = self.world.events(id).unwrap_or_default();
            table::world_events(py, events)
        })
    }

    /// The state of body ``body`` now: ``time`` (s), ``attitude``
    /// (world_from_body, w, x, y, z), ``omega_body`` (rad/s, body axes),
    /// ``l_world`` (angular momentum about the centre of mass, or the pivot,
    /// world axes), ``energy`` (J), ``position`` and ``velocity`` of the
    /// centre of mass (world axes).
    fn state<'py>(
        &self,
        py: Python<'py>,
        body: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyDict>> {
        guard(|| {
            let id = self.id(body)?;
            let s = self
                .world
                .state(id)
                .ok_or_else(|| error(format!("body: no body {body} in this world")))?;
            let q = s.world_from_body;
            let dict = PyDict::new(py);
            dict.set_item("time", s.time)?;
            dict.set_item("attitude", PyArray1::from_slice(py, &[q.w, q.x, q.y, q.z]))?;
            dict.set_item(
                "omega_body",
                PyArray1::from_slice(py, &s.omega_body.to_array()),
            )?;
            dict.set_item("l_world", PyArray1::from_slice(py, &s.l_world.to_array()))?;
            dict.set_item("energy", s.energy)?;
            dict.set_item("position", PyArray1::from_slice(py, &s.position.to_array()))?;
            dict.set_item("velocity", PyArray1::from_slice(py, &s.velocity.to_array()))?;
            Ok(dict)
        })
    }

    /// The states of all bodies, stacked: ``attitude`` (n, 4),
    /// ``omega_body``, ``l_world``, ``position``, ``velocity`` (n, 3),
    /// ``energy`` (n,), and ``time``.
    fn states<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        guard(|| {
            let n = self.ids.len();
            let mut columns: [Vec<f64>; 6] = Default::default();
            for id in &self.ids {
                let Some(s) = self.world.state(*id) else {
                    continue;
                };
                let q = s.world_from_body;
                columns[0].extend([q.w, q.x, q.y, q.z]);
                columns[1].extend(s.omega_body.to_array());
                columns[2].extend(s.l_world.to_array());
                columns[3].push(s.energy);
                columns[4].extend(s.position.to_array());
                columns[5].extend(s.velocity.to_array());
            }
            let [attitude, omega, l, energy, position, velocity] = columns;
            let stacked = |v: Vec<f64>, width: usize| -> PyResult<Bound<'py, PyArray2<f64>>> {
                PyArray1::from_vec(py, v).reshape([n, width])
            };
            let dict = PyDict::new(py);
            dict.set_item("time", self.world.time())?;
            dict.set_item("attitude", stacked(attitude, 4)?)?;
            dict.set_item("omega_body", stacked(omega, 3)?)?;
            dict.set_item("l_world", stacked(l, 3)?)?;
            dict.set_item("energy", PyArray1::from_vec(py, energy))?;
            dict.set_item("position", stacked(position, 3)?)?;
            dict.set_item("velocity", stacked(velocity, 3)?)?;
            Ok(dict)
        })
    }

    fn __repr__(&self) -> String {
        format!(
            "World(dt={}, gravity={:?}, bodies={}, time={})",
            self.world.dt(),
            self.world.gravity().to_array(),
            self.ids.len(),
            self.world.time()
        )
    }
}

/// Adds the class to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyWorld>()
}
