//! The methods as types: [`FreeBodyMethod`] for the torque-free body and
//! [`HeavyTopMethod`] for the heavy top, the one registry that the CLI
//! (`--method`, `--list-methods`), the Python package, the benches and the
//! tests read.
//!
//! Each enum is declared by one list, one line per method,
//! `Variant => &INTEGRATOR` (a `&'static dyn` integrator): the list
//! generates the enum, `ALL`, `integrator()`, `FromStr` and `Display`, and
//! the name, order, description (and a free-body method's step limit) are
//! read from the integrator, so each fact is written once, in the
//! integrator's own file.
//!
//! # Adding a method
//! 1. Write the integrator in its own file: a type implementing
//!    [`crate::FreeBodyIntegrator`] (or [`crate::HeavyTopIntegrator`]) with
//!    its name, order, one-line description, measured step limit (if any),
//!    citation and step, and a constant of it.
//! 2. Add one line to the list in `method/free_body.rs` (or
//!    `method/heavy_top.rs`): `/// docs` and `Variant => &INTEGRATOR,`.
//!
//! `method/forward_euler.rs` does exactly that in a test: forward Euler,
//! one file, and one extra line given to the list.

#[cfg(test)]
mod forward_euler;
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

/// What both method enums share: the enum itself (`auto` first and the
/// default), `ALL`, `FromStr` and `Display`, all by the `name()` that
/// each enum's own list defines.
macro_rules! method_enum {
    (
        $(#[$attr:meta])*
        $vis:vis enum $Name:ident {
            $(#[$auto_doc:meta])* Auto,
            $($(#[$doc:meta])* $Variant:ident),+
        }
    ) => {
        $(#[$attr])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
        $vis enum $Name {
            $(#[$auto_doc])*
            #[default]
            Auto,
            $($(#[$doc])* $Variant,)+
        }

        impl $Name {
            /// Every method, `auto` first, in the list's order: the order of
            /// `--list-methods`.
            pub const ALL: [Self; 1 + [$(stringify!($Variant)),+].len()] =
                [Self::Auto, $(Self::$Variant),+];
        }

        impl ::std::str::FromStr for $Name {
            type Err = $crate::DynamicsError;

            /// The method called `name` (exactly as `name()` writes it).
            ///
            /// # Errors
            /// [`DynamicsError::UnknownMethod`](crate::DynamicsError::UnknownMethod)
            /// listing every name of `ALL`.
            fn from_str(name: &str) -> Result<Self, Self::Err> {
                Self::ALL
                    .into_iter()
                    .find(|m| m.name() == name)
                    .ok_or_else(|| $crate::method::unknown_method(name, &Self::ALL.map(Self::name)))
            }
        }

        impl ::std::fmt::Display for $Name {
            /// The name; width and alignment apply (`{:<12}`).
            fn fmt(&self, f: &mut ::std::fmt::Formatter<'_>) -> ::std::fmt::Result {
                f.pad(self.name())
            }
        }
    };
}
#[cfg(test)]
pub(crate) use self::free_body::free_body_methods;
pub(crate) use method_enum;
