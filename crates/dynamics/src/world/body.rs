//! [`Body`]: the one place a rigid body is built — its mass properties, its
//! attitude and spin, and how it is held ([`Support`]).

use glam::{DMat3, DQuat, DVec2, DVec3};
use kreisel_inertia::MassProperties;

use crate::{
    ContactShape, DynamicsError, Friction, Inputs, MAX_OTHER_CONTACTS, PrincipalState, RigidBody,
    TableBody, TableContact,
};

/// How a body is held.
///
/// Applied torques and forces are not part of the support: they are the
/// body's [`Inputs`] ([`BodyBuilder::with_inputs`], [`Body::with_inputs`]),
/// for every support (on the ground they enter the contact model,
/// [`crate::GroundTop::try_with_inputs`]).
///
/// ```
/// use glam::DVec3;
/// use kreisel_dynamics::{Body, Support};
/// let b = Body::from_principal_moments(1.0, DVec3::ONE).free(DVec3::X, DVec3::Y).try_build()?;
/// assert_eq!(b.support(), Support::Free { position: DVec3::X, velocity: DVec3::Y });
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Support {
    /// Nothing holds it: the centre of mass flies ballistically under the
    /// world's gravity and the rotation is torque-free — unless the body
    /// has [`Inputs`] ([`BodyBuilder::with_inputs`]), which then push and
    /// turn it.
    ///
    /// ```text
    /// x(t) = x₀ + v₀ t + ½ g t²,   v(t) = v₀ + g t
    /// ```
    Free {
        /// Centre of mass at the time the body is added, world axes, m.
        position: DVec3,
        /// Its velocity, world axes, m/s.
        velocity: DVec3,
    },
    /// A fixed point of the body does not move: a heavy top under the
    /// world's gravity ([`crate::HeavyTop`]).
    Pivot {
        /// The pivot in body coordinates (the frame of the body's mass
        /// properties), m.
        pivot_body: DVec3,
        /// Where the pivot is, world axes, m.
        pivot_world: DVec3,
    },
    /// The body stands on the ground plane `z = 0` (the world's gravity
    /// must point along −z) touching it with `shape`, which rubs with
    /// `friction`: a [`crate::GroundTop`] in the world
    /// ([`crate::Plan::OnGround`]). It starts touching: the height of the
    /// centre of mass and its vertical velocity follow from the attitude
    /// and the angular velocity, the horizontal part is given.
    ///
    /// ```text
    /// z_G = −ρ_z,   ż_G = −(ω × ρ)_z,   (x_G, y_G) = position_xy
    /// (ẋ_G, ẏ_G) = velocity_xy;  rolling: v_G = −ω × ρ (velocity_xy must agree)
    /// ```
    ///
    /// (`ρ` the contact point seen from the centre of mass, world axes,
    /// [`ContactShape::contact_from_com_world`].)
    Ground {
        /// The surface that touches: a sphere or a disk rim, centred in
        /// body axes from the centre of mass.
        shape: ContactShape,
        /// The friction law at the contact point.
        friction: Friction,
        /// The centre of mass's horizontal position at the time the body
        /// is added, m.
        position_xy: DVec2,
        /// Its horizontal velocity, m/s (with [`Friction::Rolling`] zero
        /// means "as rolling needs"; any other value must be that one).
        velocity_xy: DVec2,
    },
    /// The body moves above and on the table `z = 0` (the world's gravity
    /// must point along −z) with all its contact shapes
    /// ([`Body::table_contacts`], [`BodyBuilder::on_table`]), each a
    /// unilateral contact with Coulomb–Contensou friction and Newton's
    /// restitution: a [`crate::TableMotion`] in the world
    /// ([`crate::Plan::OnTable`]). It may start above the table (dropped,
    /// thrown) or touching it; no shape may start below it.
    ///
    /// ```text
    /// r_G(0) = position,   v_G(0) = velocity,   every gap gᵢ = z_G + (ρᵢ)_z ≥ 0
    /// ```
    Table {
        /// The centre of mass at the time the body is added, world axes, m.
        position: DVec3,
        /// Its velocity, world axes, m/s.
        velocity: DVec3,
    },
}

