//! The set-valued contact problem finished from the modes that block
//! Gauss–Seidel has found: where the sweeps converge only linearly (an
//! ill-conditioned coupling between contacts) or wander at rounding
//! (contacts that overconstrain the body, whose forces are not unique),
//! the modes they show — open, sticking, slipping along a direction —
//! are usually already the solution's. With the modes fixed the problem
//! is linear; solved exactly (the forces of an overconstrained set
//! deepest inside the cones, [`super::force_distribution`]) and checked
//! against every law, it is the solution, found as an active-set method
//! finds it (Júdice's "guess the active set, solve, verify" for
//! complementarity problems; Acary & Brogliato, *Numerical Methods for
//! Nonsmooth Dynamical Systems*, 2008, §12).
//!
//! ```text
//! open:      x = 0,            y_N ≥ 0
//! sticking:  y_N = 0, y_T = 0, x_N ≥ 0, |x_T| ≤ μ x_N
//! slipping:  y_N = 0, x_T = −μ x_N d,  x_N ≥ 0,  y_T = |y_T| d
//! ```
//!
//! A slipping contact's direction is iterated, `d ← y_T/|y_T|`, until it
//! settles.

use glam::DVec3;

use super::contact_block::{Block, add_delassus_product};
use super::dense::solve_with_null_space;
use super::force_distribution::{Cone, largest_margin};

/// What one block does in a guessed active set.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Guess {
    Open,
    /// Normal force only (no friction directions, or μ = 0).
    Pressed,
    Sticking,
    Slipping(DVec3),
}

/// How close to the cone's edge, relative, a force of the sweeps counts
/// as slipping.
const ON_THE_CONE: f64 = 1e-6;

/// The relative slack of the laws' checks.
const SLACK: f64 = 1e-9;

/// The solution in the modes of the iterate `x` of block Gauss–Seidel,
/// `None` when those modes do not solve the problem (a law fails by more
/// than [`SLACK`] of the problem's scale).
pub(crate) fn finish(
    blocks: &[Block],
    y_free: &[[f64; 4]],
    g: &dyn Fn(usize, usize, usize, usize) -> f64,
    x: &[[f64; 4]],
) -> Option<Vec<[f64; 4]>> {
    let mut guesses: Vec<Guess> = blocks
        .iter()
        .zip(x)
        .map(|(b, x)| {
            let t = DVec3::new(x[1], x[2], x[3]);
            if x[0] <= 0.0 {
                Guess::Open
            } else if b.size == 1 || b.mu == 0.0 {
                Guess::Pressed
            } else if let Some(d) = b.slipping {
                Guess::Slipping(d)
            } else if t.length() < b.mu * x[0] * (1.0 - ON_THE_CONE) {
                Guess::Sticking
            } else {
                Guess::Slipping(-t.normalize_or_zero())
            }
        })
        .collect();
    let y_scale = y_free.iter().flatten().fold(0.0_f64, |m, v| m.max(v.abs()));
    for _ in 0..100 {
        let solved = solve_guess(blocks, y_free, g, &guesses)?;
        let y = accelerations(blocks, y_free, g, &solved);
        // Settle the free slip directions (those the problem decides;
        // a slip that only starts, its acceleration at rounding, keeps
        // the direction opposite its force).
        let mut moved: f64 = 0.0;
        for (k, guess) in guesses.iter_mut().enumerate() {
            if let Guess::Slipping(d) = guess {
                let t = DVec3::new(y[k][1], y[k][2], y[k][3]);
                if blocks[k].slipping.is_none() && t.length() > SLACK * y_scale {
                    // Damped: the plain fixed point may alternate
                    // between two directions.
                    let next = t.normalize();
                    moved = moved.max((next - *d).length());
                    *d = (*d + next).normalize_or(next);
                }
            }
        }
        if moved <= 1e-13 {
            return verified(blocks, y_free, g, &guesses, solved);
        }
    }
    None
}

/// The relative accelerations `y = y⁰ + G x` of every block.
fn accelerations(
    blocks: &[Block],
    y_free: &[[f64; 4]],
    g: &dyn Fn(usize, usize, usize, usize) -> f64,
    x: &[[f64; 4]],
) -> Vec<[f64; 4]> {
    let mut y = y_free.to_vec();
    add_delassus_product(&mut y, blocks, g, x);
    y
}

