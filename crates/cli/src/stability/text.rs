//! `kreisel stability` as words and tables.

use std::fmt::Write as _;

use kreisel_analysis::{Eigenvalue, Frame, Linearisation, Mode, Verdict};
use kreisel_scene::numbers::Shortest;

use super::{BodyReport, MapReport};

/// `x` to 10 significant digits, written shortest.
pub(super) fn sig(x: f64) -> String {
    if !x.is_finite() {
        return format!("{x}");
    }
    let rounded: f64 = format!("{x:.9e}").parse().unwrap_or(x);
    Shortest(rounded).to_string()
}

/// The report of every body.
pub fn render(reports: &[BodyReport]) -> String {
    let mut out = String::new();
    for (k, r) in reports.iter().enumerate() {
        if k > 0 {
            out.push('\n');
        }
        body(&mut out, r);
    }
    out
}

fn body(out: &mut String, r: &BodyReport) {
    let lin = &r.linearisation;
    let _ = writeln!(out, "{}: {}", r.name, r.problem.kind());
    let parameters: Vec<String> = r
        .problem
        .parameters()
        .iter()
        .map(|(p, v)| format!("{p} = {} {}", sig(*v), p.unit()))
        .collect();
    let _ = writeln!(out, "  {}", parameters.join(", "));
    let state: Vec<String> = lin
        .state_names
        .iter()
        .zip(&lin.state)
        .map(|(n, v)| format!("{} = {}", n.split(' ').next().unwrap_or(n), sig(*v)))
        .collect();
    let _ = writeln!(
        out,
        "  steady state ({}): {}",
        r.problem.coordinates(),
        state.join(", ")
    );
    let _ = writeln!(out, "  reduced by: {}", lin.reduced_by.join("; "));
    let zeros: Vec<String> = lin.zero_modes.iter().map(ToString::to_string).collect();
    let _ = writeln!(out, "  zero eigenvalues: {}", zeros.join("; "));
    let frame = match lin.frame {
        Frame::Body => "body axes",
        Frame::Space => "space",
    };
    let _ = writeln!(out, "  eigenvalues (1/s; frequencies in {frame}):");
    for mode in shown(lin) {
        eigenvalue_line(out, mode, lin);
    }
    let verdict = match &lin.verdict {
        Verdict::Unstable { growth_rate } => {
            format!("unstable (growth rate {} 1/s)", sig(*growth_rate))
        }
        other => other.to_string(),
    };
    let _ = writeln!(out, "  verdict: {verdict}");
    if let Some(map) = &r.map {
        map_lines(out, map);
    }
}

/// Each real eigenvalue, and one of each complex pair (`Im λ > 0`).
pub(super) fn shown(lin: &Linearisation) -> impl Iterator<Item = &Mode> {
    lin.modes.iter().filter(|m| m.eigenvalue.im >= 0.0)
}

fn eigenvalue_line(out: &mut String, mode: &Mode, lin: &Linearisation) {
    let Eigenvalue { re, im } = mode.eigenvalue;
    let value = if im > 0.0 {
        format!("{} ± {}i", sig(re), sig(im))
    } else {
        sig(re)
    };
    let mut line = format!("    λ = {value}");
    if let Some(space) = mode.space_frequency {
        let _ = write!(line, "   (in space: {} rad/s)", sig(space));
    }
    let _ = writeln!(out, "{line}");
    let biggest = mode.shape.iter().map(|c| c.norm()).fold(0.0, f64::max);
    let parts: Vec<String> = lin
        .state_names
        .iter()
        .zip(&mode.shape)
        .filter(|(_, c)| c.norm() > 1e-9 * biggest)
        .map(|(name, c)| {
            let name = name.split(' ').next().unwrap_or(name);
            // Rounded to 0.1° first, so that −0.04° prints as 0.0°.
            let degrees = (c.im.atan2(c.re).to_degrees() * 10.0).round() / 10.0 + 0.0;
            format!("{name} {:.4}∠{degrees:.1}°", c.norm())
        })
        .collect();
    let _ = writeln!(out, "      mode: {}", parts.join(", "));
}

fn map_lines(out: &mut String, m: &MapReport) {
    let axes: Vec<String> = m
        .map
        .axes
        .iter()
        .zip(&m.parameters)
        .map(|(a, p)| {
            format!(
                "{p} from {} to {} {} ({} values)",
                sig(a.from),
                sig(a.to),
                p.unit(),
                a.count
            )
        })
        .collect();
    let _ = writeln!(out, "  map of {}:", axes.join(" × "));
    let unstable = m.map.points.iter().filter(|p| p.is_unstable()).count();
    let missing = m.map.max_real_parts().iter().filter(|v| v.is_nan()).count();
    let largest = m
        .map
        .max_real_parts()
        .into_iter()
        .filter(|v| !v.is_nan())
        .fold(f64::NEG_INFINITY, f64::max);
    let _ = writeln!(
        out,
        "    unstable at {unstable} of {} points; largest real part {} 1/s{}",
        m.map.points.len(),
        sig(largest),
        if missing > 0 {
            format!("; no steady motion at {missing}")
        } else {
            String::new()
        }
    );
    let two = m.parameters.len() == 2;
    if two {
        let _ = writeln!(
            out,
            "    boundary: {} points located by bisection",
            m.map.boundaries.len()
        );
    }
    let mut worst: f64 = 0.0;
    for (b, exact) in m.map.boundaries.iter().zip(&m.closed_form_at_boundaries) {
        let found = b.at[b.axis];
        if let Some(e) = exact {
            worst = worst.max((found / e - 1.0).abs());
        }
        if !two {
            let mut line = format!(
                "    boundary: {} = {} {}",
                m.parameters[0],
                sig(found),
                m.parameters[0].unit()
            );
            if let Some(e) = exact {
                let _ = write!(
                    line,
                    " (closed form {}, relative difference {:.1e})",
                    sig(*e),
                    found / e - 1.0
                );
            }
            let _ = writeln!(out, "{line}");
        }
    }
    if m.map.boundaries.is_empty() {
        let _ = writeln!(out, "    boundary: none in the range");
    }
    match &m.closed_form {
        None => {
            let _ = writeln!(out, "    closed form: none known for this motion");
        }
        Some(_) if two && !m.map.boundaries.is_empty() => {
            let _ = writeln!(
                out,
                "    closed form: largest relative difference {worst:.1e}"
            );
        }
        Some(_) => {}
    }
}