/// A rigid body ready to be added to a [`crate::World`]: mass properties
/// about its centre of mass in body axes, the attitude `world_from_body`,
/// the angular velocity in body axes, its [`Support`] and what is applied
/// to it ([`Inputs`], none by default).
///
/// Built by [`Body::from_principal_moments`] or
/// [`Body::from_mass_properties`] (primitives, a tensor, a mesh through
/// `kreisel_inertia`) followed by [`BodyBuilder::try_build`], which checks
/// everything once.
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{Body, Support};
/// let body = Body::from_principal_moments(2.0, DVec3::new(1.0, 2.0, 3.0))
///     .world_from_body(DQuat::from_rotation_z(0.5))
///     .omega_body(DVec3::new(0.01, 1.0, 0.0))
///     .try_build()?;
/// assert_eq!(body.mass(), 2.0);
/// assert_eq!(body.rigid_body().principal_moments(), DVec3::new(1.0, 2.0, 3.0));
/// assert!(matches!(body.support(), Support::Free { .. }));
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone)]
pub struct Body {
    mass_properties: MassProperties,
    rigid: RigidBody,
    world_from_body: DQuat,
    omega_body: DVec3,
    support: Support,
    others: Option<OtherContacts>,
    /// The shapes and laws of a body on the table (empty otherwise).
    table: Vec<TableContact>,
    inputs: Inputs,
}

/// Further contact shapes of a body on the ground, watched for touchdown
/// ([`BodyBuilder::other_contacts`]); a fixed capacity keeps the builder
/// `Copy`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct OtherContacts {
    /// The first `given` (at most [`MAX_OTHER_CONTACTS`]) are the shapes.
    shapes: [ContactShape; MAX_OTHER_CONTACTS],
    /// How many were given (more than [`MAX_OTHER_CONTACTS`] is refused
    /// by [`BodyBuilder::try_build`]).
    given: usize,
}

impl OtherContacts {
    /// The shapes kept (at most [`MAX_OTHER_CONTACTS`]).
    fn shapes(&self) -> &[ContactShape] {
        &self.shapes[..self.given.min(MAX_OTHER_CONTACTS)]
    }
}

/// Where a body's inertia comes from.
#[derive(Debug, Clone, Copy)]
enum Inertia {
    /// Principal moments in body axes (body axes are principal axes, in
    /// this order).
    Principal { mass: f64, moments: DVec3 },
    /// Mass properties; the principal axes are found.
    Properties(MassProperties),
}

/// The settings of a [`Body`] before they are checked
/// ([`BodyBuilder::try_build`]). Defaults: identity attitude, at rest,
/// free at the origin, nothing applied. Clone it for several bodies alike.
#[derive(Debug, Clone)]
#[must_use = "a builder does nothing until try_build"]
pub struct BodyBuilder {
    inertia: Inertia,
    world_from_body: DQuat,
    omega_body: DVec3,
    support: Support,
    others: Option<OtherContacts>,
    table: Vec<TableContact>,
    inputs: Inputs,
}

