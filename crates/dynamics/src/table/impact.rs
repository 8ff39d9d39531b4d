//! Impacts on the table: Newton's restitution with Coulomb–Contensou
//! friction at every contact that touches, solved for the impulses at
//! once ([`super::contact_problem::solve_blocks`] on velocities).
//!
//! ```text
//! u⁺ = u⁻ + M⁻¹ Σ_i W_i P_i
//! ξ_N = γ_N⁺ + e γ_N⁻ ≥ 0,  P_N ≥ 0,  ξ_N P_N = 0
//! ξ_T = γ_T⁺ + e_T γ_T⁻,    |P_T| ≤ μ P_N,  P_T = −μ P_N ξ_T/|ξ_T| when ξ_T ≠ 0
//! ```
//!
//! (Glocker, *Set-Valued Force Laws*, 2001, §7; restitution only where
//! the contact approaches, `γ_N⁻ < 0`: a contact that was resting takes
//! part with `e = e_T = 0`.) A rebound `e v⁻` at or below the resolution
//! speed closes the contact (`e = 0` there) and reports where the bounces
//! would accumulate. The kinetic energy after is checked against the
//! energy before: Newton's law with several frictional contacts can gain
//! energy (Glocker, "Energetic consistency conditions for standard
//! impacts", Multibody Syst. Dyn. 29 (2013) 77); such an impact is a
//! typed error, never a silent gain.

use super::TableBody;
use super::contact_block::{Block, Rolling};
use super::contact_frame::{ContactFrame, ROLLING, Wrench};
use super::contact_newton::solve_whole;
use super::contact_problem::solve_blocks_from;
use crate::{DynamicsError, GroundTopState};

/// What an impact did.
#[derive(Debug, Clone)]
pub(crate) struct ImpactOutcome {
    /// The state just after (positions unchanged).
    pub(crate) state: GroundTopState,
    /// Per participant: contact, `−γ_N⁻`, `γ_N⁺`, whether it approached.
    pub(crate) speeds: Vec<(usize, f64, f64, bool)>,
    /// Contacts whose bounces accumulate, and how long after the impact.
    pub(crate) accumulations: Vec<(usize, f64)>,
}

