//! Test helpers and test problems shared by the integration tests of
//! kreisel-dynamics; the root package's benches, examples and tests include
//! the problems they share by path (`#[path = ".../common/NAME.rs"]`), so
//! each is defined once.
#![allow(dead_code)]

pub mod bounces;
pub mod bouncing_ball;
pub mod coin;
pub mod contact;
pub mod euler_disk;
pub mod forced_refs;
pub mod free_body;
pub mod heavy_top;
pub mod reference_csv;
pub mod tippe_top;

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
