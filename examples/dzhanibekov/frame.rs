//! One frame of the window and of the GIF: the shaded handle with its
//! principal axes, L and ω on the left, the strip chart of ω on the right,
//! and a few lines of status.

use glam::DVec3;
use kreisel_plot::figure::{Anchor, Color, Point, Rect, Text};
use kreisel_plot::{Figure, PlotError};

use super::chart::{AXIS_COLORS, History, OmegaData, strip_chart};
use super::physics::{Handle, Prediction, Simulation};
use super::render::{Camera, ClipRect, Image, Light, Material, Renderer, rgb};
use super::report::significant;

/// Seconds of ω shown by the strip chart.
pub const STRIP_WINDOW: f64 = 12.0;
/// Seconds between strip-chart samples.
pub const STRIP_SAMPLE_INTERVAL: f64 = 0.01;

/// Background of the frame and of the 3-D panel.
const BACKGROUND: u32 = 0x00ff_ffff;
/// Background of the 3-D panel.
const PANEL: u32 = 0x00ee_f1f6;
/// Colour of the angular momentum arrow (dark grey).
const L_COLOR: Color = Color::rgb(40, 40, 40);
/// Colour of the angular velocity arrow (orange).
const OMEGA_COLOR: Color = Color::rgb(255, 127, 14);
/// Where the camera looks from: 25° above the horizontal plane normal to L.
const ELEVATION_DEG: f64 = 25.0;
/// Azimuth of the camera, degrees.
const AZIMUTH_DEG: f64 = -60.0;

/// The live window's state worth showing.
#[derive(Debug, Clone, Copy)]
pub struct LiveStatus {
    /// Playback speed (real time = 1).
    pub speed: f64,
    /// Whether the simulation is paused.
    pub paused: bool,
}

/// The text lines laid over the 3-D panel.
#[derive(Debug, Clone)]
pub struct Overlay {
    lines: Vec<String>,
    footer: Option<String>,
}

impl Overlay {
    /// Time, flips and flip periods of `sim`, and for the window its speed
    /// and the keys.
    pub fn of(sim: &Simulation, prediction: &Prediction, live: Option<LiveStatus>) -> Self {
        let mut lines = vec![format!("t = {:.2} s", sim.time())];
        let flips = sim.flips.len();
        lines.push(
            match (prediction.flip_period(), sim.measured_flip_period()) {
                (Some(x), Some(y)) => format!(
                    "{flips} flips, every {} s (theory {} s)",
                    significant(y, 6),
                    significant(x, 6)
                ),
                (Some(x), None) => format!(
                    "{flips} flip{} (theory: every {} s)",
                    if flips == 1 { "" } else { "s" },
                    significant(x, 6)
                ),
                (None, _) => format!("{flips} flips (stable axis: none expected)"),
            },
        );
        let footer = live.map(|s| {
            lines.push(format!(
                "speed {}×{}",
                super::report::tidy(s.speed),
                if s.paused { " · paused" } else { "" }
            ));
            "space pause · r restart · 1/2/3 axis · +/− speed · q quit".to_owned()
        });
        Self { lines, footer }
    }
}

/// Draws frames of one size for one handle.
pub struct FrameRenderer {
    image: Image,
    renderer: Renderer,
    camera: Camera,
    panel: ClipRect,
    /// Largest distance of a vertex from the centre of mass, m.
    radius: f64,
    /// Scale of the strip chart's ω axis, rad/s.
    omega_scale: f64,
    /// The initial |ω|, the length scale of the ω arrow.
    omega_reference: f64,
}

impl FrameRenderer {
    /// Frames of `width × height` pixels (the 3-D panel is the left
    /// `height × height` square) for `handle` spun at `rate` with ω
    /// components up to `omega_scale`.
    pub fn new(width: usize, height: usize, handle: &Handle, rate: f64, omega_scale: f64) -> Self {
        let radius = handle
            .vertices_body
            .iter()
            .map(|v| v.length())
            .fold(1e-9, f64::max);
        let panel = ClipRect::new(0, 0, height.min(width), height);
        let (el, az) = (ELEVATION_DEG.to_radians(), AZIMUTH_DEG.to_radians());
        let eye = DVec3::new(el.cos() * az.cos(), el.cos() * az.sin(), el.sin());
        let distance = 8.0 * radius;
        // The reach of the labels (1.5 r) fills 95 % of the half height.
        let focal = 0.95 * 0.5 * height as f64 * (distance - 1.5 * radius) / (1.5 * radius);
        let camera = Camera::looking_at_origin(eye, DVec3::Z, distance, focal, panel.center());
        Self {
            image: Image::new(width, height, BACKGROUND),
            renderer: Renderer::new(width, height),
            camera,
            panel,
            radius,
            omega_scale,
            omega_reference: rate,
        }
    }

    /// Sets the scales after a restart with another spin.
    pub fn set_scales(&mut self, rate: f64, omega_scale: f64) {
        self.omega_reference = rate;
        self.omega_scale = omega_scale;
    }

    /// Frame size in pixels.
    pub fn size(&self) -> (usize, usize) {
        (self.image.width, self.image.height)
    }

