//! `kreisel.simulate`: a scene in the format of `kreisel simulate` (a path
//! or the TOML text) run exactly as the CLI runs it, the rows it would
//! write as a dict of numpy arrays keyed by the CSV column names; and the
//! object API over the engine's World (`kreisel.World`,
//! `simulation_world.rs`).
//!
//! No physics here: the scene is parsed by the CLI's parser into the
//! engine's World and moved along the CLI's schedule
//! ([`kreisel_scene::run::run_rows`]); where the CLI formats a row, this
//! copies the state's numbers into columns, so the arrays hold the very
//! numbers the CSV spells.

use std::num::NonZeroUsize;
use std::path::{Path, PathBuf};

use kreisel_dynamics::BodyId;
use kreisel_scene::columns::{Column, States};
use kreisel_scene::error::SceneError;
use kreisel_scene::methods;
use kreisel_scene::run::{prepare, run_rows};
use kreisel_scene::scene_file::Scene;
use numpy::PyArray1;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::arguments;
use crate::errors::{error, guard, scene_error};

#[path = "simulation_table.rs"]
mod table;
#[path = "simulation_world.rs"]
mod world;

pub(crate) use world::PyWorld;

/// The name a scene given as text goes by in messages (mesh paths in it
/// are relative to the working directory).
const TEXT_SCENE: &str = "<string>";

/// The rows of a run, one column per [`Column`].
#[derive(Default)]
struct Columns {
    /// Every numeric column, in [`Column::ALL`] order (`t` first, `body` skipped).
    numbers: Vec<Vec<f64>>,
    /// The `body` column.
    body: Vec<String>,
}

impl Columns {
    fn new() -> Self {
        Self {
            numbers: vec![Vec::new(); Column::ALL.len() - 1],
            body: Vec::new(),
        }
    }

    /// One row per body state of one time, in scene order (names from `bodies`).
    fn push(&mut self, states: &States, bodies: &[(String, BodyId)]) {
        for (index, s) in states {
            let name = &bodies[*index].0;
            // Every column but `body`, in `Column::ALL` order.
            let row = Column::ALL.into_iter().filter_map(|c| c.value(s));
            for (column, x) in self.numbers.iter_mut().zip(row) {
                column.push(x);
            }
            self.body.push(name.clone());
        }
    }
}

/// What the `scene` argument names: a file, or the TOML text itself.
fn scene_source(scene: &Bound<'_, PyAny>) -> PyResult<(PathBuf, Option<String>)> {
    if let Ok(text) = scene.extract::<String>() {
        // TOML needs a line per key: one line cannot hold a scene.
        if text.contains('\n') {
            return Ok((PathBuf::from(TEXT_SCENE), Some(text)));
        }
    }
    let path = arguments::path("scene", scene).map_err(|e| {
        if e.is_instance_of::<PyTypeError>(scene.py()) {
            PyTypeError::new_err(format!(
                "scene must be a path or the TOML text of a scene, got {}",
                scene
                    .get_type()
                    .name()
                    .map_or_else(|_| "?".to_owned(), |n| n.to_string())
            ))
        } else {
            e
        }
    })?;
    Ok((path, None))
}

/// Reads, parses and runs the scene; the columns of every row, and the
/// scene as the run left it (its bodies' events).
fn run(
    path: &Path,
    text: Option<String>,
    method: Option<&str>,
    threads: Option<NonZeroUsize>,
) -> Result<(Columns, Scene), SceneError> {
    let text = match text {
        Some(text) => text,
        None => kreisel_inertia::io::read_limited_text(path, "a scene file").map_err(|source| {
            SceneError::ReadScene {
                path: path.to_owned(),
                source,
            }
        })?,
    };
    // Parsed once, here (after the scene is read, as the CLI's errors come).
    let method = method.map(methods::parse).transpose()?;
    let (mut scene, method) = prepare(path, &text, method)?;
    let threads = threads
        .unwrap_or_else(|| std::thread::available_parallelism().unwrap_or(NonZeroUsize::MIN));
    scene.world.set_threads(threads);
    let mut columns = Columns::new();
    run_rows(&mut scene, path, method, &mut |states, bodies| {
        columns.push(states, bodies);
    })?;
    Ok((columns, scene))
}

