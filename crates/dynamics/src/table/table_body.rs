//! [`TableBody`]: a rigid body with any number of contact shapes, each
//! with its [`ContactLaw`], above or on the table `z = 0`.

use glam::{DMat3, DQuat, DVec3};

use super::ContactLaw;
use crate::contact::{AppliedLoads, check_mass_properties};
use crate::{ContactShape, DynamicsError, GroundTopState, Inputs};

/// A contact shape fixed in the body and the law of its contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TableContact {
    /// The surface (sphere, disk rim, ellipsoid), body axes from the
    /// centre of mass.
    pub shape: ContactShape,
    /// Its friction and restitution.
    pub law: ContactLaw,
}

/// A rigid body above the table `z = 0` under gravity `−g ẑ`, touching it
/// with any of its contact shapes.
///
/// ```text
/// state:   r_G, v_G, q (body → world, rotation A), L about the centre of mass (world axes)
/// ω = A I⁻¹ Aᵀ L,   u = (v_G, ω)
/// contact i: ρᵢ (lowest point of shape i from the centre of mass),
///            gᵢ = z_G + ρᵢ_z (its gap),   v_Pᵢ = v_G + ω × ρᵢ
/// E = ½ m |v_G|² + ½ L·ω + m g z_G
/// ```
///
/// ```
/// use glam::{DMat3, DVec3};
/// use kreisel_dynamics::{ContactLaw, ContactShape, SphereContact, TableBody, TableContact};
/// let ball = SphereContact::try_new(0.1, DVec3::ZERO)?;
/// let contact = TableContact { shape: ContactShape::Sphere(ball), law: ContactLaw::new(0.0) };
/// let i = DMat3::from_diagonal(DVec3::splat(0.4 * 0.1 * 0.1));
/// let body = TableBody::try_new(1.0, i, vec![contact], 9.81)?;
/// assert_eq!(body.contacts().len(), 1);
/// assert!(TableBody::try_new(1.0, i, vec![], 9.81).is_err());
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct TableBody {
    mass: f64,
    inertia_body: DMat3,
    inverse_inertia_body: DMat3,
    gravity: f64,
    contacts: Vec<TableContact>,
    /// Applied torques and forces ([`TableBody::try_with_inputs`]).
    loads: Option<AppliedLoads>,
}

impl TableBody {
    /// The most contact shapes one body may carry.
    pub const MAX_CONTACTS: usize = 8;

    /// A body of `mass` kg, inertia tensor `inertia_body` about its centre
    /// of mass (body axes), with `contacts`, under gravity `g` m/s² along
    /// −z.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidContact`] for a mass, inertia or `g` no
    /// body has (`"mass"`, `"inertia"`, `"gravity"`), for no contact shape
    /// or more than [`TableBody::MAX_CONTACTS`] (`"contacts"`).
    pub fn try_new(
        mass: f64,
        inertia_body: DMat3,
        contacts: Vec<TableContact>,
        gravity: f64,
    ) -> Result<Self, DynamicsError> {
        check_mass_properties(mass, inertia_body, gravity)?;
        if contacts.is_empty() || contacts.len() > Self::MAX_CONTACTS {
            return Err(DynamicsError::InvalidContact {
                parameter: "contacts",
                value: contacts.len() as f64,
                reason: "a body on the table needs 1 to 8 contact shapes",
            });
        }
        for c in &contacts {
            if c.law.air_layer().is_some() && !matches!(c.shape, ContactShape::Disk(_)) {
                return Err(DynamicsError::InvalidContact {
                    parameter: "air_viscosity",
                    value: c.law.air_layer().map_or(0.0, |a| a.viscosity()),
                    reason: "an air layer lies under a disk rim only",
                });
            }
        }
        Ok(Self {
            mass,
            inertia_body,
            inverse_inertia_body: inertia_body.inverse(),
            gravity,
            contacts,
            loads: None,
        })
    }

