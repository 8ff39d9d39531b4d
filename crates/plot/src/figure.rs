//! A figure as a backend-independent list of drawing primitives.
//!
//! Coordinates are figure pixels: origin at the top-left corner, x to the
//! right, y downwards. A [`Figure`] is drawn in order (later primitives on
//! top) by [`crate::svg`] or [`crate::png`]; neither backend adds anything.

/// A colour with straight (not premultiplied) alpha, 8 bits per channel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Color {
    /// Red.
    pub r: u8,
    /// Green.
    pub g: u8,
    /// Blue.
    pub b: u8,
    /// Opacity: 0 transparent, 255 opaque.
    pub a: u8,
}

impl Color {
    /// Opaque black.
    pub const BLACK: Color = Color::rgb(0, 0, 0);
    /// Opaque white.
    pub const WHITE: Color = Color::rgb(255, 255, 255);
    /// Mid grey, for grid lines and secondary outlines.
    pub const GREY: Color = Color::rgb(150, 150, 150);

    /// An opaque colour.
    pub const fn rgb(r: u8, g: u8, b: u8) -> Self {
        Self { r, g, b, a: 255 }
    }

    /// The same colour with opacity `a`.
    pub const fn with_alpha(self, a: u8) -> Self {
        Self { a, ..self }
    }

    /// `#rrggbb`, as SVG and CSS write it (the alpha is not included).
    pub fn hex(self) -> String {
        format!("#{:02x}{:02x}{:02x}", self.r, self.g, self.b)
    }

    /// The opacity as a fraction in [0, 1].
    pub fn opacity(self) -> f64 {
        f64::from(self.a) / 255.0
    }
}

/// A point in figure pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Point {
    /// Pixels from the left edge.
    pub x: f64,
    /// Pixels from the top edge.
    pub y: f64,
}

impl Point {
    /// The point `(x, y)`.
    pub const fn new(x: f64, y: f64) -> Self {
        Self { x, y }
    }
}

/// How a line is drawn.
#[derive(Debug, Clone, PartialEq)]
pub struct Stroke {
    /// Line colour.
    pub color: Color,
    /// Line width in pixels.
    pub width: f64,
    /// Dash pattern (on, off, on, … lengths in pixels); empty for a solid line.
    pub dash: Vec<f64>,
}

impl Stroke {
    /// A solid line.
    pub fn solid(color: Color, width: f64) -> Self {
        Self {
            color,
            width,
            dash: Vec::new(),
        }
    }

    /// A dashed line: `on` pixels drawn, `off` pixels skipped.
    pub fn dashed(color: Color, width: f64, on: f64, off: f64) -> Self {
        Self {
            color,
            width,
            dash: vec![on, off],
        }
    }
}

/// Where a text's anchor point is along its baseline.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Anchor {
    /// The text starts at the anchor.
    Start,
    /// The text is centred on the anchor.
    Middle,
    /// The text ends at the anchor.
    End,
}

/// One line of text.
#[derive(Debug, Clone, PartialEq)]
pub struct Text {
    /// The anchor point, on the baseline.
    pub at: Point,
    /// The text (one line; any Unicode the font covers).
    pub text: String,
    /// Font size (em height) in pixels.
    pub size: f64,
    /// Text colour.
    pub color: Color,
    /// Horizontal alignment on the anchor.
    pub anchor: Anchor,
    /// Rotation about the anchor in degrees, clockwise on screen (−90 reads upwards).
    pub rotation: f64,
}

impl Text {
    /// Unrotated black text.
    pub fn new(at: Point, text: impl Into<String>, size: f64, anchor: Anchor) -> Self {
        Self {
            at,
            text: text.into(),
            size,
            color: Color::BLACK,
            anchor,
            rotation: 0.0,
        }
    }

    /// The same text rotated by `degrees` clockwise about its anchor.
    pub fn rotated(self, degrees: f64) -> Self {
        Self {
            rotation: degrees,
            ..self
        }
    }

    /// The same text in `color`.
    pub fn colored(self, color: Color) -> Self {
        Self { color, ..self }
    }
}

