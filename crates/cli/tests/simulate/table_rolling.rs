//! The billiard-ball scene (`examples/scenes/billiard_ball.toml`, the
//! README's example of `rolling_resistance`) against the closed forms of
//! a solid ball struck without spin: it slides until
//! `t₁ = v₀/(μ g + 5 g (μ R − δ)/(2 R))`, rolls with the deceleration
//! `(5/7) δ g/R` and stops at `t₂`, where it rests at
//! `x₂ = v₀ t₁ − μ g t₁²/2 + v₁² (7 R)/(10 δ g)`.

use crate::support::scene_events_and_last_row;

#[test]
fn the_billiard_ball_slides_rolls_and_stops_as_the_closed_forms_say() {
    let (mu, g, r, delta, v0) = (0.2, 9.81, 0.028575, 3e-4, 2.0);
    let t1 = v0 / (mu * g + 2.5 * g * (mu * r - delta) / r);
    let v1 = v0 - mu * g * t1;
    let a = 5.0 / 7.0 * delta * g / r;
    let (t2, x2) = (
        t1 + v1 / a,
        v0 * t1 - 0.5 * mu * g * t1 * t1 + v1 * v1 / (2.0 * a),
    );
    let (text, last) = scene_events_and_last_row("billiard_ball", "t,x,vx,wy");
    let kinds: Vec<(f64, &str)> = text
        .lines()
        .skip(1)
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            (f[0].parse().unwrap(), f[3])
        })
        .collect();
    let names: Vec<&str> = kinds.iter().map(|k| k.1).collect();
    assert_eq!(
        names,
        ["touchdown", "stick", "stops_rolling", "rest"],
        "{text}"
    );
    assert!(
        (kinds[1].0 - t1).abs() < 1e-12 * t1,
        "{} vs {t1}",
        kinds[1].0
    );
    assert!(
        (kinds[2].0 - t2).abs() < 1e-12 * t2,
        "{} vs {t2}",
        kinds[2].0
    );
    assert!((last[1] - x2).abs() < 1e-12 * x2, "{} vs {x2}", last[1]);
    assert!(last[2].abs() < 1e-12 && last[3].abs() < 1e-12, "{last:?}");
}
