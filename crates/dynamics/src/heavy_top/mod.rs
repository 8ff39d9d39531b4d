//! The heavy top: a rigid body turning about a fixed pivot in uniform
//! gravity (notes §3.10 for the symmetric case; here any inertia tensor and
//! any centre of mass), and its integrators.

mod auto;
mod free_flow;
mod rk4;
mod splitting;
mod taylor;

use glam::{DQuat, DVec3};
use kreisel_inertia::MassProperties;

pub use self::auto::{HeavyTopAuto, MAX_SUBSTEPS};
pub use self::rk4::HeavyTopRk4;
pub use self::splitting::HeavyTopSplitting;
pub use self::taylor::{HeavyTopTaylor, TAYLOR_MAX_ORDER};

pub(crate) use self::free_flow::FreeFlow;
use crate::{DynamicsError, PrincipalState, RigidBody};

/// A rigid body on a fixed pivot in uniform gravity.
///
/// States are [`PrincipalState`]s in the principal frame of the inertia
/// tensor **about the pivot**, with `l_principal` the angular momentum about
/// the pivot; the pivot is the world origin.
///
/// ```text
/// H = ½ L·J⁻¹L + V(q),   V = −W·(R c),   W = M g_world
/// L̇ = L × ω + c × (Rᵀ W),   q̇ = ½ q ⊗ (0, ω),   ω = J⁻¹ L
/// ```
/// (`J` the inertia about the pivot, `c` the centre of mass seen from the
/// pivot in principal axes, `R` the rotation of `q`; notes §3.10, Goldstein
/// ch. 5.7, Landau & Lifshitz §35.)
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{HeavyTop, PrincipalState};
/// // A symmetric top, 1 kg, centre of mass 0.1 m above the pivot along e₃.
/// let top = HeavyTop::try_from_principal(DVec3::new(0.02, 0.02, 0.01), DVec3::new(0.0, 0.0, 0.1), 1.0, DVec3::new(0.0, 0.0, -9.81))?;
/// let s = PrincipalState { world_from_principal: DQuat::IDENTITY, l_principal: DVec3::new(0.0, 0.0, 1.0) };
/// // Upright: potential energy M g l = 0.981 J, kinetic L²/2I₃ = 50 J.
/// assert!((top.energy(&s) - 50.981).abs() < 1e-12);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone)]
pub struct HeavyTop {
    body: RigidBody,
    com_principal: DVec3,
    weight_world: DVec3,
    free: FreeFlow,
}

/// A typed error for a bad heavy-top parameter.
fn invalid(parameter: &'static str, value: f64, reason: &'static str) -> DynamicsError {
    DynamicsError::InvalidTop {
        parameter,
        value,
        reason,
    }
}

/// Checks that every component of `v` is finite.
fn check_finite(parameter: &'static str, v: DVec3) -> Result<(), DynamicsError> {
    match v.to_array().into_iter().find(|x| !x.is_finite()) {
        Some(x) => Err(invalid(parameter, x, "must be finite")),
        None => Ok(()),
    }
}

impl HeavyTop {
    /// A heavy top from its principal moments about the pivot, the centre of
    /// mass seen from the pivot in the same principal axes, its mass and
    /// the gravitational acceleration in world axes.
    ///
    /// ```text
    /// J = diag(J₁, J₂, J₃) about the pivot,   W = M g_world
    /// ```
    ///
    /// # Errors
    /// [`DynamicsError::UnphysicalInertia`] for moments that no body has;
    /// [`DynamicsError::InvalidTop`] for a mass that is not positive and
    /// finite or a non-finite vector.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::HeavyTop;
    /// let g = DVec3::new(0.0, 0.0, -9.81);
    /// assert!(HeavyTop::try_from_principal(DVec3::new(2.0, 2.0, 1.0), DVec3::Z, 1.0, g).is_ok());
    /// assert!(HeavyTop::try_from_principal(DVec3::new(2.0, 2.0, 1.0), DVec3::Z, -1.0, g).is_err());
    /// ```
    pub fn try_from_principal(
        moments_about_pivot: DVec3,
        com_principal: DVec3,
        mass: f64,
        gravity_world: DVec3,
    ) -> Result<Self, DynamicsError> {
        let body = RigidBody::try_from_principal_moments(moments_about_pivot)?;
        Self::from_parts(body, com_principal, mass, gravity_world)
    }

