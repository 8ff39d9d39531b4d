//! The physics of the demo: the handle's mass properties from its mesh, the
//! initial spin, the simulation (the handle as one body of a library
//! [`World`], moved by any free-body method the world knows; the demo only
//! observes it), the flips it shows and what theory predicts for them.
//!
//! Axes are numbered by size of moment, as in notes §3.7: 1 the minor,
//! 2 the intermediate, 3 the major principal axis (`I₁ < I₂ < I₃`).

use std::path::Path;

use glam::{DQuat, DVec3};
use kreisel::dynamics::{
    AxisStability, Body, BodyId, BodyState, EllipticMotion, FreeBodyMethod, PrincipalState,
    RigidBody, World, axis_stability, elliptic_motion,
};
use kreisel::inertia::io::SolidOptions;
use kreisel::inertia::{MassProperties, Material};

use super::DemoError;

/// The principal axis the handle is spun about.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum SpinAxis {
    /// Axis 1, the smallest moment: stable.
    Minor,
    /// Axis 2, the intermediate moment: unstable, the handle flips.
    Intermediate,
    /// Axis 3, the largest moment: stable.
    Major,
}

impl SpinAxis {
    /// Index of the axis in the principal frame (moments sorted ascending).
    pub fn index(self) -> usize {
        match self {
            Self::Minor => 0,
            Self::Intermediate => 1,
            Self::Major => 2,
        }
    }

    /// The word for the axis in the printed lines.
    pub fn name(self) -> &'static str {
        match self {
            Self::Minor => "minor",
            Self::Intermediate => "intermediate",
            Self::Major => "major",
        }
    }
}

/// The handle: its triangles about the centre of mass, and its inertia.
#[derive(Debug, Clone)]
pub struct Handle {
    /// The body's name in the mesh file (the names joined by ` + ` when the
    /// file holds several bodies).
    pub name: String,
    /// Vertices in body coordinates, relative to the centre of mass, m.
    pub vertices_body: Vec<DVec3>,
    /// Triangles (counter-clockwise seen from outside).
    pub triangles: Vec<[u32; 3]>,
    /// Mass, centre of mass (mesh coordinates) and inertia tensor.
    pub properties: MassProperties,
    /// Principal moments and frame.
    pub body: RigidBody,
}

impl Handle {
    /// Loads a mesh file as one solid of the given density (kg/m³), as
    /// `kreisel simulate` does: every body of the file, closed, together as
    /// one rigid handle (a file of one body is that body).
    ///
    /// # Errors
    /// The mesh file's errors (naming the file, and the body at fault), an
    /// open mesh, a non-positive density, an inertia tensor that is not a
    /// rigid body's, or more vertices than triangles can number.
    pub fn load(path: &Path, density: f64) -> Result<Self, DemoError> {
        let options = SolidOptions::new(Material::Density(density));
        let bodies = options.load_bodies(path)?;
        // The drawing: every body's triangles over one list of vertices, as loaded.
        let mut vertices: Vec<DVec3> = Vec::new();
        let mut triangles = Vec::new();
        for body in &bodies {
            let first = vertices.len() as u32;
            vertices.extend_from_slice(body.mesh.vertices());
            // Every index, `first + i < vertices.len()`, then fits in u32.
            if u32::try_from(vertices.len()).is_err() {
                return Err(DemoError::TooManyVertices {
                    path: path.to_path_buf(),
                });
            }
            triangles.extend(body.mesh.triangles().iter().map(|t| t.map(|i| i + first)));
        }
        let solid = options.solid(path, bodies)?;
        let properties = solid.properties;
        let rigid = RigidBody::from_mass_properties(&properties)?;
        let names: Vec<&str> = solid.bodies.iter().map(|b| b.name.as_str()).collect();
        let com = properties.center_of_mass;
        Ok(Self {
            name: names.join(" + "),
            vertices_body: vertices.into_iter().map(|v| v - com).collect(),
            triangles,
            properties,
            body: rigid,
        })
    }

