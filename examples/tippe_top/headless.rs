//! The run without a window: the simulation to `--duration`, the printed
//! physics, the GIF (`--gif`) and the chart (`--plot`), each written whole
//! or not at all.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use kreisel_plot::ImageFormat;

use super::DemoError;
use super::chart::{Sample, run_figure};
use super::drawing::{FrameData, HEIGHT, WIDTH, frame_pixels};
use super::options::Options;
use super::report::result_lines;
use super::shared::gif_out;
use super::shared::output_file::{PendingFile, write_whole};
use super::simulation::{Simulation, tilt};

/// Samples of the run kept for the chart and the GIF's tilt trace (about).
const SAMPLES: f64 = 2000.0;

/// The GIF, streamed to a temporary file beside the target as the frames
/// come, renamed over it when complete.
struct GifRecorder {
    stream: gif_out::GifStream<BufWriter<File>>,
    file: PendingFile,
    path: PathBuf,
}

impl GifRecorder {
    fn new(path: &Path, fps: f64) -> Result<Self, DemoError> {
        // Shown at a quarter of real speed.
        let delay = (400.0 / fps).round().clamp(2.0, 6000.0) as u16;
        let (file, writer) = PendingFile::create(path)?;
        let gif_error = |source| DemoError::Gif {
            path: path.to_path_buf(),
            source,
        };
        let stream = gif_out::GifStream::new(
            writer,
            WIDTH as u16,
            HEIGHT as u16,
            delay,
            gif_out::stream::PALETTE_WINDOW_PIXELS,
        )
        .map_err(gif_error)?;
        Ok(Self {
            stream,
            file,
            path: path.to_path_buf(),
        })
    }

    fn push(&mut self, data: &FrameData<'_>) -> Result<(), DemoError> {
        let pixels = frame_pixels(data)?;
        self.stream.push(&pixels).map_err(|source| DemoError::Gif {
            path: self.path.clone(),
            source,
        })
    }

    fn finish(self) -> Result<(usize, u64), DemoError> {
        let (writer, stats) = self.stream.finish().map_err(|source| DemoError::Gif {
            path: self.path.clone(),
            source,
        })?;
        self.file.commit(writer)?;
        Ok((stats.frames, stats.bytes_written))
    }
}

/// Runs `sim` to `options.duration` (or lift-off), prints the physics and
/// writes the files asked for.
///
/// # Errors
/// [`DemoError::PlotFormat`], [`DemoError::Write`] before the run for an
/// output that cannot be written; the library's errors; [`DemoError::Gif`],
/// [`DemoError::Plot`], [`DemoError::Write`] after it.
pub fn run(options: &Options, mut sim: Simulation, out: &mut dyn Write) -> Result<(), DemoError> {
    // Checked by Options::validate: a known format in an existing directory.
    let plot_format = options.plot.as_deref().and_then(ImageFormat::from_path);
    let mut gif = options
        .gif
        .as_deref()
        .map(|p| GifRecorder::new(p, options.fps))
        .transpose()?;
    let steps = (options.duration / options.dt).round().max(1.0) as u64;
    let sample_every = ((steps as f64 / SAMPLES).round() as u64).max(1);
    let frame_every = ((1.0 / (options.fps * options.dt)).round() as u64).max(1);
    let mut samples: Vec<Sample> = Vec::new();
    let mut tilts: Vec<(f64, f64)> = Vec::new();
    for i in 0..=steps {
        let last = i == steps || sim.stopped();
        if i % sample_every == 0 || last {
            let theta_deg = tilt(&sim.state).to_degrees();
            samples.push(Sample {
                t: sim.time,
                theta_deg,
                energy: sim.top.energy(&sim.state) / sim.energy0,
                jellett: sim.jellett_change(),
            });
            tilts.push((sim.time, theta_deg));
        }
        if let Some(g) = gif.as_mut()
            && (i % frame_every == 0 || last)
        {
            g.push(&FrameData {
                state: &sim.state,
                time: sim.time,
                tilt_history: &tilts,
                duration: options.duration,
                inverted_at: sim.events.inverted_at,
            })?;
        }
        if last {
            break;
        }
        sim.step()?;
    }
    for line in result_lines(&sim) {
        writeln!(out, "{line}")?;
    }
    if let Some(g) = gif {
        let (frames, bytes) = g.finish()?;
        let path = options.gif.as_deref().unwrap_or(Path::new(""));
        writeln!(
            out,
            "wrote {} ({frames} frames, {bytes} bytes)",
            path.display()
        )?;
    }
    if let (Some(path), Some(format)) = (&options.plot, plot_format) {
        let title = match sim.events.inverted_at {
            Some(t) => format!(
                "Leine & Glocker's tippe top, friction {}: inverted at t = {t:.4} s",
                options.friction_name()
            ),
            None => format!(
                "Leine & Glocker's tippe top, friction {}",
                options.friction_name()
            ),
        };
        let figure = run_figure(&samples, options.duration, sim.events.inverted_at, &title);
        write_whole(path, &format.render(&figure)?)?;
        writeln!(out, "wrote {}", path.display())?;
    }
    Ok(())
}
