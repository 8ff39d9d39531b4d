//! The figure of `kreisel simulate --plot`: one row per body (the first
//! [`MAX_BODIES`]), each with ω(t) in body axes, the relative energy
//! change, and the polhode — the path of L/|L| on the unit momentum sphere
//! in principal axes, with the separatrices of a torque-free asymmetric
//! body dashed (`kreisel_dynamics::polhode`).
//!
//! Built from the recorded [`Track`]s only, so it does not depend on how the
//! motion was computed.

use glam::DVec3;
use kreisel_plot::axes::{Axes, Labels};
use kreisel_plot::figure::{Anchor, Color, Figure, Point, Rect, Stroke, Text};
use kreisel_plot::sphere::{SpherePanel, View};

use super::record::{MAX_BODIES, Recorded, Track};
use kreisel_dynamics::polhode;
use kreisel_scene::numbers::Shortest;

/// Figure width, px.
pub const WIDTH: u32 = 1400;
/// Height of the title band, px.
const HEADER: f64 = 70.0;
/// Height of one body's row, px.
const ROW: f64 = 350.0;
/// Margin below the last row, px.
const FOOTER: f64 = 10.0;

/// The figure's height for `bodies` drawn bodies, px.
pub fn height(bodies: usize) -> u32 {
    (HEADER + ROW * bodies.clamp(1, MAX_BODIES) as f64 + FOOTER) as u32
}

/// Colours of ω₁, ω₂, ω₃.
const OMEGA: [Color; 3] = [
    Color::rgb(31, 119, 180),
    Color::rgb(255, 127, 14),
    Color::rgb(44, 160, 44),
];
/// Colour of the energy curve and the polhode.
const PATH: Color = Color::rgb(31, 90, 180);
/// Colour of the separatrices.
const SEPARATRIX: Color = Color::rgb(200, 50, 40);

/// Draws the figure: `title` on top, one row per track; a note says which
/// bodies are shown when the scene has more, and how the rows were thinned.
pub fn figure(title: &str, tracks: &[Track], recorded: Recorded) -> Figure {
    let scene_bodies = recorded.scene_bodies;
    let mut fig = Figure::new(WIDTH, height(tracks.len()));
    fig.text(Text::new(
        Point::new(f64::from(WIDTH) / 2.0, 30.0),
        title,
        18.0,
        Anchor::Middle,
    ));
    if scene_bodies > tracks.len() {
        let names: Vec<&str> = tracks.iter().map(|t| t.name.as_str()).collect();
        fig.text(
            Text::new(
                Point::new(20.0, 54.0),
                format!(
                    "showing the first {} of {scene_bodies} bodies: {} (the CSV has all)",
                    tracks.len(),
                    names.join(", ")
                ),
                14.0,
                Anchor::Start,
            )
            .colored(SEPARATRIX),
        );
    }
    if recorded.stride > 1 {
        fig.text(Text::new(
            Point::new(f64::from(WIDTH) - 20.0, 54.0),
            format!(
                "drawn: 1 row in {} of the {} rows per body, and the last",
                recorded.stride, recorded.rows
            ),
            13.0,
            Anchor::End,
        ));
    }
    for (k, track) in tracks.iter().enumerate() {
        let top = HEADER + ROW * k as f64;
        body_row(&mut fig, track, top);
    }
    fig
}

/// One body's row starting at `top`.
fn body_row(fig: &mut Figure, track: &Track, top: f64) {
    let m = track.principal.moments;
    let kind = match (track.pivot, track.driven) {
        _ if track.ground => "on the ground (contact with the plane z = 0)",
        (false, false) => "torque-free",
        (false, true) => "driven (torques, forces or damping)",
        (true, false) => "heavy top on a pivot",
        (true, true) => "driven heavy top on a pivot",
    };
    fig.text(Text::new(
        Point::new(20.0, top + 18.0),
        format!(
            "body `{}`: principal moments {}, {}, {} kg m\u{b2}; {kind}",
            track.name,
            short(m.x),
            short(m.y),
            short(m.z)
        ),
        15.0,
        Anchor::Start,
    ));
    omega_panel(fig, track, top);
    energy_panel(fig, track, top);
    polhode_panel(fig, track, top);
}

/// The data range of `values` with 5% padding, widened to ticks (a flat
/// series gets ±1 or ±10%).
fn padded_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if lo > hi {
        return (-1.0, 1.0);
    }
    let span = hi - lo;
    if span <= 1e-12 * lo.abs().max(hi.abs()) {
        let pad = if lo == 0.0 { 1.0 } else { 0.1 * lo.abs() };
        return (lo - pad, hi + pad);
    }
    // Out to the next multiple of a step of 1, 2 or 5 × 10ᵏ (about a sixth
    // of the span), so that Axes::draw (about 3 ticks per 220 px) labels
    // at least two ticks.
    let (lo, hi) = (lo - 0.05 * span, hi + 0.05 * span);
    let step = kreisel_plot::axes::nice_step(lo, hi, 6);
    ((lo / step).floor() * step, (hi / step).ceil() * step)
}