impl Body {
    /// A body of `mass` (kg) whose body axes are principal axes with the
    /// given `moments` (kg·m², about the centre of mass, which is the body
    /// origin), in this order.
    ///
    /// ```text
    /// I = diag(I₁, I₂, I₃),   centre of mass = 0
    /// ```
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::Body;
    /// let b = Body::from_principal_moments(1.0, DVec3::new(3.0, 2.0, 1.0)).try_build()?;
    /// // The given order is kept: body axes are these principal axes.
    /// assert_eq!(b.rigid_body().principal_moments(), DVec3::new(3.0, 2.0, 1.0));
    /// assert!(Body::from_principal_moments(1.0, DVec3::new(1.0, 1.0, 3.0)).try_build().is_err());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn from_principal_moments(mass: f64, moments: DVec3) -> BodyBuilder {
        BodyBuilder::new(Inertia::Principal { mass, moments })
    }

    /// A body with these mass properties (body coordinates; the inertia
    /// about the centre of mass). Its principal axes are found by
    /// [`RigidBody::from_mass_properties`].
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::Body;
    /// use kreisel_inertia::MassProperties;
    /// let brick = MassProperties::solid_box(1000.0, DVec3::new(0.1, 0.2, 0.3)).unwrap();
    /// let b = Body::from_mass_properties(brick).omega_body(DVec3::X).try_build()?;
    /// assert_eq!(b.mass(), brick.mass);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn from_mass_properties(mass_properties: MassProperties) -> BodyBuilder {
        BodyBuilder::new(Inertia::Properties(mass_properties))
    }

    /// Mass, kg.
    ///
    /// ```
    /// # use kreisel_dynamics::Body;
    /// let b = Body::from_principal_moments(3.0, glam::DVec3::ONE).try_build()?;
    /// assert_eq!(b.mass(), 3.0);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn mass(&self) -> f64 {
        self.mass_properties.mass
    }

    /// The mass properties in body coordinates.
    ///
    /// ```
    /// # use kreisel_dynamics::Body;
    /// let b = Body::from_principal_moments(3.0, glam::DVec3::ONE).try_build()?;
    /// assert_eq!(b.mass_properties().center_of_mass, glam::DVec3::ZERO);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn mass_properties(&self) -> &MassProperties {
        &self.mass_properties
    }

    /// Principal moments about the centre of mass and the body-from-principal rotation.
    ///
    /// ```
    /// # use kreisel_dynamics::Body;
    /// let b = Body::from_principal_moments(1.0, glam::DVec3::new(1.0, 2.0, 2.5)).try_build()?;
    /// assert_eq!(b.rigid_body().body_from_principal(), glam::DQuat::IDENTITY);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn rigid_body(&self) -> &RigidBody {
        &self.rigid
    }

    /// The attitude: body coordinates → world coordinates, as given (the
    /// world normalises it when the body is added).
    ///
    /// ```
    /// # use kreisel_dynamics::Body;
    /// let q = glam::DQuat::from_xyzw(0.0, 0.0, 2.0, 0.0);
    /// let b = Body::from_principal_moments(1.0, glam::DVec3::ONE).world_from_body(q).try_build()?;
    /// assert_eq!(b.world_from_body(), q);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn world_from_body(&self) -> DQuat {
        self.world_from_body
    }

    /// Angular velocity in body axes, rad/s.
    ///
    /// ```
    /// # use kreisel_dynamics::Body;
    /// let b = Body::from_principal_moments(1.0, glam::DVec3::ONE).omega_body(glam::DVec3::Z).try_build()?;
    /// assert_eq!(b.omega_body(), glam::DVec3::Z);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn omega_body(&self) -> DVec3 {
        self.omega_body
    }

    /// How the body is held.
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, Support};
    /// let b = Body::from_principal_moments(1.0, glam::DVec3::ONE).pivot(glam::DVec3::Z, glam::DVec3::ZERO).try_build()?;
    /// assert!(matches!(b.support(), Support::Pivot { .. }));
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn support(&self) -> Support {
        self.support
    }

    /// The further contact shapes of a body on the ground, watched for
    /// touchdown ([`BodyBuilder::other_contacts`]; empty by default).
    ///
    /// ```
    /// # use kreisel_dynamics::Body;
    /// let b = Body::from_principal_moments(1.0, glam::DVec3::ONE).try_build()?;
    /// assert!(b.other_contacts().is_empty());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn other_contacts(&self) -> &[ContactShape] {
        self.others.as_ref().map_or(&[], OtherContacts::shapes)
    }

    /// The contact shapes and their laws of a body on the table
    /// ([`BodyBuilder::on_table`]; empty for any other support).
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::{Body, ContactLaw, ContactShape, SphereContact, TableContact};
    /// let ball = ContactShape::Sphere(SphereContact::try_new(0.1, DVec3::ZERO)?);
    /// let contact = TableContact { shape: ball, law: ContactLaw::try_new(0.3)? };
    /// let b = Body::from_principal_moments(1.0, DVec3::splat(0.004))
    ///     .on_table(DVec3::new(0.0, 0.0, 1.0), DVec3::ZERO, &[contact])
    ///     .try_build()?;
    /// assert_eq!(b.table_contacts(), &[contact]);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn table_contacts(&self) -> &[TableContact] {
        &self.table
    }

    /// What is applied to the body (torques, forces, damping, a law).
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, Inputs};
    /// let b = Body::from_principal_moments(1.0, glam::DVec3::ONE).try_build()?.with_inputs(Inputs::default().with_torque_world(glam::DVec3::Z))?;
    /// assert_eq!(b.inputs().torque_world, glam::DVec3::Z);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn inputs(&self) -> &Inputs {
        &self.inputs
    }

    /// This body with torques and forces applied ([`Inputs`]): a
    /// [`crate::World`] then moves it by a torque splitting
    /// ([`crate::Plan::Forced`]; on a pivot [`crate::Plan::DrivenTop`]).
    /// Inputs that are all zero change nothing.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidInput`] as [`Inputs::validate`];
    /// [`DynamicsError::InvalidBody`] (`"inputs"`) for inputs that are not
    /// all zero on a body on the table ([`Support::Table`]: applied loads
    /// are not modelled there).
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::{Body, DynamicsError, Inputs};
    /// let spun = Inputs::default().with_torque_body(DVec3::Z).with_angular_damping(0.1);
    /// let b = Body::from_principal_moments(1.0, DVec3::ONE);
    /// assert_eq!(b.clone().try_build()?.with_inputs(spun.clone())?.inputs().torque_body, DVec3::Z);
    /// let top = b.pivot(-DVec3::Z, DVec3::ZERO).try_build()?.with_inputs(spun.clone())?;
    /// assert_eq!(top.inputs().torque_body, DVec3::Z);
    /// let bad = Inputs::default().with_angular_damping(-1.0);
    /// assert!(matches!(top.with_inputs(bad), Err(DynamicsError::InvalidInput { .. })));
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn with_inputs(self, inputs: Inputs) -> Result<Self, DynamicsError> {
        inputs.validate()?;
        check_table_inputs(self.support, &inputs)?;
        Ok(Self { inputs, ..self })
    }

    /// Replaces the inputs (checked by [`crate::World::set_inputs`]).
    pub(super) fn set_inputs(&mut self, inputs: Inputs) {
        self.inputs = inputs;
    }
}

