//! A 2-D panel: data ranges mapped onto a rectangle of the figure, with
//! "nice" ticks (1, 2, 5 × 10ᵏ), grid lines, tick labels, axis labels and a
//! title; curves are clipped to the frame.

use crate::figure::{Anchor, Color, Figure, Point, Rect, Stroke, Text, clip_polyline};

/// Font size of tick labels, px.
pub const TICK_FONT: f64 = 13.0;
/// Font size of axis labels, px.
pub const LABEL_FONT: f64 = 15.0;
/// Font size of panel titles, px.
pub const TITLE_FONT: f64 = 16.0;

/// Tick positions for the interval `[lo, hi]`: the multiples of a step of
/// 1, 2 or 5 × 10ᵏ inside it, the step chosen as the smallest giving at
/// most `target` intervals (at least 1). Empty for an empty, non-finite or
/// degenerate interval.
///
/// ```
/// use kreisel_plot::axes::{nice_step, nice_ticks};
///
/// assert_eq!(nice_ticks(-1.0, 1.25, 8), vec![-1.0, -0.5, 0.0, 0.5, 1.0]);
/// assert_eq!(nice_step(-1.0, 1.25, 8), 0.5);
/// assert!(nice_ticks(2.0, 2.0, 5).is_empty());
/// ```
pub fn nice_ticks(lo: f64, hi: f64, target: usize) -> Vec<f64> {
    let step = nice_step(lo, hi, target);
    if step.is_nan() {
        return Vec::new();
    }
    // Tolerance for the ends: a tick a rounding error outside still counts.
    let eps = step * 1e-9;
    let first = ((lo - eps) / step).ceil();
    let last = ((hi + eps) / step).floor();
    let mut ticks = Vec::new();
    let mut k = first;
    while k <= last && ticks.len() <= 1000 {
        // k · step, not a running sum: no accumulated rounding; no "-0".
        ticks.push(k * step + 0.0);
        k += 1.0;
    }
    ticks
}

/// The tick step [`nice_ticks`] uses, or NaN for an interval it cannot tick.
pub fn nice_step(lo: f64, hi: f64, target: usize) -> f64 {
    let span = hi - lo;
    if !(span.is_finite() && span > 0.0) || target == 0 {
        return f64::NAN;
    }
    let raw = span / target as f64;
    let magnitude = 10f64.powf(raw.log10().floor());
    for factor in [1.0, 2.0, 5.0, 10.0] {
        let step = factor * magnitude;
        // Allow for the rounding of powf and the division.
        if step >= raw * (1.0 - 1e-12) {
            return step;
        }
    }
    10.0 * magnitude
}

/// A tick label for `value` on an axis with tick spacing `step`: as many
/// decimals as the step needs, exponent form for very large or small
/// values, and a true minus sign (U+2212).
///
/// ```
/// use kreisel_plot::axes::tick_label;
///
/// assert_eq!(tick_label(0.6000000000000001, 0.2), "0.6");
/// assert_eq!(tick_label(-1.5, 0.5), "\u{2212}1.5");
/// assert_eq!(tick_label(3e6, 1e6), "3e6");
/// ```
pub fn tick_label(value: f64, step: f64) -> String {
    if value == 0.0 {
        return "0".to_owned();
    }
    let magnitude = value.abs().max(step.abs());
    let text = if (1e-3..1e6).contains(&magnitude) {
        let decimals = (-step.log10().floor()).max(0.0) as usize;
        format!("{value:.decimals$}")
    } else {
        let digits = (magnitude.log10().floor() - step.log10().floor()).clamp(0.0, 6.0) as usize;
        format!("{value:.digits$e}")
    };
    text.replace('-', "\u{2212}")
}

/// The words around a panel.
#[derive(Debug, Clone, Default)]
pub struct Labels<'a> {
    /// Above the frame.
    pub title: &'a str,
    /// Below the x axis.
    pub x: &'a str,
    /// Left of the y axis, reading upwards.
    pub y: &'a str,
}

/// A 2-D panel: `x_range` × `y_range` in data units drawn on `frame`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Axes {
    /// The plotting area in figure pixels (without the labels around it).
    pub frame: Rect,
    /// Data x at the left and right edges.
    pub x_range: (f64, f64),
    /// Data y at the bottom and top edges.
    pub y_range: (f64, f64),
}

