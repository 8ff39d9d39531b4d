//! Where the figure's on-sphere labels go: the θmin and θmax circles are
//! labelled beside a point of their own circle where the label's box
//! crosses nothing else drawn there (the axis path, the circles, the other
//! label, the z axis and its label, the magnified inset), and inside the
//! sphere's panel. A label with no free place is left out (the legend
//! below the sphere names both circles with their values).
//!
//! Text boxes are estimated, not measured: 0.75 em per character (DejaVu
//! Sans averages ~0.6 em; its widest glyphs, `m` and `W`, ~1 em) from the
//! baseline 0.85 em up to 0.25 em down, and 2 px of margin.

use glam::DVec3;
use kreisel_plot::figure::{Color, Point, Rect, clip_polyline};
use kreisel_plot::sphere::{SpherePanel, circle_of_latitude};

/// Font size of the circles' labels, px.
pub const LABEL_SIZE: f64 = 13.0;

/// A label placed on the figure: its text, where its baseline starts
/// (anchored at the start), its estimated box and colour.
#[derive(Debug, Clone, PartialEq)]
pub struct PlacedLabel {
    /// The text.
    pub text: String,
    /// The start of its baseline.
    pub at: Point,
    /// The box it covers (estimated, see the module docs).
    pub bounds: Rect,
    /// Its colour.
    pub color: Color,
}

/// The estimated box of `text` at `size` px with its baseline starting at `at`.
pub fn text_box(at: Point, text: &str, size: f64) -> Rect {
    let width = 0.75 * size * text.chars().count() as f64;
    Rect {
        left: at.x - 2.0,
        top: at.y - 0.85 * size - 2.0,
        width: width + 4.0,
        height: 1.1 * size + 4.0,
    }
}

/// Whether two boxes share any point.
pub fn boxes_overlap(a: &Rect, b: &Rect) -> bool {
    a.left <= b.right() && b.left <= a.right() && a.top <= b.bottom() && b.top <= a.bottom()
}

/// Whether the polyline (a single point: a dot) enters `rect`.
pub fn line_enters(line: &[Point], rect: Rect) -> bool {
    match line {
        [] => false,
        [p] => rect.contains(*p),
        _ => !clip_polyline(line, rect).is_empty(),
    }
}

/// What the labels must keep clear of.
pub struct Obstacles<'a> {
    /// Polylines in figure pixels (the axis path, the z axis, ...).
    pub lines: Vec<Vec<Point>>,
    /// Boxes (other text, the inset).
    pub boxes: Vec<Rect>,
    /// The region the labels must stay inside.
    pub region: Rect,
    /// The sphere, to place the circles.
    pub panel: &'a SpherePanel,
}

impl Obstacles<'_> {
    /// Whether `rect` is inside the region and clear of everything.
    fn free(&self, rect: &Rect) -> bool {
        let r = &self.region;
        let inside = rect.left >= r.left
            && rect.right() <= r.right()
            && rect.top >= r.top
            && rect.bottom() <= r.bottom();
        inside
            && !self.boxes.iter().any(|b| boxes_overlap(b, rect))
            && !self.lines.iter().any(|l| line_enters(l, *rect))
    }
}

/// The circle of latitude `theta` in figure pixels.
pub fn circle_pixels(panel: &SpherePanel, theta: f64) -> Vec<Point> {
    circle_of_latitude(theta, 240)
        .into_iter()
        .map(|v| panel.pixel(v).0)
        .collect()
}

