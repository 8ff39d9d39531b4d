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
use super::contact_frame::{ContactFrame, Wrench};
use super::contact_problem::{Block, solve_blocks};
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
/// rebound at or below `resolution_speed` closes the contact.
///
/// # Errors
/// [`DynamicsError::ImpactGainsEnergy`] (at `time`) when the impulses
/// would raise the kinetic energy beyond rounding;
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
    let mut blocks = Vec::with_capacity(participants.len());
    let mut y_free = Vec::with_capacity(participants.len());
    let mut accumulations = Vec::new();
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
    let g = |a: usize, ca: usize, b: usize, cb: usize| {
        frame.delassus(
            &frame.rows[participants[a]].directions[ca],
            &frame.rows[participants[b]].directions[cb],
        )
    };
    let impulses = solve_blocks(&blocks, &y_free, &g).map_err(|e| at_time(e, time))?;
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
    let after = GroundTopState {
        velocity_world: state.velocity_world + total.force * frame.inverse_mass,
        l_world: state.l_world + total.torque,
        ..*state
    };
    let (before_t, after_t) = (body.kinetic_energy(state), body.kinetic_energy(&after));
    if after_t > before_t * (1.0 + 1e-12) {
        return Err(DynamicsError::ImpactGainsEnergy {
            time,
            before: before_t,
            after: after_t,
        });
    }
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

/// The impulse `P = −G⁻¹ (0, γ_T)` on the contact's normal and friction
/// directions that stops the residual slip of a contact that starts to
/// stick and keeps its normal velocity `ġ` (`ΔT = −½ (0, γ_T)ᵀ G⁻¹ (0, γ_T)
/// + P_N ġ`, both velocities below the resolution speed). Stopping the
/// slip by `P_T = −G_TT⁻¹ γ_T` alone moved the normal velocity by
/// `G_NT P_T`: the thrown ellipsoid at μ = 1000 stuck with
/// `ġ = +1.3·10⁻¹⁰` m/s, and the closed contact's normal force then did
/// work `N ġ` on it (+2.6·10⁻¹¹ J in 0.05 s of rolling). (Zeroing `ġ` as
/// well stalled the spun coin of `tests/table_regressions.rs`.)
pub(crate) fn stop_slip(body: &TableBody, state: &GroundTopState, i: usize) -> GroundTopState {
    // Impulses only: the velocities, not the (time-dependent) loads, matter.
    let frame = ContactFrame::of(body, state, 0.0);
    let row = &frame.rows[i];
    if row.friction_dimensions == 0 {
        return *state;
    }
    let n = 1 + row.friction_dimensions;
    let mut a = [0.0; 16];
    let mut rhs = [0.0; 4];
    for r in 0..n {
        for k in 0..n {
            a[r * n + k] = frame.delassus(&row.directions[r], &row.directions[k]);
        }
        // The normal velocity kept, the slip stopped.
        rhs[r] = if r == 0 { 0.0 } else { -row.velocity[r] };
    }
    if !super::dense::solve_in_place(&mut a, &mut rhs, n) {
        return *state;
    }
    let mut total = Wrench::default();
    for (k, pk) in rhs.iter().enumerate().take(n) {
        total = total.plus(row.directions[k].scaled(*pk));
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
    let rho_b = disk.contact_from_com_world(q);
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
