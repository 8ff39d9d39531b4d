//! `kreisel.World`: the engine's [`World`] as a Python object: add bodies
//! (principal moments or an inertia tensor; attitude, spin; free or on a
//! pivot; torques, forces, damping), change what is applied to them, move
//! the world (`step`, `advance_steps`, `advance_to`) and read the states as
//! numpy arrays. Every number is the engine's; this file converts and
//! names errors.

use glam::{DMat3, DQuat, DVec3};
use kreisel_dynamics::{Body, BodyId, FreeBodyMethod, Inputs, World};
use kreisel_inertia::MassProperties;
use kreisel_kinematics::try_normalize_quat;
use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::errors::{error, guard};

/// A world of rigid bodies that do not interact, each moved by the
/// engine's best method for it (exact solutions for free bodies and
/// Lagrange tops, stepping methods otherwise), all SI units and radians.
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

/// The inputs from the keywords (zero when absent).
fn inputs(
    torque: Option<[f64; 3]>,
    torque_body: Option<[f64; 3]>,
    force: Option<[f64; 3]>,
    angular_damping: f64,
) -> Inputs {
    let v = |x: Option<[f64; 3]>| x.map_or(DVec3::ZERO, DVec3::from_array);
    Inputs::default()
        .with_torque_world(v(torque))
        .with_torque_body(v(torque_body))
        .with_force_world(v(force))
        .with_angular_damping(angular_damping)
}

/// The attitude `[w, x, y, z]`, normalised as a scene's `orientation` is.
fn quaternion([w, x, y, z]: [f64; 4]) -> PyResult<DQuat> {
    try_normalize_quat(DQuat::from_xyzw(x, y, z, w))
        .map_err(|_| error("attitude must be a quaternion w, x, y, z of finite numbers, not zero"))
}

impl PyWorld {
    /// The engine's id of the body Python calls `body`.
    fn id(&self, body: usize) -> PyResult<BodyId> {
        self.ids.get(body).copied().ok_or_else(|| {
            error(format!(
                "no body {body} in this world (it has {}: 0 to {})",
                self.ids.len(),
                self.ids.len() as i64 - 1
            ))
        })
    }
}

