//! The integration methods by name, for `--method`, the scene's `method`
//! and `--list-methods`: everything is read from the library's
//! [`FreeBodyMethod`] and [`HeavyTopMethod`] (names, orders, descriptions,
//! which methods have a heavy-top version), so the list cannot drift from
//! what the library runs.

#![forbid(unsafe_code)]

use std::io::{self, Write};

use kreisel_dynamics::{FreeBodyIntegrator, FreeBodyMethod, HeavyTopIntegrator, HeavyTopMethod};

/// The name that stands for the recommended method (the default).
pub const AUTO: &str = FreeBodyMethod::Auto.name();

/// The integrator called `name` (`auto` runs what
/// [`FreeBodyMethod::resolve`] says: the exact solution).
///
/// # Errors
/// A message naming the method and listing the known ones.
pub fn integrator(name: &str) -> Result<Box<dyn FreeBodyIntegrator>, String> {
    name.parse::<FreeBodyMethod>()
        .map(FreeBodyMethod::integrator)
        .map_err(|e| e.to_string())
}

/// The heavy-top integrator that the method called `name` runs for bodies
/// with a `pivot` ([`FreeBodyMethod::heavy_top`]: the one of the same
/// name).
///
/// # Errors
/// A message naming the method and listing the heavy-top ones, for a
/// method with no heavy-top version (or no method at all).
pub fn heavy_top_integrator(name: &str) -> Result<Box<dyn HeavyTopIntegrator>, String> {
    name.parse::<FreeBodyMethod>()
        .ok()
        .and_then(FreeBodyMethod::heavy_top)
        .map(HeavyTopMethod::integrator)
        .ok_or_else(|| {
            format!(
                "method `{name}` cannot move a body with a `pivot` (a heavy top); use one of {}",
                HeavyTopMethod::ALL.map(HeavyTopMethod::name).join(", ")
            )
        })
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
    fn every_method_resolves_to_what_it_runs() {
        for m in FreeBodyMethod::ALL {
            assert_eq!(integrator(m.name()).unwrap().name(), m.resolve().name());
        }
        assert_eq!(integrator(AUTO).unwrap().name(), "exact");
    }

    #[test]
    fn heavy_top_methods_resolve_and_the_others_are_refused() {
        for m in HeavyTopMethod::ALL {
            assert_eq!(heavy_top_integrator(m.name()).unwrap().name(), m.name());
        }
        for name in ["exact", "splitting", "dmv", "pdmv4", "pdmv10", "euler"] {
            assert_eq!(
                heavy_top_integrator(name).err().unwrap(),
                format!(
                    "method `{name}` cannot move a body with a `pivot` (a heavy top); \
                     use one of auto, rk4, strang, splitting4, splitting6, splitting8"
                )
            );
        }
    }

    #[test]
    fn help_names_the_methods_without_a_heavy_top_version() {
        let help: Vec<&str> = super::super::AFTER_LONG_HELP.split_whitespace().collect();
        let help = help.join(" ");
        let without = FreeBodyMethod::ALL
            .into_iter()
            .filter(|m| m.heavy_top().is_none())
            .map(FreeBodyMethod::name);
        // The help writes pdmv4 … pdmv10 as `pdmv*`.
        let mut listed: Vec<&str> = without.filter(|n| !n.starts_with("pdmv")).collect();
        listed.push("pdmv*");
        let (last, first) = listed.split_last().unwrap();
        let phrase = format!("{} and {last} have none", first.join(", "));
        assert!(help.contains(&phrase), "{phrase}");
    }

    #[test]
    fn unknown_method_lists_the_known_ones() {
        assert_eq!(
            integrator("euler").err().unwrap(),
            "unknown method `euler` (known: auto, exact, rk4, strang, splitting, splitting4, \
             splitting6, splitting8, dmv, pdmv4, pdmv6, pdmv8, pdmv10)"
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
