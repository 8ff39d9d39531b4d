//! The figure of `kreisel top --plot`: the path of the symmetry axis on the
//! unit sphere (left) and the cubic f(u) with its roots (right).
//!
//! Built from plain numbers ([`TopPlot`]), so it is independent of how the
//! motion was computed.

use glam::DVec3;
use kreisel_plot::axes::{Axes, Labels, TITLE_FONT};
use kreisel_plot::figure::{Anchor, Color, Figure, Point, Rect, Stroke, Text};
use kreisel_plot::sphere::{LocalView, SpherePanel, View, circle_of_latitude};

use super::labels::{self, LABEL_SIZE, PlacedLabel};
use kreisel_scene::numbers::Shortest;

/// Figure width, px.
pub const WIDTH: u32 = 1280;
/// Figure height, px.
pub const HEIGHT: u32 = 640;

/// Colour of the axis path.
const PATH: Color = Color::rgb(31, 90, 180);
/// Colour of the θ_min circle.
const THETA_MIN: Color = Color::rgb(200, 60, 40);
/// Colour of the θ_max circle.
const THETA_MAX: Color = Color::rgb(30, 140, 70);

/// What the figure shows.
pub struct TopPlot<'a> {
    /// The figure's title (the parameters).
    pub title: String,
    /// The symmetry axis e₃ in world coordinates at successive times.
    pub axis_path: &'a [DVec3],
    /// What the path covers, e.g. `t = 0 … 1.2 s (3 nutation periods)`.
    pub path_caption: String,
    /// Smallest polar angle of the axis, rad.
    pub theta_min: f64,
    /// Largest polar angle of the axis, rad.
    pub theta_max: f64,
    /// The cubic f(u), 1/s².
    pub f: &'a dyn Fn(f64) -> f64,
    /// The real roots of f, ascending.
    pub roots: &'a [f64],
    /// β = 2 Mgl / I₁ (its sign says which root is the third), 1/s².
    pub beta: f64,
    /// Samples of `axis_path` per nutation period, when it has periods.
    pub samples_per_period: Option<usize>,
    /// Whether the legend gives θmin and θmax in degrees.
    pub degrees: bool,
}

/// Draws the two panels.
pub fn figure(plot: &TopPlot<'_>) -> Figure {
    let mut fig = Figure::new(WIDTH, HEIGHT);
    fig.text(Text::new(
        Point::new(f64::from(WIDTH) / 2.0, 30.0),
        plot.title.clone(),
        18.0,
        Anchor::Middle,
    ));
    sphere_panel(&mut fig, plot);
    cubic_panel(&mut fig, plot);
    fig
}

/// The left panel: the axis path on the sphere with the θ_min and θ_max circles.
fn sphere_panel(fig: &mut Figure, plot: &TopPlot<'_>) {
    let panel = SPHERE;
    fig.text(Text::new(
        Point::new(panel.center.x, 72.0),
        "Symmetry axis e\u{2083} on the unit sphere (seen from above at 30\u{b0})",
        TITLE_FONT,
        Anchor::Middle,
    ));
    panel.draw_frame(fig);
    // A sleeping top's circles are the pole itself: nothing to draw.
    let dashed = |color| Stroke::dashed(color, 1.5, 6.0, 4.0);
    if plot.theta_max > 0.0 {
        panel.latitude(fig, plot.theta_min, &dashed(THETA_MIN), "");
        if plot.theta_max != plot.theta_min {
            panel.latitude(fig, plot.theta_max, &dashed(THETA_MAX), "");
        }
    }
    panel.path(fig, plot.axis_path, &Stroke::solid(PATH, 1.8));
    if let Some(&start) = plot.axis_path.first() {
        let (p, _) = panel.pixel(start);
        fig.circle(p, 4.0, Some(Color::BLACK), None);
    }
    if let Some(zoom) = zoom_of(plot, &panel) {
        sphere_zoom(fig, plot, &zoom);
    }
    for label in sphere_labels(plot, &panel) {
        fig.text(Text::new(label.at, label.text, LABEL_SIZE, Anchor::Start).colored(label.color));
    }
    // Legend below the sphere.
    let x = 40.0;
    let mut y = 580.0;
    let legend = [
        (
            PATH,
            format!(
                "axis path e\u{2083}(t), {} (dot: t = 0; faint: far side)",
                plot.path_caption
            ),
            false,
        ),
        (
            THETA_MIN,
            format!("\u{3b8}min = {}", angle(plot.theta_min, plot.degrees)),
            true,
        ),
        (
            THETA_MAX,
            format!("\u{3b8}max = {}", angle(plot.theta_max, plot.degrees)),
            true,
        ),
    ];
    for (color, label, dashed) in legend {
        let stroke = if dashed {
            Stroke::dashed(color, 1.5, 6.0, 4.0)
        } else {
            Stroke::solid(color, 2.0)
        };
        fig.line(
            Point::new(x, y - 4.0),
            Point::new(x + 28.0, y - 4.0),
            stroke,
        );
        fig.text(Text::new(
            Point::new(x + 36.0, y),
            label,
            13.0,
            Anchor::Start,
        ));
        y += 19.0;
    }
}

