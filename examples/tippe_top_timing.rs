//! How long kreisel takes to answer "when does the tippe top turn over?",
//! and how the answer converges with the step — the kreisel half of the
//! MuJoCo side-by-side in BENCHMARKS.md ("Tops on a table", issue #17;
//! the MuJoCo half is `benches/mujoco_tippe_top.py`, which runs this
//! program too).
//!
//! ```text
//! cargo run --release --example tippe_top_timing            # the table
//! cargo run --release --example tippe_top_timing -- --csv   # rows for the script
//! ```
//!
//! Cases (the top starts touching the plane, centre-of-mass velocity
//! horizontal):
//! - `lg-*`: Leine & Glocker's tippe top (m = 6 g, I₁ = 8e-7, I₃ = 7e-7
//!   kg m², ball R = 15 mm, ball centre a = 3 mm from the centre of mass
//!   towards the stem, θ₀ = 0.1 rad, spin 180 rad/s about the axis), with
//!   regularised Coulomb friction μ = 0.3 at ε = 1 mm/s, 0.1 mm/s and
//!   10 mm/s, and viscous μ = 0.3 s/m;
//! - `tutorial-*`: MuJoCo's tutorial tippe top (a 2 cm ball, a stem
//!   cylinder and an invisible ballast box, density 1000 kg/m³: its mass
//!   properties computed below by the closed forms; upright, ω = (0, 1,
//!   200) rad/s in body axes, the ball's centre at rest), with μ = 1 (the
//!   tutorial's friction) at ε = 1 mm/s and 0.1 mm/s. kreisel models the
//!   ball only; the rim of the stem's end touches down only after the
//!   axis passes ≈ 127°, after the horizontal this program reports.
//!
//! For each case and step `dt` (1e-4 … 1.25e-5 s, fixed-step RK4) it prints
//! the first time the symmetry axis passes the horizontal going down
//! (linear interpolation between steps) and the wall time of the run to
//! there (the best of `--repeat` runs), then the successive differences,
//! the observed orders, and the largest step whose answer is within 1e-6
//! relative of the finest. Then the state after 15 s (tilt θ of the axis,
//! E/E₀, the drift of Jellett's λ), the numbers MuJoCo's runs are compared with (for the tutorial
//! top only meaningful before its stem would touch, θ < 127°).

use std::process::ExitCode;
use std::time::Instant;

use glam::{DMat3, DQuat, DVec2, DVec3};
use kreisel::dynamics::{DynamicsError, Friction, GroundTop, GroundTopState, SphereContact};

/// Gravity, m/s² (MuJoCo's default).
const G: f64 = 9.81;
/// The steps of the convergence study, s.
const STEPS: [f64; 4] = [1e-4, 5e-5, 2.5e-5, 1.25e-5];
/// The longest run searched for an inversion, s.
const MAX_TIME: f64 = 40.0;
/// The end-state runs' length (MuJoCo's runs are as long), s.
const END_TIME: f64 = 15.0;
/// The step of the end-state runs, s.
const END_STEP: f64 = 2.5e-5;

/// One tippe-top set-up: the body and its initial state.
struct Case {
    name: &'static str,
    top: GroundTop,
    start: GroundTopState,
}

/// Leine & Glocker's top (Eur. J. Mech. A/Solids 22 (2003) 193) with
/// `friction`: tilted by θ₀ = 0.1 rad about x, spinning at 180 rad/s
/// about its axis, centre of mass at rest.
fn leine_glocker(name: &'static str, friction: Friction) -> Result<Case, DynamicsError> {
    let sphere = SphereContact::try_new(0.015, DVec3::new(0.0, 0.0, 0.003))?;
    let inertia = DMat3::from_diagonal(DVec3::new(8e-7, 8e-7, 7e-7));
    let top = GroundTop::try_new(0.006, inertia, sphere, friction, G)?;
    let q = DQuat::from_rotation_x(0.1);
    let start = top.try_state_on_ground(q, q * DVec3::new(0.0, 0.0, 180.0), DVec2::ZERO)?;
    Ok(Case { name, top, start })
}

/// A solid of mass `m` at height `z` on the axis with moments of inertia
/// `(I_xx, I_zz)` about its own centre.
struct Part {
    m: f64,
    z: f64,
    i_xx: f64,
    i_zz: f64,
}

