//! The window (minifb, X11, software rendering): the side view and the
//! tilt chart of [`super::drawing`], the simulation advanced in real time
//! (the engine adapting its steps inside each frame) until `--duration`
//! (the physics printed then), then held until closed.
//! Keys: q or Esc quit.

use std::io::Write;
use std::time::Instant;

use minifb::{Key, Window, WindowOptions};

use super::DemoError;
use super::drawing::{FrameData, HEIGHT, WIDTH, frame_pixels};
use super::options::Options;
use super::report::result_lines;
use super::simulation::{Simulation, tilt};

/// Wall-clock seconds simulated at most per displayed frame (a slow frame
/// does not make the simulation jump).
const MAX_FRAME_TIME: f64 = 0.1;

/// How the window ended.
pub enum Outcome {
    /// The run was shown and the window closed.
    Closed,
    /// No window could be opened, for this reason.
    NoWindow(String),
}

/// Opens the window, or says why it cannot.
fn open_window() -> Result<Window, String> {
    let opened = std::panic::catch_unwind(|| {
        Window::new(
            "kreisel: the tippe top",
            WIDTH as usize,
            HEIGHT as usize,
            WindowOptions::default(),
        )
    });
    match opened {
        Ok(Ok(window)) => Ok(window),
        Ok(Err(e)) => Err(e.to_string()),
        Err(_) => Err("the window library panicked".to_owned()),
    }
}

/// Shows `sim` in a window, then prints the physics.
///
/// # Errors
/// The library's errors, [`DemoError::Plot`], [`DemoError::Stdout`].
pub fn run(
    options: &Options,
    sim: &mut Simulation,
    out: &mut dyn Write,
) -> Result<Outcome, DemoError> {
    let mut window = match open_window() {
        Ok(window) => window,
        Err(reason) => return Ok(Outcome::NoWindow(reason)),
    };
    window.set_target_fps(60);
    let mut tilts = vec![(0.0, tilt(&sim.state()).to_degrees())];
    let mut reported = false;
    let mut last = Instant::now();
    while window.is_open() && !window.is_key_down(Key::Escape) && !window.is_key_down(Key::Q) {
        let now = Instant::now();
        let owed = (now - last).as_secs_f64().min(MAX_FRAME_TIME);
        last = now;
        // The engine adapts its own steps inside the frame.
        sim.advance_to((sim.time() + owed).min(options.duration))?;
        if tilts.last().is_some_and(|&(t, _)| t < sim.time()) {
            tilts.push((sim.time(), tilt(&sim.state()).to_degrees()));
        }
        let pixels = frame_pixels(&FrameData {
            state: &sim.state(),
            time: sim.time(),
            tilt_history: &tilts,
            duration: options.duration,
            horizontal_at: sim.horizontal_at(),
            touching: sim.touching(),
        })?;
        if !reported && sim.time() >= options.duration {
            for line in result_lines(sim, options) {
                writeln!(out, "{line}")?;
            }
            out.flush()?;
            reported = true;
        }
        if let Err(e) = window.update_with_buffer(&pixels, WIDTH as usize, HEIGHT as usize) {
            writeln!(out, "window closed: {e}")?;
            break;
        }
    }
    if !reported {
        for line in result_lines(sim, options) {
            writeln!(out, "{line}")?;
        }
    }
    Ok(Outcome::Closed)
}