    /// Principal moments `I₁ ≤ I₂ ≤ I₃`, kg·m².
    pub fn moments(&self) -> DVec3 {
        self.body.principal_moments()
    }

    /// Principal axis `index` as a unit vector in body (mesh) coordinates.
    pub fn principal_axis_body(&self, index: usize) -> DVec3 {
        self.body.body_from_principal() * DVec3::AXES[index]
    }
}

/// How the handle is thrown: spin rate about one principal axis, and the
/// angle by which ω is tilted off it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spin {
    /// The axis spun about.
    pub axis: SpinAxis,
    /// |ω| at t = 0, rad/s.
    pub rate: f64,
    /// Angle between ω and the axis at t = 0, rad; ω is tilted toward the
    /// next axis in the cycle minor → intermediate → major → minor.
    pub perturbation: f64,
}

impl Spin {
    /// ω at t = 0 in principal axes.
    ///
    /// ```text
    /// ω = Ω (cos ε eₖ + sin ε eₖ₊₁)
    /// ```
    pub fn omega_principal(&self) -> DVec3 {
        let k = self.axis.index();
        let mut omega = [0.0; 3];
        omega[k] = self.rate * self.perturbation.cos();
        omega[(k + 1) % 3] = self.rate * self.perturbation.sin();
        DVec3::from_array(omega)
    }

    /// The largest any component of ω can become during the motion, rad/s.
    ///
    /// ```text
    /// |ωₖ| ≤ min(|L|/Iₖ, √(2E/Iₖ))
    /// ```
    pub fn omega_bound(&self, moments: DVec3) -> f64 {
        let omega = self.omega_principal();
        let l = (omega * moments).length();
        let two_e = (omega * omega * moments).element_sum();
        (0..3)
            .map(|k| (l / moments[k]).min((two_e / moments[k]).sqrt()))
            .fold(0.0, f64::max)
    }

    /// The state at t = 0: ω as above, attitude chosen so that the
    /// (conserved) angular momentum points along world +z.
    pub fn initial_state(&self, moments: DVec3) -> PrincipalState {
        let l_principal = self.omega_principal() * moments;
        PrincipalState {
            world_from_principal: DQuat::from_rotation_arc(l_principal.normalize(), DVec3::Z),
            l_principal,
        }
    }
}

/// What the theory of notes §3.7 and the exact solution predict.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Prediction {
    /// Linear stability of the spin axis at the spin rate.
    pub stability: AxisStability,
    /// The exact elliptic motion (None only for a symmetric body or a
    /// spin exactly along an axis).
    pub motion: Option<EllipticMotion>,
    /// Whether the spin-axis component of ω changes sign at all: the
    /// angular momentum circulates about another axis.
    pub flips: bool,
}

impl Prediction {
    /// The prediction for `spin` of a body with sorted `moments`.
    pub fn new(moments: DVec3, spin: &Spin) -> Self {
        let motion = elliptic_motion(moments, spin.omega_principal() * moments);
        Self {
            stability: axis_stability(moments, spin.axis.index(), spin.rate),
            flips: motion.is_some_and(|m| m.axis != spin.axis.index()),
            motion,
        }
    }

    /// Time between flips (sign changes of ω along the spin axis), s,
    /// when the handle flips.
    pub fn flip_period(&self) -> Option<f64> {
        self.motion.filter(|_| self.flips).map(|m| m.half_period)
    }
}

/// A running simulation: the handle as one body of a [`World`] (its mass
/// properties, the thrown spin, the free-body method chosen), advanced by
/// the world's `step(dt)`; the flips seen so far and the drift of the
/// invariants are observed from the world's state after each step.
pub struct Simulation {
    world: World,
    id: BodyId,
    body: Body,
    method: FreeBodyMethod,
    rigid: RigidBody,
    axis: usize,
    dt: f64,
    previous: BodyState,
    energy0: f64,
    l0: f64,
    l_world0: DVec3,
    /// Instants of the flips so far, s.
    pub flips: Vec<f64>,
    /// Largest |E − E₀|/E₀ so far.
    pub energy_drift: f64,
    /// Largest ||L| − |L₀||/|L₀| so far.
    pub l_drift: f64,
    /// Largest |L_world − L_world₀|/|L₀| so far (a fixed vector in space).
    pub l_world_drift: f64,
}

