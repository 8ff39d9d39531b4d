//! [`RollingDisk`]: a coin rolling without slipping on its rim, in axes
//! that turn with the contact (Resal's frame), where rolling straight and
//! rolling in a circle are equilibria.

use glam::{DMat3, DVec3};
use kreisel_dynamics::{Body, ContactShape, DiskContact, Friction, GroundTop};
use nalgebra::DMatrix;
use num_dual::Dual64;

use super::algebra::{V3, cross};
use super::contact_equations::ContactBody;
use super::contact_equations::ground_top_of;
use super::surface::Surface;
use crate::vector_field::{conserved_gradients, jacobian};
use crate::{AnalysisError, Scalar, VectorField, ZeroMode, ZeroModeKind};

/// A disk of radius `a`, mass `m`, moments `I₁` (across) and `I₃` (about
/// its axis `n`) about its centre, which is the centre of mass, rolling
/// on its rim.
///
/// The coordinates are in Resal's frame: `e₃ = n`, `e₁` in the disk's
/// plane towards its highest point, `e₂ = e₃ × e₁` horizontal. The frame
/// turns at `Ω_F = (ω₁, ω₂, γ₃ ω₁/γ₁)`, which keeps `γ₂ = 0`; the disk is
/// symmetric about `n`, so its equations there are the body's with `Ω_F`
/// for the frame's rate:
///
/// ```text
/// x = (γ₁, γ₃, ω₁, ω₂, ω₃),   γ̇₁ = −γ₃ ω₂,   γ̇₃ = γ₁ ω₂
/// [I + m(|r|² 𝟙 − r rᵀ)] ω̇ = −Ω_F × Iω − m r × (ω × ṙ + Ω_F × (ω × r) + g γ),   r = a γ̂_plane
/// conserved: γ₁² + γ₃² (Casimir),  E = ½ m |ω × r|² + ½ ω·Iω + m g γ·r
/// steady:    ω₂ = 0 and ω̇₂ = 0  (Ω_F = (ω₁/γ₁) γ: precession about the vertical)
/// straight:  γ = e₁, ω = (V/a) e₃,  stable iff V² > m g a³ I₁ / (I₃ (I₃ + m a²))
///            wobble ω_w² = ((I₃ + m a²) I₃ V²/(a² I₁) − m g a) / (I₁ + m a²)
/// ```
///
/// (thin disk `I₁ = m a²/4`, `I₃ = m a²/2`: `V² > g a/3`, the bound of
/// O'Reilly on rolling and sliding disks, Nonlinear Dynamics (1996)). The linearised tilt and yaw,
/// `(I₁ + m a²) θ̈ = m g a θ − (I₃ + m a²)(V/a) ψ̇`, `I₁ ψ̈ = I₃ (V/a) θ̇`,
/// give the threshold and the wobble. The steady motions near one form a
/// two-parameter family (tilt and precession rate); at a fixed energy one
/// direction of it is left, a zero eigenvalue named as a symmetry
/// direction (Chaplygin's two further integrals, hypergeometric, tell those
/// circles apart; they are not written here).
///
/// ```
/// use kreisel_analysis::{Linearisation, RollingDisk, Verdict};
/// let coin = RollingDisk::thin(0.005, 0.01, 9.81)?;
/// let v_c = coin.straight_threshold_speed();
/// assert!((v_c * v_c - 9.81 * 0.01 / 3.0).abs() < 1e-15);
/// let fast = Linearisation::try_new(&coin, &coin.rolling_straight(1.1 * v_c)?)?;
/// assert!(matches!(fast.verdict, Verdict::Stable { .. }));
/// let slow = Linearisation::try_new(&coin, &coin.rolling_straight(0.9 * v_c)?)?;
/// assert!(matches!(slow.verdict, Verdict::Unstable { .. }));
/// # Ok::<(), kreisel_analysis::AnalysisError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollingDisk {
    body: ContactBody,
    radius: f64,
    moments: (f64, f64),
}

