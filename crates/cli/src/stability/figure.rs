//! `kreisel stability --plot`: the map drawn — one sweep: the largest real
//! part against the parameter; two: cells coloured stable or by growth
//! rate — with the bisected boundary points and the closed-form boundary.

use std::path::Path;

use kreisel_plot::ImageFormat;
use kreisel_plot::axes::{Axes, Labels};
use kreisel_plot::figure::{Anchor, Color, Figure, Point, Rect, Stroke, Text};

use super::text::sig;
use super::{BodyReport, MapReport};
use crate::error::CliError;

/// Figure size, px.
const WIDTH: u32 = 900;
const HEIGHT: u32 = 640;
/// Colours: stable cells, unstable (at the largest growth), curves.
const STABLE: Color = Color::rgb(214, 228, 245);
const UNSTABLE: Color = Color::rgb(200, 55, 40);
const CURVE: Color = Color::rgb(31, 90, 180);
const CLOSED_FORM: Color = Color::rgb(255, 200, 0);

/// Draws `report`'s map into `path`.
///
/// # Errors
/// [`CliError::Plot`] when rendering fails or the file cannot be written.
pub fn write(report: &BodyReport, format: ImageFormat, path: &Path) -> Result<(), CliError> {
    let Some(map) = &report.map else {
        return Ok(());
    };
    let figure = figure(&format!("{}: {}", report.name, report.problem.kind()), map);
    crate::output::write_figure(&figure, format, path)
}

/// The figure of a map.
pub fn figure(title: &str, m: &MapReport) -> Figure {
    let mut fig = Figure::new(WIDTH, HEIGHT);
    fig.text(Text::new(
        Point::new(f64::from(WIDTH) / 2.0, 28.0),
        title,
        18.0,
        Anchor::Middle,
    ));
    let frame = Rect {
        left: 110.0,
        top: 80.0,
        width: f64::from(WIDTH) - 160.0,
        height: f64::from(HEIGHT) - 170.0,
    };
    let x = &m.map.axes[0];
    let x_label = format!("{} ({})", m.parameters[0], m.parameters[0].unit());
    let values = m.map.max_real_parts();
    let dashed = Stroke::dashed(CLOSED_FORM, 2.0, 7.0, 5.0);
    let legend = "red: unstable (shade: largest Re λ), blue: stable; dots: boundary by bisection, dashed: closed form";
    if m.parameters.len() == 1 {
        let finite: Vec<f64> = values.iter().copied().filter(|v| v.is_finite()).collect();
        let top = finite.iter().copied().fold(0.0, f64::max);
        let bottom = finite.iter().copied().fold(0.0, f64::min);
        let pad = 0.05 * (top - bottom).max(1e-300);
        let axes = Axes {
            frame,
            x_range: (x.from.min(x.to), x.from.max(x.to)),
            y_range: (bottom - pad, top + pad),
        };
        axes.draw(
            &mut fig,
            &Labels {
                title: legend,
                x: &x_label,
                y: "largest Re λ (1/s)",
            },
        );
        axes.curve(
            &mut fig,
            &[(axes.x_range.0, 0.0), (axes.x_range.1, 0.0)],
            &Stroke::solid(Color::GREY, 1.0),
        );
        // Gaps where there is no steady motion.
        let mut run = Vec::new();
        for (k, v) in values.iter().enumerate() {
            if v.is_finite() {
                run.push((x.value(k), *v));
            } else if !run.is_empty() {
                axes.curve(&mut fig, &run, &Stroke::solid(CURVE, 2.0));
                run.clear();
            }
        }
        axes.curve(&mut fig, &run, &Stroke::solid(CURVE, 2.0));
        for p in m.closed_form.iter().flatten() {
            axes.curve(
                &mut fig,
                &[(p[0], axes.y_range.0), (p[0], axes.y_range.1)],
                &dashed,
            );
        }
        for b in &m.map.boundaries {
            axes.marker(&mut fig, b.at[0], 0.0, 4.0, UNSTABLE);
            fig.text(Text::new(
                axes.pixel(b.at[0], 0.0),
                format!(" {}", sig(b.at[0])),
                13.0,
                Anchor::Start,
            ));
        }
        return fig;
    }
    let y = &m.map.axes[1];
    let y_label = format!("{} ({})", m.parameters[1], m.parameters[1].unit());
    let axes = Axes {
        frame,
        x_range: (x.from.min(x.to), x.from.max(x.to)),
        y_range: (y.from.min(y.to), y.from.max(y.to)),
    };
    let largest = values
        .iter()
        .copied()
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
    let [n0, n1] = m.map.shape();
    let half = |a: &kreisel_analysis::Sweep| 0.5 * (a.to - a.from) / (a.count - 1) as f64;
    for j in 0..n1 {
        for i in 0..n0 {
            let point = &m.map.points[i + n0 * j];
            let colour = if point.is_unstable() {
                let t = (point.max_real_part() / largest).sqrt().clamp(0.15, 1.0);
                blend(Color::WHITE, UNSTABLE, t)
            } else if point.max_real_part().is_nan() {
                Color::GREY
            } else {
                STABLE
            };
            let (cx, cy, hx, hy) = (x.value(i), y.value(j), half(x), half(y));
            let corners = [
                (cx - hx, cy - hy),
                (cx + hx, cy - hy),
                (cx + hx, cy + hy),
                (cx - hx, cy + hy),
            ];
            let clip = |(a, b): (f64, f64)| {
                let (a, b) = (
                    a.clamp(axes.x_range.0, axes.x_range.1),
                    b.clamp(axes.y_range.0, axes.y_range.1),
                );
                axes.pixel(a, b)
            };
            fig.polygon(corners.into_iter().map(clip).collect(), colour, None);
        }
    }
    axes.draw(
        &mut fig,
        &Labels {
            title: legend,
            x: &x_label,
            y: &y_label,
        },
    );
    for b in &m.map.boundaries {
        axes.marker(&mut fig, b.at[0], b.at[1], 2.5, Color::BLACK);
    }
    if let Some(points) = &m.closed_form {
        let curve: Vec<(f64, f64)> = points.iter().map(|p| (p[0], p[1])).collect();
        axes.curve(&mut fig, &curve, &dashed);
    }
    fig
}

/// `a` blended towards `b` by `t ∈ [0, 1]`.
fn blend(a: Color, b: Color, t: f64) -> Color {
    let mix = |x: u8, y: u8| (f64::from(x) + (f64::from(y) - f64::from(x)) * t).round() as u8;
    Color::rgb(mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b))
}
