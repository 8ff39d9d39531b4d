//! The contact problems of a [`super::TableBody`] at one state: the
//! accelerations of the current contact modes (the smooth right-hand
//! side between events), and the set-valued problem that decides the
//! modes at an event (which contacts stay closed, which stick).
//!
//! Both act on the relative quantities of [`ContactFrame`]: per contact
//! `y = (y_N, y_T)` (accelerations here, velocities at an impact) that
//! depend linearly on the contact's unknowns `x = (x_N, x_T)` (forces
//! here, impulses at an impact) through the Delassus blocks
//! `G_ij = W_iᵀ M⁻¹ W_j`:
//!
//! ```text
//! y_i = y_i⁰ + Σ_j G_ij x_j
//! normal:   x_N ≥ 0,  y_N ≥ 0,  x_N y_N = 0                      (Signorini)
//! friction: |x_T| ≤ μ x_N,  x_T = −μ x_N y_T/|y_T| when y_T ≠ 0   (Coulomb–Contensou)
//!           or, slipping already: x_T = −μ x_N d, d the slip direction
//! rolling:  |x_R| ≤ x_N,  y_R = 0 while it holds, x_R = −x_N d_R while it rolls
//! ```
//!
//! The problem is solved contact by contact (block Gauss–Seidel; Studer &
//! Glocker, Acta Mech. 2006, call it the successive solution of the
//! inclusions), each block exactly: separation if `y_N⁰ ≥ 0`, else
//! sticking if its force lies in the cone, else slipping on the cone's
//! boundary with the direction found by Newton's method
//! ([`super::slip_onset`]; a damped fixed point, then the projected
//! iteration, where it does not settle). The sweeps have settled when the
//! unknowns stop moving or move only along the null space of `G`
//! (contacts that overconstrain the body); where they converge slowly the
//! modes they show are finished exactly ([`super::active_set`]).
//! Between events, the forces of contacts that overconstrain the body are
//! those deepest inside the cones ([`super::force_distribution`]): the
//! accelerations do not depend on that choice, the end of sticking does.

use glam::DVec3;

use super::TableBody;
use super::active_set::finish;
use super::contact_block::{Block, add_delassus_product};
use super::contact_frame::{ContactFrame, ROLLING, Wrench};
use super::dense::{solve_in_place, solve_with_null_space};
use super::force_distribution::{Cone, largest_margin};
use super::slip_onset::slip_onset;
use crate::DynamicsError;

/// What a contact does between two events.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ContactMode {
    /// Not touching (or touching without force, about to separate).
    Open,
    /// Closed, slipping (or drilling) against the friction.
    Slipping,
    /// Closed, the contact point at rest on the table (and no drilling).
    Sticking,
}

/// A contact's mode with the slip direction to use where the slip itself
/// is too small to give one (just after slipping starts); the same for
/// its rolling under a rolling resistance (`roll`: `Sticking` while the
/// resistance holds the rolling, `Slipping` while it rolls, `Open` for an
/// open contact or a law without rolling resistance).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Mode {
    pub(crate) mode: ContactMode,
    pub(crate) direction: DVec3,
    pub(crate) roll: ContactMode,
    pub(crate) roll_direction: DVec3,
}

impl Mode {
    /// An open contact.
    pub(crate) const OPEN: Mode = Mode {
        mode: ContactMode::Open,
        direction: DVec3::ZERO,
        roll: ContactMode::Open,
        roll_direction: DVec3::ZERO,
    };

    /// A closed contact in `mode` with `direction`, no rolling decided.
    pub(crate) fn closed(mode: ContactMode, direction: DVec3) -> Self {
        Self {
            mode,
            direction,
            ..Self::OPEN
        }
    }
}

