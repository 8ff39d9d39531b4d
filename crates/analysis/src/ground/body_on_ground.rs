//! [`BodyOnGround`]: any body the engine puts on the ground
//! (`kreisel_dynamics::GroundTop`: a sphere, a disk rim or an ellipsoid,
//! with any friction law) as a [`VectorField`] in body axes, the ground's
//! translations and the rotations about the vertical reduced away.

use glam::DVec3;
use kreisel_dynamics::{Body, Friction, GroundTop};

use super::algebra::{V3, cross, dot, mat_vec, sub};
use super::contact_equations::{ContactBody, ground_top_of};
use super::surface::Surface;
use crate::linearisation::relative_residual;
use crate::vector_field::jacobian;
use crate::{
    AnalysisError, Eigenvalue, STEADY_RESIDUAL, Scalar, VectorField, ZeroMode, ZeroModeKind,
};

/// A body touching the plane `z = 0` under gravity `−g ẑ`, in body axes:
/// the up vector `γ = Aᵀẑ`, the angular velocity `ω` and — unless it
/// rolls without slipping — the centre of mass's velocity `v`.
///
/// ```text
/// rolling:       x = (γ, ω) ∈ ℝ⁶,      γ̇ = γ × ω,   ω̇ from the rolling constraint
/// friction law:  x = (γ, ω, v) ∈ ℝ⁹,   γ̇ = γ × ω,   ω̇, v̇ with the normal force N
/// conserved:     |γ|² (Casimir);  γ·v_P (the contact stays on the plane, friction laws);
///                λ = Iω·r (Jellett, a sphere centred on an axis of symmetry of I);
///                E (rolling, frictionless);  L·γ (frictionless)
/// ```
///
/// (equations at the crate-private `ContactBody`; `r` from the contact to
/// the centre of mass). The position on the plane and the heading are
/// gone (the ground's translations and rotations about the vertical), so
/// a body spinning steadily about the vertical is an equilibrium. The
/// energy is exactly conserved on `γ·v_P = 0`, and with `N = m g` at
/// every steady motion its gradient is a left null vector there
/// (Marsden & Ratiu §1.7; Bou-Rabee, Marsden & Romero, SIAM J. Appl. Dyn.
/// Syst. 3:352 (2004) for the tippe top's integrals). Without friction the
/// horizontal velocity of the centre of mass is constant in space, so
/// `|v_h|²` is conserved too; it is left out: at every spinning steady
/// motion `v_h = 0` and its gradient vanishes (no zero of its own — the
/// velocity is a mode at `±iΩ`, a fixed vector seen from the turning
/// body), and at a state found by Newton's method a gradient of 1e-17
/// would be taken for an independent one.
///
/// ```
/// use glam::{DMat3, DVec3};
/// use kreisel_analysis::{BodyOnGround, Linearisation, Verdict};
/// use kreisel_dynamics::{Friction, GroundTop, SphereContact};
/// // A homogeneous ball rolling in place about the vertical: neutral, as
/// // every such spin (any axis would do).
/// let ball = SphereContact::try_new(0.03, DVec3::ZERO)?;
/// let i = DMat3::from_diagonal(DVec3::splat(0.4 * 0.2 * 0.03 * 0.03));
/// let top = GroundTop::try_new(0.2, i, ball, Friction::Rolling, 9.81)?;
/// let field = BodyOnGround::try_from_ground_top(&top)?;
/// let x = field.spinning_about_vertical(DVec3::Z, 10.0)?;
/// assert_eq!(x, vec![0.0, 0.0, 1.0, 0.0, 0.0, 10.0]);
/// let lin = Linearisation::try_new(&field, &x)?;
/// assert!(!matches!(lin.verdict, Verdict::Unstable { .. }));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyOnGround {
    body: ContactBody,
    /// The axis of symmetry of `I` through a sphere's centre, if any
    /// (Jellett's integral, rotations about it).
    symmetry_axis: Option<DVec3>,
}

