//! The printed lines: the setup before the run; after it, one line per
//! event of interest (the horizontal passage, each change of the contacts
//! that touch, bursts of rocking impacts summed up), the end state and the
//! budgets of the energy and of Jellett's λ.

use kreisel::dynamics::{ContactMode, TableEvent, TableEventKind};

use super::options::Options;
use super::simulation::{
    self, BALL_OFFSET, BALL_RADIUS, CONTACT_NAMES, I1, I3, MASS, SPIN0, STEM_OFFSET, STEM_RADIUS,
    Simulation, THETA0,
};

/// A phase of the contacts shorter than this (s) is part of a burst of
/// rocking impacts, summed up in one line (the rocking of the top falling
/// back onto ball and stem: phases of 70 ms and shorter, accumulating).
pub const ROCKING_PHASE: f64 = 0.1;

/// `value` to `digits` significant digits, without trailing zeros.
fn significant(value: f64, digits: usize) -> String {
    format!("{value:.*e}", digits - 1)
        .parse::<f64>()
        .map_or_else(|_| value.to_string(), |v| v.to_string())
}

/// A time as printed: `t = 1.371043 s` (6 decimals, the library's time
/// rounded).
pub fn time_words(t: f64) -> String {
    format!("t = {t:.6} s")
}

/// The lines printed before the run.
pub fn setup_lines(options: &Options) -> Vec<String> {
    vec![
        format!(
            "tippe top (Leine & Glocker 2003): m = {} g, I₁ = {I1:e} kg m², I₃ = {I3:e} kg m², \
             ball R = {} mm, centre of mass a = {} mm below the ball's centre (α = {}), \
             stem ball r = {} mm, {} mm from the centre of mass",
            MASS * 1e3,
            BALL_RADIUS * 1e3,
            BALL_OFFSET * 1e3,
            significant(BALL_OFFSET / BALL_RADIUS, 6),
            STEM_RADIUS * 1e3,
            STEM_OFFSET * 1e3,
        ),
        format!(
            "start: on the ball, tilt θ₀ = {THETA0} rad, spin ω₀ = {SPIN0} rad/s about the axis; \
             ball and stem: {}",
            options.law_words()
        ),
        format!(
            "engine: the library's TableMotion (unilateral contacts, set-valued friction, \
             impacts; adaptive Dormand–Prince 5(4) between events located to rounding), \
             tolerance {:e}, {} s",
            options.tolerance, options.duration
        ),
    ]
}

/// A speed in mm/s, 3 significant digits.
fn speed_words(v: f64) -> String {
    format!("{} mm/s", significant(v * 1e3, 3))
}

/// Where the top stands with `touching` (ball, stem).
fn standing(touching: [bool; 2]) -> &'static str {
    match touching {
        [true, true] => "on the ball and the stem",
        [true, false] => "on the ball",
        [false, true] => "on the stem",
        [false, false] => "in the air",
    }
}

/// One library event in words (None for stick and slip: the summary
/// counts them); rebounds below `resolution` (m/s) are zero.
fn event_words(e: &TableEvent, resolution: f64) -> Option<String> {
    let name = e.contact.map_or("top", |i| CONTACT_NAMES[i]);
    Some(match e.kind {
        TableEventKind::Impact {
            approach_speed,
            rebound_speed,
        } => {
            let rebound = if rebound_speed > resolution {
                format!(", rebounds at {}", speed_words(rebound_speed))
            } else {
                String::new()
            };
            format!(
                "the {name} strikes the table at {}{rebound}",
                speed_words(approach_speed)
            )
        }
        TableEventKind::ImpactsAccumulate { accumulation_time } => {
            format!("the {name}'s bounces accumulate at t = {accumulation_time:.6} s")
        }
        TableEventKind::Touchdown => format!("the {name} touches down"),
        TableEventKind::LiftOff => format!("the {name} lifts off"),
        TableEventKind::LandsFlat => format!("the {name} lands flat"),
        TableEventKind::StopsRolling => format!("the {name} stops rolling"),
        TableEventKind::StartsRolling => format!("the {name} starts rolling"),
        TableEventKind::Rest => "the top comes to rest".to_owned(),
        TableEventKind::Stick | TableEventKind::Slip => return None,
    })
}

