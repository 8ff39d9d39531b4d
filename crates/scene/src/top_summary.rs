//! The heavy symmetric (Lagrange) top as a request and its report: the
//! parameters and initial conditions ([`TopRequest`]) checked, solved by
//! [`kreisel_dynamics::LagrangeTop`], and the library's answers copied into
//! a [`Summary`] of plain numbers, what `kreisel top` writes and
//! `kreisel.top` returns.

use kreisel_dynamics::{
    DynamicsError, LagrangeTop, LagrangeTopInitial, LagrangeTopMotion, TopMotionKind,
};

use crate::error::SceneError;
use crate::numbers::Shortest;

/// A heavy top and its initial state (φ₀ = ψ₀ = 0), as the user gives them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TopRequest {
    /// Transverse moment of inertia about the pivot, kg m².
    pub i1: f64,
    /// Moment of inertia about the symmetry axis, kg m².
    pub i3: f64,
    /// M g l, J.
    pub mgl: f64,
    /// θ(0): the axis from the upward vertical, rad.
    pub theta0: f64,
    /// θ̇(0), rad/s.
    pub theta_dot0: f64,
    /// φ̇(0), rad/s.
    pub phi_dot0: f64,
    /// ψ̇(0), rad/s.
    pub psi_dot0: f64,
}

/// The library's answers for one top, as plain numbers.
#[derive(Debug, Clone, PartialEq)]
pub struct Summary {
    /// The top and its initial state, as given.
    pub top: TopRequest,
    /// a = p_ψ / I₁, rad/s.
    pub a: f64,
    /// b = p_φ / I₁, rad/s.
    pub b: f64,
    /// α = 2E′/I₁, 1/s².
    pub alpha: f64,
    /// β = 2Mgl/I₁, 1/s².
    pub beta: f64,
    /// The spin ω₃, rad/s.
    pub omega3: f64,
    /// Real roots of f, ascending.
    pub roots: Vec<f64>,
    /// Smallest θ, rad.
    pub theta_min: f64,
    /// Largest θ, rad.
    pub theta_max: f64,
    /// Period of θ(t), s (`None` when θ stays constant: `motion` is `None`).
    pub nutation_period: Option<f64>,
    /// Mean φ̇ over a nutation period, rad/s.
    pub mean_precession_rate: Option<f64>,
    /// `no_loops`, `loops` or `cusps`.
    pub motion: Option<&'static str>,
    /// θ₀ = 0 and θ̇₀ = 0.
    pub sleeping: bool,
    /// Whether the upright spinning top is stable (notes §3.11).
    pub sleeping_stable: bool,
}

impl Summary {
    /// The same summary with its angles in degrees: θ₀ as given
    /// (`theta0_degrees`, not converted back and forth), θ_min and θ_max
    /// by [`f64::to_degrees`].
    pub fn in_degrees(&self, theta0_degrees: f64) -> Summary {
        Summary {
            top: TopRequest {
                theta0: theta0_degrees,
                ..self.top
            },
            theta_min: self.theta_min.to_degrees(),
            theta_max: self.theta_max.to_degrees(),
            ..self.clone()
        }
    }
}

/// The name of a kind of motion in the output.
fn motion_name(kind: TopMotionKind) -> &'static str {
    match kind {
        TopMotionKind::NoLoops => "no_loops",
        TopMotionKind::Loops => "loops",
        TopMotionKind::Cusps => "cusps",
    }
}