impl Axes {
    /// Figure pixels of the data point `(x, y)` (y grows upwards).
    ///
    /// ```
    /// use kreisel_plot::axes::Axes;
    /// use kreisel_plot::figure::{Point, Rect};
    ///
    /// let axes = Axes {
    ///     frame: Rect { left: 10.0, top: 20.0, width: 100.0, height: 50.0 },
    ///     x_range: (-1.0, 1.0),
    ///     y_range: (0.0, 5.0),
    /// };
    /// assert_eq!(axes.pixel(-1.0, 0.0), Point::new(10.0, 70.0)); // bottom left
    /// assert_eq!(axes.pixel(1.0, 5.0), Point::new(110.0, 20.0)); // top right
    /// ```
    pub fn pixel(&self, x: f64, y: f64) -> Point {
        let (x0, x1) = self.x_range;
        let (y0, y1) = self.y_range;
        Point::new(
            self.frame.left + (x - x0) / (x1 - x0) * self.frame.width,
            self.frame.bottom() - (y - y0) / (y1 - y0) * self.frame.height,
        )
    }

    /// Fills the frame with `color` (e.g. white under an inset).
    pub fn fill_frame(&self, fig: &mut Figure, color: Color) {
        let f = self.frame;
        fig.polygon(f.corners(), color, None);
    }

    /// Draws the frame, grid, ticks, tick labels, axis labels and title.
    pub fn draw(&self, fig: &mut Figure, labels: &Labels<'_>) {
        let f = self.frame;
        let grid = Stroke::solid(Color::rgb(225, 225, 225), 1.0);
        let tick = Stroke::solid(Color::BLACK, 1.0);
        // About one tick label per 90 px across and per 60 px up.
        let x_target = ((f.width / 90.0) as usize).max(2);
        let y_target = ((f.height / 60.0) as usize).max(2);
        let (x0, x1) = self.x_range;
        let x_step = nice_step(x0, x1, x_target);
        for x in nice_ticks(x0, x1, x_target) {
            let p = self.pixel(x, self.y_range.0);
            fig.line(
                Point::new(p.x, f.top),
                Point::new(p.x, f.bottom()),
                grid.clone(),
            );
            fig.line(p, Point::new(p.x, p.y + 5.0), tick.clone());
            fig.text(Text::new(
                Point::new(p.x, p.y + 8.0 + TICK_FONT),
                tick_label(x, x_step),
                TICK_FONT,
                Anchor::Middle,
            ));
        }
        let (y0, y1) = self.y_range;
        let y_step = nice_step(y0, y1, y_target);
        let mut widest = 0usize;
        for y in nice_ticks(y0, y1, y_target) {
            let p = self.pixel(self.x_range.0, y);
            fig.line(
                Point::new(f.left, p.y),
                Point::new(f.right(), p.y),
                grid.clone(),
            );
            fig.line(p, Point::new(p.x - 5.0, p.y), tick.clone());
            let label = tick_label(y, y_step);
            widest = widest.max(label.chars().count());
            fig.text(Text::new(
                Point::new(p.x - 8.0, p.y + 0.36 * TICK_FONT),
                label,
                TICK_FONT,
                Anchor::End,
            ));
        }
        fig.polygon(
            f.corners(),
            Color::WHITE.with_alpha(0),
            Some(Stroke::solid(Color::BLACK, 1.0)),
        );
        fig.text(Text::new(
            Point::new(f.center().x, f.bottom() + 2.0 * TICK_FONT + LABEL_FONT),
            labels.x,
            LABEL_FONT,
            Anchor::Middle,
        ));
        // About 0.6 em per character of tick label.
        let label_x = f.left - 12.0 - 0.62 * TICK_FONT * widest as f64 - 0.4 * LABEL_FONT;
        fig.text(
            Text::new(
                Point::new(label_x, f.center().y),
                labels.y,
                LABEL_FONT,
                Anchor::Middle,
            )
            .rotated(-90.0),
        );
        fig.text(Text::new(
            Point::new(f.center().x, f.top - 0.6 * TITLE_FONT),
            labels.title,
            TITLE_FONT,
            Anchor::Middle,
        ));
    }

    /// Draws the curve through the data points, clipped to the frame.
    pub fn curve(&self, fig: &mut Figure, points: &[(f64, f64)], stroke: &Stroke) {
        let px: Vec<Point> = points.iter().map(|&(x, y)| self.pixel(x, y)).collect();
        for run in clip_polyline(&px, self.frame) {
            fig.polyline(run, stroke.clone());
        }
    }