/// The accelerations and contact forces of one state in given modes.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ModeForces {
    /// `v̇_G`, m/s².
    pub(crate) velocity_rate: DVec3,
    /// `L̇`, the torque of the contact forces about the centre of mass.
    pub(crate) l_rate: DVec3,
    /// `ω̇`.
    pub(crate) omega_rate: DVec3,
    /// Each contact's normal force `N` (0 for an open one).
    pub(crate) normal: [f64; TableBody::MAX_CONTACTS],
    /// Each contact's friction `x_T` (components along its friction
    /// directions).
    pub(crate) friction: [DVec3; TableBody::MAX_CONTACTS],
    /// Each contact's rolling resistance `x_R` (the torque `δ x_R` about
    /// the table's x and y axes; third component zero).
    pub(crate) rolling: [DVec3; TableBody::MAX_CONTACTS],
}

/// The slip direction of a slipping contact: the slip's when it exceeds
/// `floor`, else the direction kept in its mode.
pub(crate) fn slip_direction(slip: DVec3, mode: &Mode, floor: f64) -> DVec3 {
    direction_or(slip, mode.direction, floor)
}

/// The rolling direction of a rolling contact: its rolling rate's when
/// it exceeds `floor`, else the direction kept in its mode.
pub(crate) fn roll_direction(roll: DVec3, mode: &Mode, floor: f64) -> DVec3 {
    direction_or(roll, mode.roll_direction, floor)
}

/// `v/|v|` when `|v|` exceeds `floor`, `kept` below half of it, and in
/// between the direction passing over from one to the other,
///
/// ```text
/// d = normalise((1 − w) v/|v| + w kept),   w = (floor − |v|)/(floor/2)
/// ```
///
/// continuous across the floor's edge (held outright at the edge, a slip
/// hovering there while its direction turned made the right-hand side
/// jump, and the error control took steps of 1e-9 s for ever; a random
/// throw, `examples/table_scan.rs` case 24).
fn direction_or(v: DVec3, kept: DVec3, floor: f64) -> DVec3 {
    let s = v.length();
    if s > floor {
        v / s
    } else if s > 0.5 * floor {
        let w = (floor - s) / (0.5 * floor);
        ((1.0 - w) * v / s + w * kept).normalize_or(kept)
    } else {
        kept
    }
}

/// The painlevé error at `time` for the coefficient `compliance`.
fn indeterminate(compliance: f64) -> DynamicsError {
    DynamicsError::ContactIndeterminate {
        time: f64::NAN,
        compliance,
    }
}

