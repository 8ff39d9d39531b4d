//! The scene file: TOML text → a checked [`Scene`], or one error naming the
//! file, the line and the key.
//!
//! serde reads the text into raw structs (unknown keys, missing keys and
//! wrong types are its errors, with toml's span of the offending key or
//! table); every value is kept with its span, so the checks that follow
//! (positive, finite, physical) can name the line too.

#![forbid(unsafe_code)]

use std::collections::HashSet;
use std::path::Path;

use glam::DVec3;
use kreisel_dynamics::{BodyId, FreeBodyMethod, Tolerance, World};
use serde::Deserialize;
use toml::Spanned;

use crate::body_keys::{RawBody, add_body};
use crate::error::SceneError;
use crate::methods;
use crate::numbers::Shortest;
use crate::scene_keys::{Keys, SceneFile};
use crate::schedule::{INTERVAL_TOLERANCE, MAX_STEPS, Schedule, ScheduleProblem};

/// The whole file as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawScene {
    simulation: Spanned<RawSimulation>,
    #[serde(default)]
    body: Vec<Spanned<RawBody>>,
}

/// The `[simulation]` table as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSimulation {
    duration: Spanned<f64>,
    dt: Spanned<f64>,
    method: Option<Spanned<String>>,
    output_interval: Option<Spanned<f64>>,
    gravity: Option<Spanned<[f64; 3]>>,
    tolerance: Option<Spanned<f64>>,
}

/// A checked scene, ready to run.
#[derive(Debug)]
pub struct Scene {
    /// The steps and the rows written.
    pub schedule: Schedule,
    /// The `method` key, parsed; `None` when not given.
    pub method: Option<FreeBodyMethod>,
    /// The bodies, their methods, gravity and `dt`.
    pub world: World,
    /// The bodies' names and ids in file order (distinct names).
    pub bodies: Vec<(String, BodyId)>,
    /// Whether some body has a pivot (is a heavy top).
    pub has_pivot: bool,
    /// The lines of each body's contact tables, in file order (empty for
    /// a body without `contact`): a touchdown names its table's line.
    pub contact_lines: Vec<Vec<u64>>,
    /// The lines of the `mu` keys of each body's contact tables, in file
    /// order (`None` where not given): Painlevé's case names its `mu`.
    pub mu_lines: Vec<Vec<Option<u64>>>,
    /// Each body's `steady` key (the steady motion `kreisel stability`
    /// analyses) and its line, in file order; `None` where not given.
    pub steady: Vec<Option<(String, u64)>>,
}

/// Reads and checks a scene and builds its world, moved by the scene's
/// `method`; mesh paths are relative to the scene's folder.
///
/// # Errors
/// [`SceneError::Scene`] for the first problem found, naming its line and key
/// when there is one. Mesh files are loaded here, so their errors too.
pub fn parse(path: &Path, text: &str) -> Result<Scene, SceneError> {
    parse_with_method(path, text, None)
}