/// The sphere panel of the figure.
pub const SPHERE: SpherePanel = SpherePanel {
    center: Point { x: 310.0, y: 330.0 },
    radius: 215.0,
    view: View {
        elevation: std::f64::consts::PI / 6.0,
        azimuth: -std::f64::consts::PI / 3.0,
    },
};

/// Where labels on the sphere may go: the left panel between its title and
/// the legend.
pub const SPHERE_REGION: Rect = Rect {
    left: 20.0,
    top: 80.0,
    width: 580.0,
    height: 480.0,
};

/// The magnified inset of a narrow band: the piece of the path it shows
/// (two nutation periods), the direction at its centre and its frame.
struct Zoom<'a> {
    piece: &'a [DVec3],
    center: DVec3,
    frame: Rect,
}

/// The inset for a band narrower than 0.05 rad (a line at the sphere's
/// scale) with nutation periods: below the sphere's centre for a path above
/// the equator, above it otherwise.
fn zoom_of<'a>(plot: &TopPlot<'a>, panel: &SpherePanel) -> Option<Zoom<'a>> {
    let band = plot.theta_max - plot.theta_min;
    let per_period = plot
        .samples_per_period
        .filter(|_| band > 0.0 && band < 0.05)?;
    let piece = &plot.axis_path[..plot.axis_path.len().min(2 * per_period + 1)];
    let center = piece.iter().copied().sum::<DVec3>().try_normalize()?;
    let top = if center.z >= 0.0 { 430.0 } else { 120.0 };
    Some(Zoom {
        piece,
        center,
        frame: Rect {
            left: panel.center.x - 200.0,
            top,
            width: 400.0,
            height: 105.0,
        },
    })
}

/// The θmin and θmax labels on the sphere, placed clear of the path, the
/// circles, each other and the rest of the panel ([`labels::place`]).
pub fn sphere_labels(plot: &TopPlot<'_>, panel: &SpherePanel) -> Vec<PlacedLabel> {
    if plot.theta_max <= 0.0 {
        return Vec::new();
    }
    let mut wanted = vec![("\u{3b8}min".to_owned(), plot.theta_min, THETA_MIN)];
    if plot.theta_max != plot.theta_min {
        wanted.push(("\u{3b8}max".to_owned(), plot.theta_max, THETA_MAX));
    }
    let path: Vec<Point> = plot.axis_path.iter().map(|&v| panel.pixel(v).0).collect();
    let z_top = panel.pixel(DVec3::Z * 1.2).0;
    let z_axis = vec![panel.pixel(-DVec3::Z).0, z_top];
    let mut boxes = vec![labels::text_box(
        Point::new(z_top.x + 6.0, z_top.y + 5.0),
        "z (up)",
        13.0,
    )];
    if let Some(&start) = plot.axis_path.first() {
        let p = panel.pixel(start).0;
        boxes.push(Rect {
            left: p.x - 4.0,
            top: p.y - 4.0,
            width: 8.0,
            height: 8.0,
        });
    }
    if let Some(zoom) = zoom_of(plot, panel) {
        boxes.push(zoom.frame);
    }
    labels::place(
        &wanted,
        labels::Obstacles {
            lines: vec![path, z_axis],
            boxes,
            region: SPHERE_REGION,
            panel,
        },
    )
}