    /// The body with applied `inputs` (torques about the centre of mass,
    /// forces through it or at body points, damping, a user law of
    /// `(t, state)`: [`Inputs`]) acting beside gravity and the table:
    ///
    /// ```text
    /// m v̇_G = −m g ẑ + F + Σ contact forces,   L̇ = τ + Σ ρᵢ × contact forces
    /// ```
    ///
    /// The energy then changes by the inputs' power too; rest is not
    /// detected (the inputs may move the body again).
    ///
    /// # Errors
    /// [`Inputs::validate`]'s, and those of building the forced body
    /// ([`crate::ForcedBody::try_new`]).
    ///
    /// ```
    /// use glam::{DMat3, DVec3};
    /// use kreisel_dynamics::{ContactLaw, ContactShape, Inputs, SphereContact, TableBody, TableContact};
    /// let shape = ContactShape::Sphere(SphereContact::try_new(0.1, DVec3::ZERO)?);
    /// let body = TableBody::try_new(1.0, DMat3::from_diagonal(DVec3::splat(0.004)),
    ///     vec![TableContact { shape, law: ContactLaw::new(0.5) }], 9.81)?
    ///     .try_with_inputs(Inputs::default().with_torque_world(DVec3::new(0.0, 0.0, 1e-3)))?;
    /// assert!(body.inputs().is_some());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_with_inputs(self, inputs: Inputs) -> Result<Self, DynamicsError> {
        let loads = AppliedLoads::try_new(self.inertia_body, self.mass, self.gravity, inputs)?;
        Ok(Self { loads, ..self })
    }

    /// The applied inputs, if any.
    pub fn inputs(&self) -> Option<&Inputs> {
        self.loads.as_ref().map(AppliedLoads::inputs)
    }

    /// The applied torque about the centre of mass and force through it,
    /// world axes, at time `t` in `state`: the inputs' and the air
    /// layers' ([`super::AirLayer`]; zero without either).
    pub fn applied_world(&self, t: f64, state: &GroundTopState) -> (DVec3, DVec3) {
        let (mut torque, force) = self
            .loads
            .as_ref()
            .map_or((DVec3::ZERO, DVec3::ZERO), |l| l.at(t, state));
        if self.has_air_layer() {
            let omega = self.omega_world(state);
            for (i, c) in self.contacts.iter().enumerate() {
                if let (ContactShape::Disk(d), Some(air)) = (c.shape, c.law.air_layer()) {
                    let gap = self.gap(state, i);
                    torque += air.torque_world(&d, state.world_from_body, omega, gap);
                }
            }
        }
        (torque, force)
    }

    /// Whether a contact has an air layer.
    fn has_air_layer(&self) -> bool {
        self.contacts.iter().any(|c| c.law.air_layer().is_some())
    }

    /// Whether anything besides gravity and the table acts: inputs or an
    /// air layer (the flight is then integrated, not exact).
    pub fn has_loads(&self) -> bool {
        self.loads.is_some() || self.has_air_layer()
    }

    /// The mass `m`, kg.
    pub fn mass(&self) -> f64 {
        self.mass
    }

    /// The inertia tensor about the centre of mass, body axes, kg m².
    pub fn inertia_body(&self) -> DMat3 {
        self.inertia_body
    }

    /// `g`, m/s².
    pub fn gravity(&self) -> f64 {
        self.gravity
    }

    /// The contact shapes and their laws.
    pub fn contacts(&self) -> &[TableContact] {
        &self.contacts
    }

    /// The inverse inertia tensor in world axes, `I_w⁻¹ = A I⁻¹ Aᵀ`, at
    /// the unit attitude `q`.
    pub(crate) fn inverse_inertia_world(&self, q: DQuat) -> DMat3 {
        let a = DMat3::from_quat(q);
        a * self.inverse_inertia_body * a.transpose()
    }

    /// The angular velocity in world axes: `ω = A I⁻¹ Aᵀ L`.
    pub fn omega_world(&self, state: &GroundTopState) -> DVec3 {
        let q = state.world_from_body.normalize();
        q * (self.inverse_inertia_body * (q.conjugate() * state.l_world))
    }

    /// The mechanical energy, zero potential at `z_G = 0`:
    /// `E = ½ m |v_G|² + ½ L·ω + m g z_G`.
    pub fn energy(&self, state: &GroundTopState) -> f64 {
        self.kinetic_energy(state) + self.mass * self.gravity * state.com_world.z
    }

    /// The kinetic energy `T = ½ m |v_G|² + ½ L·ω`.
    pub fn kinetic_energy(&self, state: &GroundTopState) -> f64 {
        0.5 * self.mass * state.velocity_world.length_squared()
            + 0.5 * state.l_world.dot(self.omega_world(state))
    }

    /// The gap of contact `i`, the height of its lowest point: `z_G + ρᵢ_z`.
    ///
    /// # Panics
    /// For `i` out of range.
    pub fn gap(&self, state: &GroundTopState, i: usize) -> f64 {
        let q = state.world_from_body.normalize();
        state.com_world.z + self.contacts[i].shape.contact_from_com_world(q).z
    }

    /// The velocity of the body's material point at contact `i`'s lowest
    /// point: `v_P = v_G + ω × ρᵢ` (its `z` is the gap's rate).
    ///
    /// # Panics
    /// For `i` out of range.
    pub fn contact_velocity(&self, state: &GroundTopState, i: usize) -> DVec3 {
        let q = state.world_from_body.normalize();
        let rho = self.contacts[i].shape.contact_from_com_world(q);
        state.velocity_world + self.omega_world(state).cross(rho)
    }

    /// Jellett's integral about contact `i`: `λ = −L·ρᵢ` (conserved while
    /// only that sphere touches, its centre on an axis of symmetry of the
    /// inertia and no drilling friction; module docs of
    /// [`crate::contact`]).
    ///
    /// # Panics
    /// For `i` out of range.
    pub fn jellett(&self, state: &GroundTopState, i: usize) -> f64 {
        let q = state.world_from_body.normalize();
        -state
            .l_world
            .dot(self.contacts[i].shape.contact_from_com_world(q))
    }

    /// The body's length scale `ℓ`, m: its largest contact shape's size
    /// plus that shape's distance from the centre of mass.
    pub(crate) fn length_scale(&self) -> f64 {
        self.contacts
            .iter()
            .map(|c| c.shape.size() + c.shape.center_from_com_world(DQuat::IDENTITY).length())
            .fold(0.0, f64::max)
    }
}