impl Simulation {
    /// Starts at t = 0 from `spin`: a world without gravity holding the
    /// handle, moved by `method` in steps of `dt`.
    ///
    /// # Errors
    /// [`DemoError::Dynamics`]: a step or state the world refuses.
    pub fn new(
        method: FreeBodyMethod,
        handle: &Handle,
        spin: &Spin,
        dt: f64,
    ) -> Result<Self, DemoError> {
        let rigid = handle.body;
        let state = spin.initial_state(rigid.principal_moments());
        let body = Body::from_mass_properties(handle.properties)
            .world_from_body(state.world_from_body(&rigid))
            .omega_body(state.omega_body(&rigid))
            .try_build()?;
        let (world, id) = world_of(&body, method, dt)?;
        let now = world.state(id).expect("the body just added");
        Ok(Self {
            world,
            id,
            body,
            method,
            rigid,
            axis: spin.axis.index(),
            dt,
            previous: now,
            energy0: now.energy,
            l0: (state_l(&rigid, &now)).length(),
            l_world0: now.l_world,
            flips: Vec::new(),
            energy_drift: 0.0,
            l_drift: 0.0,
            l_world_drift: 0.0,
        })
    }

    /// Simulated time, s.
    pub fn time(&self) -> f64 {
        self.world.time()
    }

    /// Index of the spin axis (whose sign changes are the flips).
    pub fn spin_axis(&self) -> usize {
        self.axis
    }

    /// The time step, s.
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// The current state, as the world reports it.
    pub fn state(&self) -> BodyState {
        self.previous
    }

    /// ω in principal axes now, rad/s.
    pub fn omega_principal(&self) -> DVec3 {
        self.principal(&self.previous)
    }

    /// ω of `state` in principal axes, rad/s.
    fn principal(&self, state: &BodyState) -> DVec3 {
        self.rigid.body_from_principal().conjugate() * state.omega_body
    }

    /// Advances the world one step; records a flip when ω along the spin
    /// axis changed sign during it.
    ///
    /// # Errors
    /// [`DemoError::Dynamics`] when the world's step fails or diverges.
    pub fn step(&mut self) -> Result<(), DemoError> {
        let t0 = self.time();
        self.world.step(self.dt)?;
        let now = self.world.state(self.id).expect("the body of this world");
        let (a, b) = (
            self.principal(&self.previous)[self.axis],
            self.principal(&now)[self.axis],
        );
        if (a < 0.0) != (b < 0.0) && a != 0.0 {
            let tau = self.crossing(&self.previous, a / (a - b))?;
            self.flips.push(t0 + tau);
        }
        self.previous = now;
        self.energy_drift = self
            .energy_drift
            .max((now.energy - self.energy0).abs() / self.energy0);
        self.l_drift = self
            .l_drift
            .max((state_l(&self.rigid, &now).length() - self.l0).abs() / self.l0);
        self.l_world_drift = self
            .l_world_drift
            .max((now.l_world - self.l_world0).length() / self.l0);
        Ok(())
    }