/// One drawing primitive.
#[derive(Debug, Clone, PartialEq)]
pub enum Primitive {
    /// An open line through the points.
    Polyline {
        /// The vertices, in order.
        points: Vec<Point>,
        /// How the line is drawn.
        stroke: Stroke,
    },
    /// A closed polygon, filled (non-zero rule) and optionally outlined.
    Polygon {
        /// The vertices, in order; the last joins the first.
        points: Vec<Point>,
        /// Fill colour.
        fill: Color,
        /// Outline, if any.
        stroke: Option<Stroke>,
    },
    /// A circle (a marker, or an outline such as a sphere's silhouette).
    Circle {
        /// Centre.
        center: Point,
        /// Radius in pixels.
        radius: f64,
        /// Fill colour, if filled.
        fill: Option<Color>,
        /// Outline, if any.
        stroke: Option<Stroke>,
    },
    /// A line of text.
    Text(Text),
}

/// A figure: a size, a background and primitives drawn in order.
///
/// ```
/// use kreisel_plot::Figure;
/// use kreisel_plot::figure::{Anchor, Color, Point, Primitive, Stroke, Text};
///
/// let mut fig = Figure::new(200, 100);
/// let red = Stroke::solid(Color::rgb(200, 0, 0), 1.5);
/// fig.line(Point::new(10.0, 90.0), Point::new(190.0, 10.0), red.clone());
/// fig.polyline(vec![Point::new(0.0, 0.0)], red); // one point: nothing to draw
/// fig.circle(Point::new(100.0, 50.0), 4.0, Some(Color::BLACK), None);
/// fig.text(Text::new(Point::new(100.0, 20.0), "y(t)", 14.0, Anchor::Middle));
/// assert_eq!((fig.width, fig.height, fig.background), (200, 100, Color::WHITE));
/// assert_eq!(fig.items.len(), 3);
/// assert!(matches!(fig.items[2], Primitive::Text(_)));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Background colour (fills the whole figure first).
    pub background: Color,
    /// What is drawn, back to front.
    pub items: Vec<Primitive>,
}

impl Figure {
    /// An empty figure with a white background.
    pub fn new(width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            background: Color::WHITE,
            items: Vec::new(),
        }
    }

    /// Adds a polyline (ignored with fewer than two points).
    pub fn polyline(&mut self, points: Vec<Point>, stroke: Stroke) {
        if points.len() >= 2 {
            self.items.push(Primitive::Polyline { points, stroke });
        }
    }

    /// Adds a filled polygon (ignored with fewer than three points).
    pub fn polygon(&mut self, points: Vec<Point>, fill: Color, stroke: Option<Stroke>) {
        if points.len() >= 3 {
            self.items.push(Primitive::Polygon {
                points,
                fill,
                stroke,
            });
        }
    }

    /// Adds a circle.
    pub fn circle(
        &mut self,
        center: Point,
        radius: f64,
        fill: Option<Color>,
        stroke: Option<Stroke>,
    ) {
        self.items.push(Primitive::Circle {
            center,
            radius,
            fill,
            stroke,
        });
    }

    /// Adds a line of text.
    pub fn text(&mut self, text: Text) {
        self.items.push(Primitive::Text(text));
    }

    /// A straight segment from `a` to `b`.
    pub fn line(&mut self, a: Point, b: Point, stroke: Stroke) {
        self.polyline(vec![a, b], stroke);
    }
}

/// An axis-aligned rectangle in figure pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rect {
    /// Left edge.
    pub left: f64,
    /// Top edge.
    pub top: f64,
    /// Width (positive).
    pub width: f64,
    /// Height (positive).
    pub height: f64,
}

impl Rect {
    /// Right edge.
    pub fn right(&self) -> f64 {
        self.left + self.width
    }

    /// Bottom edge.
    pub fn bottom(&self) -> f64 {
        self.top + self.height
    }

    /// Centre point.
    pub fn center(&self) -> Point {
        Point::new(self.left + self.width / 2.0, self.top + self.height / 2.0)
    }

    /// The four corners, clockwise on screen from the top left: the
    /// rectangle as a polygon.
    ///
    /// ```
    /// use kreisel_plot::figure::{Point, Rect};
    /// let r = Rect { left: 1.0, top: 2.0, width: 3.0, height: 4.0 };
    /// assert_eq!(r.corners(), vec![
    ///     Point::new(1.0, 2.0), Point::new(4.0, 2.0), Point::new(4.0, 6.0), Point::new(1.0, 6.0),
    /// ]);
    /// ```
    pub fn corners(&self) -> Vec<Point> {
        vec![
            Point::new(self.left, self.top),
            Point::new(self.right(), self.top),
            Point::new(self.right(), self.bottom()),
            Point::new(self.left, self.bottom()),
        ]
    }