/// The time axis of a track.
fn time_range(track: &Track) -> (f64, f64) {
    let t0 = track.samples.first().map_or(0.0, |s| s.time);
    let t1 = track.samples.last().map_or(1.0, |s| s.time);
    if t1 > t0 { (t0, t1) } else { (t0, t0 + 1.0) }
}

/// ω(t) in body axes.
fn omega_panel(fig: &mut Figure, track: &Track, top: f64) {
    let axes = Axes {
        frame: Rect {
            left: 100.0,
            top: top + 60.0,
            width: 470.0,
            height: 220.0,
        },
        x_range: time_range(track),
        y_range: padded_range(track.samples.iter().flat_map(|s| s.omega_body.to_array())),
    };
    axes.draw(
        fig,
        &Labels {
            title: "angular velocity \u{3c9}(t), body axes",
            x: "t  [s]",
            y: "\u{3c9}  [rad/s]",
        },
    );
    for (i, color) in OMEGA.into_iter().enumerate() {
        let points: Vec<(f64, f64)> = track
            .samples
            .iter()
            .map(|s| (s.time, s.omega_body[i]))
            .collect();
        axes.curve(fig, &points, &Stroke::solid(color, 1.8));
    }
    // Legend in one line under the x label.
    let y = axes.frame.bottom() + 62.0;
    for (i, (color, name)) in OMEGA
        .into_iter()
        .zip(["\u{3c9}x", "\u{3c9}y", "\u{3c9}z"])
        .enumerate()
    {
        let x = axes.frame.left + 110.0 + 90.0 * i as f64;
        fig.line(
            Point::new(x, y - 4.0),
            Point::new(x + 24.0, y - 4.0),
            Stroke::solid(color, 2.5),
        );
        fig.text(Text::new(
            Point::new(x + 30.0, y),
            name,
            13.0,
            Anchor::Start,
        ));
    }
}

/// (E − E₀)/|E₀|, or E − E₀ in J when E₀ = 0.
fn energy_panel(fig: &mut Figure, track: &Track, top: f64) {
    let e0 = track.samples.first().map_or(0.0, |s| s.energy);
    let relative = e0 != 0.0 && e0.is_finite();
    let change = |e: f64| {
        if relative {
            (e - e0) / e0.abs()
        } else {
            e - e0
        }
    };
    let points: Vec<(f64, f64)> = track
        .samples
        .iter()
        .map(|s| (s.time, change(s.energy)))
        .collect();
    let largest = points
        .iter()
        .map(|p| p.1.abs())
        .filter(|v| v.is_finite())
        .fold(0.0_f64, f64::max);
    // Symmetric about 0 and ending on a tick, so the scale is labelled; an
    // exactly conserved energy shows as the 0 line.
    let half = symmetric_limit(largest);
    let axes = Axes {
        frame: Rect {
            left: 720.0,
            top: top + 60.0,
            width: 300.0,
            height: 220.0,
        },
        x_range: time_range(track),
        y_range: (-half, half),
    };
    axes.draw(
        fig,
        &Labels {
            title: if relative {
                "energy change (E \u{2212} E\u{2080}) / |E\u{2080}|"
            } else {
                "energy change E \u{2212} E\u{2080}  [J]"
            },
            x: "t  [s]",
            y: "",
        },
    );
    axes.curve(fig, &points, &Stroke::solid(PATH, 1.8));
    fig.text(Text::new(
        Point::new(axes.frame.center().x, axes.frame.bottom() + 62.0),
        format!(
            "E\u{2080} = {} J, largest change {}",
            short(e0),
            short(largest)
        ),
        13.0,
        Anchor::Middle,
    ));
}

