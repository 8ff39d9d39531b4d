//! The live window (minifb, X11 only): the simulation runs in real time
//! times a speed factor and is drawn by the software renderer each frame.
//!
//! minifb panics or fails without an X server, so [`display_available`]
//! checks for one first, and any failure to open the window falls back to
//! the headless run.

use std::ffi::OsStr;
use std::io::Write;
use std::net::{TcpStream, ToSocketAddrs};
use std::path::PathBuf;
use std::time::{Duration, Instant};

use kreisel::dynamics::FreeBodyIntegrator;
use minifb::{Key, KeyRepeat, Window, WindowOptions};

use super::DemoError;
use super::chart::History;
use super::frame::{FrameRenderer, LiveStatus, Overlay, STRIP_SAMPLE_INTERVAL, STRIP_WINDOW};
use super::options::Options;
use super::physics::{Handle, Prediction, Simulation, Spin, SpinAxis};
use super::report::{result_lines, setup_lines};

/// Window size in pixels.
const WIDTH: usize = 1080;
/// Window height in pixels.
const HEIGHT: usize = 540;
/// Longest wall-clock interval simulated in one frame, s (a stalled frame
/// does not make the simulation jump).
const MAX_FRAME_TIME: f64 = 0.1;
/// Speed limits of +/−.
const SPEEDS: (f64, f64) = (1.0 / 64.0, 64.0);

/// How the live run ended.
pub enum Outcome {
    /// The user closed the window (or `--duration` ran out).
    Closed,
    /// No window could be opened, for this reason: run headless instead.
    NoWindow(String),
}

/// Whether `display` (the value of `DISPLAY`) names an X server that
/// accepts connections: a local socket `/tmp/.X11-unix/X<n>` for `:n`,
/// TCP port 6000 + n for `host:n`.
///
/// # Errors
/// Why there is no display, in words.
pub fn display_available(display: Option<&OsStr>) -> Result<(), String> {
    let Some(name) = display.and_then(OsStr::to_str).filter(|d| !d.is_empty()) else {
        return Err("DISPLAY is not set".to_owned());
    };
    let bad = || format!("DISPLAY={name} is not of the form [host]:number[.screen]");
    let (host, rest) = name.rsplit_once(':').ok_or_else(bad)?;
    let number: u16 = rest
        .split('.')
        .next()
        .and_then(|n| n.parse().ok())
        .ok_or_else(bad)?;
    if host.is_empty() || host == "unix" || host.starts_with('/') {
        let socket = PathBuf::from(format!("/tmp/.X11-unix/X{number}"));
        return if socket.exists() {
            Ok(())
        } else {
            Err(format!(
                "DISPLAY={name} but no X server socket {}",
                socket.display()
            ))
        };
    }
    let port = 6000u16.saturating_add(number);
    let addresses = (host, port)
        .to_socket_addrs()
        .map_err(|e| format!("DISPLAY={name}: {e}"))?;
    for address in addresses {
        if TcpStream::connect_timeout(&address, Duration::from_secs(1)).is_ok() {
            return Ok(());
        }
    }
    Err(format!(
        "DISPLAY={name} but no X server answers on {host}:{port}"
    ))
}

/// Opens the window, or says why it cannot.
fn open_window() -> Result<Window, String> {
    let opened = std::panic::catch_unwind(|| {
        Window::new(
            "kreisel: the Dzhanibekov effect",
            WIDTH,
            HEIGHT,
            WindowOptions::default(),
        )
    });
    match opened {
        Ok(Ok(window)) => Ok(window),
        Ok(Err(e)) => Err(e.to_string()),
        Err(_) => Err("the window library panicked".to_owned()),
    }
}

/// What the keys change.
struct Controls {
    spin: Spin,
    speed: f64,
    paused: bool,
}

/// What a key press asks for.
enum Action {
    None,
    Restart,
    Quit,
}

