//! The contacts' problem whole — normal forces, friction (with Contensou's
//! drilling), rolling resistance — by a semismooth Newton method on the
//! Alart–Curnier equations, where the sweeps over the contacts and the
//! rolling cones settle too slowly or cycle: two contacts that nearly
//! overconstrain the body moved the sweeps by 0.9957 per sweep (2000
//! sweeps to 1e-8 where 1e-15 is asked), and contacts with rolling cones
//! cycled between the two problems (`ContactUnsolved` in 5 of 100 random
//! throws).
//!
//! With `λ` all the unknowns, `y = y_free + G λ` the accelerations, and per
//! contact a scale `r = 1/max G_ii` (Alart & Curnier, CMAME 92 (1991) 353;
//! the acceleration-level form of Bertails-Descoubes et al. 2011):
//!
//! ```text
//! Φ_N = λ_N − max(0, λ_N − r y_N)
//! Φ_T = λ_T − proj_{|·| ≤ μ λ_N⁺}(λ_T − r y_T)      (friction cone, drilling included)
//! Φ_T = λ_T + μ λ_N d                              (slipping along d already)
//! Φ_R = λ_R − proj_{|·| ≤ λ_N⁺}(λ_R − r y_R)        (rolling cone)
//! Φ_R = λ_R + λ_N d_R                              (rolling along d_R already)
//! ```
//!
//! `Φ = 0` is the laws exactly. Newton steps on `Φ` with its generalised
//! Jacobian (the projections' derivatives where they are smooth), a
//! Levenberg–Marquardt step where the Jacobian is singular (contacts that
//! overconstrain the body: any solution serves, the forces are
//! distributed afterwards), and an Armijo line search on `½|Φ|²`; where
//! no step decreases it (a local minimum at a kink), projected sweeps
//! `λ_a ← λ_a − Φ_a(λ)` over the contacts before Newton again.
//!
//! Hand-written: a dozen unknowns per problem, and the engine keeps
//! nalgebra out of `kreisel-dynamics`.

use glam::DVec3;

use super::contact_block::{Block, Rolling};
use super::contact_frame::{ContactFrame, ROLLING};
use super::dense::solve_in_place;

/// The rounding of `Φ`, in ulps of the magnitudes it is computed from
/// (`|λ| + r |y_free| + r Σ |G λ|`): a residual below it has settled.
const ROUNDING_ULPS: f64 = 64.0;

/// The most Newton steps.
const MAX_STEPS: usize = 100;

/// The most halvings of a step in the line search.
const MAX_HALVINGS: usize = 40;

/// Projected sweeps where a Newton step finds no decrease.
const PROJECTED_SWEEPS: usize = 20;

/// The unknowns of all the contacts, each contact's together: its block
/// (normal, friction), then its rolling.
struct Layout {
    /// The contact each unknown belongs to and its row direction (`0`
    /// normal, `1..=3` friction, [`ROLLING`]).
    components: Vec<(usize, usize)>,
    /// Where each contact's unknowns start (its normal).
    start: Vec<usize>,
}

impl Layout {
    fn of(blocks: &[Block], rolling: &[Rolling]) -> Self {
        let mut components = Vec::new();
        let mut start = Vec::with_capacity(blocks.len());
        for (a, b) in blocks.iter().enumerate() {
            start.push(components.len());
            components.extend((0..b.size).map(|k| (a, k)));
            if rolling[a] != Rolling::Free {
                components.extend(ROLLING.iter().map(|&r| (a, r)));
            }
        }
        Self { components, start }
    }

    /// One value per unknown: `block(a, k)` for component `k` of contact
    /// `a`'s block, `rolling(a, c)` for its rolling component `c`.
    fn gather(
        &self,
        blocks: &[Block],
        block: impl Fn(usize, usize) -> f64,
        rolling: impl Fn(usize, usize) -> f64,
    ) -> Vec<f64> {
        self.components
            .iter()
            .map(|&(a, k)| {
                if k < blocks[a].size {
                    block(a, k)
                } else {
                    rolling(a, k - ROLLING[0])
                }
            })
            .collect()
    }
}