/// The lines of the contacts' changes: one per change that lasts at least
/// [`ROCKING_PHASE`], a burst of shorter phases in one line.
fn contact_lines(sim: &Simulation, end: f64) -> Vec<(f64, String)> {
    let history = &sim.touching_history;
    let events = sim.events();
    let mut lines = Vec::new();
    let mut k = 1;
    while k < history.len() {
        // The burst: this change and the following ones while each phase
        // is short.
        let first = k;
        let lasts = |k: usize| history.get(k + 1).map_or(end, |n| n.0) - history[k].0;
        while k + 1 < history.len() && lasts(k) < ROCKING_PHASE {
            k += 1;
        }
        let (t0, t1) = (history[first].0, history[k].0);
        let after = standing(history[k].1);
        if first == k {
            let words: Vec<String> = events
                .iter()
                .filter(|e| e.time == t0)
                .filter_map(|e| event_words(e, sim.run().resolution_speed()))
                .collect();
            lines.push((
                t0,
                format!("{}: {}: {after}", time_words(t0), words.join(", ")),
            ));
        } else {
            let burst: Vec<&TableEvent> = events
                .iter()
                .filter(|e| e.time >= t0 && e.time <= t1)
                .collect();
            let fastest = burst
                .iter()
                .filter_map(|e| match e.kind {
                    TableEventKind::Impact { approach_speed, .. } => Some(approach_speed),
                    _ => None,
                })
                .fold(0.0, f64::max);
            let struck = [0, 1].map(|i| {
                burst.iter().any(|e| {
                    e.contact == Some(i) && matches!(e.kind, TableEventKind::Impact { .. })
                })
            });
            let (first_name, motion) = match struck {
                [true, true] => (
                    burst.first().and_then(|e| e.contact).unwrap_or(0),
                    "it rocks between ball and stem",
                ),
                [false, true] => (1, "it bounces on the stem"),
                _ => (0, "it bounces on the ball"),
            };
            lines.push((
                t0,
                format!(
                    "{}: the {} strikes the table: {motion}, the impacts ({} at most) \
                     accumulating by t ≈ {t1:.4} s: {after}",
                    time_words(t0),
                    CONTACT_NAMES[first_name],
                    speed_words(fastest)
                ),
            ));
        }
        k += 1;
    }
    lines
}

/// A contact's mode in words.
fn mode_word(mode: ContactMode) -> &'static str {
    match mode {
        ContactMode::Open => "open",
        ContactMode::Slipping => "slipping",
        ContactMode::Sticking => "sticking",
    }
}

/// The lines printed after the run.
pub fn result_lines(sim: &Simulation, options: &Options) -> Vec<String> {
    let end = sim.time();
    let mut timed = contact_lines(sim, end);
    if let (Some(&t), Some(&last)) = (sim.horizontal.first(), sim.horizontal.last()) {
        let nutating = if sim.horizontal.len() > 1 {
            format!(
                "; nutating, it passes it {} times, the last at t = {last:.6} s",
                sim.horizontal.len()
            )
        } else {
            String::new()
        };
        timed.push((
            t,
            format!(
                "{}: the axis passes the horizontal (θ = 90°, located by bisection on the \
                 run{nutating})",
                time_words(t)
            ),
        ));
    }
    timed.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut lines: Vec<String> = timed.into_iter().map(|(_, l)| l).collect();
    if sim.horizontal.is_empty() {
        lines.push(format!(
            "the axis stays above the horizontal for {} s",
            significant(end, 6)
        ));
    }
    if options.events {
        lines.push(format!("the library's events ({}):", sim.events().len()));
        lines.extend(sim.events().iter().map(|e| format!("  {e}")));
    }
    let state = sim.state();
    let omega = state.world_from_body.normalize() * state.omega_body;
    let modes = sim.run().modes();
    let contacts: Vec<String> = modes
        .iter()
        .zip(CONTACT_NAMES)
        .filter(|(m, _)| **m != ContactMode::Open)
        .map(|(m, name)| format!("{name} {}", mode_word(*m)))
        .collect();
    lines.push(format!(
        "at t = {} s: θ = {:.2}°, {} ({}), ω_z = {:.3} rad/s, spin about the axis {:.3} rad/s",
        significant(end, 6),
        simulation::tilt(&state).to_degrees(),
        standing(sim.touching()),
        if contacts.is_empty() {
            "no contact".to_owned()
        } else {
            contacts.join(", ")
        },
        omega.z,
        omega.dot(simulation::axis(&state)),
    ));
    let rose = if sim.energy_rise <= 0.0 {
        "it never rose between the observed instants".to_owned()
    } else {
        format!(
            "its largest rise between the observed instants: {:.0e} E₀ (tolerance {:e})",
            sim.energy_rise / sim.energy0,
            options.tolerance
        )
    };
    lines.push(format!(
        "energy: E/E₀ = {:.4} at the end (friction and impacts only take it away); {rose}",
        sim.energy_ratio()
    ));
    let phases: Vec<String> = sim
        .jellett
        .iter()
        .zip(CONTACT_NAMES)
        .filter(|(w, _)| w.time_alone > 0.0)
        .map(|(w, name)| {
            format!(
                "the {name} alone ({} s): max |Δλ|/|λ| = {:.0e}",
                significant(w.time_alone, 3),
                w.drift
            )
        })
        .collect();
    let why = if options.contensou_radius > 0.0 {
        "Contensou's drilling torque changes it; it is constant only while one sphere alone \
         touches without drilling friction (--contensou-radius 0)"
    } else {
        "constant while one sphere alone touches (no drilling friction), not across impacts \
         or with both touching"
    };
    lines.push(format!(
        "Jellett's λ = −L·ρ about the touching sphere, while {}: {why}",
        if phases.is_empty() {
            "no sphere touched alone".to_owned()
        } else {
            phases.join(", ")
        }
    ));
    lines
}
