//! The errors of the scene layer: [`SceneError`] for a scene file, a mesh
//! request or a heavy-top request that cannot be turned into an answer,
//! and [`BodyProblem`] for one body of a mesh file. Every message is one
//! line ([`one_line`]) naming the file, line and key or the argument, so
//! a client prints it as it is.

use std::io;
use std::path::PathBuf;

use kreisel_dynamics::{DynamicsError, FreeBodyMethod, HeavyTopMethod};
use kreisel_inertia::InertiaError;

use crate::body_key::BodyKeyProblem;
use crate::contact_key::ContactKeyProblem;
use crate::numbers::Shortest;

/// Everything that makes a scene, mesh or heavy-top request fail.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// A mesh file cannot be read or parsed (the library's message names the file).
    #[error("{}", one_line(&source.to_string()))]
    LoadMesh {
        /// The library's description of the problem.
        source: InertiaError,
    },
    /// A mesh file that parses but holds no body with triangles.
    #[error("{}: the file holds no mesh bodies", path.display())]
    NoBodies {
        /// The mesh file.
        path: PathBuf,
    },
    /// One body of a mesh file has no mass properties under the chosen model.
    #[error("{}: body '{}': {}", path.display(), one_line(body), problem)]
    Body {
        /// The mesh file.
        path: PathBuf,
        /// The body's name in the file.
        body: String,
        /// What went wrong.
        problem: BodyProblem,
    },
    /// `--mass` cannot be spread over the bodies: their total volume is too
    /// small (or too large) for a finite positive density.
    #[error(
        "{}: total volume {} m^3 gives no finite positive density for --mass {} kg",
        path.display(),
        Shortest(*volume),
        Shortest(*mass)
    )]
    DerivedDensity {
        /// The mesh file.
        path: PathBuf,
        /// The total mass asked for, kg.
        mass: f64,
        /// The total volume of the bodies, m³.
        volume: f64,
    },
    /// The scene file cannot be read.
    #[error("cannot read scene file {}: {source}", path.display())]
    ReadScene {
        /// The path as given.
        path: PathBuf,
        /// The operating system's reason.
        source: io::Error,
    },
    /// A problem in the scene file: `SCENE:LINE: message` (`SCENE: message`
    /// for a problem of the file as a whole).
    #[error("{}{}: {message}", path.display(), line.map(|l| format!(":{l}")).unwrap_or_default())]
    Scene {
        /// The scene file as given.
        path: PathBuf,
        /// The 1-based line of the offending key or table, when there is one.
        line: Option<u64>,
        /// What is wrong, naming the key (one line).
        message: String,
    },
    /// A body's keys that do not fit together, or that the library
    /// refuses: `SCENE:LINE: body `name`: message`, with the problem typed
    /// (which key, which value, which contact) for programs.
    #[error("{}:{line}: {message}", path.display())]
    Key {
        /// The scene file as given.
        path: PathBuf,
        /// The 1-based line of the offending key or table.
        line: u64,
        /// The body's name.
        body: String,
        /// What is wrong, typed (boxed: the error stays small).
        problem: Box<KeyProblem>,
        /// The same in words, naming the body and the key (one line).
        message: String,
    },
    /// A parameter of a request with a value that cannot be used, named as
    /// the CLI's option (`--i1`; Python names its keyword instead).
    #[error("{argument}: {message}")]
    Argument {
        /// The option as written on the command line (`--i1`).
        argument: String,
        /// What is wrong with its value (one line).
        message: String,
    },
    /// The library cannot solve the heavy top for these parameters.
    #[error("heavy top: {}", one_line(&error.to_string()))]
    Top {
        /// The library's error.
        error: DynamicsError,
    },
    /// The method the user named cannot be used.
    #[error("--method: {problem}")]
    Method {
        /// What is wrong with it.
        problem: MethodProblem,
    },
}

