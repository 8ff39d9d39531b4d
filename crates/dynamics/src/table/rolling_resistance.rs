//! The set-valued rolling resistance at an event: which rolling holds and
//! which rolls, beside the contacts' Signorini and friction problem.
//!
//! The rolling resistance of contact `a` is a torque `δ x_R` about the
//! table's x and y axes (`x_R` in newtons, the rates `γ_R = δ ω_h` in m/s,
//! [`super::ContactLaw`]) with its own cone of radius `x_N`:
//!
//! ```text
//! γ_R = γ_R⁰ + Σ_b (G_Rb x_b + G_RRb x_Rb)
//! holds:  γ_R = 0,  |x_R| ≤ x_N          rolls:  x_R = −x_N γ_R/|γ_R|
//! ```
//!
//! It is solved by Gauss–Seidel between the two problems (Studer &
//! Glocker's successive inclusions, the rolling cones as blocks of their
//! own): the contacts' blocks with the rolling torques fixed
//! ([`super::contact_problem::solve_blocks`]), then each rolling cone with
//! the contact forces fixed, until neither changes. The coupling is of
//! the order `δ/ℓ`, so a few sweeps settle it.

use glam::DVec3;

use super::contact_block::{Block, Rolling};
use super::contact_frame::{ContactFrame, ROLLING};
use super::contact_newton::solve_whole;
use super::contact_problem::solve_blocks_from;
use super::dense::solve_in_place;
use crate::DynamicsError;

/// The relative change of the forces below which the sweeps between the
/// contacts' problem and the rolling cones stop: each sweep re-solves the
/// contacts' problem to rounding, so the sweeps settle at a few hundred
/// ulps, not at one (a body on a disk rim and an ellipsoid, both with
/// rolling resistance, settled at changes of 4e-15 of the forces and never
/// below 1e-15: `ContactUnsolved`).
const OUTER_TOLERANCE: f64 = 1e-13;

/// The most sweeps between the contacts and the rolling cones: each
/// solves the contacts' problem whole, so a problem that does not settle
/// in these (contacts that overconstrain the body with their rolling
/// held) is unsolved, not a hang of millions of sweeps.
const OUTER_SWEEPS: usize = 200;

/// The contacts' unknowns `x` (normal, friction) and the rolling
/// resistances `x_R` of the `touching` contacts: by sweeps between the
/// contacts' problem and the rolling cones, and where those settle too
/// slowly or cycle, by Newton's method on the problem whole from where
/// they got to ([`solve_whole`]).
///
/// # Errors
/// Those of [`solve_blocks_from`] but `ContactUnsolved`;
/// [`DynamicsError::ContactUnsolved`] when neither settles.
pub(crate) fn solve_with_rolling(
    frame: &ContactFrame,
    touching: &[usize],
    blocks: &[Block],
    y_free: &[[f64; 4]],
    rolling: &[Rolling],
) -> Result<(Vec<[f64; 4]>, Vec<DVec3>), DynamicsError> {
    let m = touching.len();
    let (mut x, mut x_r) = (vec![[0.0; 4]; m], vec![DVec3::ZERO; m]);
    match sweep_with_rolling(frame, touching, blocks, y_free, rolling, &mut x, &mut x_r) {
        Ok(()) => Ok((x, x_r)),
        Err(DynamicsError::ContactUnsolved { .. }) => {
            solve_whole(frame, touching, blocks, y_free, rolling, Some((&x, &x_r)))
                .ok_or(DynamicsError::ContactUnsolved { time: f64::NAN })
        }
        Err(e) => Err(e),
    }
}