impl RollingDisk {
    /// A disk of `mass` kg, `radius` m, moments `transverse_moment` (`I₁`)
    /// and `axial_moment` (`I₃`) kg m² about its centre, under gravity
    /// `gravity` m/s².
    ///
    /// # Errors
    /// [`AnalysisError::Body`] for numbers the engine refuses.
    pub fn try_new(
        mass: f64,
        radius: f64,
        transverse_moment: f64,
        axial_moment: f64,
        gravity: f64,
    ) -> Result<Self, AnalysisError> {
        let rim = DiskContact::try_new(radius, DVec3::ZERO, DVec3::Z)?;
        let i = DMat3::from_diagonal(DVec3::new(
            transverse_moment,
            transverse_moment,
            axial_moment,
        ));
        let top = GroundTop::try_with_shape(
            mass,
            i,
            ContactShape::Disk(rim),
            Friction::Rolling,
            gravity,
        )?;
        Self::try_from_ground_top(&top)
    }

    /// A thin uniform disk: `I₁ = m a²/4`, `I₃ = m a²/2`.
    ///
    /// # Errors
    /// As [`RollingDisk::try_new`].
    pub fn thin(mass: f64, radius: f64, gravity: f64) -> Result<Self, AnalysisError> {
        let ma2 = mass * radius * radius;
        Self::try_new(mass, radius, 0.25 * ma2, 0.5 * ma2, gravity)
    }

    /// The engine's body on the ground, if it is a disk rolling on its
    /// rim, centred at its centre of mass, `I` symmetric about its axis.
    ///
    /// # Errors
    /// [`AnalysisError::Parameter`] (`shape`, `friction`) otherwise;
    /// [`AnalysisError::Parameter`] (`inputs`) for applied loads.
    pub fn try_from_ground_top(top: &GroundTop) -> Result<Self, AnalysisError> {
        let engine = ContactBody::of(top)?;
        if engine.friction != Friction::Rolling {
            return Err(AnalysisError::Parameter {
                name: "friction",
                value: f64::NAN,
                must: "rolling (Friction::Rolling)",
            });
        }
        let Surface::Disk { radius, axis, .. } = engine.surface else {
            return Err(AnalysisError::Parameter {
                name: "shape",
                value: f64::NAN,
                must: "a disk rim",
            });
        };
        let n = DVec3::from_array(axis);
        let offset = engine.surface.center().length();
        if offset > 1e-12 * radius || !engine.symmetric_about(n) {
            return Err(AnalysisError::Parameter {
                name: "shape",
                value: offset,
                must: "a rim centred at the centre of mass, I symmetric about its axis",
            });
        }
        let i = engine.inertia_matrix();
        let across = n.any_orthonormal_vector();
        let moments = (across.dot(i * across), n.dot(i * n));
        let in_frame = DMat3::from_diagonal(DVec3::new(moments.0, moments.0, moments.1));
        let rows = |m: DMat3| {
            let t = m.transpose();
            [
                t.x_axis.to_array(),
                t.y_axis.to_array(),
                t.z_axis.to_array(),
            ]
        };
        let body = ContactBody {
            inertia: rows(in_frame),
            inverse_inertia: rows(in_frame.inverse()),
            surface: Surface::Disk {
                radius,
                center: [0.0; 3],
                axis: [0.0, 0.0, 1.0],
            },
            ..engine
        };
        Ok(Self {
            body,
            radius,
            moments,
        })
    }

    /// A scene's body on the ground in a world of gravity `gravity`.
    ///
    /// # Errors
    /// As [`BodyOnGround::try_from_body`](crate::BodyOnGround::try_from_body)
    /// and [`RollingDisk::try_from_ground_top`].
    pub fn try_from_body(body: &Body, gravity: DVec3) -> Result<Self, AnalysisError> {
        Self::try_from_ground_top(&ground_top_of(body, gravity)?)
    }

    /// `(m, a, I₁, I₃, g)`.
    pub fn parameters(&self) -> (f64, f64, f64, f64, f64) {
        let b = &self.body;
        (
            b.mass,
            self.radius,
            self.moments.0,
            self.moments.1,
            b.gravity,
        )
    }