#[pymethods]
impl PyWorld {
    #[new]
    #[pyo3(signature = (dt, gravity=[0.0, 0.0, 0.0], method="auto"))]
    fn new(dt: f64, gravity: [f64; 3], method: &str) -> PyResult<Self> {
        guard(|| {
            let mut world = World::try_new(DVec3::from_array(gravity), dt).map_err(error)?;
            let free: FreeBodyMethod = method.parse().map_err(error)?;
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
    /// >>> import kreisel
    /// >>> w = kreisel.World(dt=0.001, gravity=(0, 0, -9.81))
    /// >>> top = w.add_body(0.5, moments=(0.02, 0.02, 0.01), omega_body=(0, 0, 50),
    /// ...                  attitude=(0.99, 0.14, 0, 0), pivot=(0, 0, -0.05))
    /// >>> w.plan(top)
    /// 'Lagrange top on a pivot: exact, closed form ...'
    #[pyo3(signature = (mass, moments=None, inertia=None, *, attitude=None, omega_body=[0.0, 0.0, 0.0], position=[0.0, 0.0, 0.0], velocity=None, pivot=None, torque=None, torque_body=None, force=None, angular_damping=0.0))]
    #[allow(clippy::too_many_arguments)] // the Python keywords, one each
    fn add_body(
        &mut self,
        mass: f64,
        moments: Option<[f64; 3]>,
        inertia: Option<[[f64; 3]; 3]>,
        attitude: Option<[f64; 4]>,
        omega_body: [f64; 3],
        position: [f64; 3],
        velocity: Option<[f64; 3]>,
        pivot: Option<[f64; 3]>,
        torque: Option<[f64; 3]>,
        torque_body: Option<[f64; 3]>,
        force: Option<[f64; 3]>,
        angular_damping: f64,
    ) -> PyResult<usize> {
        guard(|| {
            let builder = match (moments, inertia) {
                (Some(m), None) => Body::from_principal_moments(mass, DVec3::from_array(m)),
                (None, Some(rows)) => {
                    let tensor = DMat3::from_cols_array_2d(&rows).transpose();
                    let props = MassProperties::try_new(mass, DVec3::ZERO, tensor)
                        .map_err(|e| error(format!("inertia: {e}")))?;
                    Body::from_mass_properties(props)
                }
                _ => {
                    return Err(error(
                        "give exactly one of moments (principal, kg m^2) and inertia (3 x 3 tensor)",
                    ));
                }
            };
            let attitude = attitude.map_or(Ok(DQuat::IDENTITY), quaternion)?;
            let builder = builder
                .world_from_body(attitude)
                .omega_body(DVec3::from_array(omega_body));
            let position = DVec3::from_array(position);
            let builder = match (pivot, velocity) {
                (Some(_), Some(_)) => {
                    return Err(error(
                        "velocity cannot be given with pivot: the pivot is fixed",
                    ));
                }
                (Some(p), None) => builder.pivot(DVec3::from_array(p), position),
                (None, v) => builder.free(position, v.map_or(DVec3::ZERO, DVec3::from_array)),
            };
            let body = builder
                .try_build()
                .and_then(|b| b.with_inputs(inputs(torque, torque_body, force, angular_damping)))
                .map_err(error)?;
            let id = self.world.add(body).map_err(error)?;
            self.ids.push(id);
            Ok(self.ids.len() - 1)
        })
    }

    /// Replaces what is applied to body ``body`` from now on (all zero when
    /// omitted): ``torque`` (world axes), ``torque_body``, ``force``
    /// (world axes, through the centre of mass), ``angular_damping``.
    #[pyo3(signature = (body, *, torque=None, torque_body=None, force=None, angular_damping=0.0))]
    fn set_inputs(
        &mut self,
        body: usize,
        torque: Option<[f64; 3]>,
        torque_body: Option<[f64; 3]>,
        force: Option<[f64; 3]>,
        angular_damping: f64,
    ) -> PyResult<()> {
        guard(|| {
            let id = self.id(body)?;
            let inputs = inputs(torque, torque_body, force, angular_damping);
            self.world.set_inputs(id, inputs).map_err(error)
        })
    }

    /// Sets body ``body``'s attitude (w, x, y, z, normalised) and angular
    /// velocity (body axes, rad/s) now.
    fn set_rotation(
        &mut self,
        body: usize,
        attitude: [f64; 4],
        omega_body: [f64; 3],
    ) -> PyResult<()> {
        guard(|| {
            let id = self.id(body)?;
            self.world
                .set_rotation(id, quaternion(attitude)?, DVec3::from_array(omega_body))
                .map_err(error)
        })
    }

    /// One step of ``h`` seconds (exact solutions are evaluated at its end).
    fn step(&mut self, py: Python<'_>, h: f64) -> PyResult<()> {
        guard(|| py.detach(|| self.world.step(h)).map_err(error))
    }

    /// ``n`` whole steps of ``dt`` (the grid of ``kreisel simulate``).
    fn advance_steps(&mut self, py: Python<'_>, n: u64) -> PyResult<()> {
        guard(|| py.detach(|| self.world.advance_steps(n)).map_err(error))
    }

    /// Advances to time ``t`` (s): stepping methods take steps of ``dt``,
    /// the last shortened to land on ``t``; exact solutions are evaluated
    /// at ``t`` once.
    fn advance_to(&mut self, py: Python<'_>, t: f64) -> PyResult<()> {
        guard(|| py.detach(|| self.world.advance_to(t)).map_err(error))
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
    fn plan(&self, body: usize) -> PyResult<String> {
        guard(|| {
            let id = self.id(body)?;
            Ok(self
                .world
                .plan(id)
                .map(ToString::to_string)
                .unwrap_or_default())
        })
    }

    /// The state of body ``body`` now: ``time`` (s), ``attitude``
    /// (world_from_body, w, x, y, z), ``omega_body`` (rad/s, body axes),
    /// ``l_world`` (angular momentum about the centre of mass, or the pivot,
    /// world axes), ``energy`` (J), ``position`` and ``velocity`` of the
    /// centre of mass (world axes).
    fn state<'py>(&self, py: Python<'py>, body: usize) -> PyResult<Bound<'py, PyDict>> {
        guard(|| {
            let id = self.id(body)?;
            let s = self
                .world
                .state(id)
                .ok_or_else(|| error(format!("no body {body} in this world")))?;
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
