//! The equations of motion of a rigid body touching the ground plane with
//! one body-fixed sphere or disk rim: the state, the normal force solved
//! from the constraint, and the invariants.

use glam::{DMat3, DQuat, DVec2, DVec3};

use super::applied_loads::AppliedLoads;
use super::{ContactShape, Friction, SphereContact};
use crate::DynamicsError;

/// A rigid body whose sphere (or disk rim, [`GroundTop::try_with_shape`])
/// touches the plane `z = 0`, gravity `−g ẑ`. For a sphere:
///
/// ```text
/// m v̇_G = N ẑ + F − m g ẑ,   L̇ = ρ × (N ẑ + F),   q̇ = ½ (0, ω) ⊗ q
/// ω = A I⁻¹ Aᵀ L,   ρ = A c − R ẑ,   F = N f(v_P),   v_P = v_G + ω × ρ
/// N = [g − ((I_w⁻¹ (L × ω)) × A c)_z − (ω × (ω × A c))_z]
///     / [1/m + ((I_w⁻¹ (ρ × (ẑ + f))) × A c)_z]
/// ```
///
/// (`I` the inertia tensor about the centre of mass in body axes, `A` the
/// rotation of the attitude, `L` the angular momentum about the centre of
/// mass in world axes; the derivation is in the module docs,
/// [`crate::contact`].)
///
/// ```
/// use glam::{DMat3, DQuat, DVec2, DVec3};
/// use kreisel_dynamics::{Friction, GroundTop, SphereContact};
/// // Leine & Glocker's tippe top, resting upright: N = m g.
/// let sphere = SphereContact::try_new(0.015, DVec3::new(0.0, 0.0, 0.003))?;
/// let inertia = DMat3::from_diagonal(DVec3::new(8e-7, 8e-7, 7e-7));
/// let top = GroundTop::try_new(0.006, inertia, sphere, Friction::try_viscous(0.3)?, 9.81)?;
/// let s = top.try_state_on_ground(DQuat::IDENTITY, DVec3::ZERO, DVec2::ZERO)?;
/// assert!((top.normal_force(&s)? - 0.006 * 9.81).abs() < 1e-15);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct GroundTop {
    mass: f64,
    inertia_body: DMat3,
    pub(super) inverse_inertia_body: DMat3,
    gravity: f64,
    shape: ContactShape,
    friction: Friction,
    /// Further shapes watched for touchdown (at most
    /// [`super::MAX_OTHER_CONTACTS`]).
    pub(super) others: Vec<ContactShape>,
    /// Applied torques and forces ([`GroundTop::try_with_inputs`]).
    pub(super) loads: Option<AppliedLoads>,
}

/// The state of a [`GroundTop`]: centre of mass, its velocity, attitude
/// and angular momentum about the centre of mass, all in world axes.
///
/// The attitude is not renormalised by the integrator (the crate's rule for
/// its Runge–Kutta methods); every function reads it through `q/|q|`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GroundTopState {
    /// The centre of mass `r_G`, m.
    pub com_world: DVec3,
    /// Its velocity `v_G`, m/s.
    pub velocity_world: DVec3,
    /// The attitude, body → world.
    pub world_from_body: DQuat,
    /// The angular momentum about the centre of mass `L`, kg·m²/s.
    pub l_world: DVec3,
}

/// The time derivative of a [`GroundTopState`], with the normal force that
/// produced it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Rates {
    pub(crate) d_com: DVec3,
    pub(crate) d_velocity: DVec3,
    pub(crate) d_attitude: DQuat,
    pub(crate) d_l: DVec3,
    /// `N`, newtons.
    pub(crate) normal_force: f64,
    /// The whole contact force `N ẑ + F`, world axes, newtons.
    pub(crate) contact_force: DVec3,
    /// The coefficient of `N` in the constraint's second derivative, 1/kg;
    /// not positive means no normal force can keep the contact (Painlevé).
    pub(crate) compliance: f64,
}