    /// Rolling straight and upright at `speed` m/s: `γ = e₁`, `ω = (V/a) e₃`.
    ///
    /// # Errors
    /// [`AnalysisError::Parameter`] for a speed that is not finite.
    pub fn rolling_straight(&self, speed: f64) -> Result<Vec<f64>, AnalysisError> {
        if !speed.is_finite() {
            return Err(AnalysisError::Parameter {
                name: "speed",
                value: speed,
                must: "finite (m/s)",
            });
        }
        Ok(vec![1.0, 0.0, 0.0, 0.0, speed / self.radius])
    }

    /// The speed (m/s) above which rolling straight is stable.
    ///
    /// ```text
    /// V_c² = m g a³ I₁ / (I₃ (I₃ + m a²))
    /// ```
    pub fn straight_threshold_speed(&self) -> f64 {
        let (m, a, i1, i3, g) = self.parameters();
        (m * g * a.powi(3) * i1 / (i3 * (i3 + m * a * a))).sqrt()
    }

    /// The wobble's angular frequency (rad/s) rolling straight at `speed`,
    /// `None` below the threshold (it grows there, at `√(−ω_w²)`).
    ///
    /// ```text
    /// ω_w² = ((I₃ + m a²) I₃ V²/(a² I₁) − m g a) / (I₁ + m a²)
    /// ```
    pub fn wobble_frequency_squared(&self, speed: f64) -> f64 {
        let (m, a, i1, i3, g) = self.parameters();
        ((i3 + m * a * a) * i3 * speed * speed / (a * a * i1) - m * g * a) / (i1 + m * a * a)
    }

    /// Rolling in a steady circle tilted by `tilt` rad from the vertical
    /// (`γ = (cos θ, 0, sin θ)`), the frame turning about the vertical at
    /// `precession` rad/s: the spin `ω₃` that makes it steady, solved from
    /// `ω̇₂ = A + B ω₃ = 0` (affine in `ω₃`). By hand, the moments about
    /// `e₂` at `r = a e₁`, `Ω_F = ψ̇ γ`:
    ///
    /// ```text
    /// ω = (ψ̇ cos θ, 0, ω₃),   ω₃ = sin θ (I₁ ψ̇² cos θ − m g a) / ((I₃ + m a²) ψ̇ cos θ)
    /// ```
    ///
    /// so a circle exists for every tilt `|θ| < π/2` and precession
    /// `ψ̇ ≠ 0`, one spin each (`ψ̇ = 0`: only upright, `θ = 0`, at any
    /// spin — rolling straight); the centre of mass runs at `a |ω₃|` on a
    /// circle of radius `a |ω₃/ψ̇|`.
    ///
    /// # Errors
    /// [`AnalysisError::Parameter`] for a tilt outside `(−π/2, π/2)` or
    /// numbers that are not finite; [`AnalysisError::NoSuchMotion`] where
    /// `B = 0` (no spin balances that tilt at that precession).
    pub fn rolling_in_circle(&self, tilt: f64, precession: f64) -> Result<Vec<f64>, AnalysisError> {
        if !(tilt.is_finite() && tilt.abs() < std::f64::consts::FRAC_PI_2) {
            return Err(AnalysisError::Parameter {
                name: "tilt",
                value: tilt,
                must: "in (−π/2, π/2) rad (the disk not flat)",
            });
        }
        if !precession.is_finite() {
            return Err(AnalysisError::Parameter {
                name: "precession",
                value: precession,
                must: "finite (rad/s)",
            });
        }
        let (c, s) = (tilt.cos(), tilt.sin());
        // A and B at once: ω̇₂ and its exact derivative in ω₃ at ω₃ = 0.
        let x = [c, s, precession * c, 0.0, 0.0].map(Dual64::from);
        let mut x = x;
        x[4] = Dual64::new(0.0, 1.0);
        let mut dx = [Dual64::from(0.0); 5];
        self.rates(&x, &mut dx);
        let (a0, b) = (dx[3].re, dx[3].eps);
        let spin = -a0 / b;
        if !spin.is_finite() || b.abs() <= 1e-12 * a0.abs() {
            return Err(AnalysisError::NoSuchMotion {
                kind: "steady circle",
                why: format!(
                    "at tilt {tilt} rad and precession {precession} rad/s the spin does not enter \
                     the balance of moments (B = {b:e})"
                ),
            });
        }
        Ok(vec![c, s, precession * c, 0.0, spin])
    }