/// As [`parse`], the world moved by method `override_method` if given
/// (`--method`) instead of the scene's `method`.
///
/// # Errors
/// As [`parse`].
pub fn parse_with_method(
    path: &Path,
    text: &str,
    override_method: Option<FreeBodyMethod>,
) -> Result<Scene, SceneError> {
    let file = SceneFile { path, text };
    let raw: RawScene =
        toml::from_str(text).map_err(|e| file.error(e.span(), &toml_message(&e)))?;
    let sim = raw.simulation.get_ref();
    let keys = Keys::new(file, String::new());
    let duration = keys.positive("duration", &sim.duration)?;
    let dt = keys.positive("dt", &sim.dt)?;
    let interval = match &sim.output_interval {
        Some(v) => Some(keys.positive("output_interval", v)?),
        None => None,
    };
    let schedule = Schedule::new(duration, dt, interval).map_err(|problem| match problem {
        ScheduleProblem::TooManySteps { ratio } => keys.fail(
            &sim.dt,
            &format!(
                "`duration` / `dt` = {} steps is more than the limit of {MAX_STEPS}; \
                 increase `dt` or shorten `duration`",
                Shortest(ratio.ceil())
            ),
        ),
        ScheduleProblem::IntervalNotMultiple { ratio } => keys.fail(
            sim.output_interval.as_ref().map_or(&sim.dt, |v| v),
            &format!(
                "`output_interval` must be a whole multiple of `dt` \
                 (within {INTERVAL_TOLERANCE:e} relative), but it is {} times `dt`",
                Shortest(ratio)
            ),
        ),
    })?;
    let method = match &sim.method {
        Some(name) => match name.get_ref().parse::<FreeBodyMethod>() {
            Ok(method) => Some(method),
            Err(e) => return Err(keys.fail(name, &format!("`method`: {e}"))),
        },
        None => None,
    };
    let gravity = match &sim.gravity {
        Some(g) => keys.vector("gravity", g)?,
        None => DVec3::ZERO,
    };
    if raw.body.is_empty() {
        let message = "the scene has no bodies: add a [[body]] table";
        return Err(file.error(None, message));
    }
    let folder = path.parent().unwrap_or(Path::new(""));
    let mut world = World::try_new(gravity, dt).map_err(|e| file.error(None, &e.to_string()))?;
    let free = override_method.or(method).unwrap_or_default();
    // A method without a heavy-top version is refused below if a body has
    // a pivot; until then the heavy-top default stands.
    let heavy = free.heavy_top().unwrap_or_default();
    let configured = world
        .set_free_body_method(free)
        .and_then(|()| world.set_heavy_top_method(heavy));
    configured.map_err(|e| file.error(None, &e.to_string()))?;
    if let Some(value) = &sim.tolerance {
        let attitude = keys.positive("tolerance", value)?;
        if free != FreeBodyMethod::Auto {
            let message = format!(
                "`tolerance` chooses the method itself, but the method is `{free}`: \
                 remove `method` (or --method) or `tolerance`"
            );
            return Err(keys.fail(value, &message));
        }
        // The states are read at the rows written: the exact solution is
        // evaluated only there.
        let tolerance = Tolerance::try_new(attitude, duration)
            .and_then(|t| t.try_reading_every(interval.unwrap_or(dt)))
            .and_then(|t| world.set_tolerance(Some(t)));
        tolerance.map_err(|e| keys.fail(value, &format!("`tolerance`: {e}")))?;
    }
    let mut bodies: Vec<(String, BodyId)> = Vec::with_capacity(raw.body.len());
    // A set, not a search of the bodies so far: 10⁵ bodies took 31 s that way.
    let mut names: HashSet<String> = HashSet::with_capacity(raw.body.len());
    let mut has_pivot = false;
    let mut contact_lines: Vec<Vec<u64>> = Vec::with_capacity(raw.body.len());
    let mut mu_lines: Vec<Vec<Option<u64>>> = Vec::with_capacity(raw.body.len());
    let mut steady: Vec<Option<(String, u64)>> = Vec::with_capacity(raw.body.len());
    let down = gravity.x == 0.0 && gravity.y == 0.0 && gravity.z < 0.0;
    for (n, raw_body) in raw.body.iter().enumerate() {
        if let Some(contact) = raw_body.get_ref().contact_span()
            && !down
        {
            let message = "a body with `contact` stands on the ground plane z = 0: \
                           `gravity` must be [0, 0, -g] with g > 0";
            return Err(match &sim.gravity {
                Some(g) => keys.fail(g, message),
                None => file.error(
                    Some(contact),
                    &format!("{message} (it is missing: no gravity)"),
                ),
            });
        }
        let (name, id) = add_body(file, raw_body, n + 1, folder, &mut world)?;
        if !world.stays_finite(id, duration) {
            let message = format!(
                "body `{name}`: its energy or the motion of its centre of mass overflows \
                 within the run (position, velocity, gravity, mass or duration too large)"
            );
            return Err(file.error(Some(raw_body.span()), &message));
        }
        if !names.insert(name.clone()) {
            let span = raw_body.get_ref().name_span().unwrap_or(raw_body.span());
            let message = format!("body name `{name}` is used twice; names must differ");
            return Err(file.error(Some(span), &message));
        }
        has_pivot |= raw_body.get_ref().has_pivot();
        bodies.push((name, id));
        steady.push(
            raw_body
                .get_ref()
                .steady()
                .map(|(kind, span)| (kind.to_owned(), file.line_of(span.start))),
        );
        let spans = raw_body.get_ref().contact_spans();
        contact_lines.push(spans.into_iter().map(|s| file.line_of(s.start)).collect());
        let mu = raw_body.get_ref().mu_spans();
        mu_lines.push(
            mu.into_iter()
                .map(|s| s.map(|s| file.line_of(s.start)))
                .collect(),
        );
    }
    if let Some(key) = &sim.method
        && let Some(method) = method
        && has_pivot
    {
        methods::heavy_top(method)
            .map_err(|problem| keys.fail(key, &format!("`method`: {problem}")))?;
    }
    Ok(Scene {
        schedule,
        method,
        world,
        bodies,
        has_pivot,
        contact_lines,
        mu_lines,
        steady,
    })
}