/// An inset magnifying two nutation periods of the axis path, with the
/// θ_min and θ_max circles.
fn sphere_zoom(fig: &mut Figure, plot: &TopPlot<'_>, zoom: &Zoom<'_>) {
    let (piece, center, frame) = (zoom.piece, zoom.center, zoom.frame);
    let mut view = LocalView {
        frame,
        center,
        scale: 1.0,
    };
    let (east, _) = view.basis();
    let along = piece
        .iter()
        .map(|v| v.dot(east).abs())
        .fold(0.0_f64, f64::max);
    let band = plot.theta_max - plot.theta_min;
    view.scale = (0.45 * frame.width / along.max(1e-300)).min(0.6 * frame.height / band);
    let outline = Stroke::solid(Color::rgb(90, 90, 90), 1.0);
    fig.polygon(frame.corners(), Color::WHITE, Some(outline));
    for (theta, color) in [(plot.theta_min, THETA_MIN), (plot.theta_max, THETA_MAX)] {
        // The part of the circle facing the centre (the rest is far away).
        let circle: Vec<DVec3> = circle_of_latitude(theta, 20_000)
            .into_iter()
            .filter(|v| v.dot(center) > 0.9)
            .collect();
        view.path(fig, &circle, &Stroke::dashed(color, 1.5, 6.0, 4.0));
    }
    view.path(fig, piece, &Stroke::solid(PATH, 1.8));
    fig.text(Text::new(
        Point::new(frame.left + 6.0, frame.top + 15.0),
        "magnified: two nutation periods",
        12.0,
        Anchor::Start,
    ));
}