/// The sweeps of [`solve_with_rolling`], from and into `x`, `x_r`.
///
/// # Errors
/// Those of [`solve_blocks_from`]; [`DynamicsError::ContactUnsolved`] when the
/// sweeps between the two problems do not settle.
fn sweep_with_rolling(
    frame: &ContactFrame,
    touching: &[usize],
    blocks: &[Block],
    y_free: &[[f64; 4]],
    rolling: &[Rolling],
    x: &mut [[f64; 4]],
    x_r: &mut [DVec3],
) -> Result<(), DynamicsError> {
    let g = |a: usize, ca: usize, b: usize, cb: usize| {
        frame.delassus(
            &frame.rows[touching[a]].directions[ca],
            &frame.rows[touching[b]].directions[cb],
        )
    };
    let m = touching.len();
    if rolling.iter().all(|r| *r == Rolling::Free) {
        return solve_blocks_from(blocks, y_free, &g, x);
    }
    let free = (frame.free_velocity_rate, frame.free_omega_rate);
    // The share of the rolling torques (all but `skip`'s) in component
    // `ca` of contact `a`.
    let rolling_share = |a: usize, ca: usize, x_r: &[DVec3], skip: Option<usize>| -> f64 {
        (0..m)
            .filter(|&b| Some(b) != skip)
            .flat_map(|b| ROLLING.iter().enumerate().map(move |(c, &r)| (b, c, r)))
            .map(|(b, c, r)| g(a, ca, b, r) * x_r[b][c])
            .sum()
    };
    for _ in 0..OUTER_SWEEPS {
        let shifted: Vec<[f64; 4]> = (0..m)
            .map(|a| {
                let mut y = y_free[a];
                for (k, v) in y.iter_mut().enumerate().take(blocks[a].size) {
                    *v += rolling_share(a, k, x_r, None);
                }
                y
            })
            .collect();
        // From the last sweep's solution: the rolling torques moved it a
        // little.
        solve_blocks_from(blocks, &shifted, &g, x)?;
        let (mut change, mut size) = (0.0_f64, 0.0_f64);
        for a in 0..m {
            if rolling[a] == Rolling::Free {
                continue;
            }
            let mut y0 = [0.0; 2];
            for (c, &r) in ROLLING.iter().enumerate() {
                let contacts: f64 = (0..m)
                    .flat_map(|b| (0..blocks[b].size).map(move |k| (b, k)))
                    .map(|(b, k)| g(a, r, b, k) * x[b][k])
                    .sum();
                y0[c] =
                    frame.rate(touching[a], r, free) + contacts + rolling_share(a, r, x_r, Some(a));
            }
            let own = [
                [
                    g(a, ROLLING[0], a, ROLLING[0]),
                    g(a, ROLLING[0], a, ROLLING[1]),
                ],
                [
                    g(a, ROLLING[1], a, ROLLING[0]),
                    g(a, ROLLING[1], a, ROLLING[1]),
                ],
            ];
            let next = rolling_cone(x[a][0].max(0.0), &own, y0, rolling[a])?;
            change = change.max((next - x_r[a]).length());
            size = size.max(next.length()).max(x[a][0].abs());
            x_r[a] = next;
        }
        if change <= OUTER_TOLERANCE * size {
            return Ok(());
        }
    }
    Err(DynamicsError::ContactUnsolved { time: f64::NAN })
}