/// The forces of the blocks in `guesses`: the linear system of their
/// equalities, the forces of an overconstrained set by the largest margin.
fn solve_guess(
    blocks: &[Block],
    y_free: &[[f64; 4]],
    g: &dyn Fn(usize, usize, usize, usize) -> f64,
    guesses: &[Guess],
) -> Option<Vec<[f64; 4]>> {
    // Each unknown: (block, its components' coefficients), and each
    // equation: (block, component).
    let mut unknowns: Vec<(usize, [f64; 4])> = Vec::new();
    let mut equations: Vec<(usize, usize)> = Vec::new();
    let mut cones = Vec::new();
    for (i, (b, guess)) in blocks.iter().zip(guesses).enumerate() {
        let unit = |c: usize| {
            let mut e = [0.0; 4];
            e[c] = 1.0;
            e
        };
        let normal = unknowns.len();
        match guess {
            Guess::Open => continue,
            Guess::Pressed | Guess::Slipping(_) => {
                let mut column = unit(0);
                if let Guess::Slipping(d) = guess {
                    for c in 0..b.size - 1 {
                        column[1 + c] = -b.mu * d[c];
                    }
                }
                unknowns.push((i, column));
                equations.push((i, 0));
                cones.push(Cone {
                    normal,
                    bounded: [0; 3],
                    count: 0,
                    factor: 0.0,
                });
            }
            Guess::Sticking => {
                let mut bounded = [0; 3];
                for c in 0..b.size {
                    unknowns.push((i, unit(c)));
                    equations.push((i, c));
                    if c > 0 {
                        bounded[c - 1] = normal + c;
                    }
                }
                cones.push(Cone {
                    normal,
                    bounded,
                    count: b.size - 1,
                    factor: b.mu,
                });
            }
        }
    }
    let n = unknowns.len();
    let mut a = vec![0.0; n * n];
    let mut rhs = vec![0.0; n];
    for (r, &(i, ca)) in equations.iter().enumerate() {
        rhs[r] = -y_free[i][ca];
        for (k, (j, column)) in unknowns.iter().enumerate() {
            a[r * n + k] = (0..blocks[*j].size)
                .map(|cb| g(i, ca, *j, cb) * column[cb])
                .sum();
        }
    }
    let (x0, null) = solve_with_null_space(&mut a, &rhs, n)?;
    let (values, _) = largest_margin(&x0, &null, &cones);
    let mut x = vec![[0.0; 4]; blocks.len()];
    for ((j, column), v) in unknowns.iter().zip(values) {
        for c in 0..4 {
            x[*j][c] += column[c] * v;
        }
    }
    Some(x)
}

/// `x` when it satisfies every block's law in `guesses` to [`SLACK`].
fn verified(
    blocks: &[Block],
    y_free: &[[f64; 4]],
    g: &dyn Fn(usize, usize, usize, usize) -> f64,
    guesses: &[Guess],
    x: Vec<[f64; 4]>,
) -> Option<Vec<[f64; 4]>> {
    let y = accelerations(blocks, y_free, g, &x);
    let x_scale = x.iter().flatten().fold(0.0_f64, |m, v| m.max(v.abs()));
    let y_scale = y_free.iter().flatten().fold(0.0_f64, |m, v| m.max(v.abs()));
    let (tol_x, tol_y) = (SLACK * x_scale, SLACK * y_scale);
    let holds = guesses.iter().enumerate().all(|(k, guess)| {
        let t = DVec3::new(x[k][1], x[k][2], x[k][3]);
        let y_t = DVec3::new(y[k][1], y[k][2], y[k][3]);
        match guess {
            Guess::Open => y[k][0] >= -tol_y,
            Guess::Pressed => x[k][0] >= -tol_x,
            Guess::Sticking => x[k][0] >= -tol_x && t.length() <= blocks[k].mu * x[k][0] + tol_x,
            // A slip already under way keeps its direction, whatever its
            // acceleration; one that starts must accelerate along it.
            Guess::Slipping(d) => {
                x[k][0] >= -tol_x && (blocks[k].slipping.is_some() || y_t.dot(*d) >= -tol_y)
            }
        }
    });
    holds.then_some(x)
}