/// Runs a scene of `kreisel simulate` (a path, or the TOML text) as the CLI
/// does and returns the rows it would write, one numpy array per CSV
/// column: ``t``, ``body`` (str), ``qw``, ``qx``, ``qy``, ``qz``
/// (world_from_body), ``wx``, ``wy``, ``wz`` (body axes), ``energy``,
/// ``lx``, ``ly``, ``lz`` (world axes), ``x``, ``y``, ``z``, ``vx``,
/// ``vy``, ``vz``. One row per body and output time, bodies in scene order;
/// the numbers are those the CSV spells (bit for bit).
///
/// ``method`` overrides the scene's (as ``--method``); ``threads`` (at
/// least 1) as ``--threads`` (the output does not depend on it). A scene given as text
/// finds its mesh files relative to the working directory. The GIL is
/// released while the scene runs.
///
/// With ``events=True`` it returns ``(rows, events)``: ``events`` the rows
/// of the CLI's ``--events`` file, a list of tuples ``(time, body,
/// contact, kind, approach_speed, rebound_speed, accumulation_time)`` in
/// time order (bodies on the table only: impacts, touchdowns, lift-offs,
/// stick, slip, stops/starts rolling, lands flat, rest; ``contact`` the ``[[body.contact]]`` table's number,
/// 1 = the first, ``None`` for the whole body; the speeds, m/s, of an
/// ``"impact"``, the ``accumulation_time``, s, of
/// ``"impacts_accumulate"``, else ``None``), the numbers the file spells.
///
/// Raises KreiselError with the CLI's one-line message: an unreadable
/// scene, a bad key (naming its line), a body that diverges; for a bad
/// argument, a message beginning with its name (``threads: …``, ``method:
/// …``, ``scene: path is empty``); TypeError for a scene that is neither a
/// path nor text.
///
/// >>> import kreisel
/// >>> rows = kreisel.simulate('''
/// ... [simulation]
/// ... duration = 1.0
/// ... dt = 0.5
/// ... [[body]]
/// ... mass = 1.0
/// ... inertia = [1.0, 2.0, 3.0]
/// ... angular_velocity = [0.0, 0.0, 1.0]
/// ... ''')
/// >>> rows["t"].tolist(), rows["body"].tolist()
/// ([0.0, 0.5, 1.0], ['body1', 'body1', 'body1'])
/// >>> float(rows["energy"][-1])
/// 1.5
/// >>> rows, events = kreisel.simulate("examples/scenes/bouncing_ball.toml", events=True)
/// >>> events[0][1:4], round(events[0][0], 5)
/// (('ball', 1, 'impact'), 0.42835)
#[pyfunction]
#[pyo3(signature = (scene, method=None, threads=None, *, events=false))]
fn simulate<'py>(
    py: Python<'py>,
    scene: &Bound<'py, PyAny>,
    method: Option<&str>,
    threads: Option<&Bound<'py, PyAny>>,
    events: bool,
) -> PyResult<Bound<'py, PyAny>> {
    guard(|| {
        let (path, text) = scene_source(scene)?;
        let threads = threads
            .map(|n| arguments::integer("threads", n, 1, u64::MAX))
            .transpose()?
            .map(|n| {
                usize::try_from(n)
                    .ok()
                    .and_then(NonZeroUsize::new)
                    .ok_or_else(|| error(format!("threads: {n} is more than this machine counts")))
            })
            .transpose()?;
        let (columns, ran) = py
            .detach(|| run(&path, text, method, threads))
            .map_err(scene_error)?;
        let dict = PyDict::new(py);
        let np = py.import("numpy")?;
        let mut numbers = columns.numbers.into_iter();
        for column in Column::ALL {
            if column == Column::Body {
                let names = np.call_method1("array", (columns.body.clone(), "str"))?;
                dict.set_item(column.name(), names)?;
            } else if let Some(values) = numbers.next() {
                dict.set_item(column.name(), PyArray1::from_vec(py, values))?;
            }
        }
        if events {
            let events = table::scene_events(py, &ran.world, &ran.bodies)?;
            Ok((dict, events).into_pyobject(py)?.into_any())
        } else {
            Ok(dict.into_any())
        }
    })
}

/// Adds this part's functions and classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(simulate, m)?)?;
    world::register(m)
}