impl BodyOnGround {
    /// The engine's body on the ground.
    ///
    /// # Errors
    /// [`AnalysisError::Parameter`] (`inputs`) if the top has applied
    /// loads.
    pub fn try_from_ground_top(top: &GroundTop) -> Result<Self, AnalysisError> {
        let body = ContactBody::of(top)?;
        let symmetry_axis = match body.surface {
            Surface::Sphere { .. } => {
                let c = body.surface.center();
                let candidates: Vec<DVec3> = if c.length() > 0.0 {
                    vec![c.normalize()]
                } else {
                    vec![DVec3::Z, DVec3::X, DVec3::Y]
                };
                candidates.into_iter().find(|&a| body.symmetric_about(a))
            }
            Surface::Disk { .. } | Surface::Ellipsoid { .. } => None,
        };
        Ok(Self {
            body,
            symmetry_axis,
        })
    }

    /// A scene's body on the ground ([`kreisel_dynamics::Support::Ground`]) in a world of
    /// gravity `gravity` (which must point along −z): its mass properties,
    /// shape and friction, as the world builds its `GroundTop`.
    ///
    /// # Errors
    /// [`AnalysisError::Parameter`] (`support`) for a body not on the
    /// ground; [`AnalysisError::Body`] for a gravity not along −z or
    /// contact parameters the engine refuses; as
    /// [`BodyOnGround::try_from_ground_top`].
    pub fn try_from_body(body: &Body, gravity: DVec3) -> Result<Self, AnalysisError> {
        Self::try_from_ground_top(&ground_top_of(body, gravity)?)
    }

    /// Whether the body rolls without slipping (state `(γ, ω)`; else
    /// `(γ, ω, v)`).
    pub fn rolls(&self) -> bool {
        self.body.friction == Friction::Rolling
    }

    /// The friction law.
    pub fn friction(&self) -> Friction {
        self.body.friction
    }

    /// The steady spin at `spin` rad/s about the vertical with the body
    /// axis `up_body` pointing up: `γ = û`, `ω = spin û`, `v = 0`.
    ///
    /// ```text
    /// steady iff ω × Iω = 0 and r(û) ∥ û   (spin about a principal axis, the
    /// centre of mass straight above the contact)
    /// ```
    ///
    /// # Errors
    /// [`AnalysisError::Parameter`] for a non-finite or zero `up_body` or
    /// spin; [`AnalysisError::NoSuchMotion`] (with the residual) if that
    /// spin is not steady.
    pub fn spinning_about_vertical(
        &self,
        up_body: DVec3,
        spin: f64,
    ) -> Result<Vec<f64>, AnalysisError> {
        if !(up_body.is_finite() && up_body.length() > 0.0) {
            return Err(AnalysisError::Parameter {
                name: "up_body",
                value: up_body.length(),
                must: "a finite, non-zero body vector",
            });
        }
        if !spin.is_finite() {
            return Err(AnalysisError::Parameter {
                name: "spin",
                value: spin,
                must: "finite (rad/s)",
            });
        }
        let up = up_body.normalize();
        let mut x: Vec<f64> = up
            .to_array()
            .into_iter()
            .chain((up * spin).to_array())
            .collect();
        if !self.rolls() {
            x.extend([0.0; 3]);
        }
        let residual = relative_residual(self, &x, &jacobian(self, &x));
        if residual > STEADY_RESIDUAL || !residual.is_finite() {
            return Err(AnalysisError::NoSuchMotion {
                kind: "steady spin about the vertical",
                why: format!(
                    "with body axis {up_body} up the relative residual is {residual:.3e}: \
                     not a principal axis of inertia, or the centre of mass not above the contact"
                ),
            });
        }
        Ok(x)
    }

