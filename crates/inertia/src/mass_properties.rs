//! Mass, centre of mass and inertia tensor of a rigid body; parallel-axis
//! shifts, rotations and composition of parts.

use core::iter::Sum;
use core::ops::Add;

use glam::{DMat3, DQuat, DVec3};

use crate::{InertiaError, MassPropertiesError, PrincipalAxes};

/// Mass properties of a rigid body in its own (body) axes.
///
/// ```text
/// mass m,  centre of mass c,  I_ab = Σ m_i (r_i² δ_ab − r_ia r_ib),  r_i = x_i − c
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MassProperties {
    /// Mass, kg.
    pub mass: f64,
    /// Centre of mass in body coordinates, m.
    pub center_of_mass: DVec3,
    /// Inertia tensor about the centre of mass, body axes, kg·m².
    pub inertia: DMat3,
}

/// The tensor that a point mass `m` at offset `d` adds about the origin.
///
/// ```text
/// m (|d|² E − d dᵀ)
/// ```
#[inline]
fn point_tensor(mass: f64, d: DVec3) -> DMat3 {
    let outer = DMat3::from_cols(d * d.x, d * d.y, d * d.z);
    (DMat3::IDENTITY * d.length_squared() - outer) * mass
}

impl MassProperties {
    /// Builds mass properties, checking that they describe a physical body.
    ///
    /// # Errors
    /// [`MassPropertiesError::Mass`] for a mass that is not positive and
    /// finite; the other [`MassPropertiesError`]s for a centre or tensor
    /// that is not finite, a tensor not symmetric (to 1e-12 relative), with
    /// a negative principal moment, or breaking the triangle inequality
    /// `I₁ + I₂ ≥ I₃` (beyond 1e-12 relative).
    ///
    /// ```
    /// use glam::{DMat3, DVec3};
    /// use kreisel_inertia::MassProperties;
    /// let ok = MassProperties::try_new(2.0, DVec3::ZERO, DMat3::from_diagonal(DVec3::new(1.0, 1.0, 1.5)));
    /// assert!(ok.is_ok());
    /// let bad = MassProperties::try_new(2.0, DVec3::ZERO, DMat3::from_diagonal(DVec3::new(1.0, 1.0, 3.0)));
    /// assert!(bad.is_err());
    /// ```
    pub fn try_new(
        mass: f64,
        center_of_mass: DVec3,
        inertia: DMat3,
    ) -> Result<Self, MassPropertiesError> {
        let props = Self {
            mass,
            center_of_mass,
            inertia,
        };
        props.validate()?;
        Ok(props)
    }

    /// Builds mass properties from values known to be physical.
    ///
    /// # Panics
    /// On input that [`MassProperties::try_new`] rejects.
    ///
    /// ```
    /// use glam::{DMat3, DVec3};
    /// use kreisel_inertia::MassProperties;
    /// let p = MassProperties::new(1.0, DVec3::ZERO, DMat3::IDENTITY);
    /// assert_eq!(p.mass, 1.0);
    /// ```
    pub fn new(mass: f64, center_of_mass: DVec3, inertia: DMat3) -> Self {
        match Self::try_new(mass, center_of_mass, inertia) {
            Ok(p) => p,
            Err(e) => panic!("{e}"),
        }
    }

    /// Checks that the properties are physical (see [`MassProperties::try_new`]).
    ///
    /// ```text
    /// m > 0,  I = Iᵀ,  I₁ ≥ 0,  I₁ + I₂ ≥ I₃
    /// ```
    ///
    /// # Errors
    /// As [`MassProperties::try_new`].
    ///
    /// ```
    /// use kreisel_inertia::MassProperties;
    /// assert!(MassProperties::solid_sphere(1000.0, 0.1)?.validate().is_ok());
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn validate(&self) -> Result<(), MassPropertiesError> {
        if !(self.mass > 0.0 && self.mass.is_finite()) {
            return Err(MassPropertiesError::Mass { value: self.mass });
        }
        if !self.center_of_mass.is_finite() {
            return Err(MassPropertiesError::CentreOfMassNotFinite);
        }
        if !self.inertia.is_finite() {
            return Err(MassPropertiesError::TensorNotFinite);
        }
        let i = self.inertia;
        let scale = i
            .to_cols_array()
            .iter()
            .fold(0.0_f64, |a, v| a.max(v.abs()));
        let tol = 1e-12 * scale;
        let asymmetry = (i - i.transpose())
            .to_cols_array()
            .iter()
            .fold(0.0_f64, |a, v| a.max(v.abs()));
        if asymmetry > tol {
            return Err(MassPropertiesError::NotSymmetric { asymmetry });
        }
        let moments = PrincipalAxes::from_tensor(i).moments;
        if moments.x < -tol {
            return Err(MassPropertiesError::NegativeMoment { moment: moments.x });
        }
        if moments.x + moments.y < moments.z - tol {
            return Err(MassPropertiesError::TriangleInequality { moments });
        }
        Ok(())
    }

