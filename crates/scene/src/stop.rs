//! Why a body stopped a run before the end, and the one line that says
//! so: a body that diverged or whose row would not be finite, or a
//! physical event that ends what the model describes.

use std::path::Path;

use kreisel_dynamics::{ContactMode, DynamicsError, FreeBodyMethod, Plan};

use crate::error::SceneError;
use crate::numbers::Shortest;
use crate::scene_file::Scene;

/// Why a body stopped the run early.
#[derive(Debug)]
pub enum BodyStop {
    /// A row of body number `body` (0-based) at `time` would hold a
    /// number that is not finite in `column` (the last guard before a
    /// row is written; the library's checks should have stopped it).
    NonFinite {
        /// The body's number in scene order.
        body: usize,
        /// The row's time, s.
        time: f64,
        /// The column's name.
        column: &'static str,
    },
    /// Body number `body` (0-based) diverged or its method refused a step.
    Diverged {
        /// The body's number in scene order.
        body: usize,
        /// The end of the step that failed, s.
        time: f64,
        /// The library's error.
        error: kreisel_dynamics::DynamicsError,
    },
}

impl BodyStop {
    /// Whether the run stopped at a physical event that ends what the
    /// model describes (a watched contact touching down, lift-off, a disk
    /// lying flat, an indeterminate contact; on the table: contact modes
    /// that chatter, an impact the law cannot resolve without gaining
    /// energy): the rows before it are the motion up to the event. A
    /// divergence, a refused step or a number that is not finite is no
    /// event: the run failed. Neither is Painlevé's case on the table
    /// (an indeterminate contact of a body of `scene` on the table): its
    /// `mu` is beyond the bound of the slip, bad input, and nothing is
    /// written.
    pub fn is_event(&self, scene: &Scene) -> bool {
        if let BodyStop::Diverged {
            body,
            error: DynamicsError::ContactIndeterminate { .. },
            ..
        } = self
            && Failed::of(scene, *body, f64::NAN).on_table
        {
            return false;
        }
        matches!(
            self,
            BodyStop::Diverged {
                error: DynamicsError::ContactTouchdown { .. }
                    | DynamicsError::ContactLost { .. }
                    | DynamicsError::DiskFlat { .. }
                    | DynamicsError::ContactIndeterminate { .. }
                    | DynamicsError::ContactModesChatter { .. }
                    | DynamicsError::ImpactGainsEnergy { .. },
                ..
            }
        )
    }

    /// The one-line error of a run of `scene` (at `path`, moved by
    /// `method`) that stopped.
    pub fn into_error(self, scene: &Scene, path: &Path, method: FreeBodyMethod) -> SceneError {
        match self {
            BodyStop::Diverged { body, time, error } => {
                painleve_on_table(scene, path, body, &error).unwrap_or_else(|| {
                    diverged(path, &Failed::of(scene, body, time), &error, method)
                })
            }
            BodyStop::NonFinite { body, time, column } => SceneError::Scene {
                path: path.to_owned(),
                line: None,
                message: format!(
                    "body `{}`: its {column} is no longer finite at t = {} s; \
                     no row holds it",
                    Failed::of(scene, body, time).body,
                    Shortest(time)
                ),
            },
        }
    }

    /// The world's error: which body failed, when, and why.
    pub fn from_world(error: DynamicsError) -> Self {
        match error {
            DynamicsError::BodyFailed { body, time, source } => BodyStop::Diverged {
                body,
                time,
                error: *source,
            },
            other => BodyStop::Diverged {
                body: 0,
                time: f64::NAN,
                error: other,
            },
        }
    }
}

/// The body whose step failed: its name, the lines of its contact
/// tables, whether it is on the table, and the end of the step that
/// failed, s.
struct Failed<'a> {
    body: &'a str,
    contact_lines: &'a [u64],
    on_table: bool,
    time: f64,
}

impl<'a> Failed<'a> {
    /// Body number `body` (0-based, scene order) of `scene`, failed at `time`.
    fn of(scene: &'a Scene, body: usize, time: f64) -> Self {
        Self {
            body: scene
                .bodies
                .get(body)
                .map_or("?", |(name, _)| name.as_str()),
            contact_lines: scene.contact_lines.get(body).map_or(&[], Vec::as_slice),
            on_table: scene
                .bodies
                .get(body)
                .is_some_and(|(_, id)| matches!(scene.world.plan(*id), Some(Plan::OnTable { .. }))),
            time,
        }
    }
}

/// Painlevé's case of body number `body` (0-based) of `scene` on the
/// table, at `path`: one line at the `mu` key of the contact that slips
/// (the first one, else the first closed one), naming the body; `None`
/// for any other error or body.
fn painleve_on_table(
    scene: &Scene,
    path: &Path,
    body: usize,
    error: &DynamicsError,
) -> Option<SceneError> {
    if !matches!(error, DynamicsError::ContactIndeterminate { .. }) {
        return None;
    }
    let (name, id) = scene.bodies.get(body)?;
    let run = scene.world.table_motion(*id)?;
    let modes = run.modes();
    let index = modes
        .iter()
        .position(|m| *m == ContactMode::Slipping)
        .or_else(|| modes.iter().position(|m| *m != ContactMode::Open))
        .unwrap_or(0);
    let mu = run
        .body()
        .contacts()
        .get(index)
        .map_or(f64::NAN, |c| c.law.mu());
    let line = scene
        .mu_lines
        .get(body)
        .and_then(|lines| lines.get(index).copied().flatten())
        .or_else(|| scene.contact_lines.get(body)?.get(index).copied());
    Some(SceneError::Scene {
        path: path.to_owned(),
        line,
        message: format!(
            "body `{name}`: {}",
            crate::contact_keys::painleve_message(index, mu, error)
        ),
    })
}

