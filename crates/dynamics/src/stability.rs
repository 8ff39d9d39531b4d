//! Stability of steady rotation about a principal axis (notes §3.7) and the
//! exact period of the body-frame motion (Landau & Lifshitz, *Mechanics*, §37).

use glam::DVec3;

use crate::elliptic::complete_k_complementary;
use crate::elliptic::dd::Dd;
use crate::{DynamicsError, RigidBody};

/// The linearised behaviour of a small perturbation of steady spin about a
/// principal axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum AxisStability {
    /// The perturbation oscillates with this angular frequency (rad/s): the
    /// axis of the largest or smallest moment.
    Stable {
        /// Angular frequency of the oscillation, rad/s.
        frequency: f64,
    },
    /// The perturbation grows like `e^{λ t}`: the intermediate axis.
    Unstable {
        /// The growth rate λ, 1/s.
        growth_rate: f64,
    },
    /// λ² = 0: two equal moments (symmetric body) or no spin; the linear
    /// analysis does not decide.
    Neutral,
}

/// Linear stability of steady rotation at rate `omega` about principal axis `axis`.
///
/// ```text
/// λ² = Ω² (I_a − I_b)(I_c − I_a) / (I_b I_c),   (a, b, c) = (axis, axis+1, axis+2) mod 3
/// λ² > 0: unstable, growth rate λ;   λ² < 0: stable, frequency √(−λ²)
/// ```
///
/// Any `axis` is taken mod 3 (`usize::MAX` included). For checked inputs
/// see [`try_axis_stability`].
///
/// # Panics
/// Never; for moments or a rate that [`try_axis_stability`] refuses the
/// result is meaningless (e.g. [`AxisStability::Neutral`] for a NaN rate).
///
/// ```
/// use glam::DVec3;
/// use kreisel_dynamics::{axis_stability, AxisStability};
/// let moments = DVec3::new(1.0, 2.0, 3.0);
/// // The intermediate axis is unstable: λ² = 1·(2−3)(1−2)/(3·1) = 1/3.
/// match axis_stability(moments, 1, 1.0) {
///     AxisStability::Unstable { growth_rate } => assert!((growth_rate - (1.0f64 / 3.0).sqrt()).abs() < 1e-15),
///     other => panic!("{other:?}"),
/// }
/// assert!(matches!(axis_stability(moments, 2, 1.0), AxisStability::Stable { .. }));
/// ```
pub fn axis_stability(moments: DVec3, axis: usize, omega: f64) -> AxisStability {
    let m = moments.to_array();
    let a = axis % 3;
    let (b, c) = ((a + 1) % 3, (a + 2) % 3);
    // In the body's unit of inertia, ω factored out: no overflow of ω² I².
    let unit = crate::rigid_body::moment_scale(moments);
    let [ma, mb, mc] = [m[a] / unit, m[b] / unit, m[c] / unit];
    let lambda2 = ((ma - mb) * (mc - ma) / (mb * mc)) * omega * omega;
    if lambda2 > 0.0 {
        AxisStability::Unstable {
            growth_rate: lambda2.sqrt(),
        }
    } else if lambda2 < 0.0 {
        AxisStability::Stable {
            frequency: (-lambda2).sqrt(),
        }
    } else {
        AxisStability::Neutral
    }
}

