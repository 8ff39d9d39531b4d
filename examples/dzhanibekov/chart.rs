//! Charts of ω(t) in body principal axes: the strip chart of the window
//! and the GIF, and the full-run chart written by `--plot`.

use std::collections::VecDeque;

use glam::DVec3;
use kreisel_plot::Figure;
use kreisel_plot::axes::{Axes, Labels};
use kreisel_plot::figure::{Anchor, Color, Point, Rect, Stroke, Text};

/// Colours of ω₁, ω₂, ω₃ (and of body axes 1, 2, 3 in the 3-D view).
pub const AXIS_COLORS: [Color; 3] = [
    Color::rgb(31, 119, 180),
    Color::rgb(214, 39, 40),
    Color::rgb(44, 160, 44),
];

/// Names of the principal axes, by index.
const AXIS_NAMES: [&str; 3] = ["minor", "intermediate", "major"];

/// ω(t) samples, oldest first, optionally only the last `window` seconds.
#[derive(Debug, Clone, Default)]
pub struct History {
    samples: VecDeque<(f64, DVec3)>,
    window: Option<f64>,
}

impl History {
    /// Keeps every sample (`None`) or those of the last `window` seconds.
    pub fn new(window: Option<f64>) -> Self {
        Self {
            samples: VecDeque::new(),
            window,
        }
    }

    /// Appends ω at time `t` and forgets what fell out of the window.
    pub fn push(&mut self, t: f64, omega: DVec3) {
        self.samples.push_back((t, omega));
        if let Some(w) = self.window {
            while self.samples.front().is_some_and(|s| s.0 < t - w) {
                self.samples.pop_front();
            }
        }
    }

    /// Forgets everything (a restart).
    pub fn clear(&mut self) {
        self.samples.clear();
    }

    /// The samples of component `k` as (t, ωₖ).
    pub fn component(&self, k: usize) -> Vec<(f64, f64)> {
        self.samples.iter().map(|(t, w)| (*t, w[k])).collect()
    }
}

/// What an ω chart shows: the samples, the flips and the spin axis.
#[derive(Debug, Clone, Copy)]
pub struct OmegaData<'a> {
    /// ω(t) in principal axes.
    pub history: &'a History,
    /// Instants of the flips, s.
    pub flips: &'a [f64],
    /// Index of the spin axis (whose zero crossings are the flips).
    pub spin_axis: usize,
}

/// The ω curves, the flip instants and a legend inside `axes`.
fn draw_omega(fig: &mut Figure, axes: &Axes, data: &OmegaData<'_>, font: f64) {
    let OmegaData {
        history,
        flips,
        spin_axis,
    } = *data;
    let flip_line = Stroke::dashed(Color::GREY, 1.0, 4.0, 3.0);
    for &t in flips {
        if t >= axes.x_range.0 && t <= axes.x_range.1 {
            let (top, bottom) = (axes.pixel(t, axes.y_range.1), axes.pixel(t, axes.y_range.0));
            fig.line(top, bottom, flip_line.clone());
        }
    }
    fig.line(
        axes.pixel(axes.x_range.0, 0.0),
        axes.pixel(axes.x_range.1, 0.0),
        Stroke::solid(Color::rgb(120, 120, 120), 1.0),
    );
    for (k, color) in AXIS_COLORS.iter().enumerate() {
        let width = if k == spin_axis { 2.0 } else { 1.5 };
        axes.curve(fig, &history.component(k), &Stroke::solid(*color, width));
    }
    for &t in flips {
        axes.marker(fig, t, 0.0, 0.25 * font, AXIS_COLORS[spin_axis]);
    }
    let f = axes.frame;
    // A translucent box under the legend, so the curves do not cross its text
    // ("ω₂ (intermediate)", the longest line, is about 8.5 em wide).
    let legend = Rect {
        left: f.right() - 9.05 * font,
        top: f.top + 0.2 * font,
        width: 8.9 * font,
        height: 5.3 * font,
    };
    fig.polygon(legend.corners(), Color::WHITE.with_alpha(215), None);
    for (k, color) in AXIS_COLORS.iter().enumerate() {
        let subscript = ['₁', '₂', '₃'][k];
        fig.text(
            Text::new(
                Point::new(
                    f.right() - 0.4 * font,
                    f.top + (1.3 + 1.25 * k as f64) * font,
                ),
                format!("ω{subscript} ({})", AXIS_NAMES[k]),
                font,
                Anchor::End,
            )
            .colored(*color),
        );
    }
    fig.text(
        Text::new(
            Point::new(f.right() - 0.4 * font, f.top + 5.05 * font),
            format!("┆ flip (ω{} = 0)", ['₁', '₂', '₃'][spin_axis]),
            font,
            Anchor::End,
        )
        .colored(Color::rgb(90, 90, 90)),
    );
}

/// The largest |ωₖ| in the history (for a y range), at least `floor`.
fn omega_extent(history: &History, floor: f64) -> f64 {
    history
        .samples
        .iter()
        .map(|(_, w)| w.abs().max_element())
        .fold(floor, f64::max)
}

/// The full-run chart of `--plot`: ω₁, ω₂, ω₃ against t with every flip
/// marked, titled with the flip periods.
pub fn omega_figure(data: &OmegaData<'_>, duration: f64, title: &str) -> Figure {
    let mut fig = Figure::new(960, 440);
    let axes = Axes {
        frame: Rect {
            left: 80.0,
            top: 40.0,
            width: 850.0,
            height: 340.0,
        },
        x_range: (0.0, duration),
        y_range: {
            let e = 1.08 * omega_extent(data.history, 1e-9);
            (-e, e)
        },
    };
    axes.draw(
        &mut fig,
        &Labels {
            title,
            x: "t (s)",
            y: "ω in body principal axes (rad/s)",
        },
    );
    draw_omega(&mut fig, &axes, data, 13.0);
    fig
}

/// A strip chart of the last `window` seconds up to `now` inside `frame`,
/// with ticks and labels (drawn into a figure that is laid over the frame).
pub fn strip_chart(
    fig: &mut Figure,
    frame: Rect,
    data: &OmegaData<'_>,
    now: f64,
    window: f64,
    omega_scale: f64,
) {
    let axes = Axes {
        frame,
        x_range: ((now - window).max(0.0), now.max(window)),
        y_range: (-1.08 * omega_scale, 1.08 * omega_scale),
    };
    axes.fill_frame(fig, Color::WHITE);
    axes.draw(
        fig,
        &Labels {
            title: "",
            x: "t (s)",
            y: "ω (rad/s)",
        },
    );
    draw_omega(fig, &axes, data, 12.0);
}