    /// As [`HeavyTop::try_from_principal`].
    ///
    /// # Panics
    /// Where [`HeavyTop::try_from_principal`] returns an error.
    pub fn from_principal(
        moments_about_pivot: DVec3,
        com_principal: DVec3,
        mass: f64,
        gravity_world: DVec3,
    ) -> Self {
        match Self::try_from_principal(moments_about_pivot, com_principal, mass, gravity_world) {
            Ok(top) => top,
            Err(e) => panic!("{e}"),
        }
    }

    /// A heavy top from mass properties about the centre of mass (body
    /// axes) and the pivot in body coordinates.
    ///
    /// ```text
    /// J = I_cm + M (|c|² 1 − c cᵀ),   c = com − pivot   (parallel-axis theorem, notes §3.4)
    /// ```
    ///
    /// Components of `c` in principal axes within `4ε|c|` of zero (the
    /// rounding of the principal-axes rotation) are set to zero.
    ///
    /// # Errors
    /// As [`HeavyTop::try_from_principal`], and
    /// [`DynamicsError::InertiaTensor`] for mass properties that do not
    /// validate.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::HeavyTop;
    /// use kreisel_inertia::MassProperties;
    /// // Bruls, Cardona & Arnold (2012): 15 kg, centre of mass 1 m along body y.
    /// let cm = MassProperties::try_new(15.0, DVec3::new(0.0, 1.0, 0.0),
    ///     glam::DMat3::from_diagonal(DVec3::new(0.234375, 0.46875, 0.234375)))?;
    /// let top = HeavyTop::try_new(&cm, DVec3::ZERO, DVec3::new(0.0, 0.0, -9.81)).unwrap();
    /// assert_eq!(top.body().principal_moments(), DVec3::new(0.46875, 15.234375, 15.234375));
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn try_new(
        mass_properties: &MassProperties,
        pivot_body: DVec3,
        gravity_world: DVec3,
    ) -> Result<Self, DynamicsError> {
        check_finite("pivot", pivot_body)?;
        mass_properties.validate()?;
        let about_pivot = MassProperties {
            center_of_mass: pivot_body,
            inertia: mass_properties.inertia_about_point(pivot_body),
            ..*mass_properties
        };
        let body = RigidBody::from_mass_properties(&about_pivot)?;
        let com_body = mass_properties.center_of_mass - pivot_body;
        let com_principal = body.body_from_principal().conjugate() * com_body;
        // The principal frame is known to rounding only: components of c
        // within a few ulps of zero are rounding of that rotation (e.g.
        // −2.2e-16 for a centre of mass exactly on the symmetry axis), and
        // zeroing them lets a Lagrange top be recognised as one.
        let ulps = 4.0 * f64::EPSILON * com_principal.length();
        let com_principal = DVec3::select(
            com_principal.abs().cmple(DVec3::splat(ulps)),
            DVec3::ZERO,
            com_principal,
        );
        Self::from_parts(body, com_principal, mass_properties.mass, gravity_world)
    }

    fn from_parts(
        body: RigidBody,
        com_principal: DVec3,
        mass: f64,
        gravity_world: DVec3,
    ) -> Result<Self, DynamicsError> {
        if !(mass.is_finite() && mass > 0.0) {
            return Err(invalid("mass", mass, "must be positive and finite"));
        }
        check_finite("centre of mass", com_principal)?;
        check_finite("gravity", gravity_world)?;
        check_finite("weight (mass times gravity)", gravity_world * mass)?;
        let potential = (gravity_world * mass).length() * com_principal.length();
        if !potential.is_finite() {
            return Err(invalid(
                "largest potential energy |M g| |c|",
                potential,
                "must be finite (it overflows)",
            ));
        }
        Ok(Self {
            free: FreeFlow::for_moments(body.principal_moments()),
            body,
            com_principal,
            weight_world: gravity_world * mass,
        })
    }

