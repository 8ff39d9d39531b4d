//! The methods as types: [`FreeBodyMethod`] for the torque-free body and
//! [`HeavyTopMethod`] for the heavy top. Each is an enum with `ALL`, a
//! name, an order, a one-line description, `FromStr` and the integrator
//! it builds, so that the CLI (`--method`, `--list-methods`), the benches
//! and the tests read one list: adding a method is one integrator file and
//! one variant here.
//!
//! The string registries ([`crate::METHODS`], [`crate::method`],
//! [`crate::HEAVY_TOP_METHODS`], [`crate::heavy_top_method`],
//! [`crate::AUTO`]) are thin wrappers over these enums.

mod free_body;
mod heavy_top;
mod step_limit;

pub use self::free_body::FreeBodyMethod;
pub use self::heavy_top::HeavyTopMethod;
pub use self::step_limit::STEP_LIMIT_ENERGY_ERROR;

use crate::DynamicsError;

/// The error for a name that none of `names` is: the name and the known
/// names, comma-separated, in the order given.
fn unknown_method(name: &str, names: &[&str]) -> DynamicsError {
    DynamicsError::UnknownMethod {
        name: name.to_owned(),
        known: names.join(", "),
    }
}