/// The one line for a body whose run diverged: the scene, the body, the
/// time, the method, and what to try instead; for a watched contact that
/// touches down, its table's line, its time and approach speed.
fn diverged(
    scene_path: &std::path::Path,
    failed: &Failed<'_>,
    error: &kreisel_dynamics::DynamicsError,
    method: FreeBodyMethod,
) -> SceneError {
    let Failed {
        body,
        contact_lines,
        on_table,
        time,
    } = *failed;
    if on_table {
        // Its own steps, whatever dt: the error says what and when.
        return SceneError::Scene {
            path: scene_path.to_owned(),
            line: None,
            message: format!(
                "body `{body}`: on the table: {error}; the run stops there (dt is only the grid \
                 of the rows and does not change the motion; `tolerance` sets its steps)"
            ),
        };
    }
    if let DynamicsError::ContactTouchdown {
        time,
        contact,
        approach_speed,
    } = error
    {
        // The watched shapes are the tables after the first.
        return SceneError::Scene {
            path: scene_path.to_owned(),
            line: contact_lines.get(contact + 1).copied(),
            message: format!(
                "body `{body}`: [[body.contact]] #{} touches down at t = {} s (approach speed \
                 {} m/s): the impact is not modelled; the run stops there",
                contact + 2,
                Shortest(*time),
                Shortest(*approach_speed)
            ),
        };
    }
    let overflow = matches!(
        error,
        DynamicsError::Diverged {
            reason: kreisel_dynamics::Divergence::Overflow { .. },
            ..
        }
    );
    let hint = if overflow {
        // No step size helps: the numbers outgrow f64.
        "the scene's torques, forces or speeds are too large for f64".to_owned()
    } else if method == FreeBodyMethod::Auto {
        "use a smaller dt".to_owned()
    } else {
        format!(
            "use a smaller dt or the default method ({})",
            FreeBodyMethod::Auto
        )
    };
    let message = match error {
        DynamicsError::Diverged {
            method: used,
            time,
            reason,
        } => format!(
            "body `{body}`: method {used} diverged at t = {} s ({reason}); {hint}",
            Shortest(*time)
        ),
        // Its message says when, what drifted and what to change.
        DynamicsError::GroundCheckFailed { .. } => format!("body `{body}`: {error}"),
        DynamicsError::ContactLost { .. }
        | DynamicsError::DiskFlat { .. }
        | DynamicsError::ContactIndeterminate { .. } => format!(
            "body `{body}`: {error}: the run stops there (a body on the ground keeps one \
             contact with the plane; what follows is not modelled)"
        ),
        other => format!(
            "body `{body}`: the step to t = {} s failed: {other}; {hint}",
            Shortest(time)
        ),
    };
    SceneError::Scene {
        path: scene_path.to_owned(),
        line: None,
        message,
    }
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use super::*;

    /// A ball on the table, its `mu` on line 14.
    const BALL_ON_TABLE: &str = "[simulation]\nduration = 1\ndt = 0.1\ngravity = [0, 0, -9.81]\n\
        [[body]]\nname = \"ball\"\nmass = 1\ninertia = [0.004, 0.004, 0.004]\n\
        angular_velocity = [0, 0, 0]\n[[body.contact]]\nshape = \"sphere\"\nradius = 0.1\n\
        friction = \"coulomb\"\nmu = 0.3\n";

    /// A body on the table whose modes chatter: an event (the rows before
    /// it kept), one line naming the body and the library's error, and no
    /// advice to shrink dt (which does not change its motion).
    #[test]
    fn a_failure_on_the_table_is_named_without_the_dt_hint() {
        let path = Path::new("s.toml");
        let scene = crate::scene_file::parse(path, BALL_ON_TABLE).unwrap();
        let error = DynamicsError::ContactModesChatter {
            time: 0.25,
            count: 65,
        };
        let stop = BodyStop::from_world(DynamicsError::BodyFailed {
            body: 0,
            time: 0.3,
            source: Box::new(error.clone()),
        });
        assert!(stop.is_event(&scene));
        let message = stop
            .into_error(&scene, path, FreeBodyMethod::Auto)
            .to_string();
        assert_eq!(
            message,
            format!(
                "s.toml: body `ball`: on the table: {error}; the run stops there (dt is only the \
                 grid of the rows and does not change the motion; `tolerance` sets its steps)"
            )
        );
        assert!(!message.contains("smaller dt"));
    }

    /// Painlevé's case reached during a run (the table's
    /// `ContactIndeterminate` at t > 0): one line at the slipping
    /// contact's `mu`, naming the body and the time.
    #[test]
    fn a_painleve_case_during_the_run_names_the_slipping_mu() {
        let path = Path::new("s.toml");
        let scene = crate::scene_file::parse(path, BALL_ON_TABLE).unwrap();
        let error = DynamicsError::ContactIndeterminate {
            time: 0.25,
            compliance: -2.5,
        };
        let stop = BodyStop::from_world(DynamicsError::BodyFailed {
            body: 0,
            time: 0.3,
            source: Box::new(error),
        });
        let message = stop
            .into_error(&scene, path, FreeBodyMethod::Auto)
            .to_string();
        assert!(
            message.starts_with(
                "s.toml:14: body `ball`: `contact.mu` = 0.3 of [[body.contact]] #1 is beyond the \
                 Painlevé bound of its slip (the contact is indeterminate at t = 0.25 s"
            ),
            "{message}"
        );
    }
}