/// The contacts' problem, assembled.
struct Problem<'a> {
    blocks: &'a [Block],
    rolling: &'a [Rolling],
    layout: Layout,
    /// `G` row-major, `y_free`, the scale `r` of each contact.
    g: Vec<f64>,
    y_free: Vec<f64>,
    r: Vec<f64>,
}

impl<'a> Problem<'a> {
    /// The problem of `G` and `y_free` over `layout`, each contact scaled
    /// by `r = 1/max G_ii` over its unknowns.
    fn new(
        blocks: &'a [Block],
        rolling: &'a [Rolling],
        layout: Layout,
        g: Vec<f64>,
        y_free: Vec<f64>,
    ) -> Self {
        let n = layout.components.len();
        let r = (0..blocks.len())
            .map(|a| {
                let diagonal = (0..n)
                    .filter(|&i| layout.components[i].0 == a)
                    .fold(0.0_f64, |m, i| m.max(g[i * n + i]));
                1.0 / diagonal
            })
            .collect();
        Self {
            blocks,
            rolling,
            layout,
            g,
            y_free,
            r,
        }
    }

    fn n(&self) -> usize {
        self.layout.components.len()
    }

    /// The rounding of each component of `Φ(λ)` ([`ROUNDING_ULPS`]).
    fn rounding(&self, lambda: &[f64]) -> Vec<f64> {
        let n = self.n();
        (0..n)
            .map(|i| {
                let r = self.r[self.layout.components[i].0];
                let products: f64 = (0..n).map(|j| (self.g[i * n + j] * lambda[j]).abs()).sum();
                ROUNDING_ULPS
                    * f64::EPSILON
                    * (lambda[i].abs() + r * (self.y_free[i].abs() + products))
            })
            .collect()
    }

    /// A start off the cones' apexes, where the merit has local minima:
    /// each normal force alone against its free rate, no friction.
    fn normal_start(&self) -> Vec<f64> {
        let n = self.n();
        let mut lambda = vec![0.0; n];
        for &o in &self.layout.start {
            lambda[o] = (-self.y_free[o] / self.g[o * n + o]).max(0.0);
        }
        lambda
    }