    /// The frame's rate `Ω_F = (ω₁, ω₂, γ₃ ω₁/γ₁)`.
    fn frame_rate<D: Scalar>(x: &[D]) -> V3<D> {
        [x[2], x[3], x[1] * x[2] / x[0]]
    }
}

impl VectorField for RollingDisk {
    fn dim(&self) -> usize {
        5
    }

    fn state_names(&self) -> Vec<String> {
        ["γ₁", "γ₃", "ω₁ (rad/s)", "ω₂ (rad/s)", "ω₃ (rad/s)"]
            .map(String::from)
            .to_vec()
    }

    fn rates<D: Scalar>(&self, x: &[D], dx: &mut [D]) {
        let gamma = [x[0], D::from(0.0), x[1]];
        let omega = [x[2], x[3], x[4]];
        let frame = Self::frame_rate(x);
        let gamma_rate = cross(gamma, frame);
        dx[0] = gamma_rate[0];
        dx[1] = gamma_rate[2];
        let omega_rate = self.body.rolling_omega_rate(gamma, omega, frame);
        dx[2..5].copy_from_slice(&omega_rate);
    }

    fn conserved<D: Scalar>(&self, x: &[D]) -> Vec<(ZeroMode, D)> {
        let gamma = [x[0], D::from(0.0), x[1]];
        let omega = [x[2], x[3], x[4]];
        let (r, _) = self.body.surface.com_from_contact(gamma, [D::from(0.0); 3]);
        vec![
            (
                ZeroMode::new(ZeroModeKind::Casimir, "γ₁² + γ₃²"),
                x[0] * x[0] + x[1] * x[1],
            ),
            (
                ZeroMode::new(ZeroModeKind::Energy, "E"),
                self.body.energy(gamma, omega, cross(omega, r)),
            ),
        ]
    }

    /// The steady motions near `x` at its energy and `|γ|`: the direction
    /// `δ` with `δω₂ = 0`, `∇ω̇₂·δ = 0`, `∇|γ|²·δ = 0`, `∇E·δ = 0` (the
    /// smallest right singular vector of those four rows).
    fn symmetry_directions(&self, x: &[f64]) -> Vec<(ZeroMode, Vec<f64>)> {
        if x[3] != 0.0 {
            return Vec::new();
        }
        let a = jacobian(self, x);
        let mut rows: Vec<Vec<f64>> = vec![vec![0.0, 0.0, 0.0, 1.0, 0.0]];
        rows.push(a.row(3).iter().copied().collect());
        rows.extend(conserved_gradients(self, x).into_iter().map(|(_, _, g)| g));
        // Square (a zero fifth row), so that the SVD's V is complete.
        rows.resize(5, vec![0.0; 5]);
        let m = DMatrix::from_fn(5, 5, |i, k| {
            let size = rows[i].iter().map(|v| v * v).sum::<f64>().sqrt();
            if size > 0.0 { rows[i][k] / size } else { 0.0 }
        });
        let svd = m.svd(false, true);
        let Some(v_t) = svd.v_t else {
            return Vec::new();
        };
        // The right singular vector of the smallest singular value.
        let k = svd.singular_values.imin();
        vec![(
            ZeroMode::new(
                ZeroModeKind::Symmetry,
                "a neighbouring steady circle at the same energy (Chaplygin's integrals differ)",
            ),
            v_t.row(k).iter().copied().collect(),
        )]
    }

    fn reduced_by(&self) -> Vec<String> {
        vec![
            "translations of the ground plane (the position: two directions)".into(),
            "rotation about the vertical (the heading)".into(),
            "rotation about the disk's axis (the angle rolled: Resal's frame)".into(),
        ]
    }

    fn is_conservative(&self) -> bool {
        true
    }
}
