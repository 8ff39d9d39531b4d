//! Curves on the unit sphere seen in an orthographic view from above at an
//! angle: the silhouette, circles of latitude, and any path of unit vectors,
//! with the parts on the hidden (back) hemisphere dimmed.
//!
//! World axes: z up. The viewer looks at the origin from the direction
//! `toward_viewer = (cos e cos a, cos e sin a, sin e)` (elevation `e` above
//! the horizontal plane, azimuth `a` from +x towards +y); the screen's right
//! is the horizontal unit vector perpendicular to it, its up completes a
//! right-handed frame (`right × up = toward_viewer`), so world z projects
//! straight up.

use glam::DVec3;

use crate::figure::{Anchor, Color, Figure, Point, Rect, Stroke, Text, clip_polyline};

/// An orthographic view direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    /// Angle of the line of sight above the horizontal plane, radians.
    pub elevation: f64,
    /// Azimuth of the viewer, from +x towards +y, radians.
    pub azimuth: f64,
}

/// A point projected on the screen: `x` right, `y` up (in sphere radii),
/// `depth` towards the viewer (positive on the visible hemisphere).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Projected {
    /// Screen right.
    pub x: f64,
    /// Screen up.
    pub y: f64,
    /// Towards the viewer.
    pub depth: f64,
}

impl View {
    /// The screen's right, up and towards-the-viewer unit vectors in world coordinates.
    pub fn basis(&self) -> (DVec3, DVec3, DVec3) {
        let (se, ce) = self.elevation.sin_cos();
        let (sa, ca) = self.azimuth.sin_cos();
        let toward = DVec3::new(ce * ca, ce * sa, se);
        let right = DVec3::new(-sa, ca, 0.0);
        let up = toward.cross(right);
        (right, up, toward)
    }

    /// Orthographic projection of `v` (world coordinates).
    pub fn project(&self, v: DVec3) -> Projected {
        let (right, up, toward) = self.basis();
        Projected {
            x: v.dot(right),
            y: v.dot(up),
            depth: v.dot(toward),
        }
    }
}

/// A sphere of radius `radius` px drawn around `center` in the view `view`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpherePanel {
    /// Where the sphere's centre is drawn.
    pub center: Point,
    /// The silhouette's radius in pixels.
    pub radius: f64,
    /// The view direction.
    pub view: View,
}

/// Opacity of a line on the hidden hemisphere, out of 255.
const HIDDEN_ALPHA: u8 = 70;

impl SpherePanel {
    /// Figure pixels of `v`, and whether it is on the visible hemisphere.
    pub fn pixel(&self, v: DVec3) -> (Point, bool) {
        let p = self.view.project(v);
        (
            Point::new(
                self.center.x + self.radius * p.x,
                self.center.y - self.radius * p.y,
            ),
            p.depth >= 0.0,
        )
    }

    /// The silhouette, lightly filled (for a sphere whose axes the caller
    /// draws itself).
    pub fn draw_outline(&self, fig: &mut Figure) {
        fig.circle(
            self.center,
            self.radius,
            Some(Color::rgb(242, 245, 250)),
            Some(Stroke::solid(Color::rgb(90, 90, 90), 1.5)),
        );
    }

    /// The silhouette (lightly filled), the equator and the vertical axis,
    /// labelled `z`.
    pub fn draw_frame(&self, fig: &mut Figure) {
        self.draw_outline(fig);
        let equator = circle_of_latitude(std::f64::consts::FRAC_PI_2, 180);
        self.path(fig, &equator, &Stroke::dashed(Color::GREY, 1.0, 5.0, 4.0));
        let bottom = self.pixel(-DVec3::Z).0;
        let top = self.pixel(DVec3::Z * 1.2).0;
        let pole = self.pixel(DVec3::Z).0;
        // Inside the sphere the axis is hidden: faint; above the pole, solid.
        let inside = Stroke::dashed(Color::GREY.with_alpha(HIDDEN_ALPHA), 1.0, 3.0, 3.0);
        fig.line(bottom, pole, inside);
        fig.line(pole, top, Stroke::solid(Color::GREY, 1.0));
        fig.circle(self.pixel(DVec3::Z).0, 2.5, Some(Color::GREY), None);
        fig.text(Text::new(
            Point::new(top.x + 6.0, top.y + 5.0),
            "z (up)",
            13.0,
            Anchor::Start,
        ));
    }