    /// A point mass.
    ///
    /// ```text
    /// c = position,  I = 0
    /// ```
    ///
    /// ```
    /// use glam::{DMat3, DVec3};
    /// use kreisel_inertia::MassProperties;
    /// let p = MassProperties::point(2.0, DVec3::X);
    /// assert_eq!(p.inertia, DMat3::ZERO);
    /// assert_eq!(p.inertia_about_point(DVec3::ZERO), DMat3::from_diagonal(DVec3::new(0.0, 2.0, 2.0)));
    /// ```
    pub fn point(mass: f64, position: DVec3) -> Self {
        Self {
            mass,
            center_of_mass: position,
            inertia: DMat3::ZERO,
        }
    }

    /// A rigid set of point masses (the notes' discrete formula, §3.3).
    ///
    /// ```text
    /// m = Σ m_i,  c = Σ m_i x_i / m,  I_ab = Σ m_i (r_i² δ_ab − r_ia r_ib),  r_i = x_i − c
    /// ```
    ///
    /// # Errors
    /// [`InertiaError::EmptyMesh`] for no points, [`InertiaError::NonPositive`]
    /// for a point mass that is not positive and finite,
    /// [`InertiaError::NonFiniteVertex`] for a non-finite position,
    /// [`InertiaError::NotRepresentable`] when the total mass or a tensor
    /// element overflows f64.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::MassProperties;
    /// // Two unit masses 2 m apart: I about the perpendicular axes = 2 · 1² = 2.
    /// let p = MassProperties::from_point_masses(&[(1.0, DVec3::new(-1.0, 0.0, 0.0)), (1.0, DVec3::X)])?;
    /// assert_eq!(p.inertia.y_axis.y, 2.0);
    /// assert_eq!(p.inertia.x_axis.x, 0.0);
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn from_point_masses(points: &[(f64, DVec3)]) -> Result<Self, InertiaError> {
        if points.is_empty() {
            return Err(InertiaError::EmptyMesh {
                vertices: 0,
                triangles: 0,
            });
        }
        for (vertex, &(m, x)) in points.iter().enumerate() {
            check_positive("point mass", m)?;
            if !x.is_finite() {
                return Err(InertiaError::NonFiniteVertex { vertex });
            }
        }
        // Sum about the first point, so far-away clouds keep their digits.
        let origin = points[0].1;
        let mass: f64 = points.iter().map(|p| p.0).sum();
        let first: DVec3 = points.iter().map(|&(m, x)| (x - origin) * m).sum();
        let c = first / mass;
        let inertia = points.iter().fold(DMat3::ZERO, |acc, &(m, x)| {
            acc + point_tensor(m, x - origin - c)
        });
        representable(Self {
            mass,
            center_of_mass: origin + c,
            inertia,
        })
    }

    /// The inertia tensor about an arbitrary point (parallel-axis theorem,
    /// notes §3.4).
    ///
    /// ```text
    /// I_p = I_c + m (|d|² E − d dᵀ),   d = c − p
    /// ```
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::MassProperties;
    /// let rod = MassProperties::solid_box(1.0, DVec3::new(2.0, 0.01, 0.01))?;
    /// // About one end: m L²/3 (plus the tiny thickness terms).
    /// let end = rod.inertia_about_point(DVec3::new(-1.0, 0.0, 0.0));
    /// assert!((end.z_axis.z - rod.mass * 4.0 / 3.0).abs() < 1e-3 * rod.mass);
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn inertia_about_point(&self, point: DVec3) -> DMat3 {
        self.inertia + point_tensor(self.mass, self.center_of_mass - point)
    }