/// The right panel: f(u) with the roots marked and [u₁, u₂] shaded.
fn cubic_panel(fig: &mut Figure, plot: &TopPlot<'_>) {
    let f = plot.f;
    let (u1, u2) = (plot.theta_max.cos(), plot.theta_min.cos());
    // Show [−1, 1] and the third root when it is near (above 1 for Mgl > 0,
    // below −1 for a hanging top); otherwise say where it is.
    let third = plot
        .roots
        .iter()
        .zip(root_names(plot.roots, plot.beta))
        .find(|(_, name)| *name == "u\u{2083}")
        .map(|(&r, _)| r);
    let x_hi = match third {
        Some(r) if r > 1.0 && r <= 1.6 => r + 0.1,
        _ => 1.15,
    };
    let x_lo = match third {
        Some(r) if (-1.6..-1.0).contains(&r) => r - 0.1,
        _ => -1.1,
    };
    let samples: Vec<(f64, f64)> = (0..=1200)
        .map(|k| {
            let u = x_lo + (x_hi - x_lo) * f64::from(k) / 1200.0;
            (u, f(u))
        })
        .filter(|(_, y)| y.is_finite())
        .collect();
    // Scale to the hump of f over the motion's interval, where f ≥ 0.
    let hump = (0..=200)
        .map(|k| f(u1 + (u2 - u1) * f64::from(k) / 200.0))
        .filter(|y| y.is_finite())
        .fold(0.0_f64, f64::max);
    let (y_lo, y_hi) = if hump > 0.0 {
        (-1.2 * hump, 1.4 * hump)
    } else {
        let lo = samples.iter().map(|s| s.1).fold(0.0_f64, f64::min);
        let hi = samples.iter().map(|s| s.1).fold(0.0_f64, f64::max);
        let span = (hi - lo).max(1e-300);
        (lo - 0.05 * span, hi + 0.25 * span)
    };
    let axes = Axes {
        frame: Rect {
            left: 760.0,
            top: 95.0,
            width: 480.0,
            height: 420.0,
        },
        x_range: (x_lo, x_hi),
        y_range: (y_lo, y_hi),
    };
    axes.draw(
        fig,
        &Labels {
            title: "f(u) = (1 \u{2212} u\u{b2})(\u{3b1} \u{2212} \u{3b2}u) \u{2212} (b \u{2212} au)\u{b2} = (du/dt)\u{b2}",
            x: "u = cos \u{3b8}",
            y: "f(u)  [1/s\u{b2}]",
        },
    );
    let shade: Vec<(f64, f64)> = if u2 > u1 {
        (0..=300)
            .map(|k| {
                let u = u1 + (u2 - u1) * f64::from(k) / 300.0;
                (u, f(u).max(0.0))
            })
            .collect()
    } else {
        Vec::new()
    };
    axes.fill_to_zero(fig, &shade, PATH.with_alpha(70));
    let zero = Stroke::solid(Color::rgb(60, 60, 60), 1.0);
    axes.curve(fig, &[(x_lo, 0.0), (x_hi, 0.0)], &zero);
    let bound = Stroke::dashed(Color::GREY, 1.0, 4.0, 4.0);
    axes.curve(fig, &[(-1.0, y_lo), (-1.0, y_hi)], &bound);
    axes.curve(fig, &[(1.0, y_lo), (1.0, y_hi)], &bound);
    axes.curve(fig, &samples, &Stroke::solid(Color::BLACK, 2.0));
    // Roots: markers on the axis, labels above them (alternating heights);
    // u₁ ≤ u₂ bound the motion, u₃ is the third root ([`root_names`]).
    let mut off_scale = Vec::new();
    for (k, (&r, name)) in plot
        .roots
        .iter()
        .zip(root_names(plot.roots, plot.beta))
        .enumerate()
    {
        let p = axes.pixel(r, 0.0);
        if axes.frame.contains(p) {
            axes.marker(fig, r, 0.0, 5.0, Color::rgb(230, 160, 20));
            let dy = if k % 2 == 0 { -12.0 } else { 22.0 };
            fig.text(Text::new(
                Point::new(p.x, p.y + dy),
                format!("{name} = {}", short(r)),
                13.0,
                Anchor::Middle,
            ));
        } else {
            off_scale.push(format!("{name} = {} (off scale)", short(r)));
        }
    }
    // A narrow interval (a fast top) is a sliver at this scale: zoom in.
    if u2 > u1 && u2 - u1 < 0.04 * (x_hi - x_lo) {
        zoom(fig, plot, &axes, (u1, u2), hump);
    }
    let mut y = axes.frame.bottom() + 70.0;
    let x = axes.frame.left;
    fig.polygon(
        vec![
            Point::new(x, y - 12.0),
            Point::new(x + 28.0, y - 12.0),
            Point::new(x + 28.0, y + 1.0),
            Point::new(x, y + 1.0),
        ],
        PATH.with_alpha(70),
        None,
    );
    fig.text(Text::new(
        Point::new(x + 36.0, y),
        format!(
            "motion: [u\u{2081}, u\u{2082}] = [cos \u{3b8}max, cos \u{3b8}min] = [{}, {}]",
            short(u1),
            short(u2)
        ),
        13.0,
        Anchor::Start,
    ));
    for note in off_scale {
        y += 19.0;
        fig.text(Text::new(
            Point::new(x + 36.0, y),
            note,
            13.0,
            Anchor::Start,
        ));
    }
}

/// The names of the roots of f (ascending, as the library gives them):
/// u₁ ≤ u₂ bound the motion in [−1, 1], u₃ is the third root, ≥ 1 for
/// β > 0 (the largest) and ≤ −1 for β < 0 (the smallest); a free top
/// (β = 0), or one whose third root lies beyond the f64 range, has only
/// u₁ ≤ u₂. A root exactly at ±1 is named by this order too: the pole is
/// u₁ or u₂ when the axis reaches it, u₃ when it is the cubic's third root
/// (f < 0 beside it inside [−1, 1]).
pub fn root_names(roots: &[f64], beta: f64) -> Vec<&'static str> {
    const U1: &str = "u\u{2081}";
    const U2: &str = "u\u{2082}";
    const U3: &str = "u\u{2083}";
    match (roots.len(), beta) {
        (3, b) if b > 0.0 => vec![U1, U2, U3],
        (3, b) if b < 0.0 => vec![U3, U1, U2],
        (n, _) => [U1, U2, U3].into_iter().take(n).collect(),
    }
}