    /// Draws the frame for the simulation's current state.
    ///
    /// # Errors
    /// [`PlotError`] from laying the chart and text over the 3-D panel (only
    /// a corrupted embedded font: the sizes match by construction).
    pub fn draw(
        &mut self,
        handle: &Handle,
        sim: &Simulation,
        strip: &History,
        overlay: &Overlay,
    ) -> Result<&Image, PlotError> {
        let (width, height) = self.size();
        let scale = height as f64 / 540.0;
        self.image.clear(BACKGROUND);
        let p = self.panel;
        self.image.fill_rect(
            p.x as i64,
            p.y as i64,
            p.width as i64,
            p.height as i64,
            PANEL,
        );
        let mut fig = Figure::new(width as u32, height as u32);
        self.draw_body(handle, sim, &mut fig, scale);
        let chart = Rect {
            left: p.width as f64 + 78.0 * scale.max(0.75),
            top: 24.0 * scale,
            width: width as f64 - p.width as f64 - 78.0 * scale.max(0.75) - 16.0 * scale,
            // Room for the tick labels and the axis label, whose fonts do not scale.
            height: height as f64 - 24.0 * scale - (52.0 * scale).max(48.0),
        };
        if chart.width > 40.0 && chart.height > 40.0 {
            let data = OmegaData {
                history: strip,
                flips: &sim.flips,
                spin_axis: sim.spin_axis(),
            };
            strip_chart(
                &mut fig,
                chart,
                &data,
                sim.time(),
                STRIP_WINDOW,
                self.omega_scale,
            );
        }
        let font = 15.0 * scale.max(0.7);
        for (i, line) in overlay.lines.iter().enumerate() {
            fig.text(Text::new(
                Point::new(10.0 * scale, (8.0 + 1.3 * (i as f64 + 1.0) * 15.0) * scale),
                line.clone(),
                font,
                Anchor::Start,
            ));
        }
        if let Some(footer) = &overlay.footer {
            fig.text(
                Text::new(
                    Point::new(10.0 * scale, height as f64 - 12.0 * scale),
                    footer.clone(),
                    0.85 * font,
                    Anchor::Start,
                )
                .colored(Color::rgb(90, 90, 90)),
            );
        }
        kreisel_plot::png::draw_over_rgb(&fig, &mut self.image.pixels)?;
        Ok(&self.image)
    }

    /// The shaded handle, its principal axes (labelled 1, 2, 3), the fixed
    /// L along world z and the instantaneous ω, with their labels in `fig`.
    fn draw_body(&mut self, handle: &Handle, sim: &Simulation, fig: &mut Figure, scale: f64) {
        let state = sim.state();
        let world_from_body = state.world_from_body;
        let vertices: Vec<DVec3> = handle
            .vertices_body
            .iter()
            .map(|v| world_from_body * *v)
            .collect();
        let r = self.radius;
        let width = 2.0 * scale.max(0.75);
        self.renderer.begin(self.panel);
        // Steel, with enough ambient light that faces turned away stay readable.
        let material = Material {
            color: rgb(150, 163, 186),
            ambient: 0.42,
            diffuse: 0.6,
            ..Material::default()
        };
        self.renderer.draw_mesh(
            &mut self.image,
            &self.camera,
            &vertices,
            &handle.triangles,
            material,
            &Light::default(),
        );
        let mut labels = Vec::new();
        for (k, color) in AXIS_COLORS.iter().enumerate() {
            let axis = world_from_body * handle.principal_axis_body(k);
            let tip = 1.15 * r * axis;
            self.renderer.draw_line(
                &mut self.image,
                &self.camera,
                -tip,
                tip,
                width,
                to_u32(*color),
            );
            labels.push((1.27 * r * axis, ["1", "2", "3"][k], *color));
        }
        let l_tip = 1.35 * r * DVec3::Z;
        self.renderer.draw_arrow(
            &mut self.image,
            &self.camera,
            DVec3::ZERO,
            l_tip,
            1.5 * width,
            9.0 * scale.max(0.75),
            to_u32(L_COLOR),
        );
        labels.push((1.48 * r * DVec3::Z, "L", L_COLOR));
        let omega_world = world_from_body * state.omega_body;
        let omega_tip = 1.1 * r * omega_world / self.omega_reference;
        self.renderer.draw_arrow(
            &mut self.image,
            &self.camera,
            DVec3::ZERO,
            omega_tip,
            1.5 * width,
            9.0 * scale.max(0.75),
            to_u32(OMEGA_COLOR),
        );
        labels.push((omega_tip * 1.12, "ω", OMEGA_COLOR));
        let font = 15.0 * scale.max(0.7);
        for (at, text, color) in labels {
            if let Some((x, y)) = self.camera.screen_position(at) {
                fig.text(
                    Text::new(Point::new(x, y + 0.35 * font), text, font, Anchor::Middle)
                        .colored(color),
                );
            }
        }
    }
}

/// The renderer's `0x00RRGGBB` of a plot colour.
fn to_u32(c: Color) -> u32 {
    rgb(c.r, c.g, c.b)
}
