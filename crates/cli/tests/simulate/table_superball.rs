//! The superball scene (`examples/scenes/superball.toml`, the README's
//! example) against Garwin's closed-form impact map
//! (`tests/data/contact/superball.csv`, written by
//! `tests/data/gen/table_closed_forms.py` with mpmath): every impact's
//! time and normal speeds from the `--events` file, and the last row's
//! position, velocity and spin, which the flight after the tenth bounce
//! leaves as that bounce made them (vz and x following the parabola).

use crate::support::{scene_events_and_last_row, workspace};

const G: f64 = 9.81;
/// The scene's duration, s.
const DURATION: f64 = 3.5;

/// The rows of the reference's case `en0.9_et0.8` (the scene's e and eT),
/// each as a map from column name to value.
fn reference() -> Vec<std::collections::HashMap<String, f64>> {
    let text = std::fs::read_to_string(workspace("tests/data/contact/superball.csv")).unwrap();
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<String> = lines
        .next()
        .unwrap()
        .split(',')
        .map(str::to_owned)
        .collect();
    lines
        .filter(|l| l.starts_with("en0.9_et0.8,"))
        .map(|l| {
            header
                .iter()
                .zip(l.split(','))
                .skip(1)
                .map(|(h, v)| (h.clone(), v.parse().unwrap()))
                .collect()
        })
        .collect()
}

/// `|a − b| ≤ 1e-12 (1 + |b|)`.
fn close(what: &str, a: f64, b: f64) {
    assert!(
        (a - b).abs() <= 1e-12 * (1.0 + b.abs()),
        "{what}: {a} vs {b}"
    );
}

#[test]
fn the_superball_scene_bounces_as_garwins_closed_form() {
    let reference = reference();
    assert_eq!(reference.len(), 10);
    let (text, last) = scene_events_and_last_row("superball", "t,x,vx,vz,wy");
    let impacts: Vec<Vec<&str>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    assert_eq!(impacts.len(), reference.len(), "{text}");
    for (k, (event, want)) in impacts.iter().zip(&reference).enumerate() {
        assert_eq!(event[1..4], ["superball", "1", "impact"], "{event:?}");
        let number = |i: usize| event[i].parse::<f64>().unwrap();
        close(&format!("impact {} time", k + 1), number(0), want["t"]);
        close(
            &format!("impact {} approach", k + 1),
            number(4),
            -want["vz_before"],
        );
        close(
            &format!("impact {} rebound", k + 1),
            number(5),
            want["vz_after"],
        );
    }
    // The last row: after the tenth bounce, in flight.
    let tenth = &reference[9];
    let flight = DURATION - tenth["t"];
    assert_eq!(last[0], DURATION);
    close("x", last[1], tenth["x"] + tenth["vx_after"] * flight);
    close("vx", last[2], tenth["vx_after"]);
    close("vz", last[3], tenth["vz_after"] - G * flight);
    close("wy", last[4], tenth["wy_after"]);
}