    /// Draws a path of points on (or near) the sphere: the stretches on the
    /// visible hemisphere with `stroke`, the hidden ones fainter and thinner.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_plot::Figure;
    /// use kreisel_plot::figure::{Color, Point, Primitive, Stroke};
    /// use kreisel_plot::sphere::{SpherePanel, View, circle_of_latitude};
    ///
    /// let panel = SpherePanel {
    ///     center: Point::new(150.0, 150.0),
    ///     radius: 100.0,
    ///     view: View { elevation: 0.4, azimuth: 0.3 },
    /// };
    /// // The north pole is drawn straight above the centre, and seen.
    /// let (pole, visible) = panel.pixel(DVec3::Z);
    /// assert!(visible && pole.y < 150.0 && (pole.x - 150.0).abs() < 1e-9);
    ///
    /// let mut fig = Figure::new(300, 300);
    /// let blue = Stroke::solid(Color::rgb(0, 0, 200), 2.0);
    /// panel.path(&mut fig, &circle_of_latitude(1.0, 120), &blue);
    /// // In stretches: opaque in front, faint behind.
    /// let alphas: Vec<u8> = fig.items.iter().map(|item| match item {
    ///     Primitive::Polyline { stroke, .. } => stroke.color.a,
    ///     _ => unreachable!("a path is polylines"),
    /// }).collect();
    /// assert!(alphas.len() >= 2 && alphas.contains(&255) && alphas.iter().any(|&a| a < 255));
    /// ```
    pub fn path(&self, fig: &mut Figure, points: &[DVec3], stroke: &Stroke) {
        let hidden = Stroke {
            color: stroke.color.with_alpha(HIDDEN_ALPHA),
            width: stroke.width * 0.7,
            dash: stroke.dash.clone(),
        };
        let mut run: Vec<Point> = Vec::new();
        let mut run_front = true;
        for &v in points {
            let (p, front) = self.pixel(v);
            if front != run_front && !run.is_empty() {
                // The boundary point belongs to both runs, so they join.
                run.push(p);
                let style = if run_front { stroke } else { &hidden };
                fig.polyline(std::mem::take(&mut run), style.clone());
            }
            run_front = front;
            run.push(p);
        }
        if run.len() == 1 {
            // A path that never moves (a sleeping top's axis): a dot.
            let style = if run_front { stroke } else { &hidden };
            fig.circle(run[0], style.width * 1.5 + 1.0, Some(style.color), None);
        } else {
            let style = if run_front { stroke } else { &hidden };
            fig.polyline(run, style.clone());
        }
    }

    /// The circle of polar angle `theta` (from +z), hidden part faint, with
    /// `label` beside its front-most point when not empty.
    pub fn latitude(&self, fig: &mut Figure, theta: f64, stroke: &Stroke, label: &str) {
        let circle = circle_of_latitude(theta, 240);
        self.path(fig, &circle, stroke);
        if !label.is_empty() {
            // The point of the circle towards the viewer's right-front.
            let (right, _, toward) = self.view.basis();
            let dir = (right + toward).with_z(0.0).normalize_or_zero();
            let (p, _) = self.pixel(dir * theta.sin() + DVec3::Z * theta.cos());
            fig.text(
                Text::new(Point::new(p.x + 6.0, p.y + 4.0), label, 13.0, Anchor::Start)
                    .colored(stroke.color),
            );
        }
    }
}

/// A magnified view of a small patch of the sphere around `center`:
/// orthographic projection onto the tangent plane there, east to the right,
/// north (towards +z) up, `scale` px per radian, clipped to `frame`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LocalView {
    /// Where the patch is drawn.
    pub frame: Rect,
    /// The unit vector drawn at the frame's centre.
    pub center: DVec3,
    /// Pixels per radian (per unit length in the tangent plane).
    pub scale: f64,
}

impl LocalView {
    /// The east and north unit vectors of the tangent plane at the centre
    /// (east = z × centre; about x at the poles).
    pub fn basis(&self) -> (DVec3, DVec3) {
        let east = DVec3::Z
            .cross(self.center)
            .try_normalize()
            .unwrap_or(DVec3::X);
        (east, self.center.cross(east))
    }

    /// Figure pixels of `v`.
    pub fn pixel(&self, v: DVec3) -> Point {
        let (east, north) = self.basis();
        let c = self.frame.center();
        Point::new(
            c.x + self.scale * v.dot(east),
            c.y - self.scale * v.dot(north),
        )
    }

    /// Draws the path, clipped to the frame.
    pub fn path(&self, fig: &mut Figure, points: &[DVec3], stroke: &Stroke) {
        let px: Vec<Point> = points.iter().map(|&v| self.pixel(v)).collect();
        for run in clip_polyline(&px, self.frame) {
            fig.polyline(run, stroke.clone());
        }
    }
}

