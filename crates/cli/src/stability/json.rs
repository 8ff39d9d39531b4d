//! `kreisel stability --format json`.
//!
//! ```text
//! {"bodies": [{"name", "steady_motions": [{"kind", "parameters", "state",
//!   "reduced_by", "zero_modes", "frame", "eigenvalues": [[re, im], …],
//!   "space_frequencies", "modes", "verdict", "growth_rate" | "reason",
//!   "map"?}]}]}
//! ```

use std::fmt::Write as _;

use kreisel_analysis::{Linearisation, Verdict};

use super::{BodyReport, MapReport};
use crate::inertia::json::{number, string};

/// The JSON document of every body.
pub fn render(reports: &[BodyReport]) -> String {
    let mut out = String::from("{\"bodies\": [");
    for (k, r) in reports.iter().enumerate() {
        if k > 0 {
            out.push(',');
        }
        out.push_str("\n  {\"name\": ");
        string(&mut out, &r.name);
        out.push_str(", \"steady_motions\": [{\n    \"kind\": ");
        string(&mut out, r.problem.kind());
        out.push_str(",\n    \"parameters\": {");
        for (i, (p, v)) in r.problem.parameters().iter().enumerate() {
            if i > 0 {
                out.push_str(", ");
            }
            string(&mut out, p.name());
            out.push_str(": ");
            number(&mut out, *v);
        }
        out.push('}');
        linearisation(&mut out, &r.linearisation);
        if let Some(map) = &r.map {
            map_object(&mut out, map);
        }
        out.push_str("\n  }]}");
    }
    out.push_str("\n]}\n");
    out
}

fn strings(out: &mut String, items: impl Iterator<Item = String>) {
    out.push('[');
    for (i, s) in items.enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        string(out, &s);
    }
    out.push(']');
}

fn numbers(out: &mut String, items: impl Iterator<Item = f64>) {
    out.push('[');
    for (i, v) in items.enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        number(out, v);
    }
    out.push(']');
}

fn pair(out: &mut String, re: f64, im: f64) {
    out.push('[');
    number(out, re);
    out.push_str(", ");
    number(out, im);
    out.push(']');
}

fn linearisation(out: &mut String, lin: &Linearisation) {
    out.push_str(",\n    \"state_names\": ");
    strings(out, lin.state_names.iter().cloned());
    out.push_str(",\n    \"state\": ");
    numbers(out, lin.state.iter().copied());
    out.push_str(",\n    \"reduced_by\": ");
    strings(out, lin.reduced_by.iter().cloned());
    out.push_str(",\n    \"zero_modes\": [");
    for (i, z) in lin.zero_modes.iter().enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        out.push_str("{\"kind\": ");
        string(out, &z.kind.to_string());
        out.push_str(", \"name\": ");
        string(out, &z.name);
        out.push('}');
    }
    let _ = write!(
        out,
        "],\n    \"frame\": \"{}\",\n    \"eigenvalues\": [",
        lin.frame
    );
    for (i, m) in lin.modes.iter().enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        pair(out, m.eigenvalue.re, m.eigenvalue.im);
    }
    out.push_str("],\n    \"space_frequencies\": ");
    numbers(
        out,
        lin.modes
            .iter()
            .map(|m| m.space_frequency.unwrap_or(f64::NAN)),
    );
    out.push_str(",\n    \"modes\": [");
    for (i, m) in lin.modes.iter().enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        out.push('[');
        for (k, c) in m.shape.iter().enumerate() {
            if k > 0 {
                out.push_str(", ");
            }
            pair(out, c.re, c.im);
        }
        out.push(']');
    }
    let _ = write!(out, "],\n    \"verdict\": \"{}\"", lin.verdict.name());
    match &lin.verdict {
        Verdict::Unstable { growth_rate } => {
            out.push_str(",\n    \"growth_rate\": ");
            number(out, *growth_rate);
        }
        Verdict::Neutral { reason } => {
            out.push_str(",\n    \"reason\": ");
            string(out, reason);
        }
        Verdict::Stable { asymptotic } => {
            let _ = write!(out, ",\n    \"asymptotic\": {asymptotic}");
        }
    }
}

fn map_object(out: &mut String, m: &MapReport) {
    out.push_str(",\n    \"map\": {\"axes\": [");
    for (i, (a, p)) in m.map.axes.iter().zip(&m.parameters).enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        out.push_str("{\"name\": ");
        string(out, p.name());
        out.push_str(", \"values\": ");
        numbers(out, (0..a.count).map(|k| a.value(k)));
        out.push('}');
    }
    out.push_str("],\n      \"max_real_part\": ");
    numbers(out, m.map.max_real_parts().into_iter());
    out.push_str(",\n      \"verdicts\": ");
    strings(
        out,
        m.map.points.iter().map(|p| match p {
            kreisel_analysis::GridPoint::Analysed { verdict, .. } => verdict.name().to_string(),
            kreisel_analysis::GridPoint::Missing { .. } => "none".to_string(),
        }),
    );
    out.push_str(",\n      \"boundaries\": [");
    for (i, (b, exact)) in m
        .map
        .boundaries
        .iter()
        .zip(&m.closed_form_at_boundaries)
        .enumerate()
    {
        if i > 0 {
            out.push_str(", ");
        }
        out.push_str("{\"at\": ");
        numbers(out, b.at[..m.parameters.len()].iter().copied());
        let _ = write!(
            out,
            ", \"along\": \"{}\", \"width\": ",
            m.parameters[b.axis]
        );
        number(out, b.width);
        out.push_str(", \"closed_form\": ");
        number(out, exact.unwrap_or(f64::NAN));
        out.push('}');
    }
    out.push_str("],\n      \"closed_form_boundary\": ");
    match &m.closed_form {
        None => out.push_str("null"),
        Some(points) => {
            out.push('[');
            for (i, p) in points.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                numbers(out, p[..m.parameters.len()].iter().copied());
            }
            out.push(']');
        }
    }
    out.push('}');
}
