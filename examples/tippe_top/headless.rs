//! The run without a window: the simulation to `--duration`, the printed
//! physics, the GIF (`--gif`) and the chart (`--plot`), each written whole
//! or not at all.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use kreisel_plot::ImageFormat;

use super::DemoError;
use super::chart::{Marks, Sample, run_figure};
use super::drawing::{FrameData, HEIGHT, WIDTH, frame_pixels};
use super::options::Options;
use super::report::result_lines;
use super::shared::gif_out;
use super::shared::output_file::{PendingFile, write_whole};
use super::simulation::{Simulation, tilt};
use kreisel::dynamics::{TableEvent, TableEventKind};

/// Samples of the run kept for the chart and the GIF's tilt trace, besides
/// the frames.
pub const SAMPLES: usize = 4000;

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

/// The run's observation instants: `samples` chart samples and the frames
/// at `1/fps` s, in time order, each once (the end included), with whether
/// it is a frame.
pub fn grid(duration: f64, samples: usize, fps: f64) -> Vec<(f64, bool)> {
    let frames = (duration * fps + 1e-9).floor() as usize;
    let mut times: Vec<(f64, bool)> = (0..=samples)
        .map(|k| (duration * k as f64 / samples as f64, false))
        .chain((0..=frames).map(|j| (j as f64 / fps, true)))
        .collect();
    times.push((duration, true));
    times.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut merged: Vec<(f64, bool)> = Vec::with_capacity(times.len());
    for (t, frame) in times {
        match merged.last_mut() {
            Some(last) if last.0 == t => last.1 |= frame,
            _ => merged.push((t, frame)),
        }
    }
    merged
}

/// Runs `sim` to `options.duration`, prints the physics and writes the
/// files asked for.
///
/// # Errors
/// The library's errors; [`DemoError::Gif`], [`DemoError::Plot`],
/// [`DemoError::Write`] for the outputs.
pub fn run(options: &Options, mut sim: Simulation, out: &mut dyn Write) -> Result<(), DemoError> {
    // Checked by Options::validate: a known format in an existing directory.
    let plot_format = options.plot.as_deref().and_then(ImageFormat::from_path);
    let mut gif = options
        .gif
        .as_deref()
        .map(|p| GifRecorder::new(p, options.fps))
        .transpose()?;
    let mut samples: Vec<Sample> = Vec::new();
    let mut tilts: Vec<(f64, f64)> = Vec::new();
    for (t, frame) in grid(options.duration, SAMPLES, options.fps) {
        sim.advance_to(t)?;
        let state = sim.state();
        let theta_deg = tilt(&state).to_degrees();
        samples.push(Sample {
            t,
            theta_deg,
            energy: sim.energy_ratio(),
        });
        tilts.push((t, theta_deg));
        if let Some(g) = gif.as_mut()
            && frame
        {
            g.push(&FrameData {
                state: &state,
                time: t,
                tilt_history: &tilts,
                duration: options.duration,
                horizontal_at: sim.horizontal_at(),
                touching: sim.touching(),
            })?;
        }
    }
    for line in result_lines(&sim, options) {
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
        let impacts = impacts(sim.events());
        let marks = Marks {
            duration: options.duration,
            horizontal_at: sim.horizontal_at(),
            touching: &sim.touching_history,
            impacts: &impacts,
        };
        let title = format!(
            "Leine & Glocker's tippe top with its stem: μ = {}, Contensou radius {} mm",
            options.mu, options.contensou_radius
        );
        let figure = run_figure(&samples, &marks, &title);
        write_whole(path, &format.render(&figure)?)?;
        writeln!(out, "wrote {}", path.display())?;
    }
    Ok(())
}

/// The impacts among `events`: time and contact.
fn impacts(events: &[TableEvent]) -> Vec<(f64, usize)> {
    events
        .iter()
        .filter(|e| matches!(e.kind, TableEventKind::Impact { .. }))
        .filter_map(|e| e.contact.map(|c| (e.time, c)))
        .collect()
}

#[cfg(test)]
mod tests {
    #[test]
    fn grid_holds_every_frame_and_sample_once_in_order() {
        let g = super::grid(1.0, 4, 10.0);
        assert_eq!(g.len(), 11 + 2);
        assert!(g.windows(2).all(|w| w[0].0 < w[1].0));
        assert_eq!(g.iter().filter(|(_, f)| *f).count(), 11);
        assert_eq!(g.last(), Some(&(1.0, true)));
    }
}