/// [`axis_stability`] for checked inputs: physical moments, a principal
/// axis 0, 1 or 2, a rate whose `λ` is finite.
///
/// ```text
/// λ² = Ω² (I_a − I_b)(I_c − I_a) / (I_b I_c)
/// ```
///
/// # Errors
/// [`DynamicsError::UnphysicalInertia`] as
/// [`RigidBody::try_from_principal_moments`];
/// [`DynamicsError::InvalidAxis`] for `axis > 2`;
/// [`DynamicsError::InvalidRate`] for a rate that is not finite or whose
/// `λ²` overflows (e.g. `1e300` rad/s).
///
/// ```
/// use glam::DVec3;
/// use kreisel_dynamics::{try_axis_stability, AxisStability};
/// let m = DVec3::new(1.0, 2.0, 3.0);
/// assert!(matches!(try_axis_stability(m, 1, 1.0)?, AxisStability::Unstable { .. }));
/// assert!(try_axis_stability(m, usize::MAX, 1.0).is_err());
/// assert!(try_axis_stability(m, 1, 1e300).is_err());
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
pub fn try_axis_stability(
    moments: DVec3,
    axis: usize,
    omega: f64,
) -> Result<AxisStability, DynamicsError> {
    RigidBody::try_from_principal_moments(moments)?;
    if axis > 2 {
        return Err(DynamicsError::InvalidAxis { axis });
    }
    let result = axis_stability(moments, axis, omega);
    let rate = match result {
        AxisStability::Stable { frequency } => frequency,
        AxisStability::Unstable { growth_rate } => growth_rate,
        AxisStability::Neutral => 0.0,
    };
    if !(omega.is_finite() && rate.is_finite()) {
        return Err(DynamicsError::InvalidRate { omega });
    }
    Ok(result)
}

/// The periodic body-frame motion of a free asymmetric body, in the terms
/// of its elliptic-function solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EllipticMotion {
    /// Index of the principal axis the angular momentum circulates about
    /// (the smallest or the largest moment).
    pub axis: usize,
    /// The frequency scale λ of `sn(λt | m)`, 1/s.
    pub lambda: f64,
    /// The complementary parameter `m_c = 1 − m` (0 on the separatrix).
    pub complementary_parameter: f64,
    /// Period of ω(t) in the body frame, `4K/λ`, s.
    pub period: f64,
    /// Time between successive sign changes of the components that change
    /// sign (the flips of the Dzhanibekov effect), `2K/λ`, s.
    pub half_period: f64,
}

/// The elliptic motion of a free body with angular momentum `l_principal`,
/// or `None` for steady rotation about a principal axis, the separatrix, or a
/// body with two equal moments (whose motion is a uniform precession).
///
/// ```text
/// sort I₁ < I₂ < I₃;  Δⱼ = Σₖ Lₖ² (Iₖ − Iⱼ)/Iₖ = L² − 2EIⱼ  (in double-double: Δ₂ cancels)
/// Δ₁ = L² − 2EI₁,  Δ₂ = L² − 2EI₂,  Δ₃ = 2EI₃ − L²
/// Δ₂ > 0 (about I₃):  λ² = (I₃−I₂)Δ₁/(I₁I₂I₃),  m_c = (I₃−I₁)Δ₂/((I₃−I₂)Δ₁)
/// Δ₂ < 0 (about I₁):  λ² = (I₂−I₁)Δ₃/(I₁I₂I₃),  m_c = (I₃−I₁)(−Δ₂)/((I₂−I₁)Δ₃)
/// period = 4K(m)/λ,   K from m_c (accurate next to the separatrix)
/// ```
///
/// Landau & Lifshitz, *Mechanics*, §37.
///
/// ```
/// use glam::DVec3;
/// use kreisel_dynamics::elliptic_motion;
/// // Hairer–Lubich–Wanner's body: L circulates about the minor axis, period 22.5825742… s.
/// let m = elliptic_motion(DVec3::new(0.5, 0.85, 1.0), DVec3::new(1.1f64.cos(), 0.0, 1.1f64.sin())).unwrap();
/// assert_eq!(m.axis, 0);
/// assert!((m.period - 22.582574242509807).abs() < 1e-12);
/// ```
pub fn elliptic_motion(moments: DVec3, l_principal: DVec3) -> Option<EllipticMotion> {
    let m = moments.to_array();
    let l = l_principal.to_array();
    let mut idx = [0, 1, 2];
    idx.sort_by(|&i, &j| m[i].total_cmp(&m[j]));
    let [i1, i2, i3] = idx.map(|k| m[k]);
    let [l1, l2, l3] = idx.map(|k| l[k]);
    if !(i1 < i2 && i2 < i3) {
        return None;
    }
    let [d1, d2, d3] = energy_deltas([i1, i2, i3], [l1, l2, l3]);
    let product = i1 * i2 * i3;
    let (axis, lambda2, mc) = if d2 > 0.0 {
        (
            idx[2],
            (i3 - i2) * d1 / product,
            (i3 - i1) * d2 / ((i3 - i2) * d1),
        )
    } else if d2 < 0.0 {
        (
            idx[0],
            (i2 - i1) * d3 / product,
            (i3 - i1) * -d2 / ((i2 - i1) * d3),
        )
    } else {
        return None;
    };
    let lambda = lambda2.sqrt();
    // m_c = 1: steady spin about the axis itself (no motion to time).
    if !(lambda > 0.0 && mc > 0.0 && mc < 1.0 + 1e-15) {
        return None;
    }
    let k = complete_k_complementary(mc.min(1.0));
    Some(EllipticMotion {
        axis,
        lambda,
        complementary_parameter: mc,
        period: 4.0 * k / lambda,
        half_period: 2.0 * k / lambda,
    })
}

