//! A checked scene moved along its output grid: the method chosen once
//! ([`prepare`]), then the world advanced from row to row, every row's
//! states handed to the caller ([`run`], [`run_rows`]). Whatever writes
//! the rows (CSV, numpy arrays, a figure) is the caller's.

use std::convert::Infallible;
use std::path::Path;

use kreisel_dynamics::{BodyId, FreeBodyMethod, World};

use crate::columns::{self, States};
use crate::error::SceneError;
use crate::methods;
use crate::scene_file::{self, Scene};
use crate::stop::BodyStop;

/// The bodies' names and ids in scene order.
pub type Names = [(String, BodyId)];

/// Why a run stopped early: the rows' receiver failed (its error `E`), or
/// a body stopped it.
#[derive(Debug)]
pub enum Stop<E> {
    /// The receiver of the rows failed (a write error, for a writer).
    Rows(E),
    /// A body diverged, would write a number that is not finite, or met an
    /// event that ends what its model describes.
    Body(BodyStop),
}

impl<E> From<BodyStop> for Stop<E> {
    fn from(stop: BodyStop) -> Self {
        Stop::Body(stop)
    }
}

/// Someone watching a run: told the number of steps done every `every`
/// steps (a progress bar); without one the world goes from row to row in
/// one call.
pub struct Watcher<'a> {
    /// Steps between reports (at least 1).
    pub every: u64,
    /// Told the steps done.
    pub done: &'a mut dyn FnMut(u64),
}

/// The scene at `path` (whose text is `text`) parsed and checked, moved by
/// `method` if given (a user's override of the scene's `method`, parsed
/// where it was given: [`methods::parse`]): the scene and the method that
/// moves it.
///
/// # Errors
/// As [`scene_file::parse`]; [`SceneError::Method`] for a method without a
/// heavy-top version when a body has a pivot.
pub fn prepare(
    path: &Path,
    text: &str,
    method: Option<FreeBodyMethod>,
) -> Result<(Scene, FreeBodyMethod), SceneError> {
    let scene = scene_file::parse_with_method(path, text, method)?;
    let method = method.or(scene.method).unwrap_or_default();
    // Bodies with a pivot are heavy tops, moved by the heavy-top methods.
    if scene.has_pivot {
        methods::heavy_top(method).map_err(|problem| SceneError::Method { problem })?;
    }
    Ok((scene, method))
}

/// Moves a [`prepare`]d scene through its schedule, handing `rows` the
/// bodies' states at every time the output has rows for (with the bodies'
/// names and ids in scene order).
///
/// # Errors
/// The one-line error for a body that stopped the run (`path` names the
/// scene, `method` is the method [`prepare`] returned); the rows before it
/// have been handed over.
pub fn run_rows(
    scene: &mut Scene,
    path: &Path,
    method: FreeBodyMethod,
    rows: &mut dyn FnMut(&States, &Names),
) -> Result<(), SceneError> {
    let ran = run::<Infallible>(
        scene,
        &mut |states, bodies| {
            rows(states, bodies);
            Ok(())
        },
        None,
    );
    match ran {
        Ok(()) => Ok(()),
        Err(Stop::Rows(never)) => match never {},
        Err(Stop::Body(stop)) => Err(stop.into_error(scene, path, method)),
    }
}

/// Moves the world through the schedule, handing `rows` the bodies' states
/// at the rows it asks for: whole steps of `dt` up to each row before the
/// last, then the world is advanced to `duration`. The world checks every
/// state it reaches; a body whose state becomes non-finite or whose
/// invariants blow up stops the run before its row is handed over.
///
/// ```text
/// rows at t = 0, after every step k with writes_row(k), and at t = duration
/// ```
///
/// # Errors
/// [`Stop::Rows`] with the receiver's error; [`Stop::Body`] for the first
/// body that stopped the run.
pub fn run<E>(
    scene: &mut Scene,
    rows: &mut dyn FnMut(&States, &Names) -> Result<(), E>,
    mut watcher: Option<Watcher<'_>>,
) -> Result<(), Stop<E>> {
    let schedule = scene.schedule;
    let (world, bodies) = (&mut scene.world, &scene.bodies);
    // Each row's states are read once; the last guard: no row holds a
    // number that is not finite.
    let mut states = Vec::with_capacity(bodies.len());
    let mut rows = |world: &World, bodies: &Names| -> Result<(), Stop<E>> {
        columns::read_states(world, bodies, &mut states);
        if let Some((body, time, column)) = columns::first_non_finite(&states) {
            return Err(BodyStop::NonFinite { body, time, column }.into());
        }
        rows(&states, bodies).map_err(Stop::Rows)
    };
    let chunk = watcher.as_ref().map_or(u64::MAX, |w| w.every.max(1));
    let mut report = |done: u64| {
        if let Some(watcher) = watcher.as_mut() {
            (watcher.done)(done);
        }
    };
    rows(world, bodies)?;
    let steps = schedule.steps();
    let mut done = 0;
    while done < steps - 1 {
        // The next row before the last step, or the step before the last.
        let row = schedule.next_row(done).min(steps - 1);
        let target = row.min(done.saturating_add(chunk) / chunk * chunk);
        world
            .advance_steps(target - done)
            .map_err(BodyStop::from_world)?;
        done = target;
        report(done);
        if done == row && schedule.writes_row(done) {
            rows(world, bodies)?;
        }
    }
    world
        .advance_to(schedule.time(steps))
        .map_err(BodyStop::from_world)?;
    rows(world, bodies)?;
    report(steps);
    Ok(())
}