/// The impact of `body` in `state` at the contacts `participants`; a
/// rebound at or below `resolution_speed` closes the contact. Where the
/// laws as given would raise the kinetic energy, the impact takes `e_T = e`
/// at every participant, which cannot (see the body).
///
/// # Errors
/// [`DynamicsError::ImpactGainsEnergy`] (at `time`) when the impulses
/// would raise the kinetic energy beyond rounding even so;
/// [`DynamicsError::ContactIndeterminate`] when the impulse problem has no
/// solution the block solver finds.
pub(crate) fn impact(
    body: &TableBody,
    state: &GroundTopState,
    participants: &[usize],
    resolution_speed: f64,
    time: f64,
) -> Result<ImpactOutcome, DynamicsError> {
    let frame = ContactFrame::of(body, state, time);
    let free = (frame.free_velocity_rate, frame.free_omega_rate);
    let mut accumulations = Vec::new();
    // Each participant's (e, e_T).
    let mut coefficients = Vec::with_capacity(participants.len());
    for &i in participants {
        let row = &frame.rows[i];
        let law = body.contacts()[i].law;
        let approach = -row.velocity[0];
        let approaching = approach > 0.0;
        let (mut e, mut e_t) = if approaching {
            (law.restitution(), law.tangential_restitution())
        } else {
            (0.0, 0.0)
        };
        if approaching && e > 0.0 && e * approach <= resolution_speed {
            // The gap's own acceleration with the contact open, into the table.
            let a = -frame.rate(i, 0, free);
            if a > 0.0 && e < 1.0 {
                accumulations.push((i, 2.0 * e * approach / (a * (1.0 - e))));
            }
            (e, e_t) = (0.0, 0.0);
        }
        coefficients.push((e, e_t));
    }
    let g = |a: usize, ca: usize, b: usize, cb: usize| {
        frame.delassus(
            &frame.rows[participants[a]].directions[ca],
            &frame.rows[participants[b]].directions[cb],
        )
    };
    // The impulses and the state after them under the coefficients given.
    let solve = |coefficients: &[(f64, f64)]| {
        let mut blocks = Vec::with_capacity(participants.len());
        let mut y_free = Vec::with_capacity(participants.len());
        for (&i, &(e, e_t)) in participants.iter().zip(coefficients) {
            let row = &frame.rows[i];
            let size = 1 + row.friction_dimensions;
            let mut y = [0.0; 4];
            y[0] = (1.0 + e) * row.velocity[0];
            for (yk, vk) in y.iter_mut().zip(row.velocity).take(size).skip(1) {
                *yk = (1.0 + e_t) * vk;
            }
            y_free.push(y);
            blocks.push(Block {
                size,
                mu: row.mu,
                slipping: None,
            });
        }
        let mut impulses = vec![[0.0; 4]; blocks.len()];
        match solve_blocks_from(&blocks, &y_free, &g, &mut impulses) {
            // The sweeps settle too slowly or cycle: Newton's method on the
            // problem whole, from where they got to.
            Err(DynamicsError::ContactUnsolved { .. }) => {
                let none = vec![Rolling::Free; blocks.len()];
                let zero = vec![glam::DVec3::ZERO; blocks.len()];
                let start = Some((impulses.as_slice(), zero.as_slice()));
                impulses = solve_whole(&frame, participants, &blocks, &y_free, &none, start)
                    .map(|(x, _)| x)
                    .ok_or(DynamicsError::ContactUnsolved { time })?;
            }
            solved => solved.map_err(|e| at_time(e, time))?,
        }
        let mut total = Wrench::default();
        for (p, &i) in impulses.iter().zip(participants) {
            for (k, pk) in p
                .iter()
                .enumerate()
                .take(1 + frame.rows[i].friction_dimensions)
            {
                total = total.plus(frame.rows[i].directions[k].scaled(*pk));
            }
        }
        struck(body, state, &frame, total, time)
    };
    // Newton's law with e_T ≠ e can raise the energy (Kane's paradox: the
    // friction impulse along the slip before the impact, when the impact
    // reverses the slip); with e_T = e at every participant it cannot
    // (with γ⁺ = γ⁻ + G P and ξ = γ⁺ + e γ⁻ in every component,
    // ΔT = ½ Pᵀ(γ⁺ + γ⁻) = (ξᵀP − ½ (1 − e) Pᵀ G P)/(1 + e) ≤ 0, as ξᵀP ≤ 0
    // on the friction cone; Glocker, "Energetic consistency conditions for
    // standard impacts", Multibody Syst. Dyn. 2013). Where the law as given
    // would gain, the impact takes e_T = e.
    let consistent: Vec<(f64, f64)> = coefficients.iter().map(|&(e, _)| (e, e)).collect();
    let after = match solve(&coefficients) {
        Err(DynamicsError::ImpactGainsEnergy { .. }) if consistent != coefficients => {
            solve(&consistent)?
        }
        outcome => outcome?,
    };
    let speeds = participants
        .iter()
        .map(|&i| {
            let v_p = body.contact_velocity(&after, i);
            (
                i,
                -frame.rows[i].velocity[0],
                v_p.z,
                frame.rows[i].velocity[0] < 0.0,
            )
        })
        .collect();
    Ok(ImpactOutcome {
        state: after,
        speeds,
        accumulations,
    })
}

/// `state` after the impulse wrench `total` (velocities only), checked
/// against the kinetic energy before.
///
/// # Errors
/// [`DynamicsError::ImpactGainsEnergy`] (at `time`) when the kinetic
/// energy rises beyond rounding.
fn struck(
    body: &TableBody,
    state: &GroundTopState,
    frame: &ContactFrame,
    total: Wrench,
    time: f64,
) -> Result<GroundTopState, DynamicsError> {
    let after = GroundTopState {
        velocity_world: state.velocity_world + total.force * frame.inverse_mass,
        l_world: state.l_world + total.torque,
        ..*state
    };
    let (before, kinetic) = (body.kinetic_energy(state), body.kinetic_energy(&after));
    if kinetic > before * (1.0 + 1e-12) {
        return Err(DynamicsError::ImpactGainsEnergy {
            time,
            before,
            after: kinetic,
        });
    }
    Ok(after)
}