    /// The normal force `N` at the state `x`, newtons (`m g` at a steady
    /// motion); `None` when rolling (the reaction has three components).
    pub fn normal_force(&self, x: &[f64]) -> Option<f64> {
        if self.rolls() || x.len() != 9 {
            return None;
        }
        let (_, _, n) =
            self.body
                .sliding_rates([x[0], x[1], x[2]], [x[3], x[4], x[5]], [x[6], x[7], x[8]]);
        Some(n)
    }

    /// The parts of the equations the families share.
    pub(crate) fn contact_body(&self) -> &ContactBody {
        &self.body
    }
}

/// `(γ, ω, v)` of a state (`v = 0` when rolling: not used).
fn split<D: Scalar>(x: &[D]) -> (V3<D>, V3<D>, V3<D>) {
    let v = if x.len() == 9 {
        [x[6], x[7], x[8]]
    } else {
        [D::from(0.0); 3]
    };
    ([x[0], x[1], x[2]], [x[3], x[4], x[5]], v)
}

impl VectorField for BodyOnGround {
    fn dim(&self) -> usize {
        if self.rolls() { 6 } else { 9 }
    }

    fn state_names(&self) -> Vec<String> {
        let mut names: Vec<String> = ["γ_x", "γ_y", "γ_z"]
            .into_iter()
            .map(String::from)
            .chain(["ω_x (rad/s)", "ω_y (rad/s)", "ω_z (rad/s)"].map(String::from))
            .collect();
        if !self.rolls() {
            names.extend(["v_x (m/s)", "v_y (m/s)", "v_z (m/s)"].map(String::from));
        }
        names
    }

    fn rates<D: Scalar>(&self, x: &[D], dx: &mut [D]) {
        let (gamma, omega, v) = split(x);
        let gamma_rate = cross(gamma, omega);
        dx[..3].copy_from_slice(&gamma_rate);
        if self.rolls() {
            let omega_rate = self.body.rolling_omega_rate(gamma, omega, omega);
            dx[3..6].copy_from_slice(&omega_rate);
        } else {
            let (omega_rate, v_rate, _) = self.body.sliding_rates(gamma, omega, v);
            dx[3..6].copy_from_slice(&omega_rate);
            dx[6..9].copy_from_slice(&v_rate);
        }
    }

    fn conserved<D: Scalar>(&self, x: &[D]) -> Vec<(ZeroMode, D)> {
        let (gamma, omega, v) = split(x);
        let b = &self.body;
        let mut out = vec![(
            ZeroMode::new(ZeroModeKind::Casimir, "|γ|²"),
            dot(gamma, gamma),
        )];
        let energy = if self.rolls() {
            let (r, _) = b.surface.com_from_contact(gamma, [D::from(0.0); 3]);
            b.energy(gamma, omega, cross(omega, r))
        } else {
            let (r, _) = b.surface.com_from_contact(gamma, [D::from(0.0); 3]);
            let slip = sub(v, cross(omega, r));
            out.push((
                ZeroMode::new(
                    ZeroModeKind::Casimir,
                    "γ·v_P (the contact point's vertical velocity: it stays on the plane)",
                ),
                dot(gamma, slip),
            ));
            b.energy(gamma, omega, v)
        };
        if self.symmetry_axis.is_some() {
            out.push((
                ZeroMode::new(ZeroModeKind::Momentum, "Jellett's λ = L·r"),
                b.jellett(gamma, omega),
            ));
        }
        if matches!(b.friction, Friction::None | Friction::Rolling) {
            out.push((ZeroMode::new(ZeroModeKind::Energy, "E"), energy));
        }
        if b.friction == Friction::None {
            let l = mat_vec(&b.inertia, omega);
            out.push((
                ZeroMode::new(
                    ZeroModeKind::Momentum,
                    "L·γ (the vertical angular momentum)",
                ),
                dot(l, gamma),
            ));
        }
        out
    }