    /// The time within the step from `start` at which ω along the spin
    /// axis vanishes (`fraction` of the step by linear interpolation of its
    /// ends): Newton's method on `Lₖ(τ)`, each evaluation a world of the
    /// same body and method taken from `start` by one step of length τ,
    /// with `L̇ = L × ω` (Euler's equations) as the derivative, safeguarded
    /// by bisection.
    fn crossing(&self, start: &BodyState, fraction: f64) -> Result<f64, DemoError> {
        let k = self.axis;
        let moments = self.rigid.principal_moments();
        let from = Body::from_mass_properties(*self.body.mass_properties())
            .world_from_body(start.world_from_body)
            .omega_body(start.omega_body)
            .try_build()?;
        let at = |tau: f64| -> Result<(f64, f64), DemoError> {
            let (mut world, id) = world_of(&from, self.method, self.dt)?;
            if tau > 0.0 {
                world.step(tau)?;
            }
            let omega = self.principal(&world.state(id).expect("the body of this world"));
            let l = omega * moments;
            Ok((l[k], l.cross(omega)[k]))
        };
        let f_start = self.principal(start)[k];
        let (mut lo, mut hi) = (0.0, self.dt);
        // Start from the linear interpolation between the step's ends.
        let mut tau = self.dt * fraction;
        for _ in 0..60 {
            let (f, df) = at(tau)?;
            if f == 0.0 {
                return Ok(tau);
            }
            if (f < 0.0) == (f_start < 0.0) {
                lo = tau;
            } else {
                hi = tau;
            }
            let newton = tau - f / df;
            let next = if newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            if (next - tau).abs() <= 1e-15 * self.dt.max(tau) || hi - lo <= 1e-15 * self.dt {
                return Ok(next);
            }
            tau = next;
        }
        Ok(tau)
    }

    /// The flip period measured so far: the mean time between successive
    /// flips, when there have been at least two.
    pub fn measured_flip_period(&self) -> Option<f64> {
        match (self.flips.first(), self.flips.last()) {
            (Some(first), Some(last)) if self.flips.len() >= 2 => {
                Some((last - first) / (self.flips.len() - 1) as f64)
            }
            _ => None,
        }
    }
}

/// L in principal axes, kg·m²/s.
fn state_l(rigid: &RigidBody, state: &BodyState) -> DVec3 {
    rigid.principal_moments() * (rigid.body_from_principal().conjugate() * state.omega_body)
}