impl GroundTopState {
    /// `self + h · rates`, component by component.
    pub(crate) fn plus(&self, rates: &Rates, h: f64) -> Self {
        Self {
            com_world: self.com_world + rates.d_com * h,
            velocity_world: self.velocity_world + rates.d_velocity * h,
            world_from_body: self.world_from_body + rates.d_attitude * h,
            l_world: self.l_world + rates.d_l * h,
        }
    }

    /// Whether every component is finite and the attitude is not zero.
    pub fn is_valid(&self) -> bool {
        self.com_world.is_finite()
            && self.velocity_world.is_finite()
            && self.world_from_body.is_finite()
            && self.l_world.is_finite()
            && self.world_from_body.length_squared() > 0.0
    }
}

/// A typed error for a bad contact parameter.
fn invalid(parameter: &'static str, value: f64, reason: &'static str) -> DynamicsError {
    DynamicsError::InvalidContact {
        parameter,
        value,
        reason,
    }
}

/// Checks a body's mass, inertia tensor about its centre of mass (body
/// axes) and gravity: each positive and finite, the tensor symmetric and
/// positive definite.
///
/// # Errors
/// [`DynamicsError::InvalidContact`] naming `"mass"`, `"gravity"` or
/// `"inertia"`.
pub(crate) fn check_mass_properties(
    mass: f64,
    m: DMat3,
    gravity: f64,
) -> Result<(), DynamicsError> {
    if !(mass.is_finite() && mass > 0.0) {
        return Err(invalid("mass", mass, "must be positive and finite"));
    }
    if !(gravity.is_finite() && gravity > 0.0) {
        return Err(invalid(
            "gravity",
            gravity,
            "must be positive and finite (gravity along −z)",
        ));
    }
    if let Some(x) = m.to_cols_array().into_iter().find(|x| !x.is_finite()) {
        return Err(invalid("inertia", x, "must be finite"));
    }
    let asym = (m - m.transpose()).abs().to_cols_array();
    let scale = m.abs().to_cols_array().into_iter().fold(0.0, f64::max);
    if let Some(x) = asym.into_iter().find(|x| *x > 1e-12 * scale) {
        return Err(invalid("inertia", x, "must be symmetric"));
    }
    // Sylvester's criterion: the leading minors are positive.
    let minors = [
        m.x_axis.x,
        m.x_axis.x * m.y_axis.y - m.x_axis.y * m.y_axis.x,
        m.determinant(),
    ];
    if let Some(x) = minors.into_iter().find(|x| *x <= 0.0) {
        return Err(invalid(
            "inertia",
            x,
            "must be positive definite (a leading minor is not positive)",
        ));
    }
    Ok(())
}