/// The three differences `|L² − 2E Iⱼ|` of a body with sorted moments
/// `I₁ < I₂ < I₃`, signed as `[Δ₁ ≥ 0, Δ₂, Δ₃ ≥ 0]`.
///
/// ```text
/// Δ₁ = L² − 2EI₁,  Δ₂ = L² − 2EI₂,  Δ₃ = 2EI₃ − L²,   Δⱼ = ±Σₖ Lₖ² (Iₖ − Iⱼ)/Iₖ
/// ```
///
/// Δ₂ is a difference of two terms that nearly cancel next to the
/// separatrix: all three are evaluated in double-double from the exact
/// inputs, so each keeps full relative accuracy however small it is.
pub(crate) fn energy_deltas(moments: [f64; 3], l: [f64; 3]) -> [f64; 3] {
    let [i1, i2, i3] = moments;
    let [l1, l2, l3] = l;
    let term = |l: f64, ik: f64, ij: f64| {
        let l = Dd::from_f64(l);
        l.mul(l)
            .mul(Dd::from_f64(ik).add(Dd::from_f64(ij).neg()))
            .div(Dd::from_f64(ik))
    };
    let d1 = term(l2, i2, i1).add(term(l3, i3, i1)).to_f64();
    let d2 = term(l1, i1, i2).add(term(l3, i3, i2)).to_f64();
    let d3 = term(l1, i1, i3).neg().add(term(l2, i2, i3).neg()).to_f64();
    [d1, d2, d3]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Regression: `axis_stability(_, usize::MAX, _)` overflowed computing
    /// `axis + 1`. Any index is taken mod 3 (usize::MAX ≡ 0), and the
    /// checked twin refuses it.
    #[test]
    fn any_axis_index_is_safe() {
        let m = DVec3::new(1.0, 2.0, 3.0);
        assert_eq!(
            axis_stability(m, usize::MAX, 2.0),
            axis_stability(m, 0, 2.0)
        );
        assert_eq!(
            axis_stability(m, usize::MAX - 1, 2.0),
            axis_stability(m, 2, 2.0)
        );
        assert_eq!(
            try_axis_stability(m, usize::MAX, 2.0),
            Err(DynamicsError::InvalidAxis { axis: usize::MAX })
        );
        // λ² = Ω² · O(1) no longer overflows through I² for huge moments.
        assert!(matches!(
            try_axis_stability(m * 1e200, 1, 1.0),
            Ok(AxisStability::Unstable { .. })
        ));
        assert!(try_axis_stability(m, 1, f64::NAN).is_err());
        assert!(try_axis_stability(DVec3::new(1.0, 1.0, 3.0), 1, 1.0).is_err());
    }
}