    /// The rotational inertia about the pivot: principal moments and the
    /// principal frame in body axes.
    pub fn body(&self) -> &RigidBody {
        &self.body
    }

    /// The centre of mass seen from the pivot, in principal axes, m.
    pub fn com_principal(&self) -> DVec3 {
        self.com_principal
    }

    /// The weight `M g_world`, N.
    pub fn weight_world(&self) -> DVec3 {
        self.weight_world
    }

    /// The principal axis `k` about which the top is symmetric with its
    /// centre of mass on that axis (a Lagrange top), if any: then `L_k` is
    /// conserved (`p_ψ`, notes §3.10).
    ///
    /// ```text
    /// J_i = J_j (i, j ≠ k)  and  c ∥ e_k
    /// ```
    pub fn symmetry_axis(&self) -> Option<usize> {
        let j = self.body.principal_moments().to_array();
        let c = self.com_principal.to_array();
        (0..3).find(|&k| {
            let (a, b) = ((k + 1) % 3, (k + 2) % 3);
            j[a] == j[b] && c[a] == 0.0 && c[b] == 0.0
        })
    }

    /// The gravity torque about the pivot, in principal axes.
    ///
    /// ```text
    /// τ = c × (Rᵀ W)
    /// ```
    #[inline]
    pub fn torque_principal(&self, world_from_principal: DQuat) -> DVec3 {
        let weight_principal = world_from_principal.normalize().conjugate() * self.weight_world;
        self.com_principal.cross(weight_principal)
    }

    /// The potential energy, zero when the centre of mass is level with the
    /// pivot.
    ///
    /// ```text
    /// V = −W·(R c)
    /// ```
    pub fn potential_energy(&self, world_from_principal: DQuat) -> f64 {
        -self
            .weight_world
            .dot(world_from_principal.normalize() * self.com_principal)
    }

    /// The total energy, conserved.
    ///
    /// ```text
    /// E = ½ Σ Lₖ²/Jₖ − W·(R c)
    /// ```
    pub fn energy(&self, state: &PrincipalState) -> f64 {
        state.energy(&self.body) + self.potential_energy(state.world_from_principal)
    }

    /// The angular momentum about the vertical through the pivot, conserved
    /// (`p_φ` of notes §3.10; zero gravity: every component is conserved and
    /// this is the world `z` component).
    ///
    /// ```text
    /// L_v = L_world · ĝ_up,   ĝ_up = −W/|W|
    /// ```
    pub fn vertical_momentum(&self, state: &PrincipalState) -> f64 {
        let up = -self.weight_world.normalize_or(DVec3::NEG_Z);
        state.l_world().dot(up)
    }

