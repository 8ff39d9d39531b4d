//! The integration methods by name: `auto`, the library's registry, and a
//! one-line description of each for `--list-methods`.

#![forbid(unsafe_code)]

use std::io::{self, Write};

use kreisel_dynamics::{
    FreeBodyIntegrator, HEAVY_TOP_METHODS, HeavyTopIntegrator, METHODS, heavy_top_method, method,
};

/// The name that stands for the recommended method (the default).
pub const AUTO: &str = "auto";

/// What `auto` runs: the library's choice (`kreisel_dynamics::AUTO`, the
/// exact solution).
pub const DEFAULT_METHOD: &str = kreisel_dynamics::AUTO;

/// One line about each method of the registry, shown by `--list-methods`.
const DESCRIPTIONS: [(&str, &str); 12] = [
    (
        "exact",
        "the exact solution: uniform rotation, symmetric-top closed form, or Jacobi elliptic functions",
    ),
    (
        "rk4",
        "classical Runge-Kutta on L and q, the baseline; energy, |L| and |q| drift",
    ),
    (
        "strang",
        "five exact rotations about the principal axes, Strang-composed",
    ),
    (
        "splitting",
        "exact symmetric top plus one exact axis rotation (Dullweber, Leimkuhler, McLachlan)",
    ),
    (
        "splitting4",
        "Suzuki's 5-stage symmetric composition of splitting",
    ),
    (
        "splitting6",
        "Kahan and Li's 9-stage symmetric composition of splitting",
    ),
    (
        "splitting8",
        "Kahan and Li's 17-stage symmetric composition of splitting",
    ),
    (
        "dmv",
        "discrete Moser-Veselov (implicit, conserves |L|, L_world and a modified energy)",
    ),
    (
        "pdmv4",
        "Hairer and Vilmart's preprocessed discrete Moser-Veselov, order 4",
    ),
    (
        "pdmv6",
        "Hairer and Vilmart's preprocessed discrete Moser-Veselov, order 6",
    ),
    (
        "pdmv8",
        "Hairer and Vilmart's preprocessed discrete Moser-Veselov, order 8",
    ),
    (
        "pdmv10",
        "Hairer and Vilmart's preprocessed discrete Moser-Veselov, order 10",
    ),
];

/// One line about each heavy-top method (bodies with a `pivot`).
const HEAVY_TOP_DESCRIPTIONS: [(&str, &str); 6] = [
    (
        "auto",
        "the default; splitting8, sub-stepped where dt exceeds its stability limit",
    ),
    (
        "rk4",
        "classical Runge-Kutta on L and q with the gravity torque, the baseline",
    ),
    (
        "strang",
        "half gravity kick, exact free-body flow, half kick (PDMV10 for 3 distinct moments)",
    ),
    (
        "splitting4",
        "Suzuki's 5-stage symmetric composition of strang",
    ),
    (
        "splitting6",
        "Kahan and Li's 9-stage symmetric composition of strang",
    ),
    (
        "splitting8",
        "Kahan and Li's 17-stage symmetric composition of strang",
    ),
];

/// The registry's names without `auto` (listed first, separately).
fn registry() -> impl Iterator<Item = &'static str> {
    METHODS.into_iter().filter(|&name| name != AUTO)
}

/// Every name accepted by `method` and `--method`, comma-separated.
pub fn known_names() -> String {
    let mut names = vec![AUTO];
    names.extend(registry());
    names.join(", ")
}

/// The integrator called `name` (`auto` is [`DEFAULT_METHOD`]).
///
/// # Errors
/// A message naming the method and listing the known ones.
pub fn integrator(name: &str) -> Result<Box<dyn FreeBodyIntegrator>, String> {
    let resolved = if name == AUTO { DEFAULT_METHOD } else { name };
    match method(resolved) {
        Ok(integrator) => Ok(integrator),
        Err(_) => Err(format!(
            "unknown method `{name}` (known: {})",
            known_names()
        )),
    }
}