/// `e` with its time set, where it has one.
pub(crate) fn at_time(e: DynamicsError, time: f64) -> DynamicsError {
    match e {
        DynamicsError::ContactIndeterminate { compliance, .. } => {
            DynamicsError::ContactIndeterminate { time, compliance }
        }
        DynamicsError::ContactUnsolved { .. } => DynamicsError::ContactUnsolved { time },
        other => other,
    }
}

/// The impulse `P = −G⁻¹ (0, γ)` on the contact's normal direction and
/// the components stopped — the residual slip (`slip`) of a contact that
/// starts to stick, the residual rolling (`roll`) of one whose rolling
/// resistance starts to hold — that stops them and keeps the normal
/// velocity `ġ` (`ΔT = −½ (0, γ)ᵀ G⁻¹ (0, γ) + P_N ġ`, both velocities
/// below the resolution speed). Stopping the slip by `P_T = −G_TT⁻¹ γ_T`
/// alone moved the normal velocity by `G_NT P_T`: the thrown ellipsoid at
/// μ = 1000 stuck with `ġ = +1.3·10⁻¹⁰` m/s, and the closed contact's
/// normal force then did work `N ġ` on it (+2.6·10⁻¹¹ J in 0.05 s of
/// rolling). (Zeroing `ġ` as well stalled the spun coin of
/// `tests/table_regressions.rs`.)
pub(crate) fn stop_slip(
    body: &TableBody,
    state: &GroundTopState,
    i: usize,
    slip: bool,
    roll: bool,
) -> GroundTopState {
    // Impulses only: the velocities, not the (time-dependent) loads, matter.
    let frame = ContactFrame::of(body, state, 0.0);
    let row = &frame.rows[i];
    let slipping = (1..=row.friction_dimensions).filter(|_| slip);
    let rolling = ROLLING.into_iter().filter(|_| roll && row.rolls);
    let stopped: Vec<usize> = slipping.chain(rolling).collect();
    if stopped.is_empty() {
        return *state;
    }
    let components: Vec<usize> = std::iter::once(0).chain(stopped).collect();
    let n = components.len();
    let mut a = [0.0; 36];
    let mut rhs = [0.0; 6];
    for (r, &cr) in components.iter().enumerate() {
        for (k, &ck) in components.iter().enumerate() {
            a[r * n + k] = frame.delassus(&row.directions[cr], &row.directions[ck]);
        }
        // The normal velocity kept, the slip (and rolling) stopped.
        rhs[r] = if cr == 0 { 0.0 } else { -row.velocity[cr] };
    }
    if !super::dense::solve_in_place(&mut a, &mut rhs, n) {
        return *state;
    }
    let mut total = Wrench::default();
    for (&c, pk) in components.iter().zip(rhs) {
        total = total.plus(row.directions[c].scaled(pk));
    }
    GroundTopState {
        velocity_world: state.velocity_world + total.force * frame.inverse_mass,
        l_world: state.l_world + total.torque,
        ..*state
    }
}

/// The impact of a disk rim `i` rocking through flat: its far rim point
/// `B` (now the lowest) strikes while the near point `A` (the contact
/// until now) still touches — both take part at once, as two point
/// contacts of the rim's law ([`impact`] on the pair; struck one at a
/// time, each impulse would drive the other point into the table).
///
/// ```text
/// ρ_B = the rim's lowest point,  ρ_A = 2 A c − ρ_B   (c the disk's centre; the diameter through B)
/// ```
///
/// The outcome names contact `i` for both points.
///
/// # Errors
/// Those of [`impact`].
pub(crate) fn rim_flip_impact(
    body: &TableBody,
    state: &GroundTopState,
    i: usize,
    resolution_speed: f64,
    time: f64,
) -> Result<ImpactOutcome, DynamicsError> {
    let rim = body.contacts()[i];
    let crate::ContactShape::Disk(disk) = rim.shape else {
        return impact(body, state, &[i], resolution_speed, time);
    };
    let q = state.world_from_body.normalize();
    let mut rho_b = disk.contact_from_com_world(q);
    if !rho_b.is_finite() {
        // Lying exactly flat (no lowest rim point): the rim point that
        // approaches fastest, `γ_N + (ω × r)_z` least.
        let omega = ContactFrame::of(body, state, time).omega;
        let toward = glam::DVec3::new(omega.y, -omega.x, 0.0).normalize_or(glam::DVec3::X);
        rho_b = q * disk.center_body() + disk.radius() * toward;
    }
    let rho_a = 2.0 * (q * disk.center_body()) - rho_b;
    // A point contact at A: a small sphere whose lowest point is A while
    // the disk lies flat (its centre above A along the upward axis).
    let n = q * disk.normal_body();
    let up = if n.z >= 0.0 { n } else { -n };
    let r = 1e-6 * disk.radius();
    let point_a = crate::SphereContact::try_new(r, q.conjugate() * (rho_a + r * up))?;
    let pair = TableBody::try_new(
        body.mass(),
        body.inertia_body(),
        vec![
            rim,
            super::TableContact {
                shape: crate::ContactShape::Sphere(point_a),
                law: rim.law,
            },
        ],
        body.gravity(),
    )?;
    let mut outcome = impact(&pair, state, &[0, 1], resolution_speed, time)?;
    for s in &mut outcome.speeds {
        s.0 = i;
    }
    for a in &mut outcome.accumulations {
        a.0 = i;
    }
    Ok(outcome)
}

