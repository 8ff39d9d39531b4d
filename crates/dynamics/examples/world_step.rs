//! What one `World::step(1/60)` costs per body, next to one PDMV6 step (the
//! issue's game-loop goal: ≤ 2× a pdmv6 step per body), and what the
//! plans save: spheres and resting bodies against asymmetric ones, and
//! `advance_to` (evaluated once per written row) against stepping.
//!
//! ```text
//! cargo run --release -p kreisel-dynamics --example world_step
//! ```
//!
//! Timings are medians of 7 repetitions on whatever machine runs it; this
//! is a measurement, never a test.

use std::hint::black_box;
use std::time::Instant;

use glam::{DQuat, DVec3};
use kreisel_dynamics::{
    Body, FreeBodyIntegrator, FreeBodyMethod, PreprocessedMoserVeselov, PrincipalState, World,
};

const BODIES: usize = 1000;
const FRAMES: usize = 600;
const H: f64 = 1.0 / 60.0;

/// Body `k` of a family: distinct moments and a spin near the separatrix,
/// or (for `kind` = sphere / resting) the cheap cases.
fn body(k: usize, kind: &str) -> Body {
    let x = k as f64 / BODIES as f64;
    let moments = match kind {
        "sphere" => DVec3::splat(1.0 + x),
        _ => DVec3::new(1.0 + 0.1 * x, 2.0 + 0.3 * x, 3.0 + 0.2 * x),
    };
    let omega = match kind {
        "resting" => DVec3::ZERO,
        _ => DVec3::new(0.01 + 0.1 * x, 1.0, 0.2 * x),
    };
    Body::from_principal_moments(1.0, moments)
        .world_from_body(DQuat::from_rotation_z(x))
        .omega_body(omega)
        .try_build()
        .expect("a valid body")
}

/// The median of 7 runs of `f`, in ns per body-step for `work` body-steps.
fn median_ns(work: usize, mut f: impl FnMut()) -> f64 {
    let mut times: Vec<f64> = (0..7)
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed().as_secs_f64() * 1e9 / work as f64
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[3]
}

fn world_of(kind: &str, method: FreeBodyMethod) -> World {
    let mut world = World::try_new(DVec3::ZERO, H).expect("a valid world");
    world.set_free_body_method(method).expect("a method");
    for k in 0..BODIES {
        world.add(body(k, kind)).expect("a body");
    }
    world
}

fn main() {
    let work = BODIES * FRAMES;
    // The set-up (one exact solution per body, made when the body is
    // added) is outside the stepping timings and measured on its own.
    let step_world = |kind: &'static str, method: FreeBodyMethod| {
        let mut world = world_of(kind, method);
        median_ns(work, || {
            for _ in 0..FRAMES {
                world.step(H).expect("no divergence");
            }
            black_box(world.time());
        })
    };
    let setup = median_ns(BODIES, || {
        black_box(world_of("asymmetric", FreeBodyMethod::Auto));
    });
    let method = PreprocessedMoserVeselov::ORDER_6;
    let mut propagators: Vec<_> = (0..BODIES)
        .map(|k| {
            let b = body(k, "asymmetric");
            let s = PrincipalState::try_from_omega_body(
                b.rigid_body(),
                b.world_from_body(),
                b.omega_body(),
            )
            .expect("a state");
            method.propagator(b.rigid_body().principal_moments(), s)
        })
        .collect();
    // Frame-major, as a game steps its bodies.
    let pdmv6 = median_ns(work, || {
        for _ in 0..FRAMES {
            for p in &mut propagators {
                p.advance(H);
            }
        }
        black_box(propagators[0].state());
    });
    let asym = step_world("asymmetric", FreeBodyMethod::Auto);
    let asym_pdmv6 = step_world("asymmetric", FreeBodyMethod::Pdmv6);
    let sphere = step_world("sphere", FreeBodyMethod::Auto);
    let resting = step_world("resting", FreeBodyMethod::Auto);
    // A simulation: 100 s written every 1 s.
    let mut world = world_of("asymmetric", FreeBodyMethod::Auto);
    let mut second = 0.0;
    let rows = median_ns(BODIES * 6000, || {
        for _ in 0..100 {
            second += 1.0;
            world.advance_to(second).expect("no divergence");
        }
        black_box(world.time());
    });
    println!("{BODIES} bodies, {FRAMES} frames of 1/60 s (median of 7 runs, ns per body-step):");
    println!("  World::step, asymmetric, auto (exact)   {asym:8.1}");
    println!("  World::step, asymmetric, pdmv6          {asym_pdmv6:8.1}");
    println!("  pdmv6 propagator alone                  {pdmv6:8.1}");
    println!(
        "  ratio World::step(auto) / pdmv6          {:8.2}",
        asym / pdmv6
    );
    println!("  World::step, spheres                    {sphere:8.1}");
    println!("  World::step, resting                    {resting:8.1}");
    println!("  exact set-up per asymmetric body (ns)   {setup:8.0}");
    println!(
        "  advance_to, 100 s written every 1 s     {rows:8.2}  (per body and 1/60 s of simulated time)"
    );
}
