//! The headless run: simulate for `--duration`, print the results, write
//! the GIF (`--gif`) and the ω(t) chart (`--plot`).

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

use kreisel::dynamics::FreeBodyMethod;
use kreisel_plot::ImageFormat;

use super::chart::{History, OmegaData, omega_figure};
use super::frame::{FrameRenderer, Overlay};
use super::options::{HEADLESS_DURATION, Options};
use super::output_file::{PendingFile, check_directory, write_whole};
use super::physics::{Handle, Prediction, Simulation};
use super::report::{result_lines, significant};
use super::{DemoError, gif_out};

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
    method: FreeBodyMethod,
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
    let spin = options.spin();
    let prediction = Prediction::new(handle.moments(), &spin);
    let mut sim = Simulation::new(method, handle, &spin, options.dt)?;
    let steps = (duration / options.dt).round().max(1.0) as u64;
    let record_every = (steps / PLOT_SAMPLES).max(1);
    let mut full = History::new(None);
    let mut gif = match &options.gif {
        Some(path) => Some(GifRecorder::new(options, handle, path)?),
        None => None,
    };
    for i in 0..=steps {
        if i % record_every == 0 || i == steps {
            full.push(sim.time(), sim.omega_principal());
        }
        if let Some(g) = gif.as_mut() {
            g.observe(&sim, handle, &prediction)?;
        }
        if i < steps {
            sim.step()?;
        }
    }
    for line in result_lines(
        &sim,
        &prediction,
        &spin,
        method.resolve().name(),
        options.dt,
    ) {
        writeln!(out, "{line}")?;
    }
    if let (Some(path), Some(g)) = (&options.gif, gif) {
        let (frames, bytes) = g.finish(path)?;
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
        write_whole(path, &format.render(&figure)?)?;
        writeln!(out, "wrote {}", path.display())?;
    }
    Ok(())
}

/// The GIF, rendered at `--fps` of simulated time and streamed to a
/// temporary file beside the target as the frames come (bounded memory for
/// any `--duration`), renamed over the target when complete.
struct GifRecorder {
    renderer: FrameRenderer,
    strip: History,
    stream: gif_out::GifStream<BufWriter<File>>,
    file: PendingFile,
    frame_interval: f64,
    next_frame: f64,
    next_sample: f64,
    path: std::path::PathBuf,
}

impl GifRecorder {
    /// Starts the GIF for `path`.
    ///
    /// # Errors
    /// [`DemoError::Write`] when the temporary file cannot be created,
    /// [`DemoError::Gif`] for a size the encoder refuses.
    fn new(options: &Options, handle: &Handle, path: &Path) -> Result<Self, DemoError> {
        let width = options.gif_width as usize;
        let renderer = FrameRenderer::new(
            width,
            width / 2,
            handle,
            options.spin_rate,
            options.spin().omega_bound(handle.moments()),
        );
        let delay_centiseconds = (100.0 / options.fps).round().clamp(1.0, 100.0) as u16;
        let (w, h) = renderer.size();
        let (file, writer) = PendingFile::create(path)?;
        let stream = gif_out::GifStream::new(
            writer,
            w as u16,
            h as u16,
            delay_centiseconds,
            gif_out::stream::PALETTE_WINDOW_PIXELS,
        )
        .map_err(|source| DemoError::Gif {
            path: path.to_path_buf(),
            source,
        })?;
        Ok(Self {
            renderer,
            strip: History::new(Some(super::frame::STRIP_WINDOW)),
            stream,
            file,
            path: path.to_path_buf(),
            frame_interval: 1.0 / options.fps,
            next_frame: 0.0,
            next_sample: 0.0,
        })
    }

    /// Samples the strip chart and renders a frame when one is due.
    fn observe(
        &mut self,
        sim: &Simulation,
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
            self.stream
                .push(&image.pixels)
                .map_err(|source| DemoError::Gif {
                    path: self.path.clone(),
                    source,
                })?;
            self.next_frame += self.frame_interval;
        }
        Ok(())
    }

    /// Writes the rest of the GIF and renames it over the target; the
    /// number of frames and the file's size in bytes.
    ///
    /// # Errors
    /// [`DemoError::Gif`], [`DemoError::Write`]; the target is left as it was.
    fn finish(self, path: &Path) -> Result<(usize, u64), DemoError> {
        let (writer, stats) = self.stream.finish().map_err(|source| DemoError::Gif {
            path: path.to_path_buf(),
            source,
        })?;
        self.file.commit(writer)?;
        Ok((stats.frames, stats.bytes_written))
    }
}