    /// The fastest small swing under gravity: the rate the gravity kicks
    /// must resolve. Gravity turns the body about axes perpendicular to `c`
    /// only, so the moments about those axes set it.
    ///
    /// ```text
    /// Ω_g² = |W| |c| max{ nᵀ J⁻¹ n : |n| = 1, n ⟂ c }
    /// ```
    /// (the small-swing frequency `√(M g l / J)` of a pendulum, taken for
    /// the axis perpendicular to `c` with the smallest moment).
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::HeavyTop;
    /// // A thin rod pendulum about its end: J = m l²/3 about the swing axes.
    /// let (m, l) = (1.0, 0.5);
    /// let j = m * l * l / 3.0;
    /// let top = HeavyTop::try_from_principal(DVec3::new(j, j, 1e-6), DVec3::new(0.0, 0.0, -l / 2.0), m, DVec3::new(0.0, 0.0, -9.81))?;
    /// assert!((top.gravity_frequency() - (9.81 * m * l / 2.0 / j).sqrt()).abs() < 1e-12);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn gravity_frequency(&self) -> f64 {
        let c = self.com_principal;
        let Some(axis) = c.try_normalize() else {
            return 0.0;
        };
        let inverse = 1.0 / self.body.principal_moments();
        let u = axis.any_orthonormal_vector();
        let v = axis.cross(u);
        let (a, b, d) = (
            (u * u * inverse).element_sum(),
            (u * v * inverse).element_sum(),
            (v * v * inverse).element_sum(),
        );
        let largest = 0.5 * (a + d) + (0.25 * (a - d) * (a - d) + b * b).sqrt();
        (self.weight_world.length() * c.length() * largest).sqrt()
    }

    /// An upper bound on `|ω|` over the whole motion from `state`, from the
    /// conserved energy.
    ///
    /// ```text
    /// |ω|² ≤ 2T/J_min,   T = E − V ≤ E + |W| |c|
    /// ```
    pub fn angular_speed_bound(&self, state: &PrincipalState) -> f64 {
        let j_min = self.body.principal_moments().min_element();
        let t_max = self.energy(state) + self.weight_world.length() * self.com_principal.length();
        (2.0 * t_max.max(0.0) / j_min).sqrt()
    }

    /// An upper bound on how fast gravity can swing the body, over the whole
    /// motion from `state`: for a Lagrange top (symmetric about `k`, centre
    /// of mass on that axis) the rate of its axis, since the spin about the
    /// axis (`L_k` conserved) plays no part in the swing; for any other top
    /// [`HeavyTop::angular_speed_bound`].
    ///
    /// ```text
    /// Lagrange top:  ω_swing² = 2 (E + |W||c| − L_k²/2J_k) / J⊥
    /// otherwise:     ω_swing = ω_max
    /// ```
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_dynamics::{HeavyTop, PrincipalState};
    /// // A pendulum (1 kg, 1 m, J⊥ = 1) let go at rest from the top swings
    /// // through the bottom at √(2 · 2 · 9.81) rad/s.
    /// let top = HeavyTop::try_from_principal(DVec3::new(1.0, 1.0, 0.01), DVec3::Z, 1.0, DVec3::new(0.0, 0.0, -9.81))?;
    /// let s = PrincipalState { world_from_principal: DQuat::IDENTITY, l_principal: DVec3::ZERO };
    /// assert!((top.swing_rate_bound(&s) - (4.0f64 * 9.81).sqrt()).abs() < 1e-12);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn swing_rate_bound(&self, state: &PrincipalState) -> f64 {
        let Some(k) = self.symmetry_axis() else {
            return self.angular_speed_bound(state);
        };
        let j = self.body.principal_moments().to_array();
        let spin = 0.5 * state.l_principal[k] * state.l_principal[k] / j[k];
        let potential = self.weight_world.length() * self.com_principal.length();
        let swing = self.energy(state) - spin + potential;
        (2.0 * swing.max(0.0) / j[(k + 1) % 3]).sqrt()
    }

    /// Whether the free flow is exact (two equal moments) rather than PDMV10.
    pub fn free_flow_is_exact(&self) -> bool {
        matches!(self.free, FreeFlow::Symmetric { .. })
    }

    /// The exact flow of the gravity part `V(q)` for time `h`: the attitude
    /// stands still, the torque is constant.
    ///
    /// ```text
    /// L ← L + h c × (Rᵀ W)
    /// ```
    #[inline]
    pub(crate) fn kick(&self, state: &mut PrincipalState, h: f64) {
        state.l_principal += self.torque_principal(state.world_from_principal) * h;
    }

    /// The flow of the kinetic part `½ L·J⁻¹L` (the free body) for time `h`.
    #[inline]
    pub(crate) fn free_flow(&self, state: &mut PrincipalState, h: f64) {
        self.free.apply(self.body.principal_moments(), state, h);
    }
}