    /// `Φ(λ)`, and with `jacobian` its generalised Jacobian (row-major).
    fn residual(&self, lambda: &[f64], jacobian: Option<&mut Vec<f64>>) -> Vec<f64> {
        let n = self.n();
        let y: Vec<f64> = (0..n)
            .map(|i| self.y_free[i] + (0..n).map(|j| self.g[i * n + j] * lambda[j]).sum::<f64>())
            .collect();
        let mut phi = vec![0.0; n];
        let mut jac = jacobian;
        if let Some(j) = jac.as_deref_mut() {
            j.clear();
            j.resize(n * n, 0.0);
        }
        // Row i of `𝟙 − r G` for the projection's derivative.
        let shifted =
            |i: usize, r: f64, col: usize| f64::from(u8::from(i == col)) - r * self.g[i * n + col];
        for (a, block) in self.blocks.iter().enumerate() {
            let o = self.layout.start[a];
            let r = self.r[a];
            let normal = lambda[o];
            // Normal: max(0, λ_N − r y_N).
            let p = normal - r * y[o];
            phi[o] = normal - p.max(0.0);
            if let Some(j) = jac.as_deref_mut() {
                for col in 0..n {
                    let d = if p > 0.0 { shifted(o, r, col) } else { 0.0 };
                    j[o * n + col] = f64::from(u8::from(o == col)) - d;
                }
            }
            // Friction, then rolling: a disk of radius `bound` or a fixed
            // direction.
            let mut parts = Vec::with_capacity(2);
            if block.size > 1 {
                let fixed = if block.mu == 0.0 {
                    Some(DVec3::ZERO)
                } else {
                    block.slipping.map(|d| block.mu * d)
                };
                parts.push((o + 1, block.size - 1, block.mu, fixed));
            }
            let rolls_at = o + block.size;
            match self.rolling[a] {
                Rolling::Free => {}
                Rolling::Cone => parts.push((rolls_at, 2, 1.0, None)),
                Rolling::Along(d) => parts.push((rolls_at, 2, 1.0, Some(d))),
            }
            for (at, dims, scale, fixed) in parts {
                if let Some(d) = fixed {
                    // λ + s λ_N d = 0.
                    for k in 0..dims {
                        phi[at + k] = lambda[at + k] + normal * d[k];
                        if let Some(j) = jac.as_deref_mut() {
                            j[(at + k) * n + at + k] = 1.0;
                            j[(at + k) * n + o] = d[k];
                        }
                    }
                    continue;
                }
                let bound = scale * normal.max(0.0);
                let q: Vec<f64> = (0..dims).map(|k| lambda[at + k] - r * y[at + k]).collect();
                let length = q.iter().map(|v| v * v).sum::<f64>().sqrt();
                let inside = length <= bound;
                for k in 0..dims {
                    let projected = if inside { q[k] } else { bound * q[k] / length };
                    phi[at + k] = lambda[at + k] - projected;
                }
                let Some(j) = jac.as_deref_mut() else {
                    continue;
                };
                for k in 0..dims {
                    for col in 0..n {
                        // d proj / d λ = D (𝟙 − r G) + q̂ ∂bound/∂λ.
                        let mut d = 0.0;
                        for l in 0..dims {
                            let dql = if inside {
                                f64::from(u8::from(k == l))
                            } else {
                                bound / length
                                    * (f64::from(u8::from(k == l))
                                        - q[k] * q[l] / (length * length))
                            };
                            d += dql * shifted(at + l, r, col);
                        }
                        if !inside && col == o && normal > 0.0 {
                            d += scale * q[k] / length;
                        }
                        j[(at + k) * n + col] = f64::from(u8::from(at + k == col)) - d;
                    }
                }
            }
        }
        phi
    }
}

/// The unknowns `x` (normal, friction) and rolling resistances `x_R` of
/// the `touching` contacts solving the problem whole, from a start near
/// it (the sweeps' last) or without one from the normal forces alone;
/// `None` where Newton's method does not settle.
pub(crate) fn solve_whole(
    frame: &ContactFrame,
    touching: &[usize],
    blocks: &[Block],
    y_free: &[[f64; 4]],
    rolling: &[Rolling],
    start: Option<(&[[f64; 4]], &[DVec3])>,
) -> Option<(Vec<[f64; 4]>, Vec<DVec3>)> {
    let layout = Layout::of(blocks, rolling);
    let n = layout.components.len();
    let direction = |(a, k): (usize, usize)| &frame.rows[touching[a]].directions[k];
    let mut g = vec![0.0; n * n];
    for (i, &ci) in layout.components.iter().enumerate() {
        for (j, &cj) in layout.components.iter().enumerate() {
            g[i * n + j] = frame.delassus(direction(ci), direction(cj));
        }
    }
    let free = (frame.free_velocity_rate, frame.free_omega_rate);
    let y_free_all = layout.gather(
        blocks,
        |a, k| y_free[a][k],
        |a, c| frame.rate(touching[a], ROLLING[c], free),
    );
    let problem = Problem::new(blocks, rolling, layout, g, y_free_all);
    let lambda = match start {
        Some((x, x_r)) => problem
            .layout
            .gather(blocks, |a, k| x[a][k], |a, c| x_r[a][c]),
        None => problem.normal_start(),
    };
    problem
        .solve(lambda)
        .map(|lambda| unpack(&problem, &lambda))
}