/// A typed problem with a body's keys ([`SceneError::Key`]): the body's
/// own, or one of its contacts'.
#[derive(Debug, Clone, PartialEq)]
pub enum KeyProblem {
    /// The body's keys ([`BodyKeyProblem`]).
    Body(BodyKeyProblem),
    /// Its contacts' keys ([`ContactKeyProblem`]).
    Contact {
        /// The contact, 0-based (none: the list as a whole).
        contact: Option<usize>,
        /// What is wrong.
        problem: ContactKeyProblem,
    },
}

/// Why a method the user named cannot move the scene.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MethodProblem {
    /// No method has that name (the library's error lists the known ones).
    #[error("{0}")]
    Unknown(DynamicsError),
    /// The method has no heavy-top version, and a body has a pivot.
    #[error(
        "method `{method}` cannot move a body with a `pivot` (a heavy top); use one of {}",
        HeavyTopMethod::ALL.map(HeavyTopMethod::name).join(", ")
    )]
    NoHeavyTopVersion {
        /// The method named.
        method: FreeBodyMethod,
    },
}

/// Why the mass properties of one body of a mesh file cannot be computed.
#[derive(Debug, thiserror::Error)]
pub enum BodyProblem {
    /// Scaling made a coordinate overflow to infinity.
    #[error("coordinates overflow when scaled by {}", Shortest(*scale))]
    ScaleOverflow {
        /// The scale factor.
        scale: f64,
    },
    /// The library rejected the body; for surfaces that enclose no well-defined
    /// volume the message says what gives the right answer, if anything.
    #[error("{}{}", one_line(&source.to_string()), solid_hint(source))]
    Inertia {
        /// The library's description of the problem.
        #[from]
        source: InertiaError,
    },
    /// The body is open along cracks that welding within `weld` metres
    /// closes (checked).
    #[error("{}; rerun with --weld {} to close them", one_line(&source.to_string()), Shortest(*weld))]
    Cracks {
        /// The library's description of the body's problem.
        source: InertiaError,
        /// A weld tolerance that closes the body, m.
        weld: f64,
    },
    /// The body is open, but all bodies of the file together are closed.
    #[error(
        "{}; the file's bodies together form a closed surface: rerun with --merge to treat them as one solid",
        one_line(&source.to_string())
    )]
    ClosedOnlyMerged {
        /// The library's description of the body's problem.
        source: InertiaError,
    },
}

/// What gives the right answer when a mesh is no closed, orientable surface
/// and neither welding nor merging closes it: the models that hold only for
/// some shapes, said so (never advice that silently gives a wrong mass).
fn solid_hint(error: &InertiaError) -> String {
    const OPEN_ON_PURPOSE: &str = "; if the surface is open on purpose, --shell models a thin-walled part (see --thickness) and --hull a convex one";
    match error {
        InertiaError::OpenMesh { .. } | InertiaError::NonManifold { .. } => OPEN_ON_PURPOSE.into(),
        InertiaError::MeshOutOfRange { .. } => {
            " (set with --units or --scale S, metres per mesh unit)".into()
        }
        InertiaError::NonOrientable { .. } => {
            "; it bounds no volume, but --shell models it as a thin wall (see --thickness)".into()
        }
        _ => String::new(),
    }
}

/// The text with line breaks replaced by spaces, so an error stays one line.
pub fn one_line(text: &str) -> String {
    text.replace(['\r', '\n'], " ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn open_mesh_error_names_file_body_and_options() {
        let e = SceneError::Body {
            path: PathBuf::from("part.obj"),
            body: "lid\nx".into(),
            problem: BodyProblem::from(InertiaError::OpenMesh {
                boundary_edges: 4,
                at: glam::DVec3::new(1.0, 0.5, 0.0),
                weld_gap: None,
            }),
        };
        let text = e.to_string();
        assert!(
            text.starts_with("part.obj: body 'lid x': mesh is open: 4 boundary edges"),
            "{text}"
        );
        assert!(
            text.contains("--shell") && text.contains("--hull"),
            "{text}"
        );
        assert!(!text.contains('\n'));
        let e = BodyProblem::from(InertiaError::ZeroVolume);
        assert!(!e.to_string().contains("--hull"));
    }
}
