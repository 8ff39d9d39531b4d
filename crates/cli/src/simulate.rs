//! `kreisel simulate`: integrate the rotation of the bodies of a TOML scene
//! (torque-free, driven by applied torques and forces, or heavy tops on a
//! fixed pivot under gravity) and stream their states as CSV, in constant
//! memory.
//!
//! The scene layer reads and checks the scene (`kreisel_scene::run::prepare`,
//! every error naming its line and key) into a `kreisel_dynamics::World`
//! and advances it from row to row on its output grid
//! (`kreisel_scene::run::run`); the rows are written as CSV as they are
//! produced. This module parses the arguments, opens and commits the
//! output files, draws the progress bar and the figure, and reports.

#![forbid(unsafe_code)]

mod figure;
mod progress;
mod record;

use std::fs;
use std::io::{self, BufWriter, Write};
use std::num::NonZeroUsize;
use std::path::PathBuf;

use kreisel_dynamics::{Plan, table_tolerance};
use kreisel_scene::columns::{Column, CsvWriter};
use kreisel_scene::error::SceneError;
use kreisel_scene::events;
use kreisel_scene::methods;
use kreisel_scene::run::{Stop, Watcher, prepare, run as run_scene};
use kreisel_scene::scene_file::Scene;

use self::progress::Progress;
use crate::error::{CliError, Stream};

/// Size of the output buffer.
const BUFFER_BYTES: usize = 1 << 16;