/// The heavy-top integrator called `name`, for bodies with a `pivot`.
///
/// # Errors
/// A message naming the method and listing the heavy-top ones.
pub fn heavy_top_integrator(name: &str) -> Result<Box<dyn HeavyTopIntegrator>, String> {
    heavy_top_method(name).map_err(|_| {
        format!(
            "method `{name}` cannot move a body with a `pivot` (a heavy top); use one of {}",
            HEAVY_TOP_METHODS.join(", ")
        )
    })
}

/// The description of a registry method (a placeholder for a method added
/// to the library but not yet to the table).
fn description(name: &str) -> &'static str {
    DESCRIPTIONS
        .iter()
        .find(|(n, _)| *n == name)
        .map_or("(no description yet)", |(_, d)| d)
}

/// Writes one line per method: name, order, description; `auto` first,
/// marked as the default.
///
/// # Errors
/// The writer's errors.
pub fn write_list<W: Write + ?Sized>(out: &mut W) -> io::Result<()> {
    writeln!(out, "{:<12}{:>5}  DESCRIPTION", "NAME", "ORDER")?;
    // The exact solution has no order: it is shown as `exact`.
    let order = |name: &str| match method(name).map(|m| m.order()) {
        Ok(u32::MAX) => "exact".to_owned(),
        Ok(p) => p.to_string(),
        Err(_) => "?".to_owned(),
    };
    writeln!(
        out,
        "{AUTO:<12}{:>5}  the default; runs {DEFAULT_METHOD} (no truncation error at any dt)",
        order(DEFAULT_METHOD)
    )?;
    for name in registry() {
        writeln!(out, "{name:<12}{:>5}  {}", order(name), description(name))?;
    }
    writeln!(out, "\nBodies with a pivot (heavy top under gravity):")?;
    for (name, text) in HEAVY_TOP_DESCRIPTIONS {
        let order = heavy_top_method(name).map_or(0, |m| m.order());
        writeln!(out, "{name:<12}{order:>5}  {text}")?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_registry_method_is_described_and_resolves() {
        for name in registry() {
            assert_ne!(description(name), "(no description yet)", "{name}");
            assert_eq!(integrator(name).unwrap().name(), name);
        }
        assert_eq!(integrator(AUTO).unwrap().name(), DEFAULT_METHOD);
        assert_eq!(DEFAULT_METHOD, "exact", "update the help and descriptions");
        assert_eq!(DESCRIPTIONS.len(), registry().count());
    }

    #[test]
    fn every_heavy_top_method_is_described_and_resolves() {
        assert_eq!(HEAVY_TOP_DESCRIPTIONS.len(), HEAVY_TOP_METHODS.len());
        for (name, _) in HEAVY_TOP_DESCRIPTIONS {
            assert_eq!(heavy_top_integrator(name).unwrap().name(), name);
        }
        let e = heavy_top_integrator("exact").err().unwrap();
        assert!(e.contains("use one of auto, rk4, strang"), "{e}");
    }

    #[test]
    fn unknown_method_lists_the_known_ones() {
        let e = integrator("euler").err().unwrap();
        assert!(
            e.starts_with("unknown method `euler` (known: auto, exact, rk4,"),
            "{e}"
        );
        assert!(e.contains("splitting8"), "{e}");
    }

    #[test]
    fn list_has_a_line_per_method() {
        let mut out = Vec::new();
        write_list(&mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert_eq!(
            text.lines().count(),
            2 + registry().count() + 2 + HEAVY_TOP_METHODS.len()
        );
        assert!(text.contains(
            "splitting8      8  Kahan and Li's 17-stage symmetric composition of strang"
        ));
        assert!(
            text.contains("auto        exact  the default; runs exact"),
            "{text}"
        );
        assert!(text.contains("rk4             4  classical"), "{text}");
    }
}