impl TopRequest {
    /// The arguments as (option name, value), in command-line order.
    fn numbers(&self) -> [(&'static str, f64); 7] {
        [
            ("--i1", self.i1),
            ("--i3", self.i3),
            ("--mgl", self.mgl),
            ("--theta0", self.theta0),
            ("--theta-dot0", self.theta_dot0),
            ("--phi-dot0", self.phi_dot0),
            ("--psi-dot0", self.psi_dot0),
        ]
    }

    /// Checks what needs no physics (finite numbers, I₁ > 0) before the
    /// library checks the rest.
    ///
    /// # Errors
    /// [`SceneError::Argument`] naming the option.
    pub fn validate(&self) -> Result<(), SceneError> {
        for (name, value) in self.numbers() {
            if !value.is_finite() {
                return Err(argument(
                    name,
                    format!("{} is not a finite number", Shortest(value)),
                ));
            }
        }
        if self.i1 <= 0.0 {
            return Err(argument(
                "--i1",
                format!(
                    "{} kg m^2: the moment of inertia must be positive",
                    Shortest(self.i1)
                ),
            ));
        }
        Ok(())
    }

    /// The initial conditions for the library (φ₀ = ψ₀ = 0).
    fn initial(&self) -> LagrangeTopInitial {
        LagrangeTopInitial {
            theta: self.theta0,
            theta_dot: self.theta_dot0,
            phi_dot: self.phi_dot0,
            psi_dot: self.psi_dot0,
            ..LagrangeTopInitial::default()
        }
    }
}

/// An error about one command-line option.
fn argument(name: &'static str, message: String) -> SceneError {
    SceneError::Argument {
        argument: name.to_owned(),
        message,
    }
}

/// The command-line option of a parameter the library names.
fn option_name(parameter: &str) -> String {
    match parameter {
        "theta" | "theta_dot" | "phi_dot" | "psi_dot" | "phi" | "psi" => {
            format!("--{}0", parameter.replace('_', "-"))
        }
        other => format!("--{}", other.replace('_', "-")),
    }
}

/// The library's error as an error about the option it names.
fn dynamics_error(error: DynamicsError) -> SceneError {
    match error {
        DynamicsError::InvalidTop {
            parameter,
            value,
            reason,
        } => SceneError::Argument {
            argument: option_name(parameter),
            message: format!("{}: {reason}", Shortest(value)),
        },
        error => SceneError::Top { error },
    }
}

/// Solves the motion of the top the arguments describe.
///
/// # Errors
/// [`SceneError::Argument`] for a parameter the library rejects.
fn solve(args: &TopRequest) -> Result<LagrangeTopMotion, SceneError> {
    let top = LagrangeTop::try_new(args.i1, args.i3, args.mgl).map_err(dynamics_error)?;
    top.try_solve(args.initial()).map_err(dynamics_error)
}

/// Whether the axis stays on the vertical: the sleeping top (θ = 0) or
/// at rest in θ on the downward vertical (θ = π, the f64 nearest π).
pub fn on_the_vertical(motion: &LagrangeTopMotion) -> bool {
    motion.motion().is_none()
        && (motion.theta_max() == 0.0 || motion.theta_min() >= std::f64::consts::PI)
}

/// The library's answers for `motion`.
fn summarise(args: &TopRequest, motion: &LagrangeTopMotion) -> Summary {
    Summary {
        top: *args,
        a: motion.a(),
        b: motion.b(),
        alpha: motion.alpha(),
        beta: motion.beta(),
        omega3: motion.omega3(),
        roots: motion.roots(),
        theta_min: motion.theta_min(),
        theta_max: motion.theta_max(),
        // A period only for a motion that nutates (`motion` not null); on
        // the vertical (θ = 0 or π throughout) φ itself is undefined.
        nutation_period: motion.motion().and(motion.nutation_period()),
        mean_precession_rate: motion
            .mean_precession_rate()
            .filter(|_| !on_the_vertical(motion)),
        motion: motion.motion().map(motion_name),
        sleeping: motion.is_sleeping(),
        sleeping_stable: motion.sleeping_stable(),
    }
}

/// The motion of the top `args` describes and the report of it (what
/// `kreisel top` writes and `kreisel.top` returns).
///
/// ```text
/// a = p_ψ/I₁, b = p_φ/I₁, α = 2E′/I₁, β = 2Mgl/I₁;  f(u) = (α − βu)(1 − u²) − (b − au)²
/// ```
///
/// # Errors
/// [`SceneError::Argument`] for a bad parameter (naming it as the CLI's
/// option), [`SceneError::Top`] for a top the library cannot solve.
///
/// ```
/// use kreisel_scene::top_summary::{TopRequest, solve_and_summarise};
/// let top = TopRequest {
///     i1: 0.3, i3: 0.1, mgl: 2.0, theta0: 0.0,
///     theta_dot0: 0.0, phi_dot0: 0.0, psi_dot0: 200.0,
/// };
/// let (_, summary) = solve_and_summarise(&top).unwrap();
/// // Sleeping and stable: I₃²ω₃² = 400 > 4 I₁ M g l = 2.4.
/// assert!(summary.sleeping && summary.sleeping_stable);
/// assert_eq!(summary.omega3, 200.0);
/// ```
pub fn solve_and_summarise(args: &TopRequest) -> Result<(LagrangeTopMotion, Summary), SceneError> {
    args.validate()?;
    let motion = solve(args)?;
    let summary = summarise(args, &motion);
    Ok((motion, summary))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn request() -> TopRequest {
        TopRequest {
            i1: 0.3,
            i3: 0.1,
            mgl: 2.0,
            theta0: 0.5,
            theta_dot0: 0.0,
            phi_dot0: 0.0,
            psi_dot0: 60.0,
        }
    }

    #[test]
    fn validation_names_the_option() {
        let check = |change: &dyn Fn(&mut TopRequest), name: &str| {
            let mut a = request();
            change(&mut a);
            let e = a.validate().unwrap_err().to_string();
            assert!(e.starts_with(&format!("{name}: ")), "{e}");
        };
        check(&|a| a.i1 = 0.0, "--i1");
        check(&|a| a.i1 = -1.0, "--i1");
        check(&|a| a.theta_dot0 = f64::NAN, "--theta-dot0");
        check(&|a| a.psi_dot0 = f64::INFINITY, "--psi-dot0");
        assert!(request().validate().is_ok());
    }

    #[test]
    fn library_errors_name_the_option() {
        let e = dynamics_error(DynamicsError::InvalidTop {
            parameter: "theta_dot",
            value: f64::NAN,
            reason: "not finite",
        });
        assert!(e.to_string().starts_with("--theta-dot0: "), "{e}");
        assert_eq!(option_name("i3"), "--i3");
        assert_eq!(option_name("theta"), "--theta0");
    }
}
