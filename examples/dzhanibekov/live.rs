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

use kreisel::dynamics::FreeBodyMethod;
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
        let axis = match key {
            Key::Key1 | Key::NumPad1 => SpinAxis::Minor,
            Key::Key2 | Key::NumPad2 => SpinAxis::Intermediate,
            Key::Key3 | Key::NumPad3 => SpinAxis::Major,
            Key::Space => {
                self.paused = !self.paused;
                return Action::None;
            }
            Key::Equal | Key::NumPadPlus => {
                self.speed = (self.speed * 2.0).min(SPEEDS.1);
                return Action::None;
            }
            Key::Minus | Key::NumPadMinus => {
                self.speed = (self.speed / 2.0).max(SPEEDS.0);
                return Action::None;
            }
            Key::R => return Action::Restart,
            Key::Q | Key::Escape => return Action::Quit,
            _ => return Action::None,
        };
        self.spin.axis = axis;
        Action::Restart
    }
}

/// One run of the simulation, from a (re)start to the next.
struct Run {
    spin: Spin,
    prediction: Prediction,
    sim: Simulation,
    strip: History,
    next_sample: f64,
}

impl Run {
    fn new(
        method: FreeBodyMethod,
        handle: &Handle,
        spin: Spin,
        dt: f64,
    ) -> Result<Self, DemoError> {
        let sim = Simulation::new(method, handle, &spin, dt)?;
        let mut strip = History::new(Some(STRIP_WINDOW));
        strip.push(0.0, sim.omega_principal());
        Ok(Self {
            spin,
            prediction: Prediction::new(handle.moments(), &spin),
            sim,
            strip,
            next_sample: STRIP_SAMPLE_INTERVAL,
        })
    }

    /// Steps while at least one step of simulated time is owed.
    fn advance(&mut self, owed: &mut f64) -> Result<(), DemoError> {
        let dt = self.sim.dt();
        while *owed >= dt {
            self.sim.step()?;
            *owed -= dt;
            if self.sim.time() >= self.next_sample {
                self.strip.push(self.sim.time(), self.sim.omega_principal());
                self.next_sample += STRIP_SAMPLE_INTERVAL;
            }
        }
        Ok(())
    }

    /// Prints what this run measured.
    fn report(&self, method: &str, out: &mut dyn Write) -> Result<(), DemoError> {
        for line in result_lines(
            &self.sim,
            &self.prediction,
            &self.spin,
            method,
            self.sim.dt(),
        ) {
            writeln!(out, "{line}")?;
        }
        Ok(())
    }
}

/// Runs the window until it is closed (or `--duration` of simulated time
/// has passed), printing the results of each run (each restart ends one).
///
/// Keys are read once per displayed frame: minifb updates its key state in
/// `update_with_buffer`, so every pass of the loop ends with one.
///
/// # Errors
/// [`DemoError::Stdout`], [`DemoError::Plot`]: window failures end the run
/// or fall back.
pub fn run(
    options: &Options,
    handle: &Handle,
    method: FreeBodyMethod,
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
    let moments = handle.moments();
    let bound = |spin: &Spin| spin.omega_bound(moments);
    let mut renderer = FrameRenderer::new(
        WIDTH,
        HEIGHT,
        handle,
        controls.spin.rate,
        bound(&controls.spin),
    );
    let mut run = Run::new(method, handle, controls.spin, options.dt)?;
    let mut owed = 0.0;
    let mut last = Instant::now();
    while window.is_open() {
        let mut restart = false;
        let mut quit = false;
        for key in window.get_keys_pressed(KeyRepeat::No) {
            match controls.apply(key) {
                Action::Restart => restart = true,
                Action::Quit => quit = true,
                Action::None => {}
            }
        }
        if quit {
            break;
        }
        if restart {
            run.report(method.resolve().name(), out)?;
            writeln!(out, "restart")?;
            for line in setup_lines(handle, &options.mesh, options.density, &controls.spin)
                .into_iter()
                .skip(2)
            {
                writeln!(out, "{line}")?;
            }
            run = Run::new(method, handle, controls.spin, options.dt)?;
            renderer.set_scales(controls.spin.rate, bound(&controls.spin));
            owed = 0.0;
        }
        let now = Instant::now();
        let wall = (now - last).as_secs_f64().min(MAX_FRAME_TIME);
        last = now;
        if !controls.paused {
            owed += wall * controls.speed;
            run.advance(&mut owed)?;
        }
        if options.duration.is_some_and(|d| run.sim.time() >= d) {
            break;
        }
        let status = LiveStatus {
            speed: controls.speed,
            paused: controls.paused,
        };
        let overlay = Overlay::of(&run.sim, &run.prediction, Some(status));
        let image = renderer.draw(handle, &run.sim, &run.strip, &overlay)?;
        if let Err(e) = window.update_with_buffer(&image.pixels, WIDTH, HEIGHT) {
            writeln!(out, "window closed: {e}")?;
            break;
        }
    }
    run.report(method.resolve().name(), out)?;
    Ok(Outcome::Closed)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn controls() -> Controls {
        Controls {
            spin: Spin {
                axis: SpinAxis::Intermediate,
                rate: 1.0,
                perturbation: 0.1,
            },
            speed: 1.0,
            paused: false,
        }
    }

    #[test]
    fn keys_change_what_they_say() {
        let mut c = controls();
        assert!(matches!(c.apply(Key::Space), Action::None) && c.paused);
        assert!(matches!(c.apply(Key::Space), Action::None) && !c.paused);
        assert!(matches!(c.apply(Key::Key3), Action::Restart));
        assert_eq!(c.spin.axis, SpinAxis::Major);
        assert!(matches!(c.apply(Key::NumPad1), Action::Restart));
        assert_eq!(c.spin.axis, SpinAxis::Minor);
        assert!(matches!(c.apply(Key::R), Action::Restart));
        assert_eq!(c.spin.axis, SpinAxis::Minor);
        c.apply(Key::Equal);
        c.apply(Key::NumPadPlus);
        assert_eq!(c.speed, 4.0);
        for _ in 0..20 {
            c.apply(Key::Minus);
        }
        assert_eq!(c.speed, SPEEDS.0);
        assert!(matches!(c.apply(Key::Escape), Action::Quit));
        assert!(matches!(c.apply(Key::Q), Action::Quit));
        assert!(matches!(c.apply(Key::X), Action::None));
        assert_eq!(c.spin.rate, 1.0);
    }

    #[test]
    fn displays_are_checked_before_minifb_is_asked() {
        assert!(display_available(None).is_err());
        assert!(display_available(Some(OsStr::new(""))).is_err());
        assert!(display_available(Some(OsStr::new("nonsense"))).is_err());
        assert!(display_available(Some(OsStr::new(":x"))).is_err());
        // A TCP display answers while something listens on 6000 + n.
        let (n, listener) = (40..200u16)
            .find_map(|n| {
                std::net::TcpListener::bind(("127.0.0.1", 6000 + n))
                    .ok()
                    .map(|l| (n, l))
            })
            .expect("a free port");
        let name = format!("127.0.0.1:{n}.0");
        assert_eq!(display_available(Some(OsStr::new(&name))), Ok(()));
        drop(listener);
        let refused = display_available(Some(OsStr::new(&name))).unwrap_err();
        assert!(refused.contains("no X server answers"), "{refused}");
    }
}