/// A world without gravity, stepping by `dt`, moving `body` by `method`.
fn world_of(body: &Body, method: FreeBodyMethod, dt: f64) -> Result<(World, BodyId), DemoError> {
    let mut world = World::try_new(DVec3::ZERO, dt)?;
    world.set_free_body_method(method)?;
    let id = world.add(body.clone())?;
    Ok((world, id))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn handle() -> Handle {
        Handle::load(Path::new(super::super::options::DEFAULT_MESH), 7850.0).unwrap()
    }

    /// A file of two unit cubes, one at the origin and one 2 m along x:
    /// one rigid handle of both, drawn with every triangle.
    #[test]
    fn a_file_of_several_bodies_is_one_handle() {
        let faces = [
            [0, 2, 3],
            [0, 3, 1],
            [4, 5, 7],
            [4, 7, 6],
            [0, 1, 5],
            [0, 5, 4],
            [2, 6, 7],
            [2, 7, 3],
            [0, 4, 6],
            [0, 6, 2],
            [1, 3, 7],
            [1, 7, 5],
        ];
        let mut obj = String::new();
        for (name, x, first) in [("a", 0, 1), ("b", 2, 9)] {
            obj += &format!("o {name}\n");
            for i in 0..8 {
                obj += &format!("v {} {} {}\n", x + (i & 1), (i >> 1) & 1, (i >> 2) & 1);
            }
            for [p, q, r] in faces {
                obj += &format!("f {} {} {}\n", p + first, q + first, r + first);
            }
        }
        let dir = std::env::temp_dir().join(format!("dzhanibekov-handle-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("two.obj");
        std::fs::write(&path, obj).unwrap();
        let h = Handle::load(&path, 1000.0).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        assert_eq!(h.name, "a + b");
        assert_eq!((h.vertices_body.len(), h.triangles.len()), (16, 24));
        assert!(h.triangles.iter().flatten().all(|&i| i < 16));
        // m = 2 ρ, c = (1.5, 0.5, 0.5); each cube I = ρ/6 about its centre,
        // the centres 1 m from c along x: I_yy = I_zz = 2 (ρ/6 + ρ · 1²).
        let rho = 1000.0;
        assert!((h.properties.mass - 2.0 * rho).abs() < 1e-12);
        assert!((h.properties.center_of_mass - DVec3::new(1.5, 0.5, 0.5)).length() < 1e-14);
        let want = DVec3::new(rho / 3.0, 2.0 * (rho / 6.0 + rho), 2.0 * (rho / 6.0 + rho));
        assert!(
            (h.moments() - want).abs().max_element() < 1e-10,
            "{}",
            h.moments()
        );
        let mean = h.vertices_body.iter().sum::<DVec3>() / 16.0;
        assert!(mean.length() < 1e-14);
    }

    #[test]
    fn the_handle_is_the_asset_in_steel() {
        let h = handle();
        // assets/README.md: 0.1297 kg, (3.698e-05, 8.412e-05, 4.997e-05) kg·m² along x, y, z.
        assert!((h.properties.mass - 1.652e-5 * 7850.0).abs() < 1e-15);
        let m = h.moments();
        for (got, want) in [(m.x, 3.698e-5), (m.y, 4.997e-5), (m.z, 8.412e-5)] {
            assert!((got / want - 1.0).abs() < 2e-4, "{got} vs {want}");
        }
        // The intermediate axis is the stem (mesh z), the vertices are about the centre of mass.
        assert!(h.principal_axis_body(1).z.abs() > 1.0 - 1e-12);
        let mean = h.vertices_body.iter().sum::<DVec3>() / h.vertices_body.len() as f64;
        assert!(mean.x.abs() < 1e-12 && mean.y.abs() < 1e-12);
    }

    #[test]
    fn the_spin_is_what_the_options_say() {
        let moments = handle().moments();
        for axis in [SpinAxis::Minor, SpinAxis::Intermediate, SpinAxis::Major] {
            let spin = Spin {
                axis,
                rate: 5.0,
                perturbation: 0.1,
            };
            let omega = spin.omega_principal();
            assert!((omega.length() - 5.0).abs() < 1e-14);
            let e = DVec3::AXES[axis.index()];
            assert!((omega.angle_between(e) - 0.1).abs() < 1e-14);
            let s = spin.initial_state(moments);
            let l_world = s.l_world();
            assert!(l_world.normalize().dot(DVec3::Z) > 1.0 - 1e-15);
            assert!(
                (l_world.length() - (omega * moments).length()).abs() < 1e-15 * l_world.length()
            );
            let prediction = Prediction::new(moments, &spin);
            assert_eq!(prediction.flips, axis == SpinAxis::Intermediate);
            assert_eq!(
                prediction.flip_period().is_some(),
                axis == SpinAxis::Intermediate
            );
        }
    }

    #[test]
    fn omega_stays_within_its_bound_and_flips_are_sign_changes() {
        let h = handle();
        let spin = Spin {
            axis: SpinAxis::Intermediate,
            rate: 6.0,
            perturbation: 0.05,
        };
        let bound = spin.omega_bound(h.moments());
        let mut sim = Simulation::new(FreeBodyMethod::Exact, &h, &spin, 1e-2).unwrap();
        let mut largest: f64 = 0.0;
        let mut sign = sim.omega_principal().y.signum();
        let mut changes = 0;
        while sim.time() < 10.0 {
            sim.step().unwrap();
            let omega = sim.omega_principal();
            largest = largest.max(omega.abs().max_element());
            if omega.y.signum() != sign {
                sign = omega.y.signum();
                changes += 1;
            }
        }
        assert!(largest <= bound * (1.0 + 1e-12), "{largest} > {bound}");
        // Not a loose bound: the chart scaled by it is mostly used.
        assert!(largest > 0.8 * bound, "{largest} vs {bound}");
        assert_eq!(sim.flips.len(), changes);
        assert!(sim.flips.windows(2).all(|w| w[1] > w[0]));
        assert!(sim.energy_drift < 1e-13 && sim.l_drift < 1e-13);
    }
}