/// One rolling cone of radius `n` exactly: `γ_R = y0 + G x_R`, hold if the
/// holding torque lies in the cone, else roll on its boundary. Rolling,
/// `x_R` minimises `½ xᵀ G x + y0ᵀ x` over the disk `|x| ≤ n` on its edge,
/// where `γ_R = −λ x_R` (the torque opposes the rolling):
///
/// ```text
/// x(λ) = −(G + λ 𝟙)⁻¹ y0,   |x(λ)| = n,   λ > 0
/// ```
///
/// `|x(λ)|` falls with `λ` (G is positive definite), so bisection on `λ`
/// in `(0, |y0|/n]` finds it to rounding — a damped fixed point on the
/// direction did not settle where the rolling rate `λ n` is small beside
/// `y0` (its direction then lies in the rounding of `y0 + G x`).
///
/// # Errors
/// [`DynamicsError::ContactUnsolved`] when the block is singular.
fn rolling_cone(
    n: f64,
    g: &[[f64; 2]; 2],
    y0: [f64; 2],
    rolling: Rolling,
) -> Result<DVec3, DynamicsError> {
    if n == 0.0 {
        return Ok(DVec3::ZERO);
    }
    if let Rolling::Along(d) = rolling {
        return Ok(-n * d);
    }
    // x(λ) = −(G + λ𝟙)⁻¹ y0.
    let torque = |lambda: f64| {
        let mut a = [g[0][0] + lambda, g[0][1], g[1][0], g[1][1] + lambda];
        let mut x = [-y0[0], -y0[1]];
        solve_in_place(&mut a, &mut x, 2).then(|| DVec3::new(x[0], x[1], 0.0))
    };
    let unsolved = || DynamicsError::ContactUnsolved { time: f64::NAN };
    let hold = torque(0.0).ok_or_else(unsolved)?;
    if hold.length() <= n * (1.0 + 1e-12) {
        return Ok(hold);
    }
    let (mut lo, mut hi) = (0.0, DVec3::new(y0[0], y0[1], 0.0).length() / n);
    while hi - lo > 4.0 * f64::EPSILON * hi {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if torque(mid).ok_or_else(unsolved)?.length() > n {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    // On the edge exactly: the direction of x(λ), the length n.
    Ok(torque(hi).ok_or_else(unsolved)?.normalize() * n)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A ball of radius R pushed to roll: `G_RR = δ²/I 𝟙` for the torques.
    #[test]
    fn a_cone_holds_inside_and_rolls_on_its_edge() {
        let g = [[2.0, 0.0], [0.0, 2.0]];
        // Holding needs |x_R| = 1.5 N: held for x_N ≥ 1.5.
        let x = rolling_cone(2.0, &g, [3.0, 0.0], Rolling::Cone).unwrap();
        assert!((x.x + 1.5).abs() < 1e-15 && x.y == 0.0);
        // Rolling: the whole cone against the rolling.
        let x = rolling_cone(1.0, &g, [0.0, -3.0], Rolling::Cone).unwrap();
        assert!(x.x.abs() < 1e-15 && (x.y - 1.0).abs() < 1e-15, "{x}");
        // Rolling already: along its direction, whatever the rates.
        let x = rolling_cone(1.0, &g, [0.0, 0.0], Rolling::Along(DVec3::X)).unwrap();
        assert_eq!(x, -DVec3::X);
        // No normal force: no torque.
        assert_eq!(
            rolling_cone(0.0, &g, [3.0, 0.0], Rolling::Cone).unwrap(),
            DVec3::ZERO
        );
    }

    /// An anisotropic block rolls along the direction whose rate is
    /// parallel to it (the fixed point), not along the holding torque.
    #[test]
    fn an_anisotropic_cone_rolls_along_its_consistent_direction() {
        let g = [[1.0, 0.0], [0.0, 4.0]];
        let y0 = [-3.0, -3.0];
        let x = rolling_cone(1.0, &g, y0, Rolling::Cone).unwrap();
        assert!((x.length() - 1.0).abs() < 1e-14);
        let y = DVec3::new(y0[0] + x.x, y0[1] + 4.0 * x.y, 0.0);
        // x = −N y/|y|: the torque opposes the resulting rolling rate.
        assert!((x + y.normalize()).length() < 1e-12, "{x} vs {y}");
    }

    /// Regression (case 4 of `examples/table_scan.rs`, seed 26): a block
    /// whose rolling rate is small beside `y0` — the damped fixed point on
    /// the direction did not settle (`ContactUnsolved` at 1.2823 s).
    #[test]
    fn a_block_rolling_slowly_beside_its_free_rate_is_solved() {
        let n = 0.44893548990859505;
        let g = [
            [0.06305771162481419, -0.003765532434927477],
            [-0.003765532434927479, 0.03752153639456489],
        ];
        let y0 = [-0.015533859866639133, 0.017610207746564036];
        let x = rolling_cone(n, &g, y0, Rolling::Cone).unwrap();
        assert!((x.length() - n).abs() < 1e-15, "{x}");
        let y = DVec3::new(
            y0[0] + g[0][0] * x.x + g[0][1] * x.y,
            y0[1] + g[1][0] * x.x + g[1][1] * x.y,
            0.0,
        );
        assert!((x / n + y.normalize()).length() < 1e-9, "{x} vs {y}");
    }
}