    /// Mass properties from a tensor known about some point (the parallel-axis
    /// theorem backwards).
    ///
    /// ```text
    /// I_c = I_p − m (|d|² E − d dᵀ),   d = c − p
    /// ```
    ///
    /// # Errors
    /// As [`MassProperties::try_new`], for the resulting tensor about the
    /// centre of mass.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::MassProperties;
    /// let ball = MassProperties::solid_sphere(1000.0, 0.1)?.translated(DVec3::new(0.0, 0.0, 2.0));
    /// let pivot = DVec3::ZERO;
    /// let about_pivot = ball.inertia_about_point(pivot);
    /// let back = MassProperties::from_inertia_about_point(ball.mass, ball.center_of_mass, about_pivot, pivot)?;
    /// // The shift back cancels m d² against I_p: expect ulps of I_p, not of I_c.
    /// let tol = 4.0 * f64::EPSILON * about_pivot.x_axis.x;
    /// assert!((back.inertia - ball.inertia).abs().to_cols_array().iter().all(|e| *e < tol));
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn from_inertia_about_point(
        mass: f64,
        center_of_mass: DVec3,
        inertia_about_point: DMat3,
        point: DVec3,
    ) -> Result<Self, MassPropertiesError> {
        Self::try_new(
            mass,
            center_of_mass,
            inertia_about_point - point_tensor(mass, center_of_mass - point),
        )
    }

    /// The same body moved by `offset` (the tensor about the centre of mass
    /// does not change).
    ///
    /// ```text
    /// c ↦ c + offset
    /// ```
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::MassProperties;
    /// let p = MassProperties::point(1.0, DVec3::ZERO).translated(DVec3::Y);
    /// assert_eq!(p.center_of_mass, DVec3::Y);
    /// ```
    pub fn translated(self, offset: DVec3) -> Self {
        Self {
            center_of_mass: self.center_of_mass + offset,
            ..self
        }
    }

    /// The same body rotated about the origin: the properties of a part whose
    /// body coordinates map to the new frame by `rotation`.
    ///
    /// ```text
    /// c ↦ R c,   I ↦ R I Rᵀ
    /// ```
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_inertia::MassProperties;
    /// let rod = MassProperties::solid_box(1.0, DVec3::new(2.0, 0.1, 0.1))?;
    /// let turned = rod.rotated(DQuat::from_rotation_z(core::f64::consts::FRAC_PI_2));
    /// assert!((turned.inertia.x_axis.x - rod.inertia.y_axis.y).abs() < 1e-15);
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn rotated(self, rotation: DQuat) -> Self {
        let r = DMat3::from_quat(rotation);
        let inertia = r * self.inertia * r.transpose();
        Self {
            mass: self.mass,
            center_of_mass: rotation * self.center_of_mass,
            // Keep the tensor exactly symmetric.
            inertia: (inertia + inertia.transpose()) * 0.5,
        }
    }

    /// A part placed at a pose in the assembly frame: rotated, then moved.
    ///
    /// ```text
    /// c ↦ R c + t,   I ↦ R I Rᵀ
    /// ```
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_inertia::MassProperties;
    /// let p = MassProperties::point(1.0, DVec3::X).placed(DQuat::from_rotation_z(core::f64::consts::FRAC_PI_2), DVec3::Z);
    /// assert!((p.center_of_mass - DVec3::new(0.0, 1.0, 1.0)).length() < 1e-15);
    /// ```
    pub fn placed(self, rotation: DQuat, translation: DVec3) -> Self {
        self.rotated(rotation).translated(translation)
    }

    /// The same shape with its mass (and so its tensor) scaled to `mass`.
    ///
    /// ```text
    /// I ↦ I · mass / m,   m ↦ mass
    /// ```
    ///
    /// # Errors
    /// [`InertiaError::NonPositive`] if `mass` is not positive and finite;
    /// [`InertiaError::NotRepresentable`] if the scaled tensor overflows.
    ///
    /// ```
    /// use kreisel_inertia::MassProperties;
    /// let p = MassProperties::solid_sphere(1.0, 1.0)?.with_mass(2.0)?;
    /// assert!((p.inertia.x_axis.x - 0.8).abs() < 1e-15);
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn with_mass(self, mass: f64) -> Result<Self, InertiaError> {
        check_positive("mass", mass)?;
        representable(Self {
            mass,
            inertia: self.inertia * (mass / self.mass),
            ..self
        })
    }

