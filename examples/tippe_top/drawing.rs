//! The top seen from the side, as a [`Figure`]: the ball (a sphere cut
//! flat where the stem starts), the stem with its ball, the floor, a
//! body-fixed marker on the ball's equator (so the spin shows), the centre
//! of mass, and the tilt so far as a small chart.
//!
//! The camera turns with the precession: an orthographic view from the
//! side of the vertical plane that holds the axis, the axis leaning to the
//! right, looking down by [`ELEVATION`], so the tilt θ shows at (nearly)
//! its true angle (a fixed camera loses the stem behind the ball half of
//! the time). The view follows the ball's centre horizontally.

use glam::{DQuat, DVec3};
use kreisel::dynamics::BodyState;
use kreisel_plot::Figure;
use kreisel_plot::axes::{Axes, Labels};
use kreisel_plot::figure::{Anchor, Color, Point, Rect, Stroke, Text};

use super::simulation::{BALL_OFFSET, BALL_RADIUS, STEM_OFFSET, STEM_RADIUS};

/// Size of a frame, pixels.
pub const WIDTH: u32 = 640;
/// See [`WIDTH`].
pub const HEIGHT: u32 = 300;

/// Pixels per metre of the side view.
const SCALE: f64 = 3600.0;
/// The floor's height on the frame, pixels from the top.
const FLOOR: f64 = 250.0;
/// The side view's centre line, pixels from the left.
const CENTRE: f64 = 150.0;
/// Where the flat cut of the ball lies, from its centre along the axis, m.
const CUT: f64 = 0.75 * BALL_RADIUS;
/// Radius of the stem's shaft, m.
const SHAFT: f64 = 0.002;
/// How far the table reaches behind the contact point, m.
const FLOOR_DEPTH: f64 = 0.06;
/// How far the camera looks down, rad.
pub const ELEVATION: f64 = 0.25;
/// Points on a drawn circle.
const SEGMENTS: usize = 96;

const BALL: Color = Color::rgb(70, 110, 170);
const CAP: Color = Color::rgb(130, 165, 215);
const STEM: Color = Color::rgb(60, 60, 70);
const MARK: Color = Color::rgb(230, 60, 40);
const THETA_LINE: Color = Color::rgb(31, 119, 180);

/// What one frame shows.
#[derive(Debug, Clone, Copy)]
pub struct FrameData<'a> {
    /// The state drawn.
    pub state: &'a BodyState,
    /// Its time, s.
    pub time: f64,
    /// (t, θ in degrees) up to now.
    pub tilt_history: &'a [(f64, f64)],
    /// The run's length, s (the chart's x range).
    pub duration: f64,
    /// The axis' first horizontal passage, once passed.
    pub horizontal_at: Option<f64>,
    /// Whether the ball and the stem touch the table.
    pub touching: [bool; 2],
}

/// The camera: screen right and the direction towards the viewer (both
/// horizontal), and the point drawn on the centre line.
#[derive(Debug, Clone, Copy)]
struct View {
    origin: DVec3,
    right: DVec3,
    up: DVec3,
    to_viewer: DVec3,
}

impl View {
    /// The view of a top whose axis is `axis` and ball centre `ball`.
    fn new(axis: DVec3, ball: DVec3) -> Self {
        let lean = DVec3::new(axis.x, axis.y, 0.0);
        let right = if lean.length() > 1e-9 {
            lean.normalize()
        } else {
            DVec3::X
        };
        let to_viewer = ELEVATION.cos() * right.cross(DVec3::Z) + ELEVATION.sin() * DVec3::Z;
        Self {
            origin: DVec3::new(ball.x, ball.y, 0.0),
            right,
            up: to_viewer.cross(right),
            to_viewer,
        }
    }

    /// Screen position of a world point.
    fn project(&self, p: DVec3) -> Point {
        let d = p - self.origin;
        Point::new(
            CENTRE + d.dot(self.right) * SCALE,
            FLOOR - d.dot(self.up) * SCALE,
        )
    }
}

/// Lower convex hull turn test.
fn cross(o: Point, a: Point, b: Point) -> f64 {
    (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x)
}

