//! The `--plot` chart: three panels over the whole run, sharing the time
//! axis: the tilt θ(t) on bands shaded by which contacts touch (the
//! horizontal passage marked), the energy E(t)/E₀, and a strip of the
//! contacts: when the ball and when the stem touch the table, with the
//! impacts ticked.

use kreisel_plot::Figure;
use kreisel_plot::axes::{Axes, Labels};
use kreisel_plot::figure::{Anchor, Color, Point, Rect, Stroke, Text};

/// One sample of the run.
#[derive(Debug, Clone, Copy)]
pub struct Sample {
    /// Time, s.
    pub t: f64,
    /// Tilt of the axis, degrees.
    pub theta_deg: f64,
    /// E/E₀.
    pub energy: f64,
}

/// What the chart shows besides the samples.
#[derive(Debug, Clone, Copy)]
pub struct Marks<'a> {
    /// The run's length, s.
    pub duration: f64,
    /// The first horizontal passage of the axis, s.
    pub horizontal_at: Option<f64>,
    /// From each time on (until the next), whether the ball and the stem touch.
    pub touching: &'a [(f64, [bool; 2])],
    /// The impacts: time and contact (0 ball, 1 stem).
    pub impacts: &'a [(f64, usize)],
}

const BLUE: Color = Color::rgb(31, 119, 180);
const RED: Color = Color::rgb(214, 39, 40);
/// The bands and the strip's colours: the ball, the stem.
const CONTACT_COLOURS: [Color; 2] = [Color::rgb(70, 110, 170), Color::rgb(230, 140, 40)];

/// A y range holding `values`, padded by 8 %, never empty.
fn range_of(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    if !(lo.is_finite() && hi.is_finite()) {
        return (-1.0, 1.0);
    }
    if hi - lo < 1e-300 {
        (lo - 1.0, hi + 1.0)
    } else {
        let pad = 0.08 * (hi - lo);
        (lo - pad, hi + pad)
    }
}

/// The intervals `(from, to, touching)` of `marks.touching` up to the end.
fn phases(marks: &Marks<'_>) -> Vec<(f64, f64, [bool; 2])> {
    let list = marks.touching;
    list.iter()
        .enumerate()
        .map(|(k, &(t, c))| {
            let to = list.get(k + 1).map_or(marks.duration, |n| n.0);
            (t, to.min(marks.duration), c)
        })
        .filter(|(from, to, _)| to > from)
        .collect()
}

/// A rectangle of `axes` from `t0` to `t1` between `y0` and `y1`.
fn band(axes: &Axes, fig: &mut Figure, (t0, t1): (f64, f64), (y0, y1): (f64, f64), fill: Color) {
    let (a, b) = (axes.pixel(t0, y1), axes.pixel(t1, y0));
    let rect = Rect {
        left: a.x,
        top: a.y,
        width: b.x - a.x,
        height: b.y - a.y,
    };
    fig.polygon(rect.corners(), fill, None);
}

/// A dashed vertical line at `t` across `axes`.
fn mark_time(axes: &Axes, fig: &mut Figure, t: Option<f64>) {
    if let Some(t) = t {
        fig.line(
            axes.pixel(t, axes.y_range.0),
            axes.pixel(t, axes.y_range.1),
            Stroke::dashed(Color::GREY, 1.0, 4.0, 3.0),
        );
    }
}

/// The chart, `title` above it.
pub fn run_figure(samples: &[Sample], marks: &Marks<'_>, title: &str) -> Figure {
    let mut fig = Figure::new(900, 760);
    let x_range = (0.0, marks.duration);
    let phases = phases(marks);

    let theta = Axes {
        frame: Rect {
            left: 100.0,
            top: 40.0,
            width: 770.0,
            height: 240.0,
        },
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
    // Shaded by which contacts touch: blue the ball, orange the stem, both
    // overlaid.
    for &(t0, t1, c) in &phases {
        for (i, colour) in CONTACT_COLOURS.iter().enumerate() {
            if c[i] {
                band(
                    &theta,
                    &mut fig,
                    (t0, t1),
                    (0.0, 180.0),
                    colour.with_alpha(40),
                );
            }
        }
    }
    fig.line(
        theta.pixel(0.0, 90.0),
        theta.pixel(marks.duration, 90.0),
        Stroke::dashed(Color::GREY, 1.0, 2.0, 3.0),
    );
    mark_time(&theta, &mut fig, marks.horizontal_at);
    let points: Vec<(f64, f64)> = samples.iter().map(|s| (s.t, s.theta_deg)).collect();
    theta.curve(&mut fig, &points, &Stroke::solid(BLUE, 2.0));
    if let Some(t) = marks.horizontal_at {
        theta.marker(&mut fig, t, 90.0, 4.5, BLUE);
    }

    let energy = Axes {
        frame: Rect {
            left: 100.0,
            top: 370.0,
            width: 770.0,
            height: 180.0,
        },
        x_range,
        y_range: range_of(samples.iter().map(|s| s.energy)),
    };
    energy.draw(
        &mut fig,
        &Labels {
            title: "energy (friction and impacts only take it away)",
            x: "t (s)",
            y: "E / E₀",
        },
    );
    mark_time(&energy, &mut fig, marks.horizontal_at);
    let points: Vec<(f64, f64)> = samples.iter().map(|s| (s.t, s.energy)).collect();
    energy.curve(&mut fig, &points, &Stroke::solid(RED, 2.0));

    let strip = Axes {
        frame: Rect {
            left: 100.0,
            top: 640.0,
            width: 770.0,
            height: 60.0,
        },
        x_range,
        y_range: (0.0, 2.0),
    };
    strip.draw(
        &mut fig,
        &Labels {
            title: "touching the table (ticks: impacts)",
            x: "t (s)",
            y: "",
        },
    );
    for (i, (name, colour)) in ["ball", "stem"].iter().zip(CONTACT_COLOURS).enumerate() {
        // The ball on the upper row, the stem on the lower.
        let row = (1.0 - i as f64 + 0.15, 1.0 - i as f64 + 0.85);
        for &(t0, t1, c) in &phases {
            if c[i] {
                band(&strip, &mut fig, (t0, t1), row, colour);
            }
        }
        for &(t, _) in marks.impacts.iter().filter(|(_, k)| *k == i) {
            fig.line(
                strip.pixel(t, row.0 - 0.1),
                strip.pixel(t, row.1 + 0.1),
                Stroke::solid(Color::BLACK, 1.0),
            );
        }
        let at = strip.pixel(0.0, 0.5 * (row.0 + row.1));
        fig.text(
            Text::new(Point::new(at.x - 8.0, at.y + 5.0), *name, 13.0, Anchor::End).colored(colour),
        );
    }
    fig
}
