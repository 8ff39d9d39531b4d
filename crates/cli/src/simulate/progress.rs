//! A progress bar on standard error, `\r[#####     ]  50%`, drawn only for
//! a person watching a terminal.
//!
//! It is drawn when standard error is a terminal, except when the CSV goes
//! to standard output and that is a terminal too (the bar would tear the
//! rows apart). It is redrawn at most ten times a second and erased at the
//! end, also when the run fails.

#![forbid(unsafe_code)]

use std::io::{self, IsTerminal, Write};
use std::time::{Duration, Instant};

/// Width of the bar in characters, without the brackets.
const WIDTH: usize = 30;

/// Time between redraws.
const REDRAW: Duration = Duration::from_millis(100);

/// Steps between looks at the clock (a step takes about a microsecond).
pub const CHECK_EVERY: u64 = 1024;

/// The progress of a run of `total` steps.
#[derive(Debug)]
pub struct Progress {
    total: u64,
    enabled: bool,
    drawn: bool,
    last: Instant,
}

impl Progress {
    /// A bar for `total` steps, drawn only if `enabled`.
    pub fn new(total: u64, enabled: bool) -> Self {
        Self {
            total: total.max(1),
            enabled,
            drawn: false,
            last: Instant::now(),
        }
    }

    /// Whether the bar is drawn at all.
    pub fn enabled(&self) -> bool {
        self.enabled
    }

    /// Whether a person is watching: standard error is a terminal, and the
    /// CSV does not go to the same screen.
    pub fn wanted(csv_to_stdout: bool) -> bool {
        io::stderr().is_terminal() && !(csv_to_stdout && io::stdout().is_terminal())
    }

    /// Reports that `done` steps are complete; redraws when it is time.
    #[inline]
    pub fn update(&mut self, done: u64) {
        if self.enabled && done.is_multiple_of(CHECK_EVERY) && self.last.elapsed() >= REDRAW {
            self.last = Instant::now();
            self.draw(done);
        }
    }

    fn draw(&mut self, done: u64) {
        let text = bar(done, self.total);
        // A closed standard error is no reason to stop the run.
        let _ = write!(io::stderr(), "\r{text}");
        self.drawn = true;
    }

    /// Erases the bar, if one was drawn.
    pub fn finish(&mut self) {
        if self.drawn {
            let blank = " ".repeat(WIDTH + 7);
            let _ = write!(io::stderr(), "\r{blank}\r");
            self.drawn = false;
        }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        self.finish();
    }
}

/// `[#####     ]  50%` for `done` of `total` steps.
fn bar(done: u64, total: u64) -> String {
    let fraction = (done.min(total) as f64 / total as f64).clamp(0.0, 1.0);
    let filled = (fraction * WIDTH as f64) as usize;
    let percent = (fraction * 100.0) as u32;
    format!(
        "[{}{}] {percent:>3}%",
        "#".repeat(filled),
        " ".repeat(WIDTH - filled)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bar_fills_with_progress() {
        assert_eq!(bar(0, 10), format!("[{}]   0%", " ".repeat(WIDTH)));
        assert_eq!(
            bar(5, 10),
            format!("[{}{}]  50%", "#".repeat(15), " ".repeat(15))
        );
        assert_eq!(bar(12, 10), format!("[{}] 100%", "#".repeat(WIDTH)));
    }

    #[test]
    fn disabled_bar_draws_nothing() {
        let mut p = Progress::new(10, false);
        for k in 0..=CHECK_EVERY {
            p.update(k);
        }
        assert!(!p.drawn);
    }
}