    /// Principal moments (ascending) and the right-handed principal frame.
    ///
    /// ```text
    /// I = R diag(I₁, I₂, I₃) Rᵀ
    /// ```
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::MassProperties;
    /// let b = MassProperties::solid_box(1.0, DVec3::new(3.0, 1.0, 2.0))?;
    /// let p = b.principal();
    /// assert!(p.moments.x <= p.moments.y && p.moments.y <= p.moments.z);
    /// assert_eq!(p.axes.z_axis.abs(), DVec3::Y); // the largest moment is about y (3 × 2 face)
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn principal(&self) -> PrincipalAxes {
        PrincipalAxes::from_tensor(self.inertia)
    }
}

impl Add for MassProperties {
    type Output = MassProperties;

    /// Composes two parts given in the same frame into one rigid body.
    ///
    /// ```text
    /// m = m₁ + m₂,  c = (m₁c₁ + m₂c₂)/m,  I = Σ_k [I_k + m_k (|d_k|² E − d_k d_kᵀ)],  d_k = c_k − c
    /// ```
    fn add(self, other: MassProperties) -> MassProperties {
        let mass = self.mass + other.mass;
        // Centre of mass relative to self's, so distant assemblies keep digits.
        let c = self.center_of_mass
            + (other.center_of_mass - self.center_of_mass) * (other.mass / mass);
        MassProperties {
            mass,
            center_of_mass: c,
            inertia: self.inertia_about_point(c) + other.inertia_about_point(c),
        }
    }
}

impl Sum for MassProperties {
    /// Composes many parts; the sum of no parts is a zero-mass point at the origin.
    fn sum<I: Iterator<Item = MassProperties>>(iter: I) -> MassProperties {
        iter.fold(None, |acc: Option<MassProperties>, p| {
            Some(match acc {
                Some(a) => a + p,
                None => p,
            })
        })
        .unwrap_or(MassProperties::point(0.0, DVec3::ZERO))
    }
}

/// `Ok` for properties with a positive finite mass, a finite centre of mass
/// and a finite tensor, else [`InertiaError::NotRepresentable`] (what a
/// closed form gives when its inputs overflow or underflow f64).
pub(crate) fn representable(props: MassProperties) -> Result<MassProperties, InertiaError> {
    let worst = |values: &[f64]| values.iter().copied().find(|v| !v.is_finite());
    if !(props.mass > 0.0 && props.mass.is_finite()) {
        return Err(InertiaError::NotRepresentable {
            quantity: "mass",
            value: props.mass,
        });
    }
    if let Some(value) = worst(&props.center_of_mass.to_array()) {
        return Err(InertiaError::NotRepresentable {
            quantity: "centre of mass",
            value,
        });
    }
    if let Some(value) = worst(&props.inertia.to_cols_array()) {
        return Err(InertiaError::NotRepresentable {
            quantity: "inertia tensor",
            value,
        });
    }
    Ok(props)
}