/// The `--help` text of `kreisel simulate` after the option list.
const AFTER_LONG_HELP: &str = "\
Scene (TOML; SI units, radians):
  [simulation]
  duration = 20.0            simulated time, s
  dt = 0.01                  fixed step, s (at most 1e9 steps)
  method = \"auto\"            see --list-methods [default: auto]
  output_interval = 0.1      s between rows, a whole multiple of dt
                             [default: every step]
  gravity = [0, 0, -9.81]    m/s^2 [default: none]
  tolerance = 1e-6           attitude error allowed over the run, rad: the
                             cheapest method predicted to meet it (not with
                             a method other than auto) [default: none,
                             rounding level]

  [[body]]                   one table per body (at least one)
  name = \"handle\"            [default: body1, body2, ...]; unique, without
                             commas or quotes
  mass = 1.0                 kg
  inertia = [1.0, 2.0, 3.0]  principal moments about the centre of mass,
                             kg m^2; body axes = principal axes
  inertia_tensor = [[..], [..], [..]]
                             or the tensor about the centre of mass in body
                             axes, rows
  mesh = \"t_handle.obj\"      or a closed mesh in metres (.stl .obj .ply
  density = 2700.0           .gltf .glb; path relative to the scene file),
                             solid of this density in kg/m^3: no mass key,
                             body axes = mesh axes
  orientation = [1, 0, 0, 0] world_from_body quaternion w,x,y,z, normalised
                             [default: identity]
  euler = { sequence = \"ZXZ\", angles = [0.1, 0.2, 0.3] }
                             or Euler angles as in kreisel convert
                             (uppercase intrinsic, lowercase extrinsic)
  angular_velocity = [0.01, 1.0, 0.0]
                             rad/s, body axes (required)
  position = [0, 0, 0]       centre of mass, world axes, m [default: 0]
                             (with a pivot: the pivot's position)
  velocity = [0, 0, 0]       its velocity, m/s [default: 0] (not with a pivot)
  pivot = [0, 0, -0.04]      a fixed point, body coordinates, m: the body
                             is a heavy top turning about it under gravity.
                             For inertia/inertia_tensor bodies measured from
                             the centre of mass; for mesh bodies in the
                             mesh's own coordinates [default: none, free]
  torque = [0, 0, 0.1]       applied torque, N m, world axes [default: none]
  torque_body = [0, 0, 0.1]  applied torque, N m, body axes (turns with the
                             body) [default: none]
  force = [1, 0, 0]          applied force through the centre of mass, N,
                             world axes [default: none]
  angular_damping = 0.01     c >= 0: the torque -c omega, N m s [default: 0]
                             (torque, torque_body, force, angular_damping
                             with a pivot: a driven heavy top)
  [body.contact]             the body stands on the ground plane z = 0
                             (gravity must be [0, 0, -g]) touching it with:
  shape = \"sphere\"           \"sphere\" | \"disk\" | \"ellipsoid\"
  radius = 0.015             sphere or disk radius, m
  center = [0, 0, 0.003]     its centre from the centre of mass, body axes,
                             m [default: 0]
  normal = [0, 0, 1]         disk only: its axis, body axes
  semi_axes = [0.2, 0.03, 0.02]
                             ellipsoid only: semi-axes along body x, y, z, m
  friction = \"sliding\"       \"none\" | \"viscous\" (F = -mu N v_slip, mu in
                             s/m) | \"sliding\" (Coulomb, regularised:
                             F = -mu N v/sqrt(|v|^2 + eps^2)) | \"rolling\"
                             (no slip) | \"coulomb\" (exact Coulomb friction:
                             the body is on the table, see below)
  mu = 0.3                   viscous, sliding and coulomb only, >= 0
  slip_velocity = 1e-3       sliding only: eps, m/s [default: 1e-3, Leine &
                             Glocker's value; inversion times depend on it]
  restitution = 0.9          coulomb only: Newton's e in [0, 1] [default: 0]
  tangential_restitution = 0 coulomb only: Garwin's e_T in [0, 1] [default: 0]
  contensou_radius = 5e-4    coulomb only: the contact patch's radius, m,
                             for Contensou's drilling friction [default: 0]
  rolling_resistance = 1e-3  coulomb only: delta, m: the rolling torque is at
                             most delta N (set-valued) [default: 0]
  air_viscosity = 1.8e-5     coulomb disk only: Moffatt's air layer under the
                             rim (Pa s), the dissipation that brings Euler's
                             disk down
  air_gap = 1e-6             with air_viscosity: the layer's floor, m
                             [default: 1e-6]
                             The body starts touching: the height of its
                             centre of mass follows from its attitude (a
                             `position` z must agree to 1e-9 m); x, y from
                             `position`; `velocity` horizontal (not with
                             rolling: it follows from the spin). No pivot;
                             torque, torque_body, force and angular_damping
                             act besides gravity and the contact.
  [[body.contact]]           several tables (at most 5): the first is the
                             contact above; the others (shape, radius,
                             center, normal, semi_axes only: no friction,
                             mu or slip_velocity) are watched for
                             touchdown, e.g. a tippe top's stem ball: they
                             exert no force and must start above the plane.
                             With friction = \"coulomb\" (on every table: no
                             other model on the same body) the body is on
                             the table: every table is a contact with its
                             own law (at most 8), the stem's ball too;
                             `position` and `velocity` are its centre of
                             mass's start, anywhere above the table (without
                             `position`: above the origin, its lowest shape
                             touching); no torque, force or damping
  Exactly one of inertia, inertia_tensor and mesh; at most one of
  orientation and euler. Positive mass, dt, duration, density; physical
  inertia (I1 + I2 >= I3).

