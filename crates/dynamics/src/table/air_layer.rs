//! [`AirLayer`]: Moffatt's viscous air layer between a disk and the
//! table — the dissipation that brings Euler's disk down to rest in
//! finite time.
//!
//! ```text
//! h = a sin α + g⁺ + h₀              (the layer under the rim: tilt α, rim gap g⁺ ≥ 0, floor h₀)
//! ω_⊥ = ω − (ω·n) n = n × ṅ           (the disk's tilting rate)
//! τ = −(π μ_air a⁶ / (4 h³)) ω_⊥       (torque about the centre of mass)
//! ```
//!
//! Moffatt (Nature 404, 2000, 833) puts the viscous dissipation of the
//! thin air layer under a disk rolling at small tilt `α`, precessing at
//! `Ω`, at `Φ = π μ a³ Ω² / (4 α)` for a layer of thickness `h = a α`
//! (the rate that, with the rolling disk's `E = (3/2) M g a sin α` and
//! `Ω² sin α = 4 g / a`, gives his `α³ = (2π μ a / M)(t₀ − t)` and
//! `t₀ = α₀³ M / (2π μ a)`). Here that dissipation is lumped into a torque
//! opposing the tilting rate: on the rolling motion `|ω_⊥| = Ω sin α`, so
//! the torque's power `π μ a⁶ Ω² sin²α / (4 h³)` is Moffatt's `Φ` for
//! `h₀ = 0`. The floor `h₀` (roughness, the rim's rounding) keeps the
//! torque finite when the disk lies flat: Moffatt's law holds while
//! `a sin α ≫ h₀`; below, the layer damps the last tilting exponentially.
//! The torque is perpendicular to the axis `n`, so a disk on its face
//! (`ω ∥ n`) feels none.

use glam::{DQuat, DVec3};

use crate::{DiskContact, DynamicsError};

/// Moffatt's air layer under a disk rim: the air's dynamic viscosity
/// `μ_air` (Pa s) and the layer's floor `h₀` (m).
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{AirLayer, DiskContact};
/// let air = AirLayer::try_new(1.8e-5, 1e-6)?;
/// let disk = DiskContact::try_new(0.0375, DVec3::ZERO, DVec3::Z)?;
/// // Tilted by 0.1 rad about x, rolling over: the torque opposes the tilting rate.
/// let q = DQuat::from_rotation_x(0.1);
/// let omega = DVec3::X;
/// let torque = air.torque_world(&disk, q, omega, 0.0);
/// let h = 0.0375 * 0.1f64.sin() + 1e-6;
/// let c = std::f64::consts::PI * 1.8e-5 * 0.0375f64.powi(6) / (4.0 * h * h * h);
/// assert!((torque + c * DVec3::X).length() < 1e-12 * c);
/// assert!(AirLayer::try_new(-1.0, 0.0).is_err());
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AirLayer {
    viscosity: f64,
    floor: f64,
}

impl AirLayer {
    /// The layer of dynamic viscosity `viscosity` (Pa s; air at 20 °C:
    /// 1.8·10⁻⁵) over a floor `floor` (m; > 0).
    ///
    /// # Errors
    /// [`DynamicsError::InvalidContact`] naming `"air_viscosity"` for a
    /// viscosity that is negative or not finite, `"air_gap"` for a floor
    /// that is not positive and finite.
    pub fn try_new(viscosity: f64, floor: f64) -> Result<Self, DynamicsError> {
        if !(viscosity.is_finite() && viscosity >= 0.0) {
            return Err(DynamicsError::InvalidContact {
                parameter: "air_viscosity",
                value: viscosity,
                reason: "the air's viscosity must be finite and not negative",
            });
        }
        if !(floor.is_finite() && floor > 0.0) {
            return Err(DynamicsError::InvalidContact {
                parameter: "air_gap",
                value: floor,
                reason: "the air layer's floor must be finite and positive",
            });
        }
        Ok(Self { viscosity, floor })
    }

    /// `μ_air`, Pa s.
    pub fn viscosity(&self) -> f64 {
        self.viscosity
    }

    /// `h₀`, m.
    pub fn floor(&self) -> f64 {
        self.floor
    }

    /// The layer's torque on `disk` (world axes, about the centre of
    /// mass) at the attitude `world_from_body`, angular velocity
    /// `omega_world` and rim gap `gap` (the module's formula).
    pub fn torque_world(
        &self,
        disk: &DiskContact,
        world_from_body: DQuat,
        omega_world: DVec3,
        gap: f64,
    ) -> DVec3 {
        let n = world_from_body.normalize() * disk.normal_body();
        let a = disk.radius();
        let h = a * DVec3::Z.cross(n).length() + gap.max(0.0) + self.floor;
        let omega_perp = omega_world - omega_world.dot(n) * n;
        -(std::f64::consts::PI * self.viscosity * a.powi(6) / (4.0 * h * h * h)) * omega_perp
    }
}