    /// Fills the region between the curve through `points` and `y = 0`,
    /// clamped to the frame.
    pub fn fill_to_zero(&self, fig: &mut Figure, points: &[(f64, f64)], color: Color) {
        let (Some(first), Some(last)) = (points.first(), points.last()) else {
            return;
        };
        let clamp = |p: Point| {
            Point::new(
                p.x.clamp(self.frame.left, self.frame.right()),
                p.y.clamp(self.frame.top, self.frame.bottom()),
            )
        };
        let mut polygon = vec![clamp(self.pixel(first.0, 0.0))];
        polygon.extend(points.iter().map(|&(x, y)| clamp(self.pixel(x, y))));
        polygon.push(clamp(self.pixel(last.0, 0.0)));
        fig.polygon(polygon, color, None);
    }

    /// A marker at the data point, if it is inside the frame.
    pub fn marker(&self, fig: &mut Figure, x: f64, y: f64, radius: f64, color: Color) {
        let p = self.pixel(x, y);
        if self.frame.contains(p) {
            fig.circle(
                p,
                radius,
                Some(color),
                Some(Stroke::solid(Color::BLACK, 1.0)),
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_are_round_and_inside() {
        assert_eq!(
            nice_ticks(0.0, 1.0, 5),
            vec![0.0, 0.2, 0.4, 0.6000000000000001, 0.8, 1.0]
        );
        assert_eq!(nice_ticks(-1.0, 1.25, 8), vec![-1.0, -0.5, 0.0, 0.5, 1.0]);
        assert_eq!(
            nice_ticks(-3.7, 12.1, 8),
            vec![-2.0, 0.0, 2.0, 4.0, 6.0, 8.0, 10.0, 12.0]
        );
        assert_eq!(nice_ticks(1.0, 1.0, 5), Vec::<f64>::new());
        assert_eq!(nice_ticks(0.0, f64::INFINITY, 5), Vec::<f64>::new());
        assert_eq!(nice_step(0.0, 1e-7, 10), 1e-8);
        assert_eq!(nice_step(0.0, 3e5, 6), 5e4);
        for (lo, hi) in [
            (-1.0, 1.0),
            (0.123, 0.1237),
            (-5e8, 3e9),
            (2.0, 2.0 + 1e-12),
        ] {
            let ticks = nice_ticks(lo, hi, 6);
            assert!((2..=7).contains(&ticks.len()), "{lo} {hi}: {ticks:?}");
            assert!(
                ticks
                    .iter()
                    .all(|t| (lo - 1e-9 * (hi - lo)..=hi + 1e-9 * (hi - lo)).contains(t))
            );
            let step = nice_step(lo, hi, 6);
            assert!(((ticks[1] - ticks[0]) / step - 1.0).abs() < 1e-3);
            let mantissa = step / 10f64.powf(step.log10().floor());
            assert!(
                [1.0, 2.0, 5.0].iter().any(|m| (mantissa - m).abs() < 1e-6),
                "{step}"
            );
        }
    }

    #[test]
    fn labels_have_the_step_s_decimals() {
        assert_eq!(tick_label(0.6000000000000001, 0.2), "0.6");
        assert_eq!(tick_label(-0.5, 0.5), "\u{2212}0.5");
        assert_eq!(tick_label(12.0, 2.0), "12");
        assert_eq!(tick_label(0.0, 0.1), "0");
        assert_eq!(tick_label(2.5e-5, 5e-6), "2.5e-5".replace('-', "\u{2212}"));
        assert_eq!(tick_label(3e6, 1e6), "3e6");
    }

    #[test]
    fn data_maps_onto_the_frame() {
        let axes = Axes {
            frame: Rect {
                left: 10.0,
                top: 20.0,
                width: 100.0,
                height: 50.0,
            },
            x_range: (-1.0, 1.0),
            y_range: (0.0, 5.0),
        };
        assert_eq!(axes.pixel(-1.0, 0.0), Point::new(10.0, 70.0));
        assert_eq!(axes.pixel(1.0, 5.0), Point::new(110.0, 20.0));
        assert_eq!(axes.pixel(0.0, 2.5), axes.frame.center());
    }
}
