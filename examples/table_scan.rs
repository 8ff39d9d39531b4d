//! A robustness scan of the nonsmooth table: random bodies (one or two
//! contact shapes: spheres, ellipsoids, disk rims off the centre of mass),
//! random laws (μ, e, e_T, Contensou radius, rolling resistance) and
//! random throws onto the table, each run for 2 s at the default
//! tolerance. It counts how the runs end (through, at rest, or which
//! typed error), whether the energy ever rose between frames beyond
//! 1e-9 of its scale, and the slowest runs.
//!
//! ```sh
//! cargo run --release --example table_scan -- [CASES] [SEED] [TRACE]
//! ```
//!
//! With `TRACE` the case of that number alone, frame by frame: its body,
//! start, steps, modes, events and state (a regression test's start).

use std::collections::BTreeMap;
use std::time::Instant;

use glam::{DMat3, DQuat, DVec3};
use kreisel::dynamics::{
    AdaptiveTolerance, ContactLaw, ContactShape, DiskContact, DynamicsError, EllipsoidContact,
    GroundTopState, SphereContact, TableBody, TableContact, TableMotion,
};

/// A 64-bit linear congruential generator (Knuth's MMIX constants): the
/// scan needs repeatable numbers, not good ones.
struct Lcg(u64);

impl Lcg {
    fn uniform(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn between(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.uniform()
    }
    fn unit(&mut self) -> DVec3 {
        loop {
            let v = DVec3::new(
                self.between(-1.0, 1.0),
                self.between(-1.0, 1.0),
                self.between(-1.0, 1.0),
            );
            if v.length() > 0.1 && v.length() <= 1.0 {
                return v.normalize();
            }
        }
    }
}

const G: f64 = 9.81;
const LENGTH: f64 = 0.05;

fn shape(rng: &mut Lcg) -> ContactShape {
    let offset = rng.unit() * rng.between(0.0, 0.4 * LENGTH);
    let size = rng.between(0.3, 1.0) * LENGTH;
    match (rng.uniform() * 3.0) as u32 {
        0 => ContactShape::Sphere(SphereContact::try_new(size, offset).unwrap()),
        1 => ContactShape::Ellipsoid(
            EllipsoidContact::try_new(
                DVec3::new(
                    size,
                    size * rng.between(0.4, 1.0),
                    size * rng.between(0.4, 1.0),
                ),
                offset,
            )
            .unwrap(),
        ),
        _ => ContactShape::Disk(DiskContact::try_new(size, offset, rng.unit()).unwrap()),
    }
}

fn law(rng: &mut Lcg) -> ContactLaw {
    let mu = if rng.uniform() < 0.1 {
        0.0
    } else {
        rng.between(0.05, 1.2)
    };
    let mut law = ContactLaw::try_new(mu)
        .and_then(|l| l.try_with_restitution(rng.uniform()))
        .unwrap();
    if rng.uniform() < 0.2 {
        law = law.try_with_tangential_restitution(rng.uniform()).unwrap();
    }
    if rng.uniform() < 0.4 {
        law = law
            .try_with_contensou_radius(rng.between(0.0, 0.05) * LENGTH)
            .unwrap();
    }
    if rng.uniform() < 0.3 {
        law = law
            .try_with_rolling_resistance(rng.between(0.0, 0.05) * LENGTH)
            .unwrap();
    }
    law
}

/// One random case: the body and its start, or None when the draw is not
/// a body (the library refused it).
fn case(rng: &mut Lcg) -> Option<(TableBody, GroundTopState)> {
    let mass = rng.between(0.01, 1.0);
    let (a, b) = (rng.between(0.2, 1.0), rng.between(0.2, 1.0));
    let c = rng.between((a - b).abs() + 0.05, a + b);
    let inertia = DMat3::from_diagonal(DVec3::new(a, b, c) * 0.2 * mass * LENGTH * LENGTH);
    let shapes = if rng.uniform() < 0.5 { 1 } else { 2 };
    let contacts = (0..shapes)
        .map(|_| TableContact {
            shape: shape(rng),
            law: law(rng),
        })
        .collect();
    let body = TableBody::try_new(mass, inertia, contacts, G).ok()?;
    let q = DQuat::from_scaled_axis(rng.unit() * rng.between(0.0, std::f64::consts::PI));
    let lowest = body
        .contacts()
        .iter()
        .map(|c| c.shape.contact_from_com_world(q).z)
        .fold(f64::INFINITY, f64::min);
    let speed = (G * LENGTH).sqrt();
    let omega = rng.unit() * rng.between(0.0, 8.0) * speed / LENGTH;
    let world = DMat3::from_quat(q);
    let state = GroundTopState {
        com_world: DVec3::new(0.0, 0.0, -lowest + rng.between(0.0, 1.0) * LENGTH),
        velocity_world: rng.unit() * rng.between(0.0, 2.0) * speed,
        world_from_body: q,
        l_world: world * inertia * world.transpose() * omega,
    };
    Some((body, state))
}

fn main() {
    let args: Vec<u64> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("CASES and SEED are whole numbers"))
        .collect();
    let cases = args.first().copied().unwrap_or(200);
    let mut rng = Lcg(args.get(1).copied().unwrap_or(26));
    let mut outcomes: BTreeMap<String, usize> = BTreeMap::new();
    let mut slowest = Vec::new();
    let mut rises = 0;
    let trace = args.get(2).copied();
    for k in 0..cases {
        let drawn = case(&mut rng);
        if trace.is_some_and(|t| t != k) {
            continue;
        }
        if let (Some(_), Some((body, start))) = (trace, &drawn) {
            println!("{body:?}\n{start:?}");
        }
        let Some((body, start)) = drawn else {
            *outcomes.entry("not a body".into()).or_default() += 1;
            continue;
        };
        let scale = body.mass() * G * LENGTH + body.energy(&start).abs();
        let clock = Instant::now();
        let outcome = match TableMotion::try_new(body, start, AdaptiveTolerance::new(1e-10, 1e-10))
        {
            Err(e) => {
                if trace.is_some() {
                    println!("{e}");
                }
                format!("start: {}", kind(&e))
            }
            Ok(mut run) => {
                let mut energy = run.body().energy(run.state());
                let mut rose = false;
                let mut end = "through 2 s".to_owned();
                for frame in 1..=200 {
                    let t_frame = f64::from(frame) * 0.01;
                    if let Err(e) = run.try_advance_to(t_frame) {
                        if trace.is_some() {
                            println!("{e}");
                        }
                        end = kind(&e);
                        break;
                    }
                    if trace.is_some() {
                        let s = run.stats();
                        println!(
                            "t {:.2}: {} steps, {} rejected, modes {:?}, events {:?}\n  state {:?}",
                            run.time(),
                            s.accepted,
                            s.rejected,
                            run.modes(),
                            run.events().iter().rev().take(3).collect::<Vec<_>>(),
                            run.state()
                        );
                    }
                    let now = run.body().energy(run.state());
                    rose |= now > energy + 1e-9 * scale;
                    energy = now;
                    if run.is_resting() {
                        end = "at rest".into();
                        break;
                    }
                    if clock.elapsed().as_secs_f64() > 10.0 {
                        end = "slower than 10 s".into();
                        break;
                    }
                }
                rises += usize::from(rose);
                if rose {
                    end.push_str(", energy rose");
                }
                end
            }
        };
        let wall = clock.elapsed().as_secs_f64();
        println!("case {k}: {outcome} ({wall:.2} s)");
        slowest.push((wall, k, outcome.clone()));
        *outcomes.entry(outcome).or_default() += 1;
    }
    println!("{cases} cases:");
    for (outcome, n) in &outcomes {
        println!("  {n:4}  {outcome}");
    }
    println!("  energy rose beyond 1e-9 of its scale between frames: {rises}");
    slowest.sort_by(|a, b| b.0.total_cmp(&a.0));
    for (wall, k, outcome) in slowest.iter().take(5) {
        println!("  slow: case {k}: {wall:.2} s ({outcome})");
    }
}

/// The error's variant name.
fn kind(e: &DynamicsError) -> String {
    format!("{e:?}")
        .split([' ', '{', '('])
        .next()
        .unwrap_or("?")
        .to_owned()
}