impl Problem<'_> {
    /// Newton's method from `lambda` (projected sweeps where a step finds
    /// no decrease): the unknowns where `Φ` has settled to rounding; `None`
    /// where it has not within [`MAX_STEPS`] or is not finite.
    fn solve(&self, mut lambda: Vec<f64>) -> Option<Vec<f64>> {
        let n = self.n();
        let norm2 = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>();
        let mut jacobian = Vec::new();
        for _ in 0..MAX_STEPS {
            let phi = self.residual(&lambda, Some(&mut jacobian));
            if !phi.iter().all(|p| p.is_finite()) {
                return None;
            }
            if phi
                .iter()
                .zip(self.rounding(&lambda))
                .all(|(p, floor)| p.abs() <= floor)
            {
                return Some(lambda);
            }
            let merit = norm2(&phi);
            let mut accepted = false;
            if let Some(step) = newton_step(&jacobian, &phi, n) {
                let mut t = 1.0;
                for _ in 0..MAX_HALVINGS {
                    let trial: Vec<f64> =
                        lambda.iter().zip(&step).map(|(l, s)| l + t * s).collect();
                    if norm2(&self.residual(&trial, None)) <= (1.0 - 1e-4 * t) * merit {
                        lambda = trial;
                        accepted = true;
                        break;
                    }
                    t *= 0.5;
                }
            }
            if !accepted {
                // A local minimum of the merit (the generalised Jacobian
                // of a kink points nowhere down): projected sweeps, then
                // Newton again from where they got to.
                self.project_sweeps(&mut lambda);
            }
        }
        None
    }

    /// [`PROJECTED_SWEEPS`] sweeps of `λ_a ← λ_a − Φ_a(λ)` over the
    /// contacts in turn (each the projection of `λ_a − r y_a` on its laws,
    /// the others' unknowns as they are).
    fn project_sweeps(&self, lambda: &mut [f64]) {
        let n = self.n();
        for _ in 0..PROJECTED_SWEEPS {
            for a in 0..self.blocks.len() {
                let phi = self.residual(lambda, None);
                for i in (0..n).filter(|&i| self.layout.components[i].0 == a) {
                    lambda[i] -= phi[i];
                }
            }
        }
    }
}

/// The Newton step `J Δ = −Φ`; where `J` is singular, Levenberg–Marquardt's
/// `(JᵀJ + ν𝟙) Δ = −JᵀΦ`.
fn newton_step(jacobian: &[f64], phi: &[f64], n: usize) -> Option<Vec<f64>> {
    let mut a = jacobian.to_vec();
    let mut step: Vec<f64> = phi.iter().map(|p| -p).collect();
    if solve_in_place(&mut a, &mut step, n) {
        return Some(step);
    }
    let mut normal = vec![0.0; n * n];
    let mut rhs = vec![0.0; n];
    for i in 0..n {
        for k in 0..n {
            rhs[i] -= jacobian[k * n + i] * phi[k];
            for j in 0..n {
                normal[i * n + j] += jacobian[k * n + i] * jacobian[k * n + j];
            }
        }
    }
    let largest = (0..n).fold(0.0_f64, |m, i| m.max(normal[i * n + i]));
    for i in 0..n {
        normal[i * n + i] += 1e-12 * largest;
    }
    solve_in_place(&mut normal, &mut rhs, n).then_some(rhs)
}