impl GroundTop {
    /// A body of `mass` kg with inertia tensor `inertia_body` about its
    /// centre of mass (body axes), touching with `sphere`, under gravity
    /// `g` m/s² along −z.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidContact`] for a mass or `g` that is not
    /// positive and finite, an inertia tensor that is not finite, symmetric
    /// and positive definite, or bad friction parameters
    /// ([`Friction::validate`]).
    ///
    /// ```
    /// use glam::{DMat3, DVec3};
    /// use kreisel_dynamics::{Friction, GroundTop, SphereContact};
    /// let sphere = SphereContact::try_new(0.015, DVec3::new(0.0, 0.0, 0.003))?;
    /// let i = DMat3::from_diagonal(DVec3::new(8e-7, 8e-7, 7e-7));
    /// assert!(GroundTop::try_new(0.006, i, sphere, Friction::None, 9.81).is_ok());
    /// assert!(GroundTop::try_new(0.006, -i, sphere, Friction::None, 9.81).is_err());
    /// assert!(GroundTop::try_new(0.006, i, sphere, Friction::Viscous { mu: -0.3 }, 9.81).is_err());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_new(
        mass: f64,
        inertia_body: DMat3,
        sphere: SphereContact,
        friction: Friction,
        gravity: f64,
    ) -> Result<Self, DynamicsError> {
        Self::try_with_shape(
            mass,
            inertia_body,
            ContactShape::Sphere(sphere),
            friction,
            gravity,
        )
    }

    /// A body touching with any [`ContactShape`] (a sphere or a disk rim);
    /// otherwise as [`GroundTop::try_new`].
    ///
    /// # Errors
    /// As [`GroundTop::try_new`].
    ///
    /// ```
    /// use glam::{DMat3, DVec3};
    /// use kreisel_dynamics::{ContactShape, DiskContact, Friction, GroundTop};
    /// // A coin: 5 g, radius 1 cm, axis e₃.
    /// let (m, a) = (0.005, 0.01);
    /// let rim = DiskContact::try_new(a, DVec3::ZERO, DVec3::Z)?;
    /// let i = DMat3::from_diagonal(DVec3::new(0.25, 0.25, 0.5) * m * a * a);
    /// let coin = GroundTop::try_with_shape(m, i, ContactShape::Disk(rim), Friction::Rolling, 9.81)?;
    /// assert!(coin.sphere().is_none());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_with_shape(
        mass: f64,
        inertia_body: DMat3,
        shape: ContactShape,
        friction: Friction,
        gravity: f64,
    ) -> Result<Self, DynamicsError> {
        check_mass_properties(mass, inertia_body, gravity)?;
        friction.validate()?;
        let m = inertia_body;
        Ok(Self {
            mass,
            inertia_body: m,
            inverse_inertia_body: m.inverse(),
            gravity,
            shape,
            friction,
            others: Vec::new(),
            loads: None,
        })
    }

    /// The mass `m`, kg.
    pub fn mass(&self) -> f64 {
        self.mass
    }

    /// The inertia tensor `I` about the centre of mass, body axes, kg·m².
    pub fn inertia_body(&self) -> DMat3 {
        self.inertia_body
    }

    /// `g`, m/s² (gravity is `−g ẑ`).
    pub fn gravity(&self) -> f64 {
        self.gravity
    }

    /// The contact sphere (`None` for a disk rim or an ellipsoid).
    pub fn sphere(&self) -> Option<SphereContact> {
        match self.shape {
            ContactShape::Sphere(s) => Some(s),
            ContactShape::Disk(_) | ContactShape::Ellipsoid(_) => None,
        }
    }

    /// The contact surface.
    pub fn shape(&self) -> ContactShape {
        self.shape
    }

    /// The friction model.
    pub fn friction(&self) -> Friction {
        self.friction
    }

    /// A state touching the plane: attitude `world_from_body`, angular
    /// velocity `omega_world`, horizontal centre-of-mass velocity
    /// `velocity_xy`; the centre of mass above the origin at the height
    /// where the sphere touches, its vertical velocity the one that keeps
    /// the contact point on the plane.
    ///
    /// ```text
    /// z_G = −ρ_z,   ż_G = −(ω × ρ)_z,   L = A I Aᵀ ω
    /// (a sphere: ρ_z = (A c)_z − R, (ω × ρ)_z = (ω × A c)_z)
    /// ```
    ///
    /// With [`Friction::Rolling`] the velocities must already satisfy the
    /// rolling constraint `v_P = v_G + ω × ρ = 0` (the model keeps `v_P`
    /// constant, so a start with slip would slide for ever at constant
    /// slip); [`GroundTop::try_rolling_state_on_ground`] sets `v_G` from
    /// `ω`.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidState`] for a non-finite or zero attitude, a
    /// non-finite velocity, a disk lying flat, or, with
    /// [`Friction::Rolling`], a slip `|v_P|` above `1e-12 (|v_G| + |ω| |ρ|)`;
    /// [`DynamicsError::OtherContactTouching`] when one of the
    /// [`GroundTop::other_contacts`] is at or below the plane.
    ///
    /// ```
    /// use glam::{DMat3, DQuat, DVec2, DVec3};
    /// use kreisel_dynamics::{Friction, GroundTop, SphereContact};
    /// let sphere = SphereContact::try_new(0.015, DVec3::new(0.0, 0.0, 0.003))?;
    /// let top = GroundTop::try_new(0.006, DMat3::from_diagonal(DVec3::new(8e-7, 8e-7, 7e-7)), sphere, Friction::None, 9.81)?;
    /// let q = DQuat::from_rotation_x(0.1);
    /// let s = top.try_state_on_ground(q, q * DVec3::new(0.0, 0.0, 180.0), DVec2::ZERO)?;
    /// assert!(top.gap(&s).abs() < 1e-18 && top.gap_rate(&s).abs() < 1e-18);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_state_on_ground(
        &self,
        world_from_body: DQuat,
        omega_world: DVec3,
        velocity_xy: DVec2,
    ) -> Result<GroundTopState, DynamicsError> {
        if !(world_from_body.is_finite() && world_from_body.length_squared() > 0.0) {
            return Err(DynamicsError::InvalidState {
                reason: "the attitude must be a finite, non-zero quaternion",
            });
        }
        if !(omega_world.is_finite() && velocity_xy.is_finite()) {
            return Err(DynamicsError::InvalidState {
                reason: "the angular and centre-of-mass velocities must be finite",
            });
        }
        let q = world_from_body.normalize();
        let rho = self.shape.contact_from_com_world(q);
        if !rho.is_finite() {
            return Err(DynamicsError::InvalidState {
                reason: "the disk lies flat (axis vertical): no single contact point",
            });
        }
        let a = DMat3::from_quat(q);
        let state = GroundTopState {
            com_world: DVec3::new(0.0, 0.0, -rho.z),
            velocity_world: DVec3::new(velocity_xy.x, velocity_xy.y, -omega_world.cross(rho).z),
            world_from_body: q,
            l_world: a * self.inertia_body * a.transpose() * omega_world,
        };
        self.check_others_clear(&state)?;
        if self.friction == Friction::Rolling {
            let scale = state.velocity_world.length() + omega_world.length() * rho.length();
            if self.slip_velocity(&state).length() > 1e-12 * scale {
                return Err(DynamicsError::InvalidState {
                    reason: "rolling without slipping needs v_G = −ω × ρ at the start \
                             (use try_rolling_state_on_ground)",
                });
            }
        }
        Ok(state)
    }

    /// A state touching the plane and rolling without slipping: as
    /// [`GroundTop::try_state_on_ground`], with the centre of mass moving
    /// so that the contact point is at rest.
    ///
    /// ```text
    /// z_G = −ρ_z,   v_G = −ω × ρ,   L = A I Aᵀ ω
    /// ```
    ///
    /// (`ρ = A c − R ẑ` for a sphere; the vertical component `−(ω × ρ)_z`
    /// is the one of [`GroundTop::try_state_on_ground`]). Any friction
    /// model accepts it.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidState`] for a non-finite or zero attitude, a
    /// non-finite angular velocity or a disk lying flat;
    /// [`DynamicsError::OtherContactTouching`] as for
    /// [`GroundTop::try_state_on_ground`].
    ///
    /// ```
    /// use glam::{DMat3, DQuat, DVec3};
    /// use kreisel_dynamics::{Friction, GroundTop, SphereContact};
    /// let sphere = SphereContact::try_new(0.015, DVec3::new(0.0, 0.0, 0.003))?;
    /// let i = DMat3::from_diagonal(DVec3::new(8e-7, 8e-7, 7e-7));
    /// let top = GroundTop::try_new(0.006, i, sphere, Friction::Rolling, 9.81)?;
    /// let q = DQuat::from_rotation_x(0.5);
    /// let s = top.try_rolling_state_on_ground(q, DVec3::new(3.0, -20.0, 40.0))?;
    /// assert!(top.slip_velocity(&s).length() < 1e-15);
    /// assert!(top.gap(&s).abs() < 1e-18);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_rolling_state_on_ground(
        &self,
        world_from_body: DQuat,
        omega_world: DVec3,
    ) -> Result<GroundTopState, DynamicsError> {
        if !(world_from_body.is_finite() && world_from_body.length_squared() > 0.0) {
            return Err(DynamicsError::InvalidState {
                reason: "the attitude must be a finite, non-zero quaternion",
            });
        }
        if !omega_world.is_finite() {
            return Err(DynamicsError::InvalidState {
                reason: "the angular velocity must be finite",
            });
        }
        let rho = self.shape.contact_from_com_world(world_from_body);
        let v = -omega_world.cross(rho);
        self.try_state_on_ground(world_from_body, omega_world, DVec2::new(v.x, v.y))
    }

    /// The angular velocity in world axes: `ω = A I⁻¹ Aᵀ L`.
    pub fn omega_world(&self, state: &GroundTopState) -> DVec3 {
        let a = DMat3::from_quat(state.world_from_body.normalize());
        a * (self.inverse_inertia_body * (a.transpose() * state.l_world))
    }

    /// The constraint's residual, the height of the lowest point:
    /// `z_G + ρ_z` (m; `z_G + (A c)_z − R` for a sphere).
    pub fn gap(&self, state: &GroundTopState) -> f64 {
        state.com_world.z + self.shape.contact_from_com_world(state.world_from_body).z
    }

    /// Its rate, the vertical velocity of the contact point:
    /// `(v_P)_z = ż_G + (ω × ρ)_z` (m/s; `ż_G + (ω × A c)_z` for a sphere).
    pub fn gap_rate(&self, state: &GroundTopState) -> f64 {
        self.slip_velocity(state).z
    }

    /// The velocity of the body's material point at the contact:
    /// `v_P = v_G + ω × ρ` (m/s; horizontal while the contact holds).
    pub fn slip_velocity(&self, state: &GroundTopState) -> DVec3 {
        let rho = self.shape.contact_from_com_world(state.world_from_body);
        state.velocity_world + self.omega_world(state).cross(rho)
    }

    /// The mechanical energy, zero potential at `z_G = 0`.
    ///
    /// ```text
    /// E = ½ m |v_G|² + ½ L·ω + m g z_G
    /// ```
    pub fn energy(&self, state: &GroundTopState) -> f64 {
        0.5 * self.mass * state.velocity_world.length_squared()
            + 0.5 * state.l_world.dot(self.omega_world(state))
            + self.mass * self.gravity * state.com_world.z
    }

    /// Jellett's integral, conserved by every contact force of a sphere
    /// whose centre lies on an axis of symmetry of the inertia tensor (for
    /// a disk rim or an ellipsoid the same expression, not conserved).
    ///
    /// ```text
    /// λ = L · (R ẑ − A c) = −L · ρ = L · (r_G − r_P)
    /// ```
    pub fn jellett(&self, state: &GroundTopState) -> f64 {
        -state
            .l_world
            .dot(self.shape.contact_from_com_world(state.world_from_body))
    }

    /// The normal force `N` the plane exerts in `state`, newtons (applied
    /// loads, if any, read at `t = 0`: [`GroundTop::normal_force_at`] for
    /// loads that change with time).
    ///
    /// # Errors
    /// [`DynamicsError::ContactIndeterminate`] when no normal force can
    /// keep the contact (the coefficient of `N` in the constraint is not
    /// positive: Painlevé's paradox, possible with strong friction);
    /// [`DynamicsError::InvalidState`] for a non-finite state. A negative
    /// value is returned as it is: the contact would need to pull.
    pub fn normal_force(&self, state: &GroundTopState) -> Result<f64, DynamicsError> {
        self.normal_force_at(0.0, state)
    }

    /// The normal force in `state` at time `t`, newtons (the time reaches
    /// only applied loads, [`GroundTop::try_with_inputs`]).
    ///
    /// # Errors
    /// As [`GroundTop::normal_force`].
    ///
    /// ```
    /// use glam::{DMat3, DQuat, DVec2, DVec3};
    /// use kreisel_dynamics::{Friction, GroundTop, Inputs, SphereContact};
    /// // Lifted by a force that grows with time: it carries the weight at t = 1 s.
    /// let ball = SphereContact::try_new(0.1, DVec3::ZERO)?;
    /// let lift = Inputs::default().with_load(|t, _| (DVec3::ZERO, DVec3::new(0.0, 0.0, 9.81 * t)));
    /// let top = GroundTop::try_new(1.0, DMat3::from_diagonal(DVec3::splat(0.004)), ball, Friction::None, 9.81)?
    ///     .try_with_inputs(lift)?;
    /// let s = top.try_state_on_ground(DQuat::IDENTITY, DVec3::ZERO, DVec2::ZERO)?;
    /// assert!((top.normal_force_at(0.25, &s)? - 0.75 * 9.81).abs() < 1e-14);
    /// assert!(top.normal_force_at(1.0, &s)?.abs() < 1e-14);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn normal_force_at(&self, t: f64, state: &GroundTopState) -> Result<f64, DynamicsError> {
        if !state.is_valid() {
            return Err(DynamicsError::InvalidState {
                reason: "the ground-top state is not finite",
            });
        }
        let r = self.rates(t, state);
        if r.compliance > 0.0 {
            Ok(r.normal_force)
        } else {
            Err(DynamicsError::ContactIndeterminate {
                time: f64::NAN,
                compliance: r.compliance,
            })
        }
    }

    /// The whole contact force `N ẑ + F` the plane exerts in `state`, world
    /// axes, newtons: `N (ẑ + f(v_P))` for a friction law, the reaction
    /// `K⁻¹ b` of the rolling constraint for [`Friction::Rolling`] (module
    /// docs, [`crate::contact`]); applied loads read at `t = 0`
    /// ([`GroundTop::contact_force_at`]).
    ///
    /// # Errors
    /// As [`GroundTop::normal_force`].
    ///
    /// ```
    /// use glam::{DMat3, DQuat, DVec3};
    /// use kreisel_dynamics::{Friction, GroundTop, SphereContact};
    /// // A homogeneous ball rolling straight: the plane only carries it.
    /// let (m, r) = (0.2, 0.03);
    /// let ball = SphereContact::try_new(r, DVec3::ZERO)?;
    /// let i = DMat3::from_diagonal(DVec3::splat(0.4 * m * r * r));
    /// let top = GroundTop::try_new(m, i, ball, Friction::Rolling, 9.81)?;
    /// let s = top.try_rolling_state_on_ground(DQuat::IDENTITY, DVec3::new(10.0, 0.0, 0.0))?;
    /// let f = top.contact_force(&s)?;
    /// assert!((f - DVec3::new(0.0, 0.0, m * 9.81)).length() < 1e-15);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn contact_force(&self, state: &GroundTopState) -> Result<DVec3, DynamicsError> {
        self.contact_force_at(0.0, state)
    }

    /// The contact force in `state` at time `t` (as
    /// [`GroundTop::normal_force_at`]).
    ///
    /// # Errors
    /// As [`GroundTop::normal_force`].
    pub fn contact_force_at(&self, t: f64, state: &GroundTopState) -> Result<DVec3, DynamicsError> {
        self.normal_force_at(t, state)?;
        Ok(self.rates(t, state).contact_force)
    }

    /// For a disk rim, the unit direction from the rim's centre to the
    /// contact point in body axes, `Aᵀ û` (NaN lying flat); `None` for a
    /// sphere.
    pub(crate) fn rim_direction_body(&self, state: &GroundTopState) -> Option<DVec3> {
        match self.shape {
            ContactShape::Sphere(_) | ContactShape::Ellipsoid(_) => None,
            ContactShape::Disk(d) => {
                let q = state.world_from_body.normalize();
                let rho = d.contact_from_com_world(q);
                Some(q.conjugate() * (rho - q * d.center_body()) / d.radius())
            }
        }
    }

    /// The vector field and the normal force at `state` and time `t` (the
    /// time only reaches applied loads, [`GroundTop::try_with_inputs`]).
    pub(crate) fn rates(&self, t: f64, state: &GroundTopState) -> Rates {
        let q = state.world_from_body.normalize();
        let a = DMat3::from_quat(q);
        let inverse_world = a * self.inverse_inertia_body * a.transpose();
        let l = state.l_world;
        let omega = inverse_world * l;
        let (rho, rho_rate) = self.shape.offset_and_rate(q, omega);
        let (torque, force) = match &self.loads {
            Some(loads) => loads.at(t, state),
            None => (DVec3::ZERO, DVec3::ZERO),
        };
        // I_w⁻¹ (L × ω + τ): the angular acceleration without the contact.
        let free_spin = inverse_world * (l.cross(omega) + torque);
        if self.friction == Friction::Rolling {
            let loads = (torque, force);
            return self.rolling_rates(
                state,
                inverse_world,
                omega,
                (rho, rho_rate),
                free_spin,
                loads,
            );
        }
        let slip = state.velocity_world + omega.cross(rho);
        let e = DVec3::Z
            + self
                .friction
                .force_per_normal(DVec3::new(slip.x, slip.y, 0.0));
        let per_newton = inverse_world * rho.cross(e);
        let compliance = 1.0 / self.mass + per_newton.cross(rho).z;
        let free = free_spin.cross(rho).z + omega.cross(rho_rate).z + force.z / self.mass;
        let normal_force = (self.gravity - free) / compliance;
        Rates {
            d_com: state.velocity_world,
            d_velocity: e * (normal_force / self.mass) + force / self.mass
                - self.gravity * DVec3::Z,
            d_attitude: kreisel_kinematics::quat_derivative_world(state.world_from_body, omega),
            d_l: rho.cross(e) * normal_force + torque,
            normal_force,
            contact_force: e * normal_force,
            compliance,
        }
    }

    /// The vector field of rolling without slipping: the contact force
    /// `F_c` from `K F_c = b` (module docs, [`crate::contact`]), with the
    /// applied torque `τ` and force `F`, `free_spin = I_w⁻¹ (L × ω + τ)`.
    ///
    /// ```text
    /// K = 1/m 𝟙 − [ρ]× I_w⁻¹ [ρ]×
    /// b = g ẑ − F/m + ρ × (I_w⁻¹ (L × ω + τ)) − ω × ρ̇
    /// ```
    fn rolling_rates(
        &self,
        state: &GroundTopState,
        inverse_world: DMat3,
        omega: DVec3,
        (rho, rho_rate): (DVec3, DVec3),
        free_spin: DVec3,
        (torque, force): (DVec3, DVec3),
    ) -> Rates {
        let cross_rho = skew(rho);
        let k = DMat3::from_diagonal(DVec3::splat(1.0 / self.mass))
            - cross_rho * inverse_world * cross_rho;
        let b = self.gravity * DVec3::Z - force / self.mass + rho.cross(free_spin)
            - omega.cross(rho_rate);
        let k_inverse = k.inverse();
        let contact = k_inverse * b;
        Rates {
            d_com: state.velocity_world,
            d_velocity: (contact + force) / self.mass - self.gravity * DVec3::Z,
            d_attitude: kreisel_kinematics::quat_derivative_world(state.world_from_body, omega),
            d_l: rho.cross(contact) + torque,
            normal_force: contact.z,
            contact_force: contact,
            // The vertical compliance with the contact point held
            // horizontally: 1/(K⁻¹)_zz, positive as K is positive definite.
            compliance: 1.0 / k_inverse.z_axis.z,
        }
    }
}

/// The cross-product matrix: `skew(r) x = r × x`.
fn skew(r: DVec3) -> DMat3 {
    DMat3::from_cols(
        DVec3::new(0.0, r.z, -r.y),
        DVec3::new(-r.z, 0.0, r.x),
        DVec3::new(r.y, -r.x, 0.0),
    )
}