/// The mass, centre-of-mass height and `(I₁, I₃)` about the centre of mass
/// of MuJoCo's tutorial tippe top (its MJCF: sphere r = 0.02 at the body
/// origin; cylinder r = 0.004, half-length 0.008 at z = 0.02; box
/// half-sizes 0.023 × 0.023 × 0.005 at z = −0.015; density 1000 kg/m³).
///
/// ```text
/// sphere:   m = 4/3 π r³ ρ,        I_xx = I_zz = 2/5 m r²
/// cylinder: m = π r² (2h) ρ,       I_xx = m (3r² + (2h)²)/12,  I_zz = m r²/2
/// box:      m = 8 x y z ρ,         I_xx = m (y² + z²)/3,       I_zz = m (x² + y²)/3
/// I₁ = Σ I_xx + m (z − z_G)²,  I₃ = Σ I_zz
/// ```
fn tutorial_mass_properties() -> (f64, f64, f64, f64) {
    let rho = 1000.0;
    let pi = std::f64::consts::PI;
    let (rs, rc, hc) = (0.02_f64, 0.004_f64, 0.008_f64);
    let (bx, by, bz) = (0.023_f64, 0.023_f64, 0.005_f64);
    let ms = 4.0 / 3.0 * pi * rs.powi(3) * rho;
    let mc = pi * rc * rc * 2.0 * hc * rho;
    let mb = 8.0 * bx * by * bz * rho;
    let parts = [
        Part {
            m: ms,
            z: 0.0,
            i_xx: 0.4 * ms * rs * rs,
            i_zz: 0.4 * ms * rs * rs,
        },
        Part {
            m: mc,
            z: 0.02,
            i_xx: mc * (3.0 * rc * rc + 4.0 * hc * hc) / 12.0,
            i_zz: 0.5 * mc * rc * rc,
        },
        Part {
            m: mb,
            z: -0.015,
            i_xx: mb * (by * by + bz * bz) / 3.0,
            i_zz: mb * (bx * bx + by * by) / 3.0,
        },
    ];
    let m: f64 = parts.iter().map(|p| p.m).sum();
    let z_g = parts.iter().map(|p| p.m * p.z).sum::<f64>() / m;
    let i1 = parts
        .iter()
        .map(|p| p.i_xx + p.m * (p.z - z_g).powi(2))
        .sum();
    let i3 = parts.iter().map(|p| p.i_zz).sum();
    (m, z_g, i1, i3)
}

/// MuJoCo's tutorial top with Coulomb μ = 1 regularised at `slip_velocity`:
/// upright, ω = (0, 1, 200) rad/s, the ball's centre at rest (so the centre
/// of mass moves at `ω × (r_G − r_ball)`).
fn tutorial(name: &'static str, slip_velocity: f64) -> Result<Case, DynamicsError> {
    let (m, z_g, i1, i3) = tutorial_mass_properties();
    let sphere = SphereContact::try_new(0.02, DVec3::new(0.0, 0.0, -z_g))?;
    let inertia = DMat3::from_diagonal(DVec3::new(i1, i1, i3));
    let top = GroundTop::try_new(
        m,
        inertia,
        sphere,
        Friction::try_sliding(1.0, slip_velocity)?,
        G,
    )?;
    let omega = DVec3::new(0.0, 1.0, 200.0);
    let v = omega.cross(DVec3::new(0.0, 0.0, z_g));
    let start = top.try_state_on_ground(DQuat::IDENTITY, omega, DVec2::new(v.x, v.y))?;
    Ok(Case { name, top, start })
}

/// The height of the unit symmetry axis' tip (towards the stem): cos θ.
fn axis_z(s: &GroundTopState) -> f64 {
    (s.world_from_body.normalize() * DVec3::Z).z
}

/// Runs `case` at step `h` until the axis passes the horizontal going down
/// (or `MAX_TIME`); returns that time (linear interpolation) and the
/// number of steps taken.
fn time_to_horizontal(case: &Case, h: f64) -> Result<(Option<f64>, usize), DynamicsError> {
    let mut s = case.start;
    let mut z_prev = axis_z(&s);
    let steps = (MAX_TIME / h).round() as usize;
    for n in 0..steps {
        let t = n as f64 * h;
        case.top.try_step(&mut s, t, h)?;
        let z = axis_z(&s);
        if z_prev > 0.0 && z <= 0.0 {
            return Ok((Some(t + h - h * z / (z - z_prev)), n + 1));
        }
        z_prev = z;
    }
    Ok((None, steps))
}

/// The tilt (degrees), E/E₀ and |λ/λ₀ − 1| after `END_TIME` s at `END_STEP`, or the
/// error that stopped the run (lift-off) as text.
fn end_state(case: &Case) -> String {
    let mut s = case.start;
    let (e0, l0) = (case.top.energy(&s), case.top.jellett(&s));
    let steps = (END_TIME / END_STEP).round() as usize;
    match case
        .top
        .try_advance(&mut s, 0.0, END_STEP, steps, |_, _| {})
    {
        Ok(_) => format!(
            "θ = {:.2}°, E/E₀ = {:.4}, |λ/λ₀ − 1| = {:.1e}",
            axis_z(&s).clamp(-1.0, 1.0).acos().to_degrees(),
            case.top.energy(&s) / e0,
            (case.top.jellett(&s) / l0 - 1.0).abs()
        ),
        Err(e) => format!("stopped: {e}"),
    }
}