Motion:
  Bodies do not interact. A body without a pivot rotates torque-free
  (gravity exerts no torque about the centre of mass) and its centre of mass
  moves exactly: x(t) = x0 + v0 t + g t^2/2. A body with a pivot is a heavy
  top: it turns about the fixed pivot under the torque of gravity (none
  without gravity), moved by the heavy-top version of the method (see
  --list-methods; exact, splitting, dmv and pdmv* have none). A body moved
  by a stepping method (every heavy top, and every body when a method other
  than auto or exact is chosen) takes steps of dt; the last step is
  shortened to end exactly at t = duration. Under auto or exact a free body
  is not stepped: its exact solution is set up once and evaluated at the
  times written (at rest: nothing to compute; a sphere or a spin about a
  principal axis: one uniform rotation; two equal moments: a closed form).
  A free body with a nonzero torque, torque_body, force or angular_damping
  is driven: it takes steps of dt by a kick-drift-kick splitting (the free
  flow alternating with exact kicks of the torques, forces and damping),
  auto: splitting6 (order 6); strang, splitting4, splitting6, splitting8:
  the splitting of that order; the other methods cannot move it (an error).
  Its centre of mass moves under gravity and force: x'' = g + F/m.
  A heavy top with them is driven: the same splitting about the pivot, with
  gravity kicked exactly alongside the loads (a force turns the top about
  the pivot); auto: splitting8 sub-stepped within its stability limit.
  A body with [body.contact] is moved by the contact model (whatever the
  method): its centre of mass and rotation under gravity, the normal force
  and friction at the contact point, in error-controlled Dormand-Prince
  5(4) steps within every dt (dt is only where rows are read) at rtol =
  atol = 1e-11, or 1e-4 x tolerance (in [1e-13, 1e-8]) with tolerance; the
  run stops with an error at a lift-off (normal force zero), a disk lying
  flat, an indeterminate contact, or a watched [[body.contact]] touching
  down (its time located within the step; the impact is not modelled):
  an event, see Errors.
  A body with friction = \"coulomb\" is on the table, moved by an
  event-driven nonsmooth method: Dormand-Prince 5(4) with error control
  between events, each contact unilateral (Signorini), impacts by Newton's
  law with friction, set-valued Coulomb friction with Contensou's drilling.
  Impacts, touchdowns, lift-offs, stick, slip and rest are events, located
  to rounding, and the run goes on (--events). dt is only the grid of the
  rows: the motion takes its own steps (rtol = atol = 1e-10, or tolerance /
  1000 with tolerance), so rows at any dt agree to that accuracy.
  With tolerance, a driven body or heavy top takes the cheapest splitting
  and sub-steps per dt predicted to meet it, and a free asymmetric body rk4
  or pdmv6 every dt where that is predicted to meet it for less work than
  evaluating the exact solution at every row; the prediction is
  4 x (steps) x (the largest local error of one step, measured by step
  doubling along a short pilot run when the plan is made). Below 1e-10 rad
  the default plans (rounding level) stay.
  --explain prints each body's plan (what it is, which method, why; with
  tolerance, what it chose and the predicted error) and exits without running.
  --threads N moves the bodies that step every dt (heavy tops, driven
  bodies) on N threads (default: all cores); the output is byte-identical
  for every N.

Output (CSV; standard output unless --output):
  t,body,qw,qx,qy,qz,wx,wy,wz,energy,lx,ly,lz
  t          time, s: k*dt after step k; the last row is at t = duration
  body       the body's name
  qw..qz     attitude, world_from_body quaternion w,x,y,z; continuous in time
             (no sign flips); as the method holds it (rk4 does not renormalise)
  wx..wz     angular velocity in body axes, rad/s
  energy     total energy, J: rotational + m |v|^2/2 - m g.x (the last term
             only with gravity), constant for an exact solution; with a
             pivot: rotational about the pivot - m g.x (x the centre of mass)
  lx..lz     angular momentum about the centre of mass, world axes, kg m^2/s
             (about the pivot for a body with one; about the centre of mass
             for a body on the ground)
  With torque, torque_body, force or angular_damping, energy is the
  mechanical energy (the same formula): not conserved, its change is the
  work done by them (damping included).
  --columns LIST writes the columns named in LIST (comma-separated, in that
  order) instead: any of the thirteen above and
  x,y,z      centre of mass, world axes, m (for a heavy top too: where its
             centre of mass is, not the pivot)
  vx,vy,vz   its velocity, world axes, m/s
  --events FILE writes the events of the bodies on the table, in time order:
  time,body,contact,kind,approach_speed,rebound_speed,accumulation_time
  (contact: the [[body.contact]] table's number, empty for the whole body;
  kind: impact, impacts_accumulate, touchdown, lift_off, stick, slip,
  stops_rolling, starts_rolling, lands_flat, rest;
  the speeds, m/s, for an impact, accumulation_time, s, where the bounces
  end); written whole with the CSV, or not at all.
  Rows at t = 0, after every step that ends at a multiple of output_interval
  (every step without it), and at t = duration: one row per body each time,
  in scene order. Numbers in shortest round-trip form; rows are written as
  they are computed. A progress bar is drawn on standard error when it is a
  terminal (not when the CSV goes to the same terminal).