/// The impact of disk `i`'s face closing flat on the table (the disk's
/// axis within [`super::DISK_FLAT_TILT`] of the vertical): the face as a
/// distributed unilateral contact with Newton's law at each of its
/// points and Coulomb–Contensou friction, solved for the impulse wrench
/// at the face's centre `C` (`ρ_c = A c`):
///
/// ```text
/// face point r (horizontal, |r| ≤ a, from C):  γ_N(r) = γ_N + (ω × r)_z = γ_N + ω_x r_y − ω_y r_x
/// normal wrench:  w_N = (ẑ, ρ_c × ẑ),  w_α = (0, x̂),  w_β = (0, ŷ)        γ = (γ_N, ω_x, ω_y)
/// friction:       w_x, w_y at C,  w_d = (0, ε ẑ),  ε = ⅔ a (the face's lever, `face`)
/// impulses:       (P_N, M) ∈ K = {|M| ≤ a P_N}   (pressure ≥ 0 over the face: its centre within it)
/// Newton:         ξ = γ⁺ + e γ⁻ ∈ K* = {ξ_N ≥ a |ξ_M|}  (ξ(r) ≥ 0 everywhere),  ⟨ξ, P⟩ = 0
/// friction:       ξ_T = γ_T⁺ + e_T γ_T⁻,  |P_T| ≤ μ P_N,  P_T = −μ P_N ξ_T/|ξ_T| when ξ_T ≠ 0
/// ```
///
/// The face strikes face first (every point approaching, `γ_N + a|ω_h| <
/// 0`): then `ξ ≡ 0` over the face — the centre's normal speed and both
/// tilting rates reverse, `(γ_N, ω_x, ω_y)⁺ = −e (γ_N, ω_x, ω_y)⁻` — is
/// the solution whenever its wrench lies in `K` (the normal problem is
/// the complementarity of the cone `K` and its dual with a positive
/// definite Delassus matrix: that solution is the only one). A disk
/// dropped exactly flat has `ω_h = 0`, `M = 0`: `v_z⁺ = −e v_z⁻`, the
/// pressure uniform. `None` when the wrench leaves `K` (the pressure
/// gathers on the rim: the rim strikes, [`rim_flip_impact`]). A rebound
/// `e |γ_N⁻|` at or below `resolution_speed` is summed (`e = 0`, the
/// accumulation reported) as in [`impact`].
///
/// # Errors
/// [`DynamicsError::ImpactGainsEnergy`] when the impulses would raise the
/// kinetic energy beyond rounding; [`DynamicsError::ContactUnsolved`]
/// when the slipping impulse is not found.
pub(crate) fn face_impact(
    body: &TableBody,
    state: &GroundTopState,
    i: usize,
    resolution_speed: f64,
    time: f64,
) -> Result<Option<ImpactOutcome>, DynamicsError> {
    let contact = body.contacts()[i];
    let crate::ContactShape::Disk(disk) = contact.shape else {
        return Ok(None);
    };
    let frame = ContactFrame::of(body, state, time);
    let q = state.world_from_body.normalize();
    let rho = q * disk.center_body();
    let at_centre = |axis: glam::DVec3| Wrench {
        force: axis,
        torque: rho.cross(axis),
    };
    let couple = |axis: glam::DVec3| Wrench {
        force: glam::DVec3::ZERO,
        torque: axis,
    };
    let (x, y, z) = (glam::DVec3::X, glam::DVec3::Y, glam::DVec3::Z);
    let lever = super::face::face_lever(disk.radius());
    let w = [
        at_centre(z),
        couple(x),
        couple(y),
        at_centre(x),
        at_centre(y),
        couple(z * lever),
    ];
    let omega = frame.omega;
    let gamma: Vec<f64> = w
        .iter()
        .map(|wk| wk.dot_motion(state.velocity_world, omega))
        .collect();
    let approach = -gamma[0];
    let tilting = omega.truncate().length();
    if approach <= 0.0 || approach <= disk.radius() * tilting {
        return Ok(None);
    }
    let law = contact.law;
    let (mut e, mut e_t) = (law.restitution(), law.tangential_restitution());
    let mut accumulations = Vec::new();
    if e > 0.0 && e * approach <= resolution_speed {
        // The face centre's own acceleration in flight, into the table.
        let free = (frame.free_velocity_rate, frame.free_omega_rate);
        let a = -(w[0].dot_motion(free.0, free.1) + omega.cross(omega.cross(rho)).z);
        if a > 0.0 && e < 1.0 {
            accumulations.push((i, 2.0 * e * approach / (a * (1.0 - e))));
        }
        (e, e_t) = (0.0, 0.0);
    }
    let mut g = [[0.0; 6]; 6];
    for (a, row) in g.iter_mut().enumerate() {
        for (b, v) in row.iter_mut().enumerate() {
            *v = frame.delassus(&w[a], &w[b]);
        }
    }
    let mut y_free = [0.0; 6];
    for (k, yk) in y_free.iter_mut().enumerate() {
        *yk = (1.0 + if k < 3 { e } else { e_t }) * gamma[k];
    }
    let p = face_impulses(&g, &y_free, law.mu()).map_err(|e| at_time(e, time))?;
    let Some(p) = p else {
        return Ok(None);
    };
    let couple_size = (p[1] * p[1] + p[2] * p[2]).sqrt();
    if p[0] <= 0.0 || couple_size > disk.radius() * p[0] * (1.0 + 1e-12) {
        return Ok(None);
    }
    let total = w
        .iter()
        .zip(p)
        .fold(Wrench::default(), |t, (wk, pk)| t.plus(wk.scaled(pk)));
    let after = struck(body, state, &frame, total, time)?;
    let omega_after = ContactFrame::of(body, &after, time).omega;
    let rebound = w[0].dot_motion(after.velocity_world, omega_after);
    Ok(Some(ImpactOutcome {
        state: after,
        speeds: vec![(i, approach, rebound, true)],
        accumulations,
    }))
}

