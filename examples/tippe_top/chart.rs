//! The `--plot` chart: three panels over the whole run, sharing the time
//! axis: the tilt θ(t) with the inversion marked, the energy E(t)/E₀, and
//! the relative change of Jellett's λ (scaled by a power of ten to read).

use kreisel_plot::Figure;
use kreisel_plot::axes::{Axes, Labels};
use kreisel_plot::figure::{Color, Rect, Stroke};

/// One sample of the run.
#[derive(Debug, Clone, Copy)]
pub struct Sample {
    /// Time, s.
    pub t: f64,
    /// Tilt of the axis, degrees.
    pub theta_deg: f64,
    /// E/E₀.
    pub energy: f64,
    /// (λ − λ₀)/|λ₀|.
    pub jellett: f64,
}

const BLUE: Color = Color::rgb(31, 119, 180);
const RED: Color = Color::rgb(214, 39, 40);
const GREEN: Color = Color::rgb(44, 160, 44);

/// A y range holding `values`, padded by 8 %, never empty.
fn range_of(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    if !(lo.is_finite() && hi.is_finite()) {
        return (-1.0, 1.0);
    }
    let pad = 0.08 * (hi - lo).max(1e-300);
    if hi - lo < 1e-300 {
        (lo - 1.0, hi + 1.0)
    } else {
        (lo - pad, hi + pad)
    }
}

/// The power of ten that brings `extent` into [1, 1000) (0 for zero).
fn exponent_for(extent: f64) -> i32 {
    if extent > 0.0 && extent.is_finite() {
        (extent.log10() / 3.0).floor() as i32 * 3
    } else {
        0
    }
}

/// `n` in superscript digits (`-15` → `⁻¹⁵`).
fn superscript(n: i32) -> String {
    n.to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            d => ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹']
                [d.to_digit(10).unwrap_or(0) as usize],
        })
        .collect()
}

/// The chart, `title` above it.
pub fn run_figure(
    samples: &[Sample],
    duration: f64,
    inverted_at: Option<f64>,
    title: &str,
) -> Figure {
    let mut fig = Figure::new(900, 780);
    let panel = |k: usize| Rect {
        left: 100.0,
        top: 40.0 + 250.0 * k as f64,
        width: 770.0,
        height: 165.0,
    };
    let x_range = (0.0, duration);
    let line = |points: Vec<(f64, f64)>, axes: &Axes, fig: &mut Figure, color| {
        axes.curve(fig, &points, &Stroke::solid(color, 2.0));
    };
    let mark_inversion = |axes: &Axes, fig: &mut Figure| {
        if let Some(t) = inverted_at {
            fig.line(
                axes.pixel(t, axes.y_range.0),
                axes.pixel(t, axes.y_range.1),
                Stroke::dashed(Color::GREY, 1.0, 4.0, 3.0),
            );
        }
    };

    let theta = Axes {
        frame: panel(0),
        x_range,
        y_range: (0.0, 180.0),
    };
    theta.draw(
        &mut fig,
        &Labels {
            title,
            x: "t (s)",
            y: "tilt θ (degrees)",
        },
    );
    fig.line(
        theta.pixel(0.0, 90.0),
        theta.pixel(duration, 90.0),
        Stroke::dashed(Color::GREY, 1.0, 2.0, 3.0),
    );
    mark_inversion(&theta, &mut fig);
    line(
        samples.iter().map(|s| (s.t, s.theta_deg)).collect(),
        &theta,
        &mut fig,
        BLUE,
    );
    if let Some(t) = inverted_at {
        theta.marker(&mut fig, t, 90.0, 4.5, BLUE);
    }

    let energy = Axes {
        frame: panel(1),
        x_range,
        y_range: range_of(samples.iter().map(|s| s.energy)),
    };
    energy.draw(
        &mut fig,
        &Labels {
            title: "energy",
            x: "t (s)",
            y: "E / E₀",
        },
    );
    mark_inversion(&energy, &mut fig);
    line(
        samples.iter().map(|s| (s.t, s.energy)).collect(),
        &energy,
        &mut fig,
        RED,
    );

    let extent = samples.iter().map(|s| s.jellett.abs()).fold(0.0, f64::max);
    let p = exponent_for(extent);
    let scale = 10f64.powi(-p);
    let jellett = Axes {
        frame: panel(2),
        x_range,
        y_range: range_of(samples.iter().map(|s| s.jellett * scale)),
    };
    let y_label = if p == 0 {
        "(λ − λ₀)/|λ₀|".to_owned()
    } else {
        format!("(λ − λ₀)/|λ₀|  (×10{})", superscript(p))
    };
    jellett.draw(
        &mut fig,
        &Labels {
            title: "Jellett's integral λ = L·(r_G − r_P), relative change",
            x: "t (s)",
            y: &y_label,
        },
    );
    mark_inversion(&jellett, &mut fig);
    line(
        samples.iter().map(|s| (s.t, s.jellett * scale)).collect(),
        &jellett,
        &mut fig,
        GREEN,
    );
    fig
}