Plot (--plot FILE.png or FILE.svg, besides the CSV):
  one row per body (the first 4 in scene order; the figure names them when
  the scene has more): omega(t) in body axes; the energy change
  (E - E0)/|E0| (E - E0 in J when E0 = 0); and the polhode, the path of
  L/|L| on the unit sphere in principal axes (I1 <= I2 <= I3), with the
  separatrices of a torque-free body with three distinct moments dashed
  (the great circles L1/L3 = +-sqrt(I1 (I3 - I2) / (I3 (I2 - I1))), where
  the energy ellipsoid of 2E = L^2/I2 meets the sphere). Long runs are
  thinned to at most 4000 evenly spaced rows per body (the last row kept).
  The image is written whole or not at all, with the --output file: when
  the run ends or stops at an event (then up to the event).

Errors: one line, SCENE:LINE: message, naming the key; exit status 1.
  A body whose state becomes non-finite, or whose energy, |L| or |q| drifts
  by more than a factor of 10 (a step far beyond the method's stability),
  stops the run: SCENE: body `NAME`: method M diverged at t = T s (...),
  with a hint; exit status 1. So does a row that would hold a number that
  is not finite (e.g. an energy beyond 1.8e308 J). Such a run writes
  nothing: an existing --output or --plot file stays as it was (on
  standard output the rows before it have been written).
  Events end what the model describes: a lift-off, a disk lying flat, an
  indeterminate contact, a watched contact touching down (on the ground);
  contact modes that chatter, an impact the law cannot resolve without
  gaining energy (on the table). The run stops there with one line naming
  it, exit status 1; the --output file, the --plot image and the --events
  file hold the motion up to the event (its last row the last output time
  before it). An indeterminate contact on the table (Painlevé's case: no
  normal force keeps a sliding contact, its mu beyond the bound of the
  slip) is bad input: one line at that contact's mu, nothing written.
  A free body stepped by a method beyond that method's step limit, dt
  times the fastest angular speed |L|/I1 the body can reach (--explain
  prints both), gets one warning line on standard error, and the run goes
  on: its energy error may pass 10 % (or a step fails).
  Ctrl-C (SIGINT) or SIGTERM removes the unfinished --output and --plot
  files and exits with status 130 or 143; the temporary files a killed
  run leaves (.NAME.kreisel-PID-N.tmp) are removed by the next run
  writing NAME (Linux: when process PID no longer exists).

Examples:
  kreisel simulate spin.toml --output spin.csv
  kreisel simulate spin.toml --method rk4 | head
  kreisel simulate examples/scenes/heavy_top.toml
  kreisel simulate examples/scenes/heavy_top.toml --explain
  kreisel simulate examples/scenes/tippe_top.toml --columns t,z,energy,lz
  kreisel simulate examples/scenes/spin_up.toml --columns t,wz,lz,energy
  kreisel simulate examples/scenes/dzhanibekov.toml --output run.csv --plot run.png
  kreisel simulate examples/scenes/bouncing_ball.toml --events bounces.csv
  kreisel simulate examples/scenes/tippe_top_coulomb.toml --columns t,z,energy
  kreisel simulate --list-methods";

/// Arguments of `kreisel simulate`.
#[derive(Debug, Clone, clap::Args)]
#[command(after_long_help = AFTER_LONG_HELP)]
pub struct SimulateArgs {
    /// Scene file (TOML): simulation settings and bodies
    #[arg(value_name = "SCENE", required_unless_present = "list_methods")]
    pub scene: Option<PathBuf>,

    /// Write the CSV to FILE instead of standard output (replaced when the run ends, or stops at an event: then up to it; see Errors)
    #[arg(long, value_name = "FILE")]
    pub output: Option<PathBuf>,

    /// Integration method, overriding the scene's `method` (see --list-methods)
    #[arg(long, value_name = "NAME")]
    pub method: Option<String>,

    /// List the integration methods with their order and exit
    #[arg(long)]
    pub list_methods: bool,

    /// Print each body's plan (what it is, which method, why) and exit without running
    #[arg(long)]
    pub explain: bool,

    /// Write only these CSV columns, comma-separated, in this order (see below; adds x,y,z,vx,vy,vz)
    #[arg(long, value_name = "LIST")]
    pub columns: Option<String>,

    /// Threads moving the bodies, N >= 1 (default: all cores); the output does not depend on N
    #[arg(long, value_name = "N")]
    pub threads: Option<usize>,

    /// Also draw omega(t), the energy change and the polhode of each body into FILE (.png or .svg)
    #[arg(long, value_name = "FILE")]
    pub plot: Option<PathBuf>,

    /// Also write the events of the bodies on the table (impacts, lift-offs, stick, slip, rest) to FILE as CSV
    #[arg(long, value_name = "FILE")]
    pub events: Option<PathBuf>,
}

/// Runs `kreisel simulate`.
///
/// # Errors
/// A [`CliError`] for an unreadable or invalid scene, an unknown method, an
/// output file that cannot be created, or an I/O error while writing. Rows
/// written before a write error stay written.
pub fn run(args: &SimulateArgs) -> Result<(), CliError> {
    let scene_path = match (&args.scene, args.list_methods) {
        (Some(path), false) => path,
        // clap requires SCENE unless --list-methods.
        _ => return list_methods(),
    };
    // Parsed once, here; a bad --method is reported before the scene is even read.
    let method = args.method.as_deref().map(methods::parse).transpose()?;
    let columns = match &args.columns {
        Some(list) => Column::parse_list(list).map_err(|message| CliError::Argument {
            argument: "--columns".to_owned(),
            message,
        })?,
        None => Column::default_columns(),
    };
    let threads = match args.threads {
        Some(n) => NonZeroUsize::new(n).ok_or_else(|| CliError::Argument {
            argument: "--threads".to_owned(),
            message: "must be at least 1".to_owned(),
        })?,
        None => std::thread::available_parallelism().unwrap_or(NonZeroUsize::MIN),
    };
    let plot_format = match &args.plot {
        Some(plot) => Some(check_plot(plot, scene_path, args.output.as_deref())?),
        None => None,
    };
    if let Some(events) = &args.events {
        let others = [
            Some(scene_path.as_path()),
            args.output.as_deref(),
            args.plot.as_deref(),
        ];
        if others
            .into_iter()
            .flatten()
            .any(|other| same_file(events, other))
        {
            return Err(CliError::Argument {
                argument: "--events".to_owned(),
                message: format!(
                    "{}: is the scene, the --output or the --plot file; refusing to overwrite it",
                    events.display()
                ),
            });
        }
    }
    let text =
        kreisel_inertia::io::read_limited_text(scene_path, "a scene file").map_err(|source| {
            SceneError::ReadScene {
                path: scene_path.clone(),
                source,
            }
        })?;
    let (mut scene, method) = prepare(scene_path, &text, method)?;
    if args.explain {
        return explain(&scene);
    }
    warn_step_limits(&scene, scene_path);
    scene.world.set_threads(threads);
    let (writer, output, pending) =
        crate::output::open_output(args.output.as_deref(), Some(scene_path))?;
    // The image file is opened before the run, so a bad path fails at once.
    let plot = match (&args.plot, plot_format) {
        (Some(path), Some(format)) => {
            let (file, pending) =
                crate::output::atomic_file::create(path).map_err(|source| CliError::Plot {
                    path: path.clone(),
                    message: format!("cannot create the file: {source}"),
                })?;
            Some((path, format, file, pending))
        }
        _ => None,
    };
    // Opened before the run too; written when the run ends (or stops at an event).
    let events_file = match &args.events {
        Some(path) => {
            let (file, pending) = crate::output::atomic_file::create(path)
                .map_err(|source| events_error(path, &source))?;
            Some((path, file, pending))
        }
        None => None,
    };
    let mut recorder = plot
        .as_ref()
        .map(|_| record::Recorder::new(&scene.world, &scene.bodies));
    let mut progress = Progress::new(
        scene.schedule.steps(),
        Progress::wanted(output == Stream::Standard),
    );
    let mut csv = CsvWriter::with_columns(BufWriter::with_capacity(BUFFER_BYTES, writer), columns)
        .map_err(|source| write_error(&output, source))?;
    let enabled = progress.enabled();
    let mut report = |done| progress.update(done);
    let watcher = enabled.then_some(Watcher {
        every: progress::CHECK_EVERY,
        done: &mut report,
    });
    let simulated = run_scene(
        &mut scene,
        &mut |states, bodies| {
            if let Some(recorder) = recorder.as_mut() {
                recorder.record(states);
            }
            csv.rows(states, bodies)
        },
        watcher,
    );
    progress.finish();
    // The rows written before a divergence are valid: flushed either way.
    let flushed = csv.flush();
    drop(csv);
    // A run that stops at a physical event keeps its rows and its figure
    // up to the event; any other failure writes nothing (the pending files
    // are dropped: an existing --output or --plot file stays as it was).
    let stopped = match simulated {
        Ok(()) => None,
        Err(Stop::Rows(source)) => return Err(write_error(&output, source)),
        Err(Stop::Body(stop)) if stop.is_event(&scene) => Some(stop),
        Err(Stop::Body(stop)) => return Err(stop.into_error(&scene, scene_path, method).into()),
    };
    flushed.map_err(|source| write_error(&output, source))?;
    // The image is drawn before the CSV is put in place: a figure that
    // cannot be written leaves neither.
    let image = match (plot, recorder) {
        (Some((path, format, file, pending)), Some(recorder)) => {
            let scene_name = scene_path.file_name().unwrap_or(scene_path.as_os_str());
            let mut title = format!(
                "kreisel simulate {} (method {method})",
                std::path::Path::new(scene_name).display()
            );
            if stopped.is_some() {
                title.push_str(", stopped at an event");
            }
            let (tracks, recorded) = recorder.finish();
            let bytes = format
                .render(&figure::figure(&title, &tracks, recorded))
                .map_err(|e| CliError::Plot {
                    path: path.clone(),
                    message: e.to_string(),
                })?;
            let mut file = file;
            file.write_all(&bytes)
                .and_then(|()| file.flush())
                .map_err(|source| CliError::Plot {
                    path: path.clone(),
                    message: format!("cannot write the file: {source}"),
                })?;
            Some((path, pending))
        }
        _ => None,
    };
    let events_written = match events_file {
        Some((path, file, pending)) => {
            let mut out = BufWriter::new(file);
            events::write(&scene.world, &scene.bodies, &mut out)
                .and_then(|()| out.flush())
                .map_err(|source| events_error(path, &source))?;
            Some((path, pending))
        }
        None => None,
    };
    // Whole or not at all: the --output file appears only now.
    crate::output::commit_output(pending, output.clone())?;
    if let Some((path, pending)) = events_written {
        pending
            .commit()
            .map_err(|source| events_error(path, &source))?;
    }
    if let Some((path, pending)) = image {
        pending.commit().map_err(|source| CliError::Plot {
            path: path.clone(),
            message: format!("cannot write the file: {source}"),
        })?;
    }
    match stopped {
        None => Ok(()),
        Some(stop) => Err(stop.into_error(&scene, scene_path, method).into()),
    }
}

/// Writes each body's plan, `NAME: plan`, to standard output.
fn explain(scene: &Scene) -> Result<(), CliError> {
    let mut out = io::stdout().lock();
    write_plans(scene, &mut out)
        .and_then(|()| out.flush())
        .map_err(|source| write_error(&Stream::Standard, source))
}

/// One line per body, `NAME: plan`, in scene order.
///
/// # Errors
/// The writer's errors.
fn write_plans<W: Write + ?Sized>(scene: &Scene, out: &mut W) -> io::Result<()> {
    for (name, id) in &scene.bodies {
        if let Some(plan) = scene.world.plan(*id) {
            write!(out, "{name}: {plan}")?;
            if let Some(choice) = scene.world.choice(*id) {
                write!(out, "; {choice}")?;
            }
            if let Some(limit) = methods::StepLimit::of(&scene.world, *id) {
                write!(out, "; {}", limit.explain())?;
            }
            if let Plan::OnTable { .. } = plan {
                let tol = table_tolerance(scene.world.tolerance());
                write!(out, "; rtol = atol = {:.2e}", tol.rtol())?;
            }
            writeln!(out)?;
        }
    }
    Ok(())
}

/// One warning line on standard error per body whose stepping method runs
/// beyond its step limit (`dt ω_max`, [`methods::StepLimit`]): its rows
/// are then no longer the body's motion, though the run goes on.
fn warn_step_limits(scene: &Scene, path: &std::path::Path) {
    let mut err = io::stderr().lock();
    for (name, id) in &scene.bodies {
        if let Some(limit) = methods::StepLimit::of(&scene.world, *id)
            && limit.exceeded()
        {
            let _ = writeln!(
                err,
                "kreisel: warning: {}: body `{name}`: {}",
                path.display(),
                limit.warning(scene.world.dt())
            );
        }
    }
}

/// Writes the method list to standard output.
fn list_methods() -> Result<(), CliError> {
    let mut out = io::stdout().lock();
    methods::write_list(&mut out)
        .and_then(|()| out.flush())
        .map_err(|source| write_error(&Stream::Standard, source))
}

/// The image format of `--plot PLOT`, a path that is neither the scene nor
/// the `--output` file.
///
/// # Errors
/// [`CliError::Argument`] for an unknown extension or a file that must
/// not be overwritten.
fn check_plot(
    plot: &std::path::Path,
    scene: &std::path::Path,
    output: Option<&std::path::Path>,
) -> Result<kreisel_plot::ImageFormat, CliError> {
    let fail = |message: &str| CliError::Argument {
        argument: "--plot".to_owned(),
        message: format!("{}: {message}", plot.display()),
    };
    let format = kreisel_plot::ImageFormat::from_path(plot)
        .ok_or_else(|| fail("unknown image format (use a .svg or .png file name)"))?;
    if [Some(scene), output]
        .into_iter()
        .flatten()
        .any(|other| same_file(plot, other))
    {
        return Err(fail(
            "is the scene or the --output file; refusing to overwrite it",
        ));
    }
    Ok(format)
}

/// Whether `a` and `b` name the same file (the same path as written, or
/// the same existing file).
fn same_file(a: &std::path::Path, b: &std::path::Path) -> bool {
    a == b
        || matches!(
            (fs::canonicalize(a), fs::canonicalize(b)),
            (Ok(x), Ok(y)) if x == y
        )
}

/// The error of creating or writing the `--events` file `path`.
fn events_error(path: &std::path::Path, source: &io::Error) -> CliError {
    CliError::Argument {
        argument: "--events".to_owned(),
        message: format!("{}: cannot write the file: {source}", path.display()),
    }
}

/// The error of writing to `output`.
fn write_error(output: &Stream, source: io::Error) -> CliError {
    CliError::Write {
        output: output.clone(),
        source,
    }
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use kreisel_dynamics::FreeBodyMethod;

    use super::*;

    const SCENE: &str = "[simulation]\nduration = 1\ndt = 0.1\ngravity = [0, 0, -9.81]\n\
        [[body]]\nname = \"still\"\nmass = 1\ninertia = [1, 2, 3]\nangular_velocity = [0, 0, 0]\n\
        [[body]]\nname = \"ball\"\nmass = 1\ninertia = [2, 2, 2]\nangular_velocity = [1, 2, 3]\n\
        [[body]]\nname = \"disc\"\nmass = 1\ninertia = [1, 1, 2]\nangular_velocity = [0.1, 0, 1]\n\
        [[body]]\nname = \"handle\"\nmass = 1\ninertia = [1, 2, 3]\nangular_velocity = [0.01, 1, 0]\n\
        [[body]]\nname = \"top\"\nmass = 1\ninertia = [0.02, 0.02, 0.01]\nangular_velocity = [0, 0, 50]\npivot = [0, 0, -0.1]\n\
        [[body]]\nname = \"tippe\"\nmass = 0.006\ninertia = [8e-7, 8e-7, 7e-7]\nangular_velocity = [0, 0, 180]\n\
        [body.contact]\nshape = \"sphere\"\nradius = 0.015\ncenter = [0, 0, 0.003]\nfriction = \"viscous\"\nmu = 0.3\n";

    fn plans(method: Option<FreeBodyMethod>) -> Vec<String> {
        let scene =
            kreisel_scene::scene_file::parse_with_method(Path::new("s.toml"), SCENE, method)
                .unwrap();
        let mut out = Vec::new();
        write_plans(&scene, &mut out).unwrap();
        String::from_utf8(out)
            .unwrap()
            .lines()
            .map(str::to_owned)
            .collect()
    }

    #[test]
    fn explain_names_a_body_on_the_table_and_its_tolerance() {
        let ball = "[[body]]\nname = \"ball\"\nmass = 1\ninertia = [0.004, 0.004, 0.004]\n\
            angular_velocity = [0, 0, 0]\nposition = [0, 0, 1]\n[[body.contact]]\n\
            shape = \"sphere\"\nradius = 0.1\nfriction = \"coulomb\"\nmu = 0.3\n";
        for (tolerance, rtol) in [("", "1.00e-10"), ("tolerance = 1e-6\n", "1.00e-9")] {
            let text = format!(
                "[simulation]\nduration = 1\ndt = 0.1\ngravity = [0, 0, -9.81]\n{tolerance}{ball}"
            );
            let scene = kreisel_scene::scene_file::parse(Path::new("s.toml"), &text).unwrap();
            let mut out = Vec::new();
            write_plans(&scene, &mut out).unwrap();
            let line = String::from_utf8(out).unwrap();
            assert!(
                line.starts_with(
                    "ball: body on the table: event-driven dopri5 (order 5) with error control, \
                     its own steps within each dt (unilateral contact of 1 shape with the plane"
                ),
                "{line}"
            );
            assert!(
                line.ends_with(&format!("; rtol = atol = {rtol}\n")),
                "{line}"
            );
        }
    }

    #[test]
    fn explain_names_each_body_and_its_plan() {
        let lines = plans(None);
        let starts = [
            "still: resting free body: exact, nothing to compute",
            "ball: free sphere: exact, one uniform rotation",
            "disc: symmetric free body: exact, closed form",
            "handle: asymmetric free body: exact, Jacobi elliptic solution",
            "top: Lagrange top on a pivot: exact, closed form",
            "tippe: body on the ground: ground-top dopri5 (order 5), error-controlled steps at rtol 1e-11, atol 1e-11 within every dt, landing on it (contact with the plane z = 0, friction viscous",
        ];
        assert_eq!(lines.len(), starts.len());
        for (line, start) in lines.iter().zip(starts) {
            assert!(line.starts_with(start), "{line}");
        }
        // A stepping method chosen: every body is stepped by it.
        let lines = plans(Some(FreeBodyMethod::Rk4));
        assert!(
            lines[0].starts_with("still: free body stepped by rk4 (order 4)"),
            "{lines:?}"
        );
        assert!(
            lines[4].starts_with("top: heavy top on a pivot: rk4 (order 4)"),
            "{lines:?}"
        );
        // A body on the ground keeps its contact model's error control.
        assert!(
            lines[5].starts_with("tippe: body on the ground: ground-top dopri5"),
            "{lines:?}"
        );
    }

    #[test]
    fn help_names_the_methods_without_a_heavy_top_version() {
        let help: Vec<&str> = AFTER_LONG_HELP.split_whitespace().collect();
        let help = help.join(" ");
        let without = kreisel_dynamics::FreeBodyMethod::ALL
            .into_iter()
            .filter(|m| m.heavy_top().is_none())
            .map(kreisel_dynamics::FreeBodyMethod::name);
        // The help writes pdmv4 … pdmv10 as `pdmv*`.
        let mut listed: Vec<&str> = without.filter(|n| !n.starts_with("pdmv")).collect();
        listed.push("pdmv*");
        let (last, first) = listed.split_last().unwrap();
        let phrase = format!("{} and {last} have none", first.join(", "));
        assert!(help.contains(&phrase), "{phrase}");
    }
}
