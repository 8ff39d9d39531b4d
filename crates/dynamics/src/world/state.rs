//! [`BodyState`]: what a [`crate::World`] reports about one body at its
//! current time, and [`BodyId`], the handle that names the body.

use glam::{DQuat, DVec3};

/// The handle of a body in a [`crate::World`], returned by
/// [`crate::World::add`]: bodies are numbered from 0 in the order added.
///
/// ```
/// use glam::DVec3;
/// use kreisel_dynamics::{Body, World};
/// let mut world = World::try_new(DVec3::ZERO, 0.01)?;
/// let a = world.add(Body::from_principal_moments(1.0, DVec3::ONE).try_build()?)?;
/// let b = world.add(Body::from_principal_moments(1.0, DVec3::ONE).try_build()?)?;
/// assert_eq!((a.index(), b.index()), (0, 1));
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct BodyId(pub(crate) usize);

impl BodyId {
    /// The body's number, from 0 in the order added.
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, World};
    /// let mut world = World::try_new(glam::DVec3::ZERO, 0.01)?;
    /// let id = world.add(Body::from_principal_moments(1.0, glam::DVec3::ONE).try_build()?)?;
    /// assert_eq!(id.index(), 0);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn index(self) -> usize {
        self.0
    }
}

/// One body's state at the world's current time ([`crate::World::state`]).
///
/// ```text
/// free:   energy = ½ L·I⁻¹L + ½ m |v|² − m g·x,    l_world about the centre of mass
/// pivot:  energy = ½ L·J⁻¹L − m g·(p + R c),     l_world about the pivot p (J about it)
/// forced: energy = ½ L·I⁻¹L + ½ m |v|² − m g·x,    x, v from the splitting
/// driven top (pivot with inputs): energy = ½ L·J⁻¹L − m g·x,  x = p + R c
/// on the ground: energy = ½ L·ω + ½ m |v|² + m g z,    l_world about the centre of mass
/// ```
///
/// For a body with applied inputs ([`crate::Plan::Forced`]) the energy is
/// the mechanical energy ([`crate::ForcedBody::mechanical_energy`]): not
/// conserved, its change from `t₀` to `t` is the work of the inputs
/// (damping included), `∫ (τ·ω + F·v) dt`, to the method's accuracy.
///
/// ```
/// use glam::DVec3;
/// use kreisel_dynamics::{Body, World};
/// let mut world = World::try_new(DVec3::new(0.0, 0.0, -9.81), 0.01)?;
/// let id = world.add(Body::from_principal_moments(2.0, DVec3::ONE).free(DVec3::ZERO, DVec3::new(1.0, 0.0, 0.0)).try_build()?)?;
/// let s = world.state(id).unwrap();
/// assert_eq!(s.energy, 1.0);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyState {
    /// The world time, s.
    pub time: f64,
    /// Attitude, body → world.
    pub world_from_body: DQuat,
    /// Angular velocity in body axes, rad/s.
    pub omega_body: DVec3,
    /// Angular momentum in world axes, kg·m²/s: about the centre of mass,
    /// or about the pivot for a body with one.
    pub l_world: DVec3,
    /// Total energy, J (see above).
    pub energy: f64,
    /// Centre of mass, world axes, m.
    pub position: DVec3,
    /// Its velocity, world axes, m/s.
    pub velocity: DVec3,
}

impl BodyState {
    /// The angular momentum in body axes, kg·m²/s (about the same point as
    /// [`BodyState::l_world`]).
    ///
    /// ```text
    /// L_body = q⁻¹ L_world q,   q = world_from_body
    /// ```
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_dynamics::BodyState;
    /// let s = BodyState {
    ///     time: 0.0,
    ///     world_from_body: DQuat::from_rotation_z(std::f64::consts::FRAC_PI_2),
    ///     omega_body: DVec3::ZERO,
    ///     l_world: DVec3::Y,
    ///     energy: 0.0,
    ///     position: DVec3::ZERO,
    ///     velocity: DVec3::ZERO,
    /// };
    /// // The world's y axis is the body's x axis after a quarter turn about z.
    /// assert!((s.l_body() - DVec3::X).length() < 1e-15);
    /// ```
    pub fn l_body(&self) -> DVec3 {
        self.world_from_body.inverse() * self.l_world
    }
}