    /// Whether `p` lies inside or on the edge.
    pub fn contains(&self, p: Point) -> bool {
        (self.left..=self.right()).contains(&p.x) && (self.top..=self.bottom()).contains(&p.y)
    }
}

/// Cuts a polyline to the parts inside `rect` (Liang–Barsky on each
/// segment): one polyline per run that stays inside.
///
/// ```
/// use kreisel_plot::figure::{Point, Rect, clip_polyline};
///
/// let frame = Rect { left: 0.0, top: 0.0, width: 10.0, height: 10.0 };
/// // In, out through the right edge, and back in.
/// let line = [Point::new(5.0, 2.0), Point::new(15.0, 2.0), Point::new(15.0, 8.0), Point::new(5.0, 8.0)];
/// let runs = clip_polyline(&line, frame);
/// assert_eq!(runs, vec![
///     vec![Point::new(5.0, 2.0), Point::new(10.0, 2.0)],
///     vec![Point::new(10.0, 8.0), Point::new(5.0, 8.0)],
/// ]);
/// ```
pub fn clip_polyline(points: &[Point], rect: Rect) -> Vec<Vec<Point>> {
    let mut runs: Vec<Vec<Point>> = Vec::new();
    let mut current: Vec<Point> = Vec::new();
    for pair in points.windows(2) {
        match clip_segment(pair[0], pair[1], rect) {
            Some((a, b)) => {
                let joins = current.last().is_some_and(|last| *last == a);
                if !joins {
                    if current.len() >= 2 {
                        runs.push(std::mem::take(&mut current));
                    }
                    current.clear();
                    current.push(a);
                }
                current.push(b);
            }
            None => {
                if current.len() >= 2 {
                    runs.push(std::mem::take(&mut current));
                }
                current.clear();
            }
        }
    }
    if current.len() >= 2 {
        runs.push(current);
    }
    runs
}

/// The part of the segment `a`–`b` inside `rect`, if any.
fn clip_segment(a: Point, b: Point, rect: Rect) -> Option<(Point, Point)> {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    for (p, q) in [
        (-dx, a.x - rect.left),
        (dx, rect.right() - a.x),
        (-dy, a.y - rect.top),
        (dy, rect.bottom() - a.y),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    if t0 > t1 || !t0.is_finite() || !t1.is_finite() {
        return None;
    }
    let at = |t: f64| {
        if t == 0.0 {
            a
        } else if t == 1.0 {
            b
        } else {
            Point::new(a.x + t * dx, a.y + t * dy)
        }
    };
    Some((at(t0), at(t1)))
}

#[cfg(test)]
mod tests {
    use super::*;

    const BOX: Rect = Rect {
        left: 0.0,
        top: 0.0,
        width: 10.0,
        height: 10.0,
    };

    #[test]
    fn clipping_keeps_inside_runs() {
        let inside = vec![
            Point::new(1.0, 1.0),
            Point::new(5.0, 5.0),
            Point::new(9.0, 1.0),
        ];
        assert_eq!(clip_polyline(&inside, BOX), vec![inside.clone()]);
        // Out through the bottom and back in: two runs, cut at y = 10.
        let pts = [
            Point::new(2.0, 5.0),
            Point::new(2.0, 15.0),
            Point::new(8.0, 5.0),
        ];
        let runs = clip_polyline(&pts, BOX);
        assert_eq!(runs.len(), 2);
        assert_eq!(runs[0], vec![Point::new(2.0, 5.0), Point::new(2.0, 10.0)]);
        assert!((runs[1][0].y - 10.0).abs() < 1e-12 && runs[1][1] == Point::new(8.0, 5.0));
        assert!(clip_polyline(&[Point::new(-1.0, -1.0), Point::new(-5.0, 20.0)], BOX).is_empty());
    }

    #[test]
    fn colours_print_as_hex() {
        assert_eq!(Color::rgb(255, 16, 0).hex(), "#ff1000");
        assert_eq!(Color::BLACK.with_alpha(51).opacity(), 0.2);
    }
}