    fn symmetry_directions(&self, x: &[f64]) -> Vec<(ZeroMode, Vec<f64>)> {
        let (gamma, omega, v) = split(x);
        let mut out = Vec::new();
        let pad = |mut d: Vec<f64>| {
            d.resize(self.dim(), 0.0);
            d
        };
        // The steady spins about the vertical at other rates, `δω = γ`:
        // Jellett's λ and L·γ tell them apart, and the energy does unless
        // the body is at rest; otherwise they are a family of their own.
        let dissipative = matches!(
            self.body.friction,
            Friction::Viscous { .. } | Friction::Sliding { .. }
        );
        let at_rest = omega == [0.0; 3] && self.body.friction == Friction::Rolling;
        if self.symmetry_axis.is_none() && (dissipative || at_rest) {
            let d: Vec<f64> = [0.0; 3].into_iter().chain(gamma).collect();
            out.push((
                ZeroMode::new(
                    ZeroModeKind::Symmetry,
                    "a steady spin about the vertical at another rate",
                ),
                pad(d),
            ));
        }
        if let Some(axis) = self.symmetry_axis {
            let a = axis.to_array();
            let mut d: Vec<f64> = cross(a, gamma).into_iter().chain(cross(a, omega)).collect();
            if !self.rolls() {
                d.extend(cross(a, v));
            }
            // On the axis (spinning upright or inverted) the rotation
            // moves nothing: no zero of its own. A state found by Newton's
            // method lies there only to its tolerance, so a direction below
            // 1e-8 of the state counts as none.
            let size = |u: &[f64]| u.iter().map(|c| c * c).sum::<f64>().sqrt();
            if size(&d) <= 1e-8 * size(x) {
                return out;
            }
            out.push((
                ZeroMode::new(
                    ZeroModeKind::Symmetry,
                    "rotation about the body's axis of symmetry",
                ),
                d,
            ));
        }
        out
    }

    /// At a spin about the vertical (`γ ∥ ω`) the body axes turn at
    /// `Ω = ω·γ̂` about it; a circular mode (its transverse `δγ`, or `δv`
    /// where `δγ = 0`, turns about `γ̂` at the signed rate `ω_b`) is seen in
    /// space at `|ω_b + Ω|`.
    ///
    /// ```text
    /// ω_b = Im λ · (−Im(v̄ × v)·γ̂)/|v_⊥|²,   circular iff |Im(v̄ × v)·γ̂| = |v_⊥|² (to 1e-6)
    /// ```
    fn space_frequency(
        &self,
        x: &[f64],
        eigenvalue: Eigenvalue,
        shape: &[Eigenvalue],
    ) -> Option<f64> {
        let up = DVec3::new(x[0], x[1], x[2]).normalize();
        let omega = DVec3::new(x[3], x[4], x[5]);
        if up.cross(omega).length() > 1e-12 * omega.length().max(f64::MIN_POSITIVE) {
            return None;
        }
        let part = |k: usize| {
            let re = DVec3::new(shape[k].re, shape[k + 1].re, shape[k + 2].re);
            let im = DVec3::new(shape[k].im, shape[k + 1].im, shape[k + 2].im);
            (re - up * up.dot(re), im - up * up.dot(im))
        };
        let (mut re, mut im) = part(0);
        if re.length_squared() + im.length_squared() < 1e-20 && shape.len() == 9 {
            (re, im) = part(6);
        }
        let size = re.length_squared() + im.length_squared();
        // Im(v̄ × v) = 2 re × im.
        let turn = -2.0 * re.cross(im).dot(up);
        if size == 0.0 || (turn.abs() / size - 1.0).abs() > 1e-6 {
            return None;
        }
        Some((eigenvalue.im * turn / size + omega.dot(up)).abs())
    }

    fn reduced_by(&self) -> Vec<String> {
        vec![
            "translations of the ground plane (the position: two directions)".into(),
            "rotation about the vertical (the heading)".into(),
        ]
    }

    fn is_conservative(&self) -> bool {
        matches!(self.body.friction, Friction::None | Friction::Rolling)
    }
}
