//! The headless run: simulate for `--duration`, print the results, write
//! the GIF (`--gif`) and the ω(t) chart (`--plot`).

use std::io::Write;
use std::path::Path;

use kreisel::dynamics::FreeBodyIntegrator;
use kreisel_plot::ImageFormat;

use super::chart::{History, OmegaData, omega_figure};
use super::frame::{FrameRenderer, Overlay};
use super::options::{HEADLESS_DURATION, Options};
use super::physics::{Handle, Prediction, Simulation};
use super::report::{result_lines, significant};
use super::{DemoError, gif_out};

/// The most pixels the GIF's frames may hold together (they are kept in
/// memory, 4 bytes each, until the palette is built from all of them).
const GIF_PIXELS: u64 = 150_000_000;

/// Samples of ω kept for the `--plot` chart (at most).
const PLOT_SAMPLES: u64 = 20_000;

/// Runs headless: prints the flip period and drift lines, writes the files.
///
/// # Errors
/// [`DemoError::Write`] for an output file, [`DemoError::Gif`],
/// [`DemoError::Plot`], [`DemoError::PlotFormat`].
pub fn run(
    options: &Options,
    handle: &Handle,
    method: &dyn FreeBodyIntegrator,
    out: &mut dyn Write,
) -> Result<(), DemoError> {
    // Refuse an unknown plot format before spending the run on it.
    let plot_format = match &options.plot {
        Some(path) => Some(
            ImageFormat::from_path(path).ok_or_else(|| DemoError::PlotFormat {
                path: path.to_path_buf(),
            })?,
        ),
        None => None,
    };
    // Refuse outputs that cannot be written before spending the run on them.
    for path in options.gif.iter().chain(&options.plot) {
        check_directory(path)?;
    }
    let duration = options.duration.unwrap_or(HEADLESS_DURATION);
    if options.gif.is_some() {
        let frames = (duration * options.fps) as u64 + 1;
        let (width, height) = (options.gif_width, options.gif_width / 2);
        if frames.saturating_mul(u64::from(width) * u64::from(height)) > GIF_PIXELS {
            return Err(DemoError::GifTooLarge {
                frames,
                width,
                height,
                limit: GIF_PIXELS,
            });
        }
    }
    let spin = options.spin();
    let prediction = Prediction::new(handle.moments(), &spin);
    let mut sim = Simulation::new(method, handle.body, &spin, options.dt);
    let steps = (duration / options.dt).round().max(1.0) as u64;
    let record_every = (steps / PLOT_SAMPLES).max(1);
    let mut full = History::new(None);
    let mut gif = options
        .gif
        .as_ref()
        .map(|_| GifRecorder::new(options, handle));
    for i in 0..=steps {
        if i % record_every == 0 || i == steps {
            full.push(sim.time(), sim.omega_principal());
        }
        if let Some(g) = gif.as_mut() {
            g.observe(&sim, handle, &prediction)?;
        }
        if i < steps {
            sim.step();
        }
    }
    for line in result_lines(&sim, &prediction, &spin, method.name(), options.dt) {
        writeln!(out, "{line}")?;
    }
    if let (Some(path), Some(g)) = (&options.gif, gif) {
        let frames = g.frames.len();
        let bytes = g.write(path)?;
        writeln!(
            out,
            "wrote {} ({frames} frames, {bytes} bytes)",
            path.display()
        )?;
    }
    if let (Some(path), Some(format)) = (&options.plot, plot_format) {
        let title = match (prediction.flip_period(), sim.measured_flip_period()) {
            (Some(x), Some(y)) => format!(
                "T-handle spun about its {} axis: flips every {} s (predicted {} s)",
                spin.axis.name(),
                significant(y, 6),
                significant(x, 6)
            ),
            _ => format!(
                "T-handle spun about its {} axis: {} flips",
                spin.axis.name(),
                sim.flips.len()
            ),
        };
        let data = OmegaData {
            history: &full,
            flips: &sim.flips,
            spin_axis: spin.axis.index(),
        };
        let figure = omega_figure(&data, sim.time(), &title);
        write_file(path, &format.render(&figure)?)?;
        writeln!(out, "wrote {}", path.display())?;
    }
    Ok(())
}

/// Fails unless the directory `path` is to be written in exists.
fn check_directory(path: &Path) -> Result<(), DemoError> {
    let dir = match path.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir,
        _ => Path::new("."),
    };
    if dir.is_dir() {
        Ok(())
    } else {
        Err(DemoError::Write {
            path: path.to_path_buf(),
            source: std::io::Error::new(
                std::io::ErrorKind::NotFound,
                format!("no directory {}", dir.display()),
            ),
        })
    }
}

/// Writes `bytes` to `path`.
fn write_file(path: &Path, bytes: &[u8]) -> Result<(), DemoError> {
    std::fs::write(path, bytes).map_err(|source| DemoError::Write {
        path: path.to_path_buf(),
        source,
    })
}

/// Frames of the GIF, rendered at `--fps` of simulated time.
struct GifRecorder {
    renderer: FrameRenderer,
    strip: History,
    frames: Vec<Vec<u32>>,
    frame_interval: f64,
    next_frame: f64,
    next_sample: f64,
    delay_centiseconds: u16,
}

impl GifRecorder {
    fn new(options: &Options, handle: &Handle) -> Self {
        let width = options.gif_width as usize;
        Self {
            renderer: FrameRenderer::new(
                width,
                width / 2,
                handle,
                options.spin_rate,
                options.spin().omega_bound(handle.moments()),
            ),
            strip: History::new(Some(super::frame::STRIP_WINDOW)),
            frames: Vec::new(),
            frame_interval: 1.0 / options.fps,
            next_frame: 0.0,
            next_sample: 0.0,
            delay_centiseconds: (100.0 / options.fps).round().clamp(1.0, 100.0) as u16,
        }
    }

    /// Samples the strip chart and renders a frame when one is due.
    fn observe(
        &mut self,
        sim: &Simulation<'_>,
        handle: &Handle,
        prediction: &Prediction,
    ) -> Result<(), DemoError> {
        let t = sim.time();
        let half_step = 0.5 * sim.dt();
        if t + half_step >= self.next_sample {
            self.strip.push(t, sim.omega_principal());
            self.next_sample += super::frame::STRIP_SAMPLE_INTERVAL;
        }
        if t + half_step >= self.next_frame {
            let overlay = Overlay::of(sim, prediction, None);
            let image = self.renderer.draw(handle, sim, &self.strip, &overlay)?;
            self.frames.push(image.pixels.clone());
            self.next_frame += self.frame_interval;
        }
        Ok(())
    }

    /// Encodes the frames to `path`; the file's size in bytes.
    fn write(self, path: &Path) -> Result<u64, DemoError> {
        let file = std::fs::File::create(path).map_err(|source| DemoError::Write {
            path: path.to_path_buf(),
            source,
        })?;
        let writer = std::io::BufWriter::new(file);
        let (w, h) = self.renderer.size();
        let stats = gif_out::write_gif(
            writer,
            w as u16,
            h as u16,
            &self.frames,
            self.delay_centiseconds,
        )
        .map_err(|source| DemoError::Gif {
            path: path.to_path_buf(),
            source,
        })?;
        Ok(stats.bytes_written)
    }
}