/// The successive differences of the answers at `STEPS`, the observed
/// orders `log₂(|tₖ − tₖ₊₁|/|tₖ₊₁ − tₖ₊₂|)` (meaningless once a difference
/// is at the noise of the linear interpolation, ≈ 1e-8 s), and the largest
/// step whose answer is within 1e-6 relative of the finest one.
fn convergence(times: &[Option<f64>]) -> Option<String> {
    let t: Vec<f64> = times.iter().copied().collect::<Option<_>>()?;
    let finest = *t.last()?;
    let d: Vec<f64> = t.windows(2).map(|w| (w[0] - w[1]).abs()).collect();
    let orders: Vec<String> = d
        .windows(2)
        .map(|w| format!("{:.2}", (w[0] / w[1]).log2()))
        .collect();
    let within = STEPS
        .iter()
        .zip(&t)
        .find(|(_, t)| ((*t - finest) / finest).abs() <= 1e-6)
        .map(|(h, _)| *h)?;
    let shown: Vec<String> = d.iter().map(|x| format!("{x:.2e}")).collect();
    Some(format!(
        "differences {} s, observed orders {}; within 1e-6 relative of the finest from dt = {within:e} s",
        shown.join(" "),
        orders.join(" ")
    ))
}

fn run(csv: bool, repeat: usize) -> Result<(), DynamicsError> {
    let cases = [
        leine_glocker("lg-sliding-eps1mm", Friction::try_sliding(0.3, 1e-3)?)?,
        leine_glocker("lg-sliding-eps0.1mm", Friction::try_sliding(0.3, 1e-4)?)?,
        leine_glocker("lg-sliding-eps10mm", Friction::try_sliding(0.3, 1e-2)?)?,
        leine_glocker("lg-viscous", Friction::try_viscous(0.3)?)?,
        tutorial("tutorial-sliding-eps1mm", 1e-3)?,
        tutorial("tutorial-sliding-eps0.1mm", 1e-4)?,
    ];
    let (m, z_g, i1, i3) = tutorial_mass_properties();
    if csv {
        println!("# tutorial top: m {m:.9e} kg, z_G {z_g:.9e} m, I1 {i1:.9e}, I3 {i3:.9e} kg m2");
        println!("case,dt_s,horizontal_s,wall_s,steps");
    } else {
        println!(
            "MuJoCo tutorial top (closed forms): m = {m:.6} kg, centre of mass {:.4} mm below \
             the ball's centre, I1 = {i1:.4e}, I3 = {i3:.4e} kg m²",
            -z_g * 1e3
        );
    }
    for case in &cases {
        if !csv {
            println!("\n{}", case.name);
            println!("  dt (s)     axis horizontal at (s)   wall (s)   steps");
        }
        let mut times = Vec::new();
        for h in STEPS {
            let mut best = f64::INFINITY;
            let mut answer = (None, 0);
            for _ in 0..repeat.max(1) {
                let clock = Instant::now();
                answer = time_to_horizontal(case, h)?;
                best = best.min(clock.elapsed().as_secs_f64());
            }
            let (t, steps) = answer;
            let shown = t.map_or("never".to_string(), |t| format!("{t:.9}"));
            if csv {
                println!("{},{h:e},{shown},{best:.4},{steps}", case.name);
            } else {
                println!("  {h:<9.3e}  {shown:>22}   {best:>8.3}   {steps}");
            }
            times.push(t);
        }
        if let Some(line) = convergence(&times) {
            if csv {
                println!("# {}: {line}", case.name);
            } else {
                println!("  {line}");
            }
        }
        {
            let end = end_state(case);
            if csv {
                println!(
                    "# {}: at {END_TIME} s (dt = {END_STEP:e} s): {end}",
                    case.name
                );
            } else {
                println!("  after {END_TIME} s at dt = {END_STEP:e}: {end}");
            }
        }
    }
    Ok(())
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let csv = args.iter().any(|a| a == "--csv");
    let repeat = match args.iter().position(|a| a == "--repeat") {
        Some(i) => match args.get(i + 1).and_then(|r| r.parse::<usize>().ok()) {
            Some(r) => r,
            None => {
                eprintln!("error: --repeat takes a positive integer");
                return ExitCode::FAILURE;
            }
        },
        None => 1,
    };
    match run(csv, repeat) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
