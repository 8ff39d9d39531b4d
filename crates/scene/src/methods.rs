//! The integration methods for `--method`, the scene's `method` and
//! `--list-methods`: everything is read from the library's
//! [`FreeBodyMethod`] and [`HeavyTopMethod`] (names, orders, descriptions,
//! which methods have a heavy-top version), so the list cannot drift from
//! what the library runs. A method's name is parsed once, where the
//! user's text enters ([`parse`] for `--method` and Python's `method`, the
//! scene file's `method` key in [`crate::scene_file`]); from there on it is
//! a [`FreeBodyMethod`].

#![forbid(unsafe_code)]

use std::io::{self, Write};

use kreisel_dynamics::{BodyId, FreeBodyMethod, HeavyTopMethod, Plan, World};

use crate::error::{MethodProblem, SceneError};

/// The method the user named (`--method`, Python's `method`), parsed
/// where the text enters.
///
/// # Errors
/// [`SceneError::Method`] naming the method and listing the known ones.
///
/// ```
/// use kreisel_dynamics::FreeBodyMethod;
/// use kreisel_scene::methods::parse;
/// assert_eq!(parse("rk4").unwrap(), FreeBodyMethod::Rk4);
/// assert!(parse("x").unwrap_err().to_string().starts_with("--method: unknown method `x` (known: auto,"));
/// ```
pub fn parse(name: &str) -> Result<FreeBodyMethod, SceneError> {
    name.parse().map_err(|e| SceneError::Method {
        problem: MethodProblem::Unknown(e),
    })
}

/// The heavy-top method that `method` runs for bodies with a `pivot`
/// ([`FreeBodyMethod::heavy_top`]: the one of the same name).
///
/// # Errors
/// [`MethodProblem::NoHeavyTopVersion`] for a method with no heavy-top
/// version (its message lists the heavy-top ones).
///
/// ```
/// use kreisel_dynamics::{FreeBodyMethod, HeavyTopMethod};
/// use kreisel_scene::methods::heavy_top;
/// assert_eq!(heavy_top(FreeBodyMethod::Strang), Ok(HeavyTopMethod::Strang));
/// let e = heavy_top(FreeBodyMethod::Dmv).unwrap_err();
/// assert!(e.to_string().starts_with("method `dmv` cannot move"));
/// ```
pub fn heavy_top(method: FreeBodyMethod) -> Result<HeavyTopMethod, MethodProblem> {
    method
        .heavy_top()
        .ok_or(MethodProblem::NoHeavyTopVersion { method })
}

/// A free body stepped by a method with a step limit
/// ([`FreeBodyMethod::step_limit`]): the method, `dt ω_max` and the limit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepLimit {
    /// The method stepping the body.
    pub method: FreeBodyMethod,
    /// `dt ω_max` of the body ([`FreeBodyMethod::step_ratio`]).
    pub ratio: f64,
    /// The method's limit of it.
    pub limit: f64,
}

impl StepLimit {
    /// Body `id` of `world` when a stepping method with a limit moves it
    /// torque-free (`None` otherwise: exact plans, driven bodies, heavy
    /// tops, bodies on the ground).
    pub fn of(world: &World, id: BodyId) -> Option<Self> {
        let Some(Plan::Stepping(method)) = world.plan(id) else {
            return None;
        };
        let limit = method.step_limit()?;
        let moments = world.body(id)?.mass_properties().principal().moments;
        let l = world.state(id)?.l_world;
        Some(Self {
            method: *method,
            ratio: FreeBodyMethod::step_ratio(moments, l, world.dt()),
            limit,
        })
    }

    /// Whether `dt ω_max` is beyond the limit (or not a number).
    pub fn exceeded(&self) -> bool {
        self.ratio.is_nan() || self.ratio > self.limit
    }

    /// What `--explain` adds to the plan: `dt·ω_max = X (METHOD's step
    /// limit L)`.
    pub fn explain(&self) -> String {
        format!(
            "dt·ω_max = {:.3} ({}'s step limit {}{})",
            self.ratio,
            self.method,
            self.limit,
            if self.exceeded() { ": beyond it" } else { "" }
        )
    }

    /// The warning for a body beyond the limit, after `body `NAME`: `.
    pub fn warning(&self, dt: f64) -> String {
        format!(
            "dt·ω_max = {:.3} is beyond {}'s step limit {} (energy errors above {} % or \
             failed steps); use dt <= {:.2e} s or the default method ({})",
            self.ratio,
            self.method,
            self.limit,
            100.0 * kreisel_dynamics::STEP_LIMIT_ENERGY_ERROR,
            dt * self.limit / self.ratio,
            FreeBodyMethod::Auto
        )
    }
}

/// The order column: the order, or `exact` for no truncation error.
fn order(method: FreeBodyMethod) -> String {
    method
        .order()
        .map_or_else(|| "exact".to_owned(), |p| p.to_string())
}

/// Writes one line per method: name, order, description; `auto` first,
/// marked as the default; then the heavy-top methods.
///
/// # Errors
/// The writer's errors.
pub fn write_list<W: Write + ?Sized>(out: &mut W) -> io::Result<()> {
    writeln!(out, "{:<12}{:>5}  DESCRIPTION", "NAME", "ORDER")?;
    for m in FreeBodyMethod::ALL {
        writeln!(out, "{m:<12}{:>5}  {}", order(m), m.description())?;
    }
    writeln!(out, "\nBodies with a pivot (heavy top under gravity):")?;
    for m in HeavyTopMethod::ALL {
        writeln!(out, "{m:<12}{:>5}  {}", m.order(), m.description())?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn heavy_top_methods_resolve_and_the_others_are_refused() {
        for m in HeavyTopMethod::ALL {
            let free: FreeBodyMethod = m.name().parse().unwrap();
            assert_eq!(heavy_top(free), Ok(m));
        }
        for name in ["exact", "splitting", "dmv", "pdmv4", "pdmv10"] {
            assert_eq!(
                heavy_top(name.parse().unwrap()).unwrap_err().to_string(),
                format!(
                    "method `{name}` cannot move a body with a `pivot` (a heavy top); \
                     use one of auto, rk4, strang, splitting4, splitting6, splitting8"
                )
            );
        }
    }

    #[test]
    fn unknown_method_lists_the_known_ones() {
        assert_eq!(
            parse("euler").unwrap_err().to_string(),
            "--method: unknown method `euler` (known: auto, exact, rk4, strang, splitting, \
             splitting4, splitting6, splitting8, dmv, pdmv4, pdmv6, pdmv8, pdmv10)"
        );
    }

    #[test]
    fn list_has_a_line_per_method() {
        let mut out = Vec::new();
        write_list(&mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert_eq!(
            text.lines().count(),
            1 + FreeBodyMethod::ALL.len() + 2 + HeavyTopMethod::ALL.len()
        );
        assert!(text.contains(
            "splitting8      8  Kahan and Li's 17-stage symmetric composition of strang"
        ));
        assert!(text.contains(
            "auto        exact  the default; runs exact (no truncation error at any dt)\n"
        ));
        assert!(text.contains("rk4             4  classical"), "{text}");
        assert!(
            text.contains("pdmv10         10  Hairer and Vilmart's"),
            "{text}"
        );
    }
}