/// The convex hull of `points` (Andrew's monotone chain), counter-clockwise.
fn convex_hull(mut points: Vec<Point>) -> Vec<Point> {
    points.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    let mut hull: Vec<Point> = Vec::with_capacity(points.len() + 1);
    for pass in 0..2 {
        let start = hull.len();
        let iter: Box<dyn Iterator<Item = &Point>> = if pass == 0 {
            Box::new(points.iter())
        } else {
            Box::new(points.iter().rev())
        };
        for &p in iter {
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0
            {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
    }
    hull
}

/// Points of the circle of `radius` about `centre` perpendicular to `normal`.
fn circle_3d(centre: DVec3, normal: DVec3, radius: f64) -> Vec<DVec3> {
    let u = normal.any_orthonormal_vector();
    let v = normal.cross(u);
    (0..=SEGMENTS)
        .map(|k| {
            let phi = std::f64::consts::TAU * k as f64 / SEGMENTS as f64;
            centre + radius * (phi.cos() * u + phi.sin() * v)
        })
        .collect()
}

/// The top itself.
fn draw_top(fig: &mut Figure, state: &BodyState) {
    let q: DQuat = state.world_from_body.normalize();
    let axis = q * DVec3::Z;
    let ball = state.position + BALL_OFFSET * axis;
    let view = View::new(axis, ball);
    let to_viewer = view.to_viewer;
    let px = |p: DVec3| view.project(p);
    // The ball without its cap: the hull of the silhouette (the great
    // circle facing the viewer) below the cut and of the cut's rim.
    let rim_centre = ball + CUT * axis;
    let rim = circle_3d(
        rim_centre,
        axis,
        (BALL_RADIUS * BALL_RADIUS - CUT * CUT).sqrt(),
    );
    let outline: Vec<Point> = circle_3d(ball, to_viewer, BALL_RADIUS)
        .into_iter()
        .filter(|p| (*p - ball).dot(axis) <= CUT)
        .chain(rim.iter().copied())
        .map(px)
        .collect();
    let stem_ball = state.position + STEM_OFFSET * axis;
    let stem_in_front = axis.dot(to_viewer) > 0.0;
    let draw_stem = |fig: &mut Figure| {
        fig.line(
            px(rim_centre),
            px(stem_ball),
            Stroke::solid(STEM, 2.0 * SHAFT * SCALE),
        );
        fig.circle(px(stem_ball), STEM_RADIUS * SCALE, Some(STEM), None);
        fig.circle(
            px(stem_ball + 0.4 * STEM_RADIUS * DVec3::new(-1.0, 0.0, 1.0)),
            0.3 * STEM_RADIUS * SCALE,
            Some(Color::rgb(140, 140, 150)),
            None,
        );
    };
    let shadow: Vec<Point> = circle_3d(view.origin, DVec3::Z, 0.8 * BALL_RADIUS)
        .into_iter()
        .map(px)
        .collect();
    fig.polygon(shadow, Color::rgb(120, 100, 70).with_alpha(90), None);
    if !stem_in_front {
        draw_stem(fig);
    }
    fig.polygon(
        convex_hull(outline),
        BALL,
        Some(Stroke::solid(Color::rgb(30, 50, 90), 1.5)),
    );
    // A highlight towards the light (up and left), on the sphere's part.
    let light = ball + 0.45 * BALL_RADIUS * (view.up + view.to_viewer - view.right).normalize();
    if (light - ball).dot(axis) < CUT {
        fig.circle(
            px(light),
            0.28 * BALL_RADIUS * SCALE,
            Some(Color::WHITE.with_alpha(70)),
            None,
        );
    }
    // The flat cut, when it faces the viewer (always, seen edge-on at most,
    // with this camera; kept general).
    if stem_in_front {
        let cap: Vec<Point> = rim.iter().copied().map(px).collect();
        fig.polygon(cap, CAP, Some(Stroke::solid(Color::rgb(30, 50, 90), 1.0)));
        draw_stem(fig);
    }
    // The equator (its visible half) and a body-fixed marker on it.
    let equator = circle_3d(ball, axis, BALL_RADIUS);
    for pair in equator.windows(2) {
        if (pair[0] - ball).dot(to_viewer) > 0.0 && (pair[1] - ball).dot(to_viewer) > 0.0 {
            fig.line(
                px(pair[0]),
                px(pair[1]),
                Stroke::solid(Color::rgb(200, 215, 235), 1.5),
            );
        }
    }
    for (k, colour) in [(1.0, MARK), (-1.0, Color::rgb(250, 200, 40))] {
        let mark = ball + BALL_RADIUS * (q * DVec3::new(k, 0.0, 0.0));
        if (mark - ball).dot(to_viewer) > 0.0 {
            fig.circle(
                px(mark),
                5.0,
                Some(colour),
                Some(Stroke::solid(Color::BLACK, 1.0)),
            );
        }
    }
    // The centre of mass.
    let g = px(state.position);
    fig.circle(
        g,
        3.5,
        Some(Color::WHITE),
        Some(Stroke::solid(Color::BLACK, 1.5)),
    );
    fig.circle(g, 1.2, Some(Color::BLACK), None);
}

/// One frame: the side view on the left, θ(t) so far on the right.
pub fn frame_figure(data: &FrameData<'_>) -> Figure {
    let mut fig = Figure::new(WIDTH, HEIGHT);
    // The table, seen from above at ELEVATION: its far edge FLOOR_DEPTH behind the contact.
    let far = FLOOR - FLOOR_DEPTH * ELEVATION.sin() * SCALE;
    fig.polygon(
        Rect {
            left: 0.0,
            top: far,
            width: 300.0,
            height: f64::from(HEIGHT) - far,
        }
        .corners(),
        Color::rgb(228, 218, 198),
        None,
    );
    fig.line(
        Point::new(0.0, far),
        Point::new(300.0, far),
        Stroke::solid(Color::rgb(150, 130, 100), 1.5),
    );
    draw_top(&mut fig, data.state);
    let theta = super::simulation::tilt(data.state).to_degrees();
    fig.text(Text::new(
        Point::new(12.0, 24.0),
        format!("t = {:.3} s", data.time),
        15.0,
        Anchor::Start,
    ));
    fig.text(
        Text::new(
            Point::new(12.0, 44.0),
            format!("θ = {theta:.1}°"),
            15.0,
            Anchor::Start,
        )
        .colored(THETA_LINE),
    );
    let on = match data.touching {
        [true, true] => "on the ball and the stem",
        [true, false] => "on the ball",
        [false, true] => "on the stem",
        [false, false] => "in the air",
    };
    fig.text(Text::new(
        Point::new(12.0, 64.0),
        on.to_owned(),
        13.0,
        Anchor::Start,
    ));
    if let Some(t) = data.horizontal_at {
        fig.text(Text::new(
            Point::new(12.0, 82.0),
            format!("horizontal at {t:.3} s"),
            13.0,
            Anchor::Start,
        ));
    }
    let axes = Axes {
        frame: Rect {
            left: 360.0,
            top: 30.0,
            width: 260.0,
            height: 220.0,
        },
        x_range: (0.0, data.duration),
        y_range: (0.0, 180.0),
    };
    axes.draw(
        &mut fig,
        &Labels {
            title: "tilt of the axis",
            x: "t (s)",
            y: "θ (degrees)",
        },
    );
    fig.line(
        axes.pixel(0.0, 90.0),
        axes.pixel(data.duration, 90.0),
        Stroke::dashed(Color::GREY, 1.0, 4.0, 3.0),
    );
    axes.curve(&mut fig, data.tilt_history, &Stroke::solid(THETA_LINE, 2.0));
    axes.marker(&mut fig, data.time, theta, 4.0, THETA_LINE);
    fig
}

/// The frame as `0x00RRGGBB` pixels on white.
///
/// # Errors
/// [`kreisel_plot::PlotError`] from the rasteriser.
pub fn frame_pixels(data: &FrameData<'_>) -> Result<Vec<u32>, kreisel_plot::PlotError> {
    let mut pixels = vec![0x00ff_ffff_u32; (WIDTH * HEIGHT) as usize];
    kreisel_plot::png::draw_over_rgb(&frame_figure(data), &mut pixels)?;
    Ok(pixels)
}
