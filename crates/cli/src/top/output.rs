//! `--format text` and `--format json` of a [`Summary`].
//!
//! Numbers in shortest round-trip form ([`Shortest`]); a quantity the
//! motion does not have (the nutation of a sleeping top) is `null` in JSON
//! and `none` in text.

use core::fmt::Write;

use super::Summary;
use kreisel_scene::numbers::Shortest;

/// One field of the report: its JSON key, its value, its unit (text only).
enum Value<'a> {
    Number(f64),
    Optional(Option<f64>),
    List(&'a [f64]),
    Word(Option<&'a str>),
    Flag(bool),
}

/// An angle field `(key, value, "rad")`, or with `degrees` (the value
/// already in degrees) `(key_deg, value, "deg")`.
fn angle<'a>(
    keys: (&'static str, &'static str),
    value: f64,
    degrees: bool,
) -> (&'static str, Value<'a>, &'static str) {
    if degrees {
        (keys.1, Value::Number(value), "deg")
    } else {
        (keys.0, Value::Number(value), "rad")
    }
}

/// The fields in output order, with their units (with `degrees` the
/// summary's angles are in degrees, [`Summary::in_degrees`], and their
/// keys end in `_deg`).
fn fields(s: &Summary, degrees: bool) -> Vec<(&'static str, Value<'_>, &'static str)> {
    use Value::{Flag, List, Number, Optional, Word};
    vec![
        ("i1", Number(s.top.i1), "kg m^2 (about the pivot)"),
        ("i3", Number(s.top.i3), "kg m^2"),
        ("mgl", Number(s.top.mgl), "J"),
        angle(("theta0", "theta0_deg"), s.top.theta0, degrees),
        ("theta_dot0", Number(s.top.theta_dot0), "rad/s"),
        ("phi_dot0", Number(s.top.phi_dot0), "rad/s"),
        ("psi_dot0", Number(s.top.psi_dot0), "rad/s"),
        ("a", Number(s.a), "rad/s"),
        ("b", Number(s.b), "rad/s"),
        ("alpha", Number(s.alpha), "1/s^2"),
        ("beta", Number(s.beta), "1/s^2"),
        ("omega3", Number(s.omega3), "rad/s"),
        ("roots", List(&s.roots), "(u = cos theta, ascending)"),
        angle(("theta_min", "theta_min_deg"), s.theta_min, degrees),
        angle(("theta_max", "theta_max_deg"), s.theta_max, degrees),
        ("nutation_period", Optional(s.nutation_period), "s"),
        (
            "mean_precession_rate",
            Optional(s.mean_precession_rate),
            "rad/s",
        ),
        ("motion", Word(s.motion), ""),
        ("sleeping", Flag(s.sleeping), ""),
        ("sleeping_stable", Flag(s.sleeping_stable), ""),
    ]
}

/// A number, or `null` for a non-finite one (JSON has no spelling for it).
fn json_number(out: &mut String, value: f64) {
    if value.is_finite() {
        let _ = write!(out, "{}", Shortest(value));
    } else {
        out.push_str("null");
    }
}

/// The JSON report: one object, one member per line, ending with a newline.
pub fn json(s: &Summary, degrees: bool) -> String {
    let mut out = String::from("{\n");
    for (i, (key, value, _)) in fields(s, degrees).into_iter().enumerate() {
        if i > 0 {
            out.push_str(",\n");
        }
        // Keys are fixed identifiers: nothing to escape.
        let _ = write!(out, "  \"{key}\": ");
        match value {
            Value::Number(v) => json_number(&mut out, v),
            Value::Optional(v) => match v {
                Some(v) => json_number(&mut out, v),
                None => out.push_str("null"),
            },
            Value::List(values) => {
                out.push('[');
                for (k, &v) in values.iter().enumerate() {
                    if k > 0 {
                        out.push_str(", ");
                    }
                    json_number(&mut out, v);
                }
                out.push(']');
            }
            Value::Word(Some(word)) => {
                let _ = write!(out, "\"{word}\"");
            }
            Value::Word(None) => out.push_str("null"),
            Value::Flag(flag) => {
                let _ = write!(out, "{flag}");
            }
        }
    }
    out.push_str("\n}\n");
    out
}

/// The text report: `name: value unit`, one per line.
pub fn text(s: &Summary, degrees: bool) -> String {
    let mut out = String::new();
    for (key, value, unit) in fields(s, degrees) {
        let _ = write!(out, "{key}: ");
        let mut with_unit = true;
        match value {
            Value::Number(v) | Value::Optional(Some(v)) => {
                let _ = write!(out, "{}", Shortest(v));
            }
            Value::Optional(None) | Value::Word(None) => {
                out.push_str("none");
                with_unit = false;
            }
            Value::List(values) => {
                let shown: Vec<String> = values.iter().map(|&v| Shortest(v).to_string()).collect();
                out.push_str(&shown.join(", "));
            }
            Value::Word(Some(word)) => out.push_str(word),
            Value::Flag(flag) => {
                let _ = write!(out, "{flag}");
            }
        }
        if with_unit && !unit.is_empty() {
            let _ = write!(out, " {unit}");
        }
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn summary() -> Summary {
        Summary {
            top: crate::top::tests::args().request(),
            a: 20.0,
            b: 17.5,
            alpha: 11.7,
            beta: 13.3,
            omega3: 60.0,
            roots: vec![0.8, 0.87, 30.0],
            theta_min: 0.5,
            theta_max: 0.6,
            nutation_period: None,
            mean_precession_rate: Some(1e-5),
            motion: Some("cusps"),
            sleeping: false,
            sleeping_stable: false,
        }
    }

    #[test]
    fn json_has_every_field_and_nulls() {
        let json = json(&summary(), false);
        assert!(json.starts_with("{\n  \"i1\": 0.3,\n"), "{json}");
        assert!(json.contains("\"roots\": [0.8, 0.87, 30],\n"), "{json}");
        assert!(json.contains("\"nutation_period\": null,\n"));
        assert!(json.contains("\"mean_precession_rate\": 1e-5,\n"));
        assert!(json.contains("\"motion\": \"cusps\",\n"));
        assert!(json.ends_with("\"sleeping_stable\": false\n}\n"));
    }

    #[test]
    fn text_has_units() {
        let text = text(&summary(), false);
        assert!(text.contains("\nomega3: 60 rad/s\n"), "{text}");
        assert!(text.contains("\nnutation_period: none\n"), "{text}");
        assert!(
            text.contains("\nroots: 0.8, 0.87, 30 (u = cos theta, ascending)\n"),
            "{text}"
        );
        assert_eq!(text.lines().count(), 20);
    }
}