/// `Ok` for a positive finite value, else [`InertiaError::NonPositive`].
pub(crate) fn check_positive(quantity: &'static str, value: f64) -> Result<f64, InertiaError> {
    if value > 0.0 && value.is_finite() {
        Ok(value)
    } else {
        Err(InertiaError::NonPositive { quantity, value })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn max_abs(m: DMat3) -> f64 {
        m.to_cols_array()
            .iter()
            .fold(0.0_f64, |a, v| a.max(v.abs()))
    }

    #[test]
    fn parts_summed_equal_the_whole() {
        // A 2×1×1 box = two unit cubes side by side.
        let whole = MassProperties::solid_box(3.0, DVec3::new(2.0, 1.0, 1.0)).unwrap();
        let half = MassProperties::solid_box(3.0, DVec3::ONE).unwrap();
        let sum = half.translated(DVec3::new(-0.5, 0.0, 0.0))
            + half.translated(DVec3::new(0.5, 0.0, 0.0));
        assert!((sum.mass - whole.mass).abs() < 1e-15);
        assert!(sum.center_of_mass.length() < 1e-16);
        assert!(max_abs(sum.inertia - whole.inertia) < 1e-15);
        let listed: MassProperties = [
            half.translated(-DVec3::X * 0.5),
            half.translated(DVec3::X * 0.5),
        ]
        .into_iter()
        .sum();
        assert_eq!(listed, sum);
    }

    #[test]
    fn parallel_axis_both_ways_and_rotation() {
        let b = MassProperties::solid_box(2.0, DVec3::new(1.0, 2.0, 3.0))
            .unwrap()
            .placed(
                DQuat::from_euler(glam::EulerRot::XYZ, 0.3, -0.4, 1.0),
                DVec3::new(1.0, -2.0, 0.5),
            );
        let p = DVec3::new(0.2, 0.1, -0.3);
        let back = MassProperties::from_inertia_about_point(
            b.mass,
            b.center_of_mass,
            b.inertia_about_point(p),
            p,
        )
        .unwrap();
        assert!(max_abs(back.inertia - b.inertia) < 1e-13);
        // Rotating about the origin keeps the principal moments.
        let m0 = b.principal().moments;
        let m1 = b.rotated(DQuat::from_rotation_y(0.8)).principal().moments;
        assert!((m0 - m1).abs().max_element() < 1e-13);
    }

    #[test]
    fn point_masses_match_the_discrete_formula() {
        // Four masses at the corners of a square in the xy plane.
        let pts = [
            (1.0, DVec3::new(1.0, 1.0, 0.0)),
            (2.0, DVec3::new(-1.0, 1.0, 0.0)),
            (3.0, DVec3::new(-1.0, -1.0, 0.0)),
            (4.0, DVec3::new(1.0, -1.0, 0.0)),
        ];
        let p = MassProperties::from_point_masses(&pts).unwrap();
        let c = pts.iter().map(|&(m, x)| x * m).sum::<DVec3>() / 10.0;
        let mut expect = DMat3::ZERO;
        for &(m, x) in &pts {
            let r = x - c;
            for a in 0..3 {
                for b in 0..3 {
                    let delta = if a == b { 1.0 } else { 0.0 };
                    expect.col_mut(b)[a] += m * (r.length_squared() * delta - r[a] * r[b]);
                }
            }
        }
        assert!((p.center_of_mass - c).length() < 1e-15);
        assert!(max_abs(p.inertia - expect) < 1e-14);
        // Planar body: perpendicular-axis theorem Izz = Ixx + Iyy.
        assert!((p.inertia.z_axis.z - p.inertia.x_axis.x - p.inertia.y_axis.y).abs() < 1e-14);
        assert!(p.validate().is_ok());
    }

    #[test]
    fn validation_rejects_unphysical() {
        assert!(MassProperties::try_new(-1.0, DVec3::ZERO, DMat3::IDENTITY).is_err());
        assert!(MassProperties::try_new(1.0, DVec3::ZERO, DMat3::IDENTITY * -1.0).is_err());
        let mut asym = DMat3::IDENTITY;
        asym.x_axis.y = 0.1;
        assert!(MassProperties::try_new(1.0, DVec3::ZERO, asym).is_err());
        assert!(
            MassProperties::try_new(
                1.0,
                DVec3::ZERO,
                DMat3::from_diagonal(DVec3::new(1.0, 1.0, 2.0))
            )
            .is_ok()
        );
    }

    #[test]
    fn overflowing_point_masses_are_errors() {
        // Regression: masses of 1e200 at 1e200 m gave Ok with an infinite tensor.
        let far = MassProperties::from_point_masses(&[
            (1e200, DVec3::new(-1e200, 0.0, 0.0)),
            (1e200, DVec3::new(1e200, 0.0, 0.0)),
        ]);
        assert!(
            matches!(far, Err(InertiaError::NotRepresentable { .. })),
            "{far:?}"
        );
        let heavy = MassProperties::from_point_masses(&[(1e308, DVec3::ZERO), (1e308, DVec3::X)]);
        assert!(
            matches!(heavy, Err(InertiaError::NotRepresentable { .. })),
            "{heavy:?}"
        );
        let scaled = MassProperties::solid_box(1.0, DVec3::splat(1e50))
            .unwrap()
            .with_mass(1e300);
        assert!(
            matches!(scaled, Err(InertiaError::NotRepresentable { .. })),
            "{scaled:?}"
        );
    }
}