/// The accelerations of `frame` with the contacts in `modes`: each closed
/// contact keeps `g̈ = 0`, each sticking one `γ̇_T = 0`, each slipping one
/// rubs with `−μ N d`.
///
/// # Errors
/// [`DynamicsError::ContactIndeterminate`] (its time NaN: the caller
/// knows it) when a slipping contact's normal coefficient
/// `w_Nᵀ M⁻¹ (w_N − μ W_T d)` is not positive or the system has an entry
/// that is not finite. A singular system (contacts that overconstrain the
/// body) is solved with the forces of the largest margin.
pub(crate) fn mode_forces(
    frame: &ContactFrame,
    modes: &[Mode],
    slip_floor: f64,
) -> Result<ModeForces, DynamicsError> {
    let free = (frame.free_velocity_rate, frame.free_omega_rate);
    let unknowns: usize = frame
        .rows
        .iter()
        .zip(modes)
        .map(|(row, mode)| match mode.mode {
            ContactMode::Open => 0,
            ContactMode::Slipping => 1,
            ContactMode::Sticking => 1 + row.friction_dimensions,
        } + if row.rolls && mode.mode != ContactMode::Open && mode.roll == ContactMode::Sticking {
            ROLLING.len()
        } else {
            0
        })
        .sum();
    // Sized to the problem: a memset of the largest (32 × 32) in every
    // evaluation cost a quarter of the run (measured with perf).
    let mut rows = Vec::with_capacity(unknowns);
    let mut cols = Vec::with_capacity(unknowns);
    let mut rhs = Vec::with_capacity(unknowns);
    // (contact, component) of each unknown.
    let mut owner = Vec::with_capacity(unknowns);
    let mut directions = [DVec3::ZERO; TableBody::MAX_CONTACTS];
    let mut roll_directions = [DVec3::ZERO; TableBody::MAX_CONTACTS];
    for (i, (row, mode)) in frame.rows.iter().zip(modes).enumerate() {
        if mode.mode == ContactMode::Open {
            continue;
        }
        let mut normal_col = row.directions[0];
        let nf = row.friction_dimensions;
        let slipping = mode.mode == ContactMode::Slipping && nf > 0;
        if slipping {
            let d = slip_direction(row.slip(), mode, slip_floor);
            directions[i] = d;
            for c in 0..nf {
                normal_col = normal_col.plus(row.directions[1 + c].scaled(-row.mu * d[c]));
            }
        }
        let rolling = row.rolls && mode.roll == ContactMode::Slipping;
        if rolling {
            let d = roll_direction(row.roll(), mode, slip_floor);
            roll_directions[i] = d;
            for (c, &k) in ROLLING.iter().enumerate() {
                normal_col = normal_col.plus(row.directions[k].scaled(-d[c]));
            }
        }
        if slipping || rolling {
            let compliance = frame.delassus(&row.directions[0], &normal_col);
            if compliance.is_nan() || compliance <= 0.0 {
                return Err(indeterminate(compliance));
            }
        }
        let sticking = mode.mode == ContactMode::Sticking;
        let holding = row.rolls && mode.roll == ContactMode::Sticking;
        let components =
            (0..if sticking { 1 + nf } else { 1 }).chain(ROLLING.into_iter().filter(|_| holding));
        for k in components {
            rows.push(row.directions[k]);
            cols.push(if k == 0 {
                normal_col
            } else {
                row.directions[k]
            });
            rhs.push(-frame.rate(i, k, free));
            owner.push((i, k));
        }
    }
    let n = rhs.len();
    let matrix = || {
        let mut a = vec![0.0; n * n];
        for (r, row) in rows.iter().enumerate() {
            for (k, col) in cols.iter().enumerate() {
                a[r * n + k] = frame.delassus(row, col);
            }
        }
        a
    };
    if !solve_in_place(&mut matrix(), &mut rhs, n) {
        // Contacts that overconstrain the body: the accelerations are
        // unique, the forces are taken deepest inside the cones (the
        // right-hand side built again: the failed solve consumed it).
        let b: Vec<f64> = owner
            .iter()
            .map(|&(i, k)| -frame.rate(i, k, free))
            .collect();
        let (x0, null) =
            solve_with_null_space(&mut matrix(), &b, n).ok_or_else(|| indeterminate(0.0))?;
        rhs = largest_margin(&x0, &null, &cones_of(&owner, frame)).0;
    }
    let mut total = Wrench::default();
    let mut out = ModeForces {
        velocity_rate: DVec3::ZERO,
        l_rate: DVec3::ZERO,
        omega_rate: DVec3::ZERO,
        normal: [0.0; TableBody::MAX_CONTACTS],
        friction: [DVec3::ZERO; TableBody::MAX_CONTACTS],
        rolling: [DVec3::ZERO; TableBody::MAX_CONTACTS],
    };
    for k in 0..n {
        total = total.plus(cols[k].scaled(rhs[k]));
        let (i, c) = owner[k];
        if c == 0 {
            out.normal[i] = rhs[k];
            if modes[i].mode == ContactMode::Slipping {
                out.friction[i] = -frame.rows[i].mu * rhs[k] * directions[i];
            }
            if modes[i].roll == ContactMode::Slipping {
                out.rolling[i] = -rhs[k] * roll_directions[i];
            }
        } else if c >= ROLLING[0] {
            out.rolling[i][c - ROLLING[0]] = rhs[k];
        } else {
            out.friction[i][c - 1] = rhs[k];
        }
    }
    let (dv, dw) = frame.response(&total);
    out.velocity_rate = frame.free_velocity_rate + dv;
    out.omega_rate = frame.free_omega_rate + dw;
    out.l_rate = total.torque + frame.applied_torque;
    Ok(out)
}