/// Places the labels `(text, polar angle of its circle, colour)` in turn,
/// each clear of the obstacles and of the labels placed before it (see the
/// module docs). The circles themselves are obstacles too.
pub fn place(labels: &[(String, f64, Color)], mut obstacles: Obstacles<'_>) -> Vec<PlacedLabel> {
    for &(_, theta, _) in labels {
        obstacles.lines.push(circle_pixels(obstacles.panel, theta));
    }
    let (right, _, toward) = obstacles.panel.view.basis();
    // Azimuths of the circle's points, most in front and to the right first.
    let preferred = (right + toward).with_z(0.0).normalize_or(DVec3::X);
    let mut azimuths: Vec<DVec3> = (0..48)
        .map(|k| {
            let a = std::f64::consts::TAU * f64::from(k) / 48.0;
            DVec3::new(a.cos(), a.sin(), 0.0)
        })
        .collect();
    azimuths.sort_by(|x, y| y.dot(preferred).total_cmp(&x.dot(preferred)));
    let mut placed = Vec::new();
    for (text, theta, color) in labels {
        let width = text_box(Point::new(0.0, 0.0), text, LABEL_SIZE).width;
        let (s, c) = theta.sin_cos();
        let spot = azimuths.iter().find_map(|dir| {
            let (p, visible) = obstacles.panel.pixel(*dir * s + DVec3::Z * c);
            if !visible {
                return None;
            }
            // Right, left, above, below the point.
            [
                Point::new(p.x + 6.0, p.y + 4.0),
                Point::new(p.x - 6.0 - width, p.y + 4.0),
                Point::new(p.x - 0.5 * width, p.y - 8.0),
                Point::new(p.x - 0.5 * width, p.y + 18.0),
            ]
            .into_iter()
            .map(|at| (at, text_box(at, text, LABEL_SIZE)))
            .find(|(_, b)| obstacles.free(b))
        });
        if let Some((at, bounds)) = spot {
            obstacles.boxes.push(bounds);
            placed.push(PlacedLabel {
                text: text.clone(),
                at,
                bounds,
                color: *color,
            });
        }
    }
    placed
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::top::figure::{SPHERE, SPHERE_REGION, TopPlot, sphere_labels};
    use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};

    /// The labels of the figure of a real top, with the path in pixels.
    fn labels_of(theta: f64, phi_dot: f64, psi_dot: f64) -> (Vec<PlacedLabel>, Vec<Point>, f64) {
        let motion = LagrangeTop::new(0.3, 0.1, 2.0)
            .try_solve(LagrangeTopInitial {
                theta,
                phi_dot,
                psi_dot,
                ..LagrangeTopInitial::default()
            })
            .unwrap();
        let (path, caption, per_period) = crate::top::axis_path(&motion);
        let f = |u: f64| motion.f(u);
        let roots = motion.roots();
        let plot = TopPlot {
            title: String::new(),
            axis_path: &path,
            path_caption: caption,
            theta_min: motion.theta_min(),
            theta_max: motion.theta_max(),
            f: &f,
            roots: &roots,
            beta: motion.beta(),
            samples_per_period: per_period,
            degrees: false,
        };
        let pixels = path.iter().map(|&v| SPHERE.pixel(v).0).collect();
        (
            sphere_labels(&plot, &SPHERE),
            pixels,
            motion.theta_max() - motion.theta_min(),
        )
    }

    #[test]
    fn circle_labels_clear_each_other_and_the_path() {
        let (mut narrow, mut wide) = (0, 0);
        for theta in [0.2, 0.5, 1.0, 1.6, 2.2, 2.9] {
            for psi_dot in [0.0, 3.0, 10.0, 30.0, 60.0, 300.0, 3000.0] {
                for phi_dot in [0.0, -2.0, 1.0] {
                    let (labels, path, band) = labels_of(theta, phi_dot, psi_dot);
                    let case = format!("θ₀ {theta}, φ̇₀ {phi_dot}, ψ̇₀ {psi_dot}, band {band:e}");
                    for (i, l) in labels.iter().enumerate() {
                        assert!(!line_enters(&path, l.bounds), "{case}: {l:?} on the path");
                        for m in &labels[i + 1..] {
                            assert!(!boxes_overlap(&l.bounds, &m.bounds), "{case}: {l:?} {m:?}");
                        }
                        let r = SPHERE_REGION;
                        let inside = l.bounds.left >= r.left
                            && l.bounds.right() <= r.right()
                            && l.bounds.top >= r.top
                            && l.bounds.bottom() <= r.bottom();
                        assert!(inside, "{case}: {l:?}");
                    }
                    if band > 0.0 && labels.len() == 2 {
                        if band < 0.05 {
                            narrow += 1;
                        } else {
                            wide += 1;
                        }
                    }
                }
            }
        }
        // Not vacuous: most narrow and wide bands have both labels.
        eprintln!("both labels on {narrow} narrow and {wide} wide bands");
        assert!(narrow >= 20 && wide >= 20, "{narrow} narrow, {wide} wide");
        // The narrow band (0.0167 rad): both labels, apart.
        let (labels, _, band) = labels_of(0.5, 0.0, 60.0);
        assert!(band < 0.02 && labels.len() == 2, "{labels:?}");
    }

    #[test]
    fn boxes_and_lines_meet_where_they_should() {
        let a = Rect {
            left: 0.0,
            top: 0.0,
            width: 10.0,
            height: 10.0,
        };
        let b = Rect { left: 10.5, ..a };
        assert!(!boxes_overlap(&a, &b));
        assert!(boxes_overlap(&a, &Rect { left: 9.0, ..a }));
        let through = [Point::new(-5.0, 5.0), Point::new(15.0, 5.0)];
        let beside = [Point::new(-5.0, 11.0), Point::new(15.0, 11.0)];
        assert!(line_enters(&through, a) && !line_enters(&beside, a));
        assert!(line_enters(&[Point::new(5.0, 5.0)], a));
        // 4 characters at 13 px: 39 px wide + margins.
        let t = text_box(Point::new(100.0, 50.0), "θmin", 13.0);
        assert_eq!((t.left, t.width), (98.0, 43.0));
    }
}