/// The polhode: L/|L| in principal axes on the unit sphere.
fn polhode_panel(fig: &mut Figure, track: &Track, top: f64) {
    let axes = track.principal.axes;
    let path: Vec<DVec3> = track
        .samples
        .iter()
        .filter_map(|s| (axes.transpose() * s.l_body()).try_normalize())
        .collect();
    let panel = SpherePanel {
        center: Point::new(1225.0, top + 195.0),
        radius: 105.0,
        view: view_of(&path),
    };
    fig.text(Text::new(
        Point::new(panel.center.x, top + 44.0),
        "polhode: L/|L| in principal axes",
        16.0,
        Anchor::Middle,
    ));
    panel.draw_outline(fig);
    // The principal axes: inside the sphere faint, outside solid, labelled.
    let axis_stroke = Stroke::solid(Color::rgb(110, 110, 110), 1.0);
    for (k, e) in [DVec3::X, DVec3::Y, DVec3::Z].into_iter().enumerate() {
        let inside: Vec<DVec3> = (0..=20).map(|j| e * (-1.0 + 0.1 * f64::from(j))).collect();
        panel.path(fig, &inside, &Stroke::dashed(Color::GREY, 1.0, 3.0, 3.0));
        let (a, _) = panel.pixel(e);
        let (b, _) = panel.pixel(e * 1.15);
        fig.line(a, b, axis_stroke.clone());
        let (label, _) = panel.pixel(e * 1.27);
        // An axis pointing at the viewer would be labelled over the path.
        let off_centre = (label.x - panel.center.x).hypot(label.y - panel.center.y);
        if off_centre < 0.4 * panel.radius {
            continue;
        }
        fig.text(Text::new(
            Point::new(label.x, label.y + 5.0),
            ["1", "2", "3"][k],
            14.0,
            Anchor::Middle,
        ));
    }
    let note = if track.pivot {
        "L about the pivot (not conserved)"
    } else if track.ground {
        "on the ground: L turned by the contact force"
    } else if track.driven {
        "driven: L not conserved"
    } else if let Some(curves) = polhode::separatrices(track.principal.moments, 360) {
        for curve in curves {
            panel.path(fig, &curve, &Stroke::dashed(SEPARATRIX, 1.5, 6.0, 4.0));
        }
        "dashed: separatrices (2E = L\u{b2}/I\u{2082})"
    } else {
        "two equal moments: no separatrices"
    };
    panel.path(fig, &path, &Stroke::solid(PATH, 2.0));
    let caption = match path.first() {
        Some(&start) => {
            let (p, _) = panel.pixel(start);
            fig.circle(p, 3.0, Some(Color::BLACK), None);
            "dot: t = 0; faint: far side"
        }
        None => "L = 0: no polhode",
    };
    for (k, line) in [caption, note].into_iter().enumerate() {
        fig.text(Text::new(
            Point::new(panel.center.x, top + 318.0 + 17.0 * k as f64),
            line,
            13.0,
            Anchor::Middle,
        ));
    }
}

/// The view of the polhode sphere: from above at 22°, unless the path
/// keeps to one side of the sphere (a polhode about the largest or the
/// smallest axis), which is then turned towards the viewer (tilted
/// towards the default view, so the axes stay apart).
fn view_of(path: &[DVec3]) -> View {
    let default = View {
        elevation: 22f64.to_radians(),
        azimuth: -38f64.to_radians(),
    };
    let mean = path.iter().copied().sum::<DVec3>() / path.len().max(1) as f64;
    if mean.length() < 0.3 {
        return default;
    }
    let (_, _, toward) = default.basis();
    let look = (2.0 * mean.normalize() + toward).normalize();
    View {
        elevation: look.z.clamp(-1.0, 1.0).asin(),
        azimuth: look.y.atan2(look.x),
    }
}

/// The half-height of a y range symmetric about 0 that holds ±`largest`
/// with some room and ends on a tick of [`Axes::draw`] (about 3 ticks per
/// 220 px): 1, 2 or 5 × 10ᵏ times a whole number.
fn symmetric_limit(largest: f64) -> f64 {
    if !(largest > 0.0 && largest.is_finite()) {
        return 1e-16;
    }
    let wanted = 1.1 * largest;
    let step = kreisel_plot::axes::nice_step(-wanted, wanted, 3);
    (wanted / step).ceil() * step
}

/// A number with 4 significant digits, for labels.
fn short(value: f64) -> String {
    let rounded: f64 = format!("{value:.3e}").parse().unwrap_or(value);
    Shortest(rounded).to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_pad_and_survive_flat_series() {
        assert_eq!(padded_range([0.0, 0.0].into_iter()), (-1.0, 1.0));
        assert_eq!(padded_range([2.0, 2.0].into_iter()), (1.8, 2.2));
        assert_eq!(padded_range([0.0, 10.0].into_iter()), (-2.0, 12.0));
        assert_eq!(padded_range([-0.3, 1.2].into_iter()), (-0.5, 1.5));
        assert_eq!(padded_range(std::iter::empty()), (-1.0, 1.0));
        assert_eq!(height(1), 430);
        assert_eq!(height(9), height(MAX_BODIES));
        assert_eq!(short(0.123456), "0.1235");
        assert!((symmetric_limit(3.997e-15) - 5e-15).abs() < 1e-28);
        assert!((symmetric_limit(0.3) - 0.5).abs() < 1e-15);
        assert_eq!(symmetric_limit(0.0), 1e-16);
        // A polhode about the bottom pole is turned towards the viewer.
        let ring: Vec<DVec3> = (0..100)
            .map(|k| {
                let a = f64::from(k) * 0.0628;
                DVec3::new(0.1 * a.cos(), 0.1 * a.sin(), -1.0).normalize()
            })
            .collect();
        let view = view_of(&ring);
        assert!(view.project(-DVec3::Z).depth > 0.8, "{view:?}");
        // A path all around the sphere keeps the default view.
        let around = [DVec3::X, -DVec3::X, DVec3::Y, -DVec3::Y];
        assert_eq!(view_of(&around).elevation, 22f64.to_radians());
    }
}