/// An inset in the upper left of `main`: f(u) on [u₁, u₂] and a little around it.
fn zoom(fig: &mut Figure, plot: &TopPlot<'_>, main: &Axes, (u1, u2): (f64, f64), hump: f64) {
    let f = plot.f;
    let w = u2 - u1;
    let (x_lo, x_hi) = (u1 - 0.3 * w, u2 + 0.3 * w);
    let inset = Axes {
        frame: Rect {
            left: main.frame.left + 75.0,
            top: main.frame.top + 35.0,
            width: 190.0,
            height: 120.0,
        },
        x_range: (x_lo, x_hi),
        y_range: (-0.5 * hump, 1.3 * hump),
    };
    let outer = Rect {
        left: inset.frame.left - 70.0,
        top: inset.frame.top - 28.0,
        width: inset.frame.width + 80.0,
        height: inset.frame.height + 60.0,
    };
    Axes {
        frame: outer,
        ..inset
    }
    .fill_frame(fig, Color::WHITE);
    inset.draw(
        fig,
        &Labels {
            title: "zoom on [u\u{2081}, u\u{2082}]",
            x: "",
            y: "",
        },
    );
    let samples: Vec<(f64, f64)> = (0..=400)
        .map(|k| {
            let u = x_lo + (x_hi - x_lo) * f64::from(k) / 400.0;
            (u, f(u))
        })
        .collect();
    let shade: Vec<(f64, f64)> = samples
        .iter()
        .filter(|(u, _)| (u1..=u2).contains(u))
        .map(|&(u, y)| (u, y.max(0.0)))
        .collect();
    inset.fill_to_zero(fig, &shade, PATH.with_alpha(70));
    inset.curve(
        fig,
        &[(x_lo, 0.0), (x_hi, 0.0)],
        &Stroke::solid(Color::rgb(60, 60, 60), 1.0),
    );
    inset.curve(fig, &samples, &Stroke::solid(Color::BLACK, 2.0));
    for u in [u1, u2] {
        inset.marker(fig, u, 0.0, 4.0, Color::rgb(230, 160, 20));
    }
}

/// An angle (given in radians) for a label: `0.5 rad`, or `28.6479°`.
fn angle(radians: f64, degrees: bool) -> String {
    if degrees {
        format!("{}\u{b0}", short(radians.to_degrees()))
    } else {
        format!("{} rad", short(radians))
    }
}

/// A number with 6 significant digits, for labels.
fn short(value: f64) -> String {
    let text = format!("{:.5e}", value);
    // Plain notation when it is short.
    let plain = format!("{}", Shortest(text.parse::<f64>().unwrap_or(value)));
    if plain.len() <= 9 { plain } else { text }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kreisel_plot::figure::Primitive;

    #[test]
    fn draws_both_panels() {
        let path: Vec<DVec3> = (0..100)
            .map(|k| {
                let t = f64::from(k) * 0.1;
                let theta = 0.5 + 0.1 * (3.0 * t).sin();
                DVec3::new(theta.sin() * t.sin(), -theta.sin() * t.cos(), theta.cos())
            })
            .collect();
        let f = |u: f64| (1.0 - u * u) * (10.0 - 5.0 * u) - (4.0 - 4.5 * u).powi(2);
        let fig = figure(&TopPlot {
            title: "test".into(),
            axis_path: &path,
            path_caption: "t = 0 … 10 s".into(),
            theta_min: 0.4,
            theta_max: 0.6,
            f: &f,
            roots: &[0.8, 0.9, 3.0],
            beta: 10.0,
            samples_per_period: Some(30),
            degrees: false,
        });
        let texts: Vec<&str> = fig
            .items
            .iter()
            .filter_map(|p| match p {
                Primitive::Text(t) => Some(t.text.as_str()),
                _ => None,
            })
            .collect();
        assert!(texts.contains(&"u = cos \u{3b8}"), "{texts:?}");
        assert!(
            texts
                .iter()
                .any(|t| t.starts_with("u\u{2083} = 3 (off scale)")),
            "{texts:?}"
        );
        assert!(
            texts.iter().any(|t| t.starts_with("u\u{2081} = 0.8")),
            "{texts:?}"
        );
        assert_eq!(short(0.123456789), "0.123457");
        assert_eq!(short(1234567.0), "1234570");
        assert_eq!(short(-1.234567e9), "-1.23457e9");
    }
}