impl BodyBuilder {
    fn new(inertia: Inertia) -> Self {
        Self {
            inertia,
            world_from_body: DQuat::IDENTITY,
            omega_body: DVec3::ZERO,
            support: Support::Free {
                position: DVec3::ZERO,
                velocity: DVec3::ZERO,
            },
            others: None,
            table: Vec::new(),
            inputs: Inputs::default(),
        }
    }

    /// The attitude, body → world (any non-zero finite quaternion: the
    /// world normalises it).
    ///
    /// ```
    /// # use kreisel_dynamics::Body;
    /// let q = glam::DQuat::from_rotation_y(0.4);
    /// let b = Body::from_principal_moments(1.0, glam::DVec3::ONE).world_from_body(q).try_build()?;
    /// assert_eq!(b.world_from_body(), q);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn world_from_body(self, world_from_body: DQuat) -> Self {
        Self {
            world_from_body,
            ..self
        }
    }

    /// The angular velocity in body axes, rad/s.
    ///
    /// ```
    /// # use kreisel_dynamics::Body;
    /// let b = Body::from_principal_moments(1.0, glam::DVec3::ONE).omega_body(glam::DVec3::X).try_build()?;
    /// assert_eq!(b.omega_body(), glam::DVec3::X);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn omega_body(self, omega_body: DVec3) -> Self {
        Self { omega_body, ..self }
    }

    /// A free body with its centre of mass at `position` (m) moving at
    /// `velocity` (m/s), world axes.
    ///
    /// ```
    /// # use kreisel_dynamics::Body;
    /// use glam::DVec3;
    /// let b = Body::from_principal_moments(1.0, DVec3::ONE).free(DVec3::ZERO, DVec3::NAN);
    /// assert!(b.try_build().is_err());
    /// ```
    pub fn free(self, position: DVec3, velocity: DVec3) -> Self {
        Self {
            support: Support::Free { position, velocity },
            ..self
        }
    }

    /// A body turning about the fixed point `pivot_body` (body coordinates)
    /// placed at `pivot_world` (world axes): a heavy top.
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, Support};
    /// use glam::DVec3;
    /// let b = Body::from_principal_moments(1.0, DVec3::ONE).pivot(-DVec3::Z, DVec3::ZERO).try_build()?;
    /// assert_eq!(b.support(), Support::Pivot { pivot_body: -DVec3::Z, pivot_world: DVec3::ZERO });
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn pivot(self, pivot_body: DVec3, pivot_world: DVec3) -> Self {
        Self {
            support: Support::Pivot {
                pivot_body,
                pivot_world,
            },
            ..self
        }
    }

    /// A body standing on the ground plane with `shape` (centred in body
    /// axes from the centre of mass), rubbing with `friction`, its centre
    /// of mass above the origin and at rest horizontally (with
    /// [`Friction::Rolling`]: moving as rolling needs); see
    /// [`Support::Ground`].
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_dynamics::{Body, ContactShape, Friction, SphereContact, World};
    /// // Leine & Glocker's tippe top, tilted by 0.1 rad, spinning at 180 rad/s.
    /// let ball = ContactShape::Sphere(SphereContact::try_new(0.015, DVec3::new(0.0, 0.0, 0.003))?);
    /// let top = Body::from_principal_moments(0.006, DVec3::new(8e-7, 8e-7, 7e-7))
    ///     .world_from_body(DQuat::from_rotation_x(0.1))
    ///     .omega_body(DVec3::new(0.0, 0.0, 180.0))
    ///     .on_ground(ball, Friction::try_sliding(0.3, 1e-3)?)
    ///     .try_build()?;
    /// let mut world = World::try_new(DVec3::new(0.0, 0.0, -9.81), 1e-5)?;
    /// let id = world.add(top)?;
    /// // Touching: the ball's centre is R above the floor.
    /// let s = world.state(id).unwrap();
    /// let centre = s.position + s.world_from_body * DVec3::new(0.0, 0.0, 0.003);
    /// assert!((centre.z - 0.015).abs() < 1e-17);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn on_ground(self, shape: ContactShape, friction: Friction) -> Self {
        self.on_ground_at(shape, friction, DVec2::ZERO, DVec2::ZERO)
    }

    /// As [`BodyBuilder::on_ground`], the centre of mass above
    /// `position_xy` (m) moving horizontally at `velocity_xy` (m/s).
    ///
    /// ```
    /// use glam::{DVec2, DVec3};
    /// use kreisel_dynamics::{Body, ContactShape, Friction, SphereContact, Support};
    /// let ball = ContactShape::Sphere(SphereContact::try_new(0.1, DVec3::ZERO)?);
    /// let b = Body::from_principal_moments(1.0, DVec3::splat(0.004))
    ///     .on_ground_at(ball, Friction::None, DVec2::new(1.0, 2.0), DVec2::X)
    ///     .try_build()?;
    /// assert!(matches!(b.support(), Support::Ground { velocity_xy, .. } if velocity_xy == DVec2::X));
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn on_ground_at(
        self,
        shape: ContactShape,
        friction: Friction,
        position_xy: DVec2,
        velocity_xy: DVec2,
    ) -> Self {
        Self {
            support: Support::Ground {
                shape,
                friction,
                position_xy,
                velocity_xy,
            },
            ..self
        }
    }

    /// A body above or on the table `z = 0` ([`Support::Table`]): its
    /// centre of mass at `position` (m) moving at `velocity` (m/s), world
    /// axes, touching the table with any of `contacts` (each a shape centred
    /// in body axes from the centre of mass and its [`crate::ContactLaw`]:
    /// friction, restitution, Contensou's patch). The world moves it by a
    /// [`crate::TableMotion`] through impacts, lift-offs, sticking and
    /// slipping, to rest ([`crate::Plan::OnTable`]).
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::{Body, ContactLaw, ContactShape, Plan, SphereContact, TableContact, World};
    /// // A ball dropped from 1 m (centre), e = 0.9: the first impact at √(2 · 0.9/9.81) s.
    /// let ball = ContactShape::Sphere(SphereContact::try_new(0.1, DVec3::ZERO)?);
    /// let law = ContactLaw::try_new(0.0)?.try_with_restitution(0.9)?;
    /// let body = Body::from_principal_moments(1.0, DVec3::splat(0.004))
    ///     .on_table(DVec3::new(0.0, 0.0, 1.0), DVec3::ZERO, &[TableContact { shape: ball, law }])
    ///     .try_build()?;
    /// let mut world = World::try_new(DVec3::new(0.0, 0.0, -9.81), 1.0 / 60.0)?;
    /// let id = world.add(body)?;
    /// assert_eq!(world.plan(id), Some(&Plan::OnTable { contacts: 1 }));
    /// world.advance_to(0.5)?;
    /// let first = world.events(id).unwrap()[0];
    /// assert!((first.time - (2.0 * 0.9 / 9.81f64).sqrt()).abs() < 1e-12);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn on_table(self, position: DVec3, velocity: DVec3, contacts: &[TableContact]) -> Self {
        Self {
            support: Support::Table { position, velocity },
            table: contacts.to_vec(),
            ..self
        }
    }

    /// A body on the ground ([`BodyBuilder::on_ground`]) with further
    /// body-fixed contact shapes that do not touch the plane at the start
    /// — the stem's ball of a tippe top — watched for touchdown (replacing
    /// any given before; none by default). They exert no force: the body
    /// moves on its one contact ([`crate::GroundTop::try_with_other_contacts`]).
    ///
    /// ```text
    /// gᵢ = z_G + (ρᵢ)_z > 0 at the start;  gᵢ = 0 later: the world's failure,
    /// DynamicsError::ContactTouchdown { time, contact: i, approach_speed: −ġᵢ }
    /// ```
    ///
    /// The shapes are checked by [`BodyBuilder::try_build`] (at most
    /// [`MAX_OTHER_CONTACTS`], only on the ground) and their gaps by
    /// [`crate::World::add`] ([`DynamicsError::OtherContactTouching`]).
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_dynamics::{Body, ContactShape, DynamicsError, Friction, SphereContact, World};
    /// // Leine & Glocker's tippe top and its stem's ball (5 mm, 16 mm up the axis).
    /// let ball = ContactShape::Sphere(SphereContact::try_new(0.015, DVec3::new(0.0, 0.0, 0.003))?);
    /// let stem = ContactShape::Sphere(SphereContact::try_new(0.005, DVec3::new(0.0, 0.0, 0.016))?);
    /// let top = Body::from_principal_moments(0.006, DVec3::new(8e-7, 8e-7, 7e-7))
    ///     .on_ground(ball, Friction::None)
    ///     .other_contacts(&[stem]);
    /// let mut world = World::try_new(DVec3::new(0.0, 0.0, -9.81), 1e-4)?;
    /// assert_eq!(world.add(top.clone().try_build()?)?.index(), 0);
    /// // Upside down the stem's ball would be in the table: refused.
    /// let upside_down = top.world_from_body(DQuat::from_rotation_x(3.0)).try_build()?;
    /// assert!(matches!(world.add(upside_down), Err(DynamicsError::OtherContactTouching { contact: 0, .. })));
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn other_contacts(self, shapes: &[ContactShape]) -> Self {
        let others = shapes.first().map(|&first| {
            let mut kept = [first; MAX_OTHER_CONTACTS];
            let n = shapes.len().min(MAX_OTHER_CONTACTS);
            kept[..n].copy_from_slice(&shapes[..n]);
            OtherContacts {
                shapes: kept,
                given: shapes.len(),
            }
        });
        Self { others, ..self }
    }

    /// What is applied to the body ([`Inputs`]: torques, forces, damping,
    /// a law; none by default), checked by [`BodyBuilder::try_build`]. The
    /// same as giving them to the built body ([`Body::with_inputs`]) or, once
    /// it is in a world, to [`crate::World::set_inputs`].
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::{Body, Inputs, World};
    /// // A motor's torque of 0.5 N m about world z on a resting brick.
    /// let motor = Inputs::default().with_torque_world(DVec3::new(0.0, 0.0, 0.5));
    /// let brick = Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0)).with_inputs(motor);
    /// let mut world = World::try_new(DVec3::ZERO, 0.01)?;
    /// let id = world.add(brick.try_build()?)?;
    /// world.advance_to(2.0)?;
    /// // L = τ t: 1 kg m²/s about z after 2 s.
    /// let l = world.state(id).unwrap().l_world;
    /// assert!((l - DVec3::Z).length() < 1e-13, "{l}");
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn with_inputs(self, inputs: Inputs) -> Self {
        Self { inputs, ..self }
    }

    /// Checks the settings and builds the body.
    ///
    /// # Errors
    /// [`DynamicsError::UnphysicalInertia`] or
    /// [`DynamicsError::InertiaTensor`] for inertia no body has (the
    /// triangle inequality, a mass that is not positive);
    /// [`DynamicsError::InvalidState`] for an attitude that is zero or not
    /// finite, an angular velocity that is not finite or whose energy
    /// overflows; [`DynamicsError::InvalidBody`] for a support with
    /// non-finite vectors or further contact shapes
    /// ([`BodyBuilder::other_contacts`]) on a body not on the ground;
    /// [`DynamicsError::InvalidContact`] for more than
    /// [`MAX_OTHER_CONTACTS`] of them; for a body on the ground the errors
    /// of [`Friction::validate`]; [`DynamicsError::InvalidInput`] for
    /// inputs ([`BodyBuilder::with_inputs`]) as [`Inputs::validate`]; for
    /// a body on the table ([`BodyBuilder::on_table`]) the errors of
    /// [`TableBody::try_new`] (no contact shape, more than
    /// [`TableBody::MAX_CONTACTS`]) and [`DynamicsError::InvalidBody`]
    /// (`"inputs"`) for inputs that are not all zero.
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_dynamics::{Body, DynamicsError, Inputs};
    /// let b = Body::from_principal_moments(1.0, DVec3::ONE);
    /// assert!(matches!(b.clone().world_from_body(DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0)).try_build(), Err(DynamicsError::InvalidState { .. })));
    /// assert!(matches!(b.clone().free(DVec3::NAN, DVec3::ZERO).try_build(), Err(DynamicsError::InvalidBody { field: "position", .. })));
    /// let brake = Inputs::default().with_angular_damping(-1.0);
    /// assert!(matches!(b.with_inputs(brake).try_build(), Err(DynamicsError::InvalidInput { .. })));
    /// assert!(matches!(Body::from_principal_moments(-1.0, DVec3::ONE).try_build(), Err(DynamicsError::InertiaTensor { .. })));
    /// ```
    pub fn try_build(self) -> Result<Body, DynamicsError> {
        let (mass_properties, rigid) = match self.inertia {
            Inertia::Principal { mass, moments } => {
                let rigid = RigidBody::try_from_principal_moments(moments)?;
                let props =
                    MassProperties::try_new(mass, DVec3::ZERO, DMat3::from_diagonal(moments))?;
                (props, rigid)
            }
            Inertia::Properties(props) => {
                props.validate()?;
                (props, RigidBody::from_mass_properties(&props)?)
            }
        };
        let finite = |field: &'static str, v: DVec3| {
            if v.is_finite() {
                Ok(())
            } else {
                Err(DynamicsError::InvalidBody {
                    field,
                    reason: "must be finite",
                })
            }
        };
        match self.support {
            Support::Free { position, velocity } => {
                finite("position", position)?;
                finite("velocity", velocity)?;
            }
            Support::Pivot {
                pivot_body,
                pivot_world,
            } => {
                finite("pivot_body", pivot_body)?;
                finite("pivot_world", pivot_world)?;
            }
            Support::Ground {
                friction,
                position_xy,
                velocity_xy,
                ..
            } => {
                finite("position", position_xy.extend(0.0))?;
                finite("velocity", velocity_xy.extend(0.0))?;
                friction.validate()?;
            }
            Support::Table { position, velocity } => {
                finite("position", position)?;
                finite("velocity", velocity)?;
            }
        }
        if !self.table.is_empty() && !matches!(self.support, Support::Table { .. }) {
            return Err(DynamicsError::InvalidBody {
                field: "table_contacts",
                reason: "are only for a body on the table (BodyBuilder::on_table)",
            });
        }
        if let Some(others) = &self.others {
            if !matches!(self.support, Support::Ground { .. }) {
                return Err(DynamicsError::InvalidBody {
                    field: "other_contacts",
                    reason: "are only for a body on the ground (BodyBuilder::on_ground)",
                });
            }
            if others.given > MAX_OTHER_CONTACTS {
                return Err(DynamicsError::InvalidContact {
                    parameter: "other_contacts",
                    value: others.given as f64,
                    reason: "too many further contact shapes (at most MAX_OTHER_CONTACTS = 4)",
                });
            }
        }
        PrincipalState::try_from_omega_body(&rigid, self.world_from_body, self.omega_body)?;
        self.inputs.validate()?;
        if matches!(self.support, Support::Table { .. }) {
            // The shapes and the mass properties as the table will take them.
            TableBody::try_new(
                mass_properties.mass,
                mass_properties.inertia,
                self.table.clone(),
                1.0,
            )?;
            check_table_inputs(self.support, &self.inputs)?;
        }
        Ok(Body {
            mass_properties,
            rigid,
            world_from_body: self.world_from_body,
            omega_body: self.omega_body,
            support: self.support,
            others: self.others,
            table: self.table,
            inputs: self.inputs,
        })
    }
}

