//! Test helpers shared by the integration tests of kreisel-dynamics.
#![allow(dead_code)]

pub mod forced_refs;

use kreisel_dynamics::{Body, PrincipalState};

/// The principal-frame state of `body` as given.
pub fn initial(body: &Body) -> PrincipalState {
    PrincipalState::try_from_omega_body(
        body.rigid_body(),
        body.world_from_body(),
        body.omega_body(),
    )
    .unwrap()
}