/// The face's impulses `P = (P_N, M_x, M_y, P_x, P_y, P_d)` with
/// `ξ = y_free + G P` zero in its normal part (`ξ_N = ξ_α = ξ_β = 0`) and
/// Coulomb's law on its friction part: sticking (`ξ_T = 0`) when that
/// impulse lies in the cone `|P_T| ≤ μ P_N`, else slipping along the slip
/// after, `P_T = −μ P_N ξ_T/|ξ_T|` (by bisection on `μ P_N/|ξ_T|`).
/// `None` when the normal part is singular.
///
/// # Errors
/// [`DynamicsError::ContactUnsolved`] (its time NaN) when no slip
/// satisfies the cone (the bracket is not found).
fn face_impulses(
    g: &[[f64; 6]; 6],
    y_free: &[f64; 6],
    mu: f64,
) -> Result<Option<[f64; 6]>, DynamicsError> {
    let solve = |n: usize| {
        let mut a = [0.0; 36];
        let mut rhs = [0.0; 6];
        for r in 0..n {
            for k in 0..n {
                a[r * n + k] = g[r][k];
            }
            rhs[r] = -y_free[r];
        }
        super::dense::solve_in_place(&mut a, &mut rhs, n).then_some(rhs)
    };
    if mu == 0.0 {
        return Ok(solve(3));
    }
    // Sticking: ξ = 0 in all six.
    let Some(stick) = solve(6) else {
        return Ok(None);
    };
    let friction = glam::DVec3::new(stick[3], stick[4], stick[5]);
    if stick[0] > 0.0 && friction.length() <= mu * stick[0] * (1.0 + 1e-12) {
        return Ok(Some(stick));
    }
    // Slipping: P_T = −λ ξ_T with λ = μ P_N/|ξ_T| > 0. For a given λ the
    // impulses and the slip after are linear; λ is the root of
    // h(λ) = λ |ξ_T| − μ P_N (h(0) = −μ P_N < 0; h → |P_T| of sticking
    // > μ P_N as λ → ∞), bracketed and bisected to rounding.
    let at = |lambda: f64| {
        let mut a = [0.0; 36];
        let mut rhs = [0.0; 6];
        for r in 0..6 {
            for k in 0..6 {
                a[r * 6 + k] = if k < 3 {
                    g[r][k]
                } else {
                    -lambda * g[r][k] - if k == r { 1.0 } else { 0.0 }
                };
            }
            rhs[r] = -y_free[r];
        }
        super::dense::solve_in_place(&mut a, &mut rhs, 6).then_some(rhs)
    };
    let h = |z: &[f64; 6], lambda: f64| {
        lambda * glam::DVec3::new(z[3], z[4], z[5]).length() - mu * z[0]
    };
    let (mut lo, mut hi) = (0.0, 1.0 / g[3][3]);
    let mut bracketed = false;
    for _ in 0..200 {
        let Some(z) = at(hi) else {
            return Ok(None);
        };
        if h(&z, hi) > 0.0 {
            bracketed = true;
            break;
        }
        (lo, hi) = (hi, 2.0 * hi);
    }
    if !bracketed {
        return Err(DynamicsError::ContactUnsolved { time: f64::NAN });
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        let Some(z) = at(mid) else {
            return Ok(None);
        };
        if h(&z, mid) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let lambda = 0.5 * (lo + hi);
    let Some(z) = at(lambda) else {
        return Ok(None);
    };
    // The friction on the cone exactly: P_T = −μ P_N ξ_T/|ξ_T|.
    let d = glam::DVec3::new(z[3], z[4], z[5]).normalize_or_zero();
    let mut p = [0.0; 6];
    p[..3].copy_from_slice(&z[..3]);
    for c in 0..3 {
        p[3 + c] = -mu * z[0] * d[c];
    }
    Ok(Some(p))
}

#[cfg(test)]
mod tests {
    use glam::{DMat3, DQuat, DVec3};

    use super::*;
    use crate::table::{ContactLaw, TableContact};
    use crate::{ContactShape, DiskContact};

    const M: f64 = 0.01;
    const A: f64 = 0.02;

    /// A disk of radius `A` lying flat, its face in the centre of mass's
    /// plane, horizontal inertia `i_h`, law `law`.
    fn flat_disk(i_h: f64, law: ContactLaw) -> TableBody {
        let rim = DiskContact::try_new(A, DVec3::ZERO, DVec3::Z).unwrap();
        let inertia = DMat3::from_diagonal(DVec3::new(i_h, i_h, 0.5 * M * A * A));
        let contacts = vec![TableContact {
            shape: ContactShape::Disk(rim),
            law,
        }];
        TableBody::try_new(M, inertia, contacts, 9.81).unwrap()
    }

    /// Flat on the table, striking at `v_z` with tilting rates `omega`.
    fn striking(body: &TableBody, v: DVec3, omega: DVec3) -> GroundTopState {
        let i = body.inertia_body();
        GroundTopState {
            com_world: DVec3::ZERO,
            velocity_world: v,
            world_from_body: DQuat::IDENTITY,
            l_world: i * omega,
        }
    }

    #[test]
    fn the_centre_speed_and_both_tilting_rates_reverse_by_e() {
        let law = ContactLaw::new(0.0).try_with_restitution(0.5).unwrap();
        let body = flat_disk(0.25 * M * A * A, law);
        let omega = DVec3::new(5.0, -3.0, 7.0);
        let state = striking(&body, DVec3::new(0.2, 0.0, -1.0), omega);
        let out = face_impact(&body, &state, 0, 1e-9, 0.0).unwrap().unwrap();
        let after = out.state;
        let omega_after = body.omega_world(&after);
        // v_z⁺ = −e v_z⁻, ω_h⁺ = −e ω_h⁻; sliding and spin untouched.
        assert!((after.velocity_world - DVec3::new(0.2, 0.0, 0.5)).length() < 1e-15);
        assert!((omega_after - DVec3::new(-2.5, 1.5, 7.0)).length() < 1e-13);
        assert_eq!(out.speeds, vec![(0, 1.0, 0.5, true)]);
    }

    #[test]
    fn an_elastic_frictionless_face_keeps_the_energy_and_friction_loses_it() {
        let elastic = ContactLaw::new(0.0).try_with_restitution(1.0).unwrap();
        let body = flat_disk(0.25 * M * A * A, elastic);
        let state = striking(
            &body,
            DVec3::new(0.3, 0.1, -1.0),
            DVec3::new(2.0, 1.0, 30.0),
        );
        let after = face_impact(&body, &state, 0, 1e-9, 0.0)
            .unwrap()
            .unwrap()
            .state;
        let (t0, t1) = (body.kinetic_energy(&state), body.kinetic_energy(&after));
        assert!((t1 - t0).abs() < 1e-15 * t0, "{t0} → {t1}");
        let rough = flat_disk(
            0.25 * M * A * A,
            ContactLaw::new(0.2).try_with_restitution(1.0).unwrap(),
        );
        let after = face_impact(&rough, &state, 0, 1e-9, 0.0)
            .unwrap()
            .unwrap()
            .state;
        assert!(rough.kinetic_energy(&after) < t0);
    }

    #[test]
    fn an_impulse_that_would_raise_the_kinetic_energy_is_a_typed_error() {
        let law = ContactLaw::new(0.3).try_with_restitution(0.5).unwrap();
        let body = flat_disk(0.25 * M * A * A, law);
        let state = striking(&body, DVec3::new(0.0, 0.0, -1.0), DVec3::ZERO);
        let frame = ContactFrame::of(&body, &state, 0.0);
        // Pushed down harder: |v_z| rises from 1 to 1.5 m/s.
        let down = Wrench {
            force: DVec3::new(0.0, 0.0, -0.5 * M),
            torque: DVec3::ZERO,
        };
        match struck(&body, &state, &frame, down, 0.25) {
            Err(DynamicsError::ImpactGainsEnergy {
                time,
                before,
                after,
            }) => {
                assert_eq!(time, 0.25);
                assert!((before - 0.5 * M).abs() < 1e-18 && (after - 0.5 * M * 2.25).abs() < 1e-17);
            }
            other => panic!("{other:?}"),
        }
        // The face's own impulse (e = 0.5) loses energy.
        assert!(struck(&body, &state, &frame, down.scaled(-3.0), 0.25).is_ok());
    }

    #[test]
    fn a_face_whose_pressure_would_leave_it_or_that_does_not_strike_face_first_is_no_face_impact() {
        let law = ContactLaw::new(0.0).try_with_restitution(0.5).unwrap();
        // A long body (I_h = 10 m a²): reversing a|ω_h| = |v_z|/2 needs
        // a couple 5 a P_N, its centre of pressure 5 a from the face's
        // centre.
        let long = flat_disk(10.0 * M * A * A, law);
        let state = striking(
            &long,
            DVec3::new(0.0, 0.0, -1.0),
            DVec3::new(0.5 / A, 0.0, 0.0),
        );
        assert!(face_impact(&long, &state, 0, 1e-9, 0.0).unwrap().is_none());
        // A thin disk rocking faster than it falls: a rim point rises.
        let thin = flat_disk(0.25 * M * A * A, law);
        let state = striking(
            &thin,
            DVec3::new(0.0, 0.0, -1.0),
            DVec3::new(0.0, 2.0 / A, 0.0),
        );
        assert!(face_impact(&thin, &state, 0, 1e-9, 0.0).unwrap().is_none());
        // Rising: no impact.
        let state = striking(&thin, DVec3::new(0.0, 0.0, 1.0), DVec3::ZERO);
        assert!(face_impact(&thin, &state, 0, 1e-9, 0.0).unwrap().is_none());
    }
}