/// [`DynamicsError::InvalidBody`] (`"inputs"`) for inputs that are not all
/// zero on a body on the table.
pub(super) fn check_table_inputs(support: Support, inputs: &Inputs) -> Result<(), DynamicsError> {
    if matches!(support, Support::Table { .. }) && !inputs.is_none() {
        return Err(DynamicsError::InvalidBody {
            field: "inputs",
            reason: "are not modelled for a body on the table (only gravity and the contacts act)",
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use glam::{DQuat, DVec3};

    use crate::{Body, DynamicsError, Inputs, World};

    /// Inputs given to the builder move the body exactly as the same
    /// inputs given to the world once the body is in it
    /// ([`World::set_inputs`]) or to the built body ([`Body::with_inputs`]):
    /// the same plan and the same states, bit for bit, free and on a pivot.
    #[test]
    fn builder_inputs_equal_set_inputs_after_adding() -> Result<(), DynamicsError> {
        let inputs = Inputs::default()
            .with_torque_world(DVec3::new(0.0, 0.0, 0.3))
            .with_torque_body(DVec3::new(0.1, 0.0, 0.0))
            .with_angular_damping(0.05);
        let handle = Body::from_principal_moments(0.2, DVec3::new(1.0, 2.0, 3.0))
            .world_from_body(DQuat::from_rotation_x(0.4))
            .omega_body(DVec3::new(0.01, 1.0, 0.0));
        let top = handle
            .clone()
            .pivot(DVec3::new(0.0, 0.0, -0.1), DVec3::ZERO);
        for builder in [handle, top] {
            let mut worlds = Vec::new();
            for way in 0..3 {
                let mut world = World::try_new(DVec3::new(0.0, 0.0, -9.81), 0.01)?;
                let id = match way {
                    0 => world.add(builder.clone().with_inputs(inputs.clone()).try_build()?)?,
                    1 => world.add(builder.clone().try_build()?.with_inputs(inputs.clone())?)?,
                    _ => {
                        let id = world.add(builder.clone().try_build()?)?;
                        world.set_inputs(id, inputs.clone())?;
                        id
                    }
                };
                for _ in 0..90 {
                    world.step(1.0 / 60.0)?;
                }
                worlds.push((world.plan(id).copied(), world.state(id)));
            }
            assert!(worlds[0].1.is_some());
            assert_eq!(worlds[0], worlds[1]);
            assert_eq!(worlds[0], worlds[2]);
        }
        Ok(())
    }

    /// A torque given to the builder acts: a world-axes torque τ on a body
    /// at rest gives L = τ t (no damping, no gravity torque on a free body).
    #[test]
    fn builder_torque_changes_the_momentum_by_torque_times_time() -> Result<(), DynamicsError> {
        let torque = DVec3::new(0.2, -0.1, 0.4);
        let body = Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0))
            .with_inputs(Inputs::default().with_torque_world(torque))
            .try_build()?;
        let mut world = World::try_new(DVec3::ZERO, 1.0 / 60.0)?;
        let id = world.add(body)?;
        for _ in 0..120 {
            world.step(1.0 / 60.0)?;
        }
        let state = world.state(id).expect("the body");
        let error = (state.l_world - 2.0 * torque).length();
        assert!(error < 1e-13, "{error:e}");
        Ok(())
    }
}