/// `n + 1` points (closed) of the circle at polar angle `theta` from +z.
pub fn circle_of_latitude(theta: f64, n: usize) -> Vec<DVec3> {
    let (s, c) = theta.sin_cos();
    (0..=n)
        .map(|k| {
            let phi = std::f64::consts::TAU * k as f64 / n as f64;
            DVec3::new(s * phi.cos(), s * phi.sin(), c)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn views() -> Vec<View> {
        let mut out = Vec::new();
        for e in [-1.2, 0.0, 0.3, 0.6, 1.5] {
            for a in [-2.0, -1.0, 0.0, 0.7, 3.0] {
                out.push(View {
                    elevation: e,
                    azimuth: a,
                });
            }
        }
        out
    }

    #[test]
    fn projection_is_a_rotation() {
        for view in views() {
            let (r, u, t) = view.basis();
            assert!((r.length() - 1.0).abs() < 1e-15 && (u.length() - 1.0).abs() < 1e-15);
            assert!(r.dot(u).abs() < 1e-15 && r.dot(t).abs() < 1e-15 && u.dot(t).abs() < 1e-15);
            assert!((r.cross(u) - t).length() < 1e-15, "right-handed");
            // Lengths are kept: x² + y² + depth² = |v|².
            for v in [
                DVec3::new(0.3, -0.5, 0.8),
                DVec3::X,
                DVec3::new(-2.0, 1.0, 0.5),
            ] {
                let p = view.project(v);
                assert!(
                    (p.x * p.x + p.y * p.y + p.depth * p.depth - v.length_squared()).abs() < 1e-14
                );
            }
        }
    }

    #[test]
    fn vertical_projects_up_and_the_rim_onto_the_silhouette() {
        for view in views() {
            let z = view.project(DVec3::Z);
            assert!(z.x.abs() < 1e-15);
            assert!((z.y - view.elevation.cos()).abs() < 1e-15);
            assert!((z.depth - view.elevation.sin()).abs() < 1e-15);
            // Points with depth 0 (the rim) land on the unit circle.
            let (r, u, _) = view.basis();
            for k in 0..12 {
                let a = k as f64 * 0.5;
                let rim = r * a.cos() + u * a.sin();
                let p = view.project(rim);
                assert!((p.x.hypot(p.y) - 1.0).abs() < 1e-14 && p.depth.abs() < 1e-14);
            }
        }
    }

    #[test]
    fn local_view_is_east_right_north_up() {
        let center = DVec3::new(0.0, -0.5f64.sin(), 0.5f64.cos());
        let view = LocalView {
            frame: Rect {
                left: 0.0,
                top: 0.0,
                width: 100.0,
                height: 50.0,
            },
            center,
            scale: 1000.0,
        };
        let (east, north) = view.basis();
        assert!((east - DVec3::X).length() < 1e-15, "{east}");
        assert!(north.z > 0.0 && north.dot(center).abs() < 1e-15);
        assert_eq!(view.pixel(center), Point::new(50.0, 25.0));
        // A step up in latitude (smaller theta) goes up on screen.
        let up = DVec3::new(0.0, -0.49f64.sin(), 0.49f64.cos());
        let p = view.pixel(up);
        assert!(
            p.x.abs() - 50.0 < 1e-9 && (p.y - (25.0 - 10.0)).abs() < 1e-3,
            "{p:?}"
        );
    }

    #[test]
    fn pixels_flip_y_and_hide_the_back() {
        let panel = SpherePanel {
            center: Point::new(100.0, 100.0),
            radius: 50.0,
            view: View {
                elevation: 0.0,
                azimuth: -std::f64::consts::FRAC_PI_2,
            },
        };
        // Seen from −y: x is right, z is up, −y is towards the viewer.
        let (p, front) = panel.pixel(DVec3::Z);
        assert!((p.x - 100.0).abs() < 1e-12 && (p.y - 50.0).abs() < 1e-12 && front);
        let (p, front) = panel.pixel(DVec3::X);
        assert!((p.x - 150.0).abs() < 1e-12 && (p.y - 100.0).abs() < 1e-12 && front);
        assert!(panel.pixel(-DVec3::Y).1 && !panel.pixel(DVec3::new(0.0, 1.0, 0.1)).1);
        let circle = circle_of_latitude(0.5, 8);
        assert_eq!(circle.len(), 9);
        assert!(
            circle
                .iter()
                .all(|v| (v.length() - 1.0).abs() < 1e-15 && (v.z - 0.5f64.cos()).abs() < 1e-15)
        );
    }
}