/// The cones of the closed contacts over the unknowns `owner` ((contact,
/// component) of each, as [`mode_forces`] lays them out: each contact's
/// normal, then its friction if it sticks, then its rolling if that
/// holds).
fn cones_of(owner: &[(usize, usize)], frame: &ContactFrame) -> Vec<Cone> {
    let mut cones: Vec<Cone> = Vec::new();
    let mut normal = 0;
    for (k, &(i, c)) in owner.iter().enumerate() {
        if c == 0 {
            normal = k;
            cones.push(Cone {
                normal,
                bounded: [0; 3],
                count: 0,
                factor: frame.rows[i].mu,
            });
        } else if c == ROLLING[0] {
            // Both rolling components follow each other.
            cones.push(Cone {
                normal,
                bounded: [k, k + 1, 0],
                count: 2,
                factor: 1.0,
            });
        } else if c < ROLLING[0]
            // A friction component: its contact's cone is the last pushed
            // (the normal comes first, the rolling after the friction).
            && let Some(cone) = cones.last_mut()
        {
            cone.bounded[cone.count] = k;
            cone.count += 1;
        }
    }
    cones
}

/// The relative change of the unknowns below which block Gauss–Seidel
/// stops.
pub(crate) const SWEEP_TOLERANCE: f64 = 1e-15;

/// The change of the accelerations `G Δx` over a sweep, relative to
/// `max G_ii · max |x|`, below which the sweeps have settled while the
/// unknowns still move (along the null space of `G`).
pub(crate) const NULL_TOLERANCE: f64 = 1e-14;

/// How many sweeps between two tries to finish the problem from the
/// sweeps' modes ([`finish`]).
const FINISH_EVERY: usize = 50;

/// The most sweeps (and slip-direction iterations) before the problem is
/// called unsolved.
pub(crate) const MAX_SWEEPS: usize = 2000;