/// toml's message, prefixed with the dotted key it concerns when toml
/// knows it (`body.mass`: invalid type: …).
fn toml_message(error: &toml::de::Error) -> String {
    // Without the input, toml's Display appends the key path as "in `a.b`".
    let mut bare = error.clone();
    bare.set_input(None);
    let shown = bare.to_string();
    let key = shown
        .lines()
        .find_map(|line| line.strip_prefix("in `")?.strip_suffix('`'));
    let message = error.message();
    match key {
        Some("body") if message.starts_with("invalid type: map") => {
            format!("`body`: {message}: write [[body]], one table per body")
        }
        Some(key) if !key.is_empty() => format!("`{key}`: {message}"),
        _ => message.to_owned(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn error(text: &str) -> String {
        match parse(Path::new("s.toml"), text) {
            Ok(_) => panic!("accepted:\n{text}"),
            Err(e) => e.to_string(),
        }
    }

    const SIM: &str = "[simulation]\nduration = 1.0\ndt = 0.1\n";

    #[test]
    fn reads_a_minimal_scene() {
        let text =
            format!("{SIM}[[body]]\nmass = 1\ninertia = [1, 2, 3]\nangular_velocity = [0, 1, 0]\n");
        let scene = parse(Path::new("s.toml"), &text).unwrap();
        assert_eq!(scene.schedule.steps(), 10);
        assert_eq!((scene.method, scene.world.gravity()), (None, DVec3::ZERO));
        assert_eq!(scene.bodies[0].0, "body1");
    }

    #[test]
    fn errors_name_line_and_key() {
        let e = error("[simulation]\nduration = 1.0\ndt = 0.1\nspeed = 2\n");
        assert!(
            e.starts_with("s.toml:4: `simulation`: unknown field `speed`"),
            "{e}"
        );
        let e = error("[simulation]\nduration = 1.0\ndt = -0.1\n");
        assert_eq!(e, "s.toml:3: `dt` must be positive and finite, got -0.1");
        let e = error("[simulation]\nduration = 1.0\ndt = 0.1\nmethod = \"euler\"\n");
        assert!(
            e.starts_with("s.toml:4: `method`: unknown method `euler` (known: auto,"),
            "{e}"
        );
        let e = error(SIM);
        assert_eq!(e, "s.toml: the scene has no bodies: add a [[body]] table");
        let e = error("[simulation]\nduration = 1e10\ndt = 1\n");
        assert!(
            e.starts_with("s.toml:3: `duration` / `dt` = 10000000000 steps"),
            "{e}"
        );
        let e = error("[simulation]\nduration = 1\ndt = 0.1\noutput_interval = 0.25\n");
        assert!(
            e.starts_with("s.toml:4: `output_interval` must be a whole multiple"),
            "{e}"
        );
    }

    #[test]
    fn overflowing_ballistics_are_refused() {
        let body = "[[body]]\nmass = 1\ninertia = [1, 1, 1]\nangular_velocity = [0, 0, 1]\n";
        let e = error(&format!("{SIM}{body}velocity = [1e200, 0, 0]\n"));
        assert!(e.starts_with("s.toml:4: body `body1`: its energy"), "{e}");
        let e = error(&format!(
            "{SIM}gravity = [0, 0, -1e300]\n{body}position = [0, 0, 1e300]\n"
        ));
        assert!(e.contains("overflows within the run"), "{e}");
    }

    #[test]
    fn key_problems_are_typed() {
        use crate::body_key::BodyKeyProblem;
        use crate::contact_key::{ContactKey, ContactKeyProblem, Needs};
        use crate::error::KeyProblem;
        let typed = |text: &str| match parse(Path::new("s.toml"), text) {
            Err(SceneError::Key {
                line,
                body,
                problem,
                message,
                ..
            }) => (line, body, *problem, message),
            other => panic!("not a key problem: {other:?}"),
        };
        let body = "[[body]]\nname = \"top\"\nmass = 1\ninertia = [1, 1, 1]\nangular_velocity = [0, 0, 1]\n";
        let (line, name, problem, message) = typed(&format!("{SIM}{body}angular_damping = -2\n"));
        assert_eq!((line, name.as_str()), (9, "top"));
        assert_eq!(
            problem,
            KeyProblem::Body(BodyKeyProblem::Damping { value: -2.0 })
        );
        assert!(
            message.starts_with("body `top`: `angular_damping`"),
            "{message}"
        );
        let contact =
            "[[body.contact]]\nshape = \"sphere\"\nradius = 0.1\nfriction = \"sliding\"\n";
        let (line, _, problem, _) =
            typed(&format!("{SIM}gravity = [0, 0, -9.81]\n{body}{contact}"));
        let missing = ContactKeyProblem::Missing {
            key: ContactKey::Mu,
            needs: Needs::Coefficient {
                friction: crate::contact_key::FrictionName::Ground(
                    kreisel_dynamics::FrictionModel::Sliding,
                ),
            },
        };
        assert_eq!(line, 13, "at the friction key");
        let contact = KeyProblem::Contact {
            contact: Some(0),
            problem: missing,
        };
        assert_eq!(problem, contact);
        let (_, _, problem, _) = typed(&format!(
            "{SIM}{body}pivot = [0, 0, 0]\nvelocity = [1, 0, 0]\n"
        ));
        assert_eq!(problem, KeyProblem::Body(BodyKeyProblem::VelocityWithPivot));
    }

    #[test]
    fn body_names_must_differ() {
        let body =
            "[[body]]\nname = \"a\"\nmass = 1\ninertia = [1, 1, 1]\nangular_velocity = [0, 0, 1]\n";
        let e = error(&format!("{SIM}{body}{body}"));
        assert!(
            e.starts_with("s.toml:10: body name `a` is used twice"),
            "{e}"
        );
    }
}