impl Controls {
    fn apply(&mut self, key: Key) -> Action {
        let axis = |k| SpinAxis::from_index(k).map_or(SpinAxis::Intermediate, |a| a);
        match key {
            Key::Space => self.paused = !self.paused,
            Key::R => return Action::Restart,
            Key::Key1 | Key::NumPad1 => self.spin.axis = axis(0),
            Key::Key2 | Key::NumPad2 => self.spin.axis = axis(1),
            Key::Key3 | Key::NumPad3 => self.spin.axis = axis(2),
            Key::Equal | Key::NumPadPlus => self.speed = (self.speed * 2.0).min(SPEEDS.1),
            Key::Minus | Key::NumPadMinus => self.speed = (self.speed / 2.0).max(SPEEDS.0),
            Key::Q | Key::Escape => return Action::Quit,
            _ => return Action::None,
        }
        if matches!(
            key,
            Key::Key1 | Key::NumPad1 | Key::Key2 | Key::NumPad2 | Key::Key3 | Key::NumPad3
        ) {
            return Action::Restart;
        }
        Action::None
    }
}

/// Runs the window until it is closed (or `--duration` of simulated time
/// has passed), printing the results of each run (each restart ends one).
///
/// # Errors
/// [`DemoError::Stdout`] only: window failures end the run or fall back.
pub fn run(
    options: &Options,
    handle: &Handle,
    method: &dyn FreeBodyIntegrator,
    out: &mut dyn Write,
) -> Result<Outcome, DemoError> {
    let mut window = match open_window() {
        Ok(window) => window,
        Err(reason) => return Ok(Outcome::NoWindow(reason)),
    };
    window.set_target_fps(60);
    let mut controls = Controls {
        spin: options.spin(),
        speed: options.speed,
        paused: false,
    };
    let spin = options.spin();
    let mut renderer = FrameRenderer::new(
        WIDTH,
        HEIGHT,
        handle,
        spin.rate,
        spin.omega_bound(handle.moments()),
    );
    'runs: loop {
        let spin = controls.spin;
        renderer.set_scales(spin.rate, spin.omega_bound(handle.moments()));
        let prediction = Prediction::new(handle.moments(), &spin);
        let mut sim = Simulation::new(method, handle.body, &spin, options.dt);
        let mut strip = History::new(Some(STRIP_WINDOW));
        strip.push(0.0, sim.omega_principal());
        let mut next_sample = STRIP_SAMPLE_INTERVAL;
        let mut owed = 0.0;
        let mut last = Instant::now();
        let mut quit = false;
        loop {
            if !window.is_open() {
                quit = true;
                break;
            }
            let mut restart = false;
            for key in window.get_keys_pressed(KeyRepeat::No) {
                match controls.apply(key) {
                    Action::Restart => restart = true,
                    Action::Quit => quit = true,
                    Action::None => {}
                }
            }
            if quit || restart {
                break;
            }
            let now = Instant::now();
            let wall = (now - last).as_secs_f64().min(MAX_FRAME_TIME);
            last = now;
            if !controls.paused {
                owed += wall * controls.speed;
                while owed >= options.dt {
                    sim.step();
                    owed -= options.dt;
                    if sim.time() >= next_sample {
                        strip.push(sim.time(), sim.omega_principal());
                        next_sample += STRIP_SAMPLE_INTERVAL;
                    }
                }
            }
            if options.duration.is_some_and(|d| sim.time() >= d) {
                quit = true;
                break;
            }
            let status = LiveStatus {
                speed: controls.speed,
                paused: controls.paused,
            };
            let overlay = Overlay::of(&sim, &prediction, Some(status));
            let image = renderer.draw(handle, &sim, &strip, &overlay);
            if let Err(e) = window.update_with_buffer(&image.pixels, WIDTH, HEIGHT) {
                writeln!(out, "window closed: {e}")?;
                quit = true;
                break;
            }
        }
        for line in result_lines(&sim, &prediction, &spin, method.name(), options.dt) {
            writeln!(out, "{line}")?;
        }
        if quit {
            break 'runs;
        }
        // A restart: say what the new run is.
        writeln!(out, "restart")?;
        for line in setup_lines(handle, &options.mesh, options.density, &controls.spin)
            .into_iter()
            .skip(2)
        {
            writeln!(out, "{line}")?;
        }
    }
    Ok(Outcome::Closed)
}