/// Solves `y_i = y⁰_i + Σ_j G_ij x_j` with each block's law, by block
/// Gauss–Seidel from the unknowns `x` (zero, or a warm start: the
/// previous solution of a problem that changed a little), into them;
/// where the sweeps do not settle, `x` is where they got to.
///
/// `g(i, a, j, b)` is the Delassus entry between component `a` of contact
/// `i` and component `b` of contact `j`.
///
/// # Errors
/// [`DynamicsError::ContactIndeterminate`] for a slipping block whose
/// normal coefficient is not positive (Painlevé);
/// [`DynamicsError::ContactUnsolved`] when the sweeps or a slip direction
/// do not settle.
pub(crate) fn solve_blocks_from(
    blocks: &[Block],
    y_free: &[[f64; 4]],
    g: &dyn Fn(usize, usize, usize, usize) -> f64,
    x: &mut [[f64; 4]],
) -> Result<(), DynamicsError> {
    let m = blocks.len();
    let g_scale = (0..m)
        .flat_map(|i| (0..blocks[i].size).map(move |a| (i, a)))
        .fold(0.0_f64, |s, (i, a)| s.max(g(i, a, i, a).abs()));
    // The unknowns before a sweep, then its change; and G times that.
    let mut step = x.to_vec();
    let mut moved_by = vec![[0.0; 4]; m];
    for sweep in 0..MAX_SWEEPS {
        step.copy_from_slice(x);
        let mut change: f64 = 0.0;
        let mut size: f64 = 0.0;
        for i in 0..m {
            let bi = &blocks[i];
            let mut y0 = y_free[i];
            for (j, xj) in x.iter().enumerate() {
                if j == i {
                    continue;
                }
                for (a, y) in y0.iter_mut().enumerate().take(bi.size) {
                    for (b, xb) in xj.iter().enumerate().take(blocks[j].size) {
                        *y += g(i, a, j, b) * xb;
                    }
                }
            }
            let mut gii = [[0.0; 4]; 4];
            for (a, row) in gii.iter_mut().enumerate().take(bi.size) {
                for (b, v) in row.iter_mut().enumerate().take(bi.size) {
                    *v = g(i, a, i, b);
                }
            }
            let xi = solve_block(bi, &gii, &y0)?;
            for k in 0..bi.size {
                change = change.max((xi[k] - x[i][k]).abs());
                size = size.max(xi[k].abs());
            }
            x[i] = xi;
        }
        if m == 1 || change <= SWEEP_TOLERANCE * size {
            return Ok(());
        }
        // The sweep moved the unknowns only along the null space of G
        // (several sticking contacts overconstrain the body: their forces
        // are not unique, the accelerations are): settled.
        for (d, now) in step.iter_mut().zip(x.iter()) {
            d.iter_mut().zip(now).for_each(|(d, now)| *d = now - *d);
        }
        moved_by.iter_mut().for_each(|y| *y = [0.0; 4]);
        add_delassus_product(&mut moved_by, blocks, g, &step);
        let moved = moved_by
            .iter()
            .flatten()
            .fold(0.0_f64, |m, v| m.max(v.abs()));
        if moved <= NULL_TOLERANCE * g_scale * size {
            return Ok(());
        }
        // Slow sweeps: the modes they show, finished exactly.
        if sweep % FINISH_EVERY == FINISH_EVERY - 1
            && let Some(finished) = finish(blocks, y_free, g, x)
        {
            x.copy_from_slice(&finished);
            return Ok(());
        }
    }
    Err(unsolved())
}

/// One block exactly: separation, sticking, or slipping on the cone (the
/// slip's direction by [`slip_onset`] from the direction opposite the
/// sticking force; where that does not settle, the damped fixed point
/// `d ← (d + y_T/|y_T|)/|…|`, then [`prox_block`]).
fn solve_block(b: &Block, g: &[[f64; 4]; 4], y0: &[f64; 4]) -> Result<[f64; 4], DynamicsError> {
    let n = b.size;
    let mut x = [0.0; 4];
    if y0[0] >= 0.0 {
        return Ok(x); // separating: no force
    }
    if n == 1 || b.mu == 0.0 {
        x[0] = -y0[0] / g[0][0];
        return Ok(x);
    }
    if let Some(d) = b.slipping {
        return slip_along(b, g, y0, d);
    }
    // Sticking: y = 0 in every component.
    let mut a = [0.0; 16];
    let mut rhs = [0.0; 4];
    for r in 0..n {
        for k in 0..n {
            a[r * n + k] = g[r][k];
        }
        rhs[r] = -y0[r];
    }
    if solve_in_place(&mut a, &mut rhs, n) {
        let t = DVec3::new(
            rhs[1],
            rhs.get(2).copied().unwrap_or(0.0),
            if n > 3 { rhs[3] } else { 0.0 },
        );
        if rhs[0] >= 0.0 && t.length() <= b.mu * rhs[0] * (1.0 + 1e-12) {
            x[..n].copy_from_slice(&rhs[..n]);
            return Ok(x);
        }
        // Slipping: start from the direction opposite the sticking force,
        // Newton's method on the slip direction first.
        let mut d = -t.normalize_or_zero();
        if let Some(x) = slip_onset(g, y0, n, b.mu, d) {
            return Ok(x);
        }
        for _ in 0..MAX_SWEEPS {
            let xs = slip_along(b, g, y0, d)?;
            let y_t = tangential(g, y0, &xs, n);
            let next = y_t.normalize_or_zero();
            if next == DVec3::ZERO || (next - d).length() <= 1e-14 {
                return Ok(xs);
            }
            // Damped: the plain fixed point may oscillate between two
            // directions when the block is far from isotropic.
            d = (d + next).normalize_or(next);
        }
        // The direction did not settle (a block far from isotropic):
        // the projected iteration instead, slower but steady.
        return prox_block(b, g, y0).ok_or_else(unsolved);
    }
    // A singular sticking block: no friction response to solve with.
    Err(indeterminate(0.0))
}