/// The blocks' unknowns and the rolling resistances of `lambda`.
fn unpack(problem: &Problem, lambda: &[f64]) -> (Vec<[f64; 4]>, Vec<DVec3>) {
    let m = problem.blocks.len();
    let mut x = vec![[0.0; 4]; m];
    let mut x_r = vec![DVec3::ZERO; m];
    for (i, &(a, k)) in problem.layout.components.iter().enumerate() {
        if k < problem.blocks[a].size {
            x[a][k] = lambda[i];
        } else {
            x_r[a][k - ROLLING[0]] = lambda[i];
        }
    }
    (x, x_r)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::table::contact_problem::solve_blocks_from;

    /// Repeatable numbers in [−1, 1) (a 64-bit LCG: the tests need
    /// variety, not quality).
    struct Lcg(u64);

    impl Lcg {
        fn next(&mut self) -> f64 {
            self.0 = self
                .0
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
        }
    }

    /// A body's problem: `G = W M⁻¹ Wᵀ`, `y_free = W u` (the free
    /// accelerations of a rigid body, so sticking everywhere is
    /// consistent even where the contacts overconstrain it).
    fn random_problem(rng: &mut Lcg, n: usize) -> (Vec<f64>, Vec<f64>) {
        let inverse_mass = [2.0, 2.0, 2.0, 50.0, 80.0, 30.0];
        let w: Vec<[f64; 6]> = (0..n)
            .map(|_| std::array::from_fn(|_| rng.next()))
            .collect();
        let u: [f64; 6] = std::array::from_fn(|_| 5.0 * rng.next());
        let mut g = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                g[i * n + j] = (0..6).map(|k| w[i][k] * inverse_mass[k] * w[j][k]).sum();
            }
        }
        let y_free = (0..n)
            .map(|i| (0..6).map(|k| w[i][k] * u[k]).sum())
            .collect();
        (g, y_free)
    }

    /// Whether `lambda` obeys the laws of `problem` (Signorini, the cones
    /// with maximal dissipation, the fixed directions), each to `tol` of
    /// the problem's magnitudes — checked from `y = y_free + G λ`, not
    /// from `Φ`.
    fn obeys_the_laws(problem: &Problem, lambda: &[f64], tol: f64) -> Result<(), String> {
        let n = problem.n();
        let y: Vec<f64> = (0..n)
            .map(|i| {
                problem.y_free[i]
                    + (0..n)
                        .map(|j| problem.g[i * n + j] * lambda[j])
                        .sum::<f64>()
            })
            .collect();
        let force = lambda.iter().fold(1e-300_f64, |m, x| m.max(x.abs()));
        let rate = y
            .iter()
            .chain(&problem.y_free)
            .fold(1e-300_f64, |m, x| m.max(x.abs()));
        for (a, block) in problem.blocks.iter().enumerate() {
            let o = problem.layout.start[a];
            let (normal, y_n) = (lambda[o], y[o]);
            if normal < -tol * force
                || y_n < -tol * rate
                || (normal * y_n).abs() > tol * force * rate
            {
                return Err(format!("Signorini at {a}: λ_N {normal}, y_N {y_n}"));
            }
            let mut cones = vec![(o + 1, block.size - 1, block.mu, block.slipping)];
            if problem.rolling[a] != Rolling::Free {
                let along = match problem.rolling[a] {
                    Rolling::Along(d) => Some(d),
                    _ => None,
                };
                cones.push((o + block.size, 2, 1.0, along));
            }
            for (at, dims, mu, along) in cones {
                let t = DVec3::from_slice(
                    &[lambda[at..at + dims].to_vec(), vec![0.0; 3 - dims]].concat(),
                );
                let v =
                    DVec3::from_slice(&[y[at..at + dims].to_vec(), vec![0.0; 3 - dims]].concat());
                let bound = mu * normal.max(0.0);
                let expected = match along {
                    Some(d) => -bound * d,
                    None if v.length() <= tol * rate => {
                        if t.length() > bound + tol * force {
                            return Err(format!("outside the cone at {a}: {t} beyond {bound}"));
                        }
                        t
                    }
                    None => -bound * v.normalize(),
                };
                if (t - expected).length() > tol * force {
                    return Err(format!("at {a}: {t}, the law's {expected} (rate {v})"));
                }
            }
        }
        Ok(())
    }

    fn layout_and_problem<'a>(
        blocks: &'a [Block],
        rolling: &'a [Rolling],
        rng: &mut Lcg,
    ) -> Problem<'a> {
        let layout = Layout::of(blocks, rolling);
        let (g, y_free) = random_problem(rng, layout.components.len());
        Problem::new(blocks, rolling, layout, g, y_free)
    }

    #[test]
    fn one_contact_with_drilling_friction_obeys_its_laws() {
        let mut rng = Lcg(7);
        for case in 0..200 {
            let blocks = [Block {
                size: 4,
                mu: 0.1 + 0.9 * (rng.next() + 1.0),
                slipping: None,
            }];
            let rolling = [Rolling::Free];
            let problem = layout_and_problem(&blocks, &rolling, &mut rng);
            // From near the sweeps' solution (1 % off), as where the
            // sweeps hand over.
            let g = |i: usize, a: usize, j: usize, b: usize| problem.g[(4 * i + a) * 4 + 4 * j + b];
            let y: [f64; 4] = std::array::from_fn(|k| problem.y_free[k]);
            let mut swept = [[0.0; 4]];
            solve_blocks_from(&blocks, &[y], &g, &mut swept).unwrap();
            let start: Vec<f64> = swept[0].iter().map(|x| x * 1.01).collect();
            let lambda = problem
                .solve(start)
                .unwrap_or_else(|| panic!("case {case} unsolved"));
            obeys_the_laws(&problem, &lambda, 1e-11).unwrap_or_else(|e| panic!("case {case}: {e}"));
        }
    }

    #[test]
    fn two_contacts_with_rolling_cones_that_overconstrain_the_body_obey_their_laws() {
        let mut rng = Lcg(11);
        let mut solved = 0;
        for case in 0..200 {
            let blocks: Vec<Block> = (0..2)
                .map(|_| Block {
                    size: 4,
                    mu: 0.1 + 0.9 * (rng.next() + 1.0),
                    slipping: None,
                })
                .collect();
            let rolling = [Rolling::Cone, Rolling::Cone];
            let problem = layout_and_problem(&blocks, &rolling, &mut rng);
            if let Some(lambda) = problem.solve(problem.normal_start()) {
                obeys_the_laws(&problem, &lambda, 1e-11)
                    .unwrap_or_else(|e| panic!("case {case}: {e}"));
                solved += 1;
            }
        }
        assert!(solved >= 190, "{solved} of 200");
    }

    #[test]
    fn slips_and_rolls_along_their_directions_keep_them() {
        let mut rng = Lcg(13);
        let mut solved = 0;
        for case in 0..100 {
            let d = DVec3::new(rng.next(), rng.next(), rng.next()).normalize();
            let d_r = DVec3::new(rng.next(), rng.next(), 0.0).normalize();
            let blocks = [Block {
                size: 4,
                mu: 0.5,
                slipping: Some(d),
            }];
            let rolling = [Rolling::Along(d_r)];
            let problem = layout_and_problem(&blocks, &rolling, &mut rng);
            // The normal force's own coefficient with the friction and the
            // rolling tied to it: not positive is Painlevé's case (no
            // unique solution), not asked of the solver.
            let n = problem.n();
            let tied: Vec<f64> = [1.0, -0.5 * d.x, -0.5 * d.y, -0.5 * d.z, -d_r.x, -d_r.y].to_vec();
            let kappa: f64 = (0..n).map(|j| problem.g[j] * tied[j]).sum();
            if kappa <= 0.0 {
                continue;
            }
            solved += 1;
            let lambda = problem
                .solve(problem.normal_start())
                .unwrap_or_else(|| panic!("case {case} unsolved (κ = {kappa})"));
            obeys_the_laws(&problem, &lambda, 1e-11).unwrap_or_else(|e| panic!("case {case}: {e}"));
        }
        assert!(solved > 50, "{solved}");
    }
}
