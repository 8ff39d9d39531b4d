//! `--events FILE`: the events of the bodies on the table (impacts,
//! touchdowns, lift-offs, sticking, slipping, rest) as CSV, in time order.
//!
//! ```text
//! time,body,contact,kind,approach_speed,rebound_speed,accumulation_time
//! time               s
//! body               the body's name
//! contact            the [[body.contact]] table's number (1 = the first); empty: the whole body
//! kind               impact | impacts_accumulate | touchdown | lift_off | stick | slip | stops_rolling | starts_rolling | lands_flat | rest
//! approach_speed     impact: the normal speed before, m/s (else empty)
//! rebound_speed      impact: the normal speed after, m/s (else empty)
//! accumulation_time  impacts_accumulate: where the bounces end, s (else empty)
//! ```
//!
//! Events at the same time keep the bodies' scene order, and each body's
//! own order.

#![forbid(unsafe_code)]

use std::io::{self, Write};

use kreisel_dynamics::{TableEvent, TableEventKind, World};

use crate::numbers::Shortest;
use crate::run::Names;

/// The header line, without its newline.
pub const HEADER: &str = "time,body,contact,kind,approach_speed,rebound_speed,accumulation_time";

/// The name of an event's kind in the CSV.
///
/// ```
/// use kreisel_scene::events::kind_name;
/// use kreisel_dynamics::TableEventKind;
/// assert_eq!(kind_name(TableEventKind::LiftOff), "lift_off");
/// ```
pub fn kind_name(kind: TableEventKind) -> &'static str {
    match kind {
        TableEventKind::Impact { .. } => "impact",
        TableEventKind::ImpactsAccumulate { .. } => "impacts_accumulate",
        TableEventKind::Touchdown => "touchdown",
        TableEventKind::LiftOff => "lift_off",
        TableEventKind::Stick => "stick",
        TableEventKind::Slip => "slip",
        TableEventKind::StopsRolling => "stops_rolling",
        TableEventKind::StartsRolling => "starts_rolling",
        TableEventKind::LandsFlat => "lands_flat",
        TableEventKind::Rest => "rest",
    }
}

/// Every body's events in `world`, merged in time order (a stable sort:
/// ties keep the scene order and each body's order).
pub fn merged<'a>(world: &'a World, bodies: &'a Names) -> Vec<(&'a str, TableEvent)> {
    let mut all: Vec<(&str, TableEvent)> = bodies
        .iter()
        .flat_map(|(name, id)| {
            let events = world.events(*id).unwrap_or_default();
            events.iter().map(move |e| (name.as_str(), *e))
        })
        .collect();
    all.sort_by(|a, b| a.1.time.total_cmp(&b.1.time));
    all
}

/// Writes the header and one row per event of the bodies of `world`.
///
/// # Errors
/// The writer's errors.
pub fn write<W: Write + ?Sized>(world: &World, bodies: &Names, out: &mut W) -> io::Result<()> {
    writeln!(out, "{HEADER}")?;
    for (name, event) in merged(world, bodies) {
        write!(out, "{},{name},", Shortest(event.time))?;
        if let Some(i) = event.contact {
            write!(out, "{}", i + 1)?;
        }
        write!(out, ",{}", kind_name(event.kind))?;
        match event.kind {
            TableEventKind::Impact {
                approach_speed,
                rebound_speed,
            } => writeln!(
                out,
                ",{},{},",
                Shortest(approach_speed),
                Shortest(rebound_speed)
            )?,
            TableEventKind::ImpactsAccumulate { accumulation_time } => {
                writeln!(out, ",,,{}", Shortest(accumulation_time))?;
            }
            _ => writeln!(out, ",,,")?,
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use super::*;

    /// Two balls dropped on the table, the lower one first: their impacts
    /// merged in time order, each row with its fields.
    #[test]
    fn the_events_of_every_body_are_merged_in_time_order() {
        let body = |name: &str, z: f64| {
            format!(
                "[[body]]\nname = \"{name}\"\nmass = 1\ninertia = [0.004, 0.004, 0.004]\n\
                 angular_velocity = [0, 0, 0]\nposition = [0, 0, {z}]\n[[body.contact]]\n\
                 shape = \"sphere\"\nradius = 0.1\nfriction = \"coulomb\"\nmu = 0\n\
                 restitution = 0.5\n"
            )
        };
        let text = format!(
            "[simulation]\nduration = 0.5\ndt = 0.1\ngravity = [0, 0, -9.81]\n{}{}",
            body("high", 1.0),
            body("low", 0.5)
        );
        let mut scene = crate::scene_file::parse(Path::new("s.toml"), &text).unwrap();
        scene.world.advance_to(0.5).unwrap();
        let mut out = Vec::new();
        write(&scene.world, &scene.bodies, &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        let rows: Vec<&str> = text.lines().collect();
        assert_eq!(rows[0], HEADER);
        // t = √(2 (z − R)/g): 0.303 s (low), 0.428 s (high).
        let expect = [("low", 0.4), ("high", 0.9)];
        assert_eq!(rows.len(), 1 + expect.len(), "{text}");
        for (row, (name, drop)) in rows[1..].iter().zip(expect) {
            let fields: Vec<&str> = row.split(',').collect();
            assert_eq!(fields[1..4], [name, "1", "impact"], "{row}");
            let t: f64 = fields[0].parse().unwrap();
            let v: f64 = fields[4].parse().unwrap();
            let rebound: f64 = fields[5].parse().unwrap();
            assert!((t - (2.0 * drop / 9.81f64).sqrt()).abs() < 1e-12, "{row}");
            assert!((v - (2.0 * 9.81 * drop).sqrt()).abs() < 1e-9, "{row}");
            assert!((rebound - 0.5 * v).abs() < 1e-12, "{row}");
            assert_eq!(fields[6], "", "{row}");
        }
    }
}