/// The block by the projected iteration of Alart & Curnier's
/// augmented Lagrangian form (Studer & Glocker's successive inclusions):
///
/// ```text
/// x_N ← max(0, x_N − r_N y_N),   x_T ← proj_{|x_T| ≤ μ x_N}(x_T − r_T y_T),   y = y0 + G x
/// r_N = 1/G_NN,  r_T = 1/trace(G_TT)
/// ```
///
/// until the change is below rounding; `None` when it does not settle.
fn prox_block(b: &Block, g: &[[f64; 4]; 4], y0: &[f64; 4]) -> Option<[f64; 4]> {
    let n = b.size;
    let r_n = 1.0 / g[0][0];
    let r_t = 1.0 / (1..n).map(|k| g[k][k]).sum::<f64>();
    let mut x = [0.0; 4];
    for _ in 0..200_000 {
        let y = |x: &[f64; 4], r: usize| y0[r] + (0..n).map(|k| g[r][k] * x[k]).sum::<f64>();
        let x_n = (x[0] - r_n * y(&x, 0)).max(0.0);
        let mut next = x;
        next[0] = x_n;
        let mut t = DVec3::ZERO;
        for c in 0..n - 1 {
            t[c] = x[1 + c] - r_t * y(&next, 1 + c);
        }
        let limit = b.mu * x_n;
        if t.length() > limit {
            t = t.normalize_or_zero() * limit;
        }
        for c in 0..n - 1 {
            next[1 + c] = t[c];
        }
        let change = (0..n).map(|k| (next[k] - x[k]).abs()).fold(0.0, f64::max);
        let size = (0..n).map(|k| next[k].abs()).fold(0.0, f64::max);
        x = next;
        if change <= SWEEP_TOLERANCE * size.max(f64::MIN_POSITIVE) {
            return Some(x);
        }
    }
    None
}

/// [`DynamicsError::ContactUnsolved`] (its time NaN: the caller knows it).
fn unsolved() -> DynamicsError {
    DynamicsError::ContactUnsolved { time: f64::NAN }
}

/// The block slipping along `d`: `x_T = −μ x_N d`, `y_N = 0`.
///
/// # Errors
/// [`DynamicsError::ContactIndeterminate`] with the normal coefficient
/// `κ = G_NN − μ G_NT d` when it is not positive (Painlevé).
fn slip_along(
    b: &Block,
    g: &[[f64; 4]; 4],
    y0: &[f64; 4],
    d: DVec3,
) -> Result<[f64; 4], DynamicsError> {
    let n = b.size;
    let mut kappa = g[0][0];
    for c in 0..n - 1 {
        kappa -= b.mu * g[0][1 + c] * d[c];
    }
    if kappa.is_nan() || kappa <= 0.0 {
        return Err(indeterminate(kappa));
    }
    let mut x = [0.0; 4];
    x[0] = (-y0[0] / kappa).max(0.0);
    for c in 0..n - 1 {
        x[1 + c] = -b.mu * x[0] * d[c];
    }
    Ok(x)
}

/// The friction components of `y = y0 + G x` for one block.
fn tangential(g: &[[f64; 4]; 4], y0: &[f64; 4], x: &[f64; 4], n: usize) -> DVec3 {
    let mut t = DVec3::ZERO;
    for c in 0..n - 1 {
        let mut v = y0[1 + c];
        for k in 0..n {
            v += g[1 + c][k] * x[k];
        }
        t[c] = v;
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A block with the Delassus matrix of a point mass (`G = 𝟙/m`).
    fn mass_block(mu: f64) -> (Block, [[f64; 4]; 4]) {
        let mut g = [[0.0; 4]; 4];
        for (k, row) in g.iter_mut().enumerate().take(3) {
            row[k] = 2.0; // m = 0.5 kg
        }
        (
            Block {
                size: 3,
                mu,
                slipping: None,
            },
            g,
        )
    }

    /// Regression: the held direction jumped at the band's edge; it is
    /// continuous there now, and held below half the band.
    #[test]
    fn the_direction_within_the_band_is_continuous_at_its_edge() {
        let kept = DVec3::X;
        let along = |s: f64| direction_or(DVec3::new(0.0, s, 0.0), kept, 1e-6);
        for (s, want) in [
            (1e-6 * (1.0 + 1e-12), DVec3::Y),
            (1e-6, DVec3::Y),
            (0.5e-6, DVec3::X),
        ] {
            assert!((along(s) - want).length() < 1e-6, "{s}: {:?}", along(s));
        }
        // Across the outer half: the angle from `kept` grows steadily.
        let angle = |s: f64| along(s).angle_between(kept);
        let mut last = 0.0;
        for k in 1..=100 {
            let a = angle(0.5e-6 * (1.0 + f64::from(k) / 100.0));
            assert!(a >= last && a - last < 0.05, "{k}: {a} after {last}");
            last = a;
        }
        assert_eq!(along(0.0), kept);
    }

    #[test]
    fn a_point_mass_sticks_inside_the_cone_and_slips_outside() {
        // A mass pressed down at 10 m/s² and pulled sideways at 3 m/s²:
        // N = 5 N, sticking needs F = 1.5 N ≤ μ N for μ ≥ 0.3.
        let (b, g) = mass_block(0.5);
        let x = solve_block(&b, &g, &[-10.0, 3.0, 0.0, 0.0]).unwrap();
        assert!((x[0] - 5.0).abs() < 1e-14 && (x[1] + 1.5).abs() < 1e-14);
        let (b, g) = mass_block(0.2);
        let x = solve_block(&b, &g, &[-10.0, 3.0, 0.0, 0.0]).unwrap();
        // Slipping: F = −μ N along the pull.
        assert!(
            (x[0] - 5.0).abs() < 1e-14 && (x[1] + 1.0).abs() < 1e-14,
            "{x:?}"
        );
        // Separating: no force.
        assert_eq!(
            solve_block(&b, &g, &[1.0, 3.0, 0.0, 0.0]).unwrap(),
            [0.0; 4]
        );
    }

    /// Regression: the thrown ellipsoid at μ = 1000 where its sticking
    /// force reaches the cone (t = 0.14518 s): the slip's acceleration is
    /// at rounding there, the damped fixed point on its direction wandered
    /// off and the projected iteration did not settle — `ContactUnsolved`
    /// on the 1/60 s grid, a slip on the others. It slips along the
    /// direction opposite the sticking force, with that force.
    #[test]
    fn a_block_whose_sticking_force_is_on_the_cone_edge_slips_with_it() {
        let (g, y0) = crate::table::slip_onset::tests::ellipsoid_at_the_cone();
        let b = Block {
            size: 3,
            mu: 1000.0,
            slipping: None,
        };
        let x = solve_block(&b, &g, &y0).unwrap();
        let mut a = [0.0; 16];
        let mut stick = [-y0[0], -y0[1], -y0[2], 0.0];
        for r in 0..3 {
            for k in 0..3 {
                a[r * 3 + k] = g[r][k];
            }
        }
        assert!(solve_in_place(&mut a, &mut stick, 3));
        for k in 0..3 {
            assert!(
                (x[k] - stick[k]).abs() < 1e-9 * stick[k].abs(),
                "{x:?} vs {stick:?}"
            );
        }
        assert!((x[1].hypot(x[2]) / x[0] - 1000.0).abs() < 1e-9);
    }
}
